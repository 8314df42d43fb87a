#include "protocols/common/ConfigReader.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace ocu {

using nlohmann::json;

// A small recursive-descent JSON parser: nlohmann's DOM does not keep source positions, and the
// configuration's messages must name the line of the offending key.
class ConfigJsonParser {
public:
    ConfigJsonParser(std::string_view text, ConfigDocument& doc) : m_text(text), m_doc(doc) {}

    Result<bool> run() {
        skipWs();
        json root;
        if (!value(root, "", 0))
            return fail();
        skipWs();
        if (m_pos != m_text.size()) {
            m_error = "unexpected characters after the JSON document";
            return fail();
        }
        *m_doc.m_root = std::move(root);
        return true;
    }

private:
    Error fail() {
        std::ostringstream os;
        os << m_doc.m_fileName << ":" << m_line << ": JSON syntax error: " << m_error;
        return Error{os.str()};
    }
    void skipWs() {
        while (m_pos < m_text.size()) {
            char c = m_text[m_pos];
            if (c == '\n')
                ++m_line;
            if (c == ' ' || c == '\t' || c == '\r' || c == '\n')
                ++m_pos;
            else
                break;
        }
    }
    bool expect(char c) {
        skipWs();
        if (m_pos < m_text.size() && m_text[m_pos] == c) {
            ++m_pos;
            return true;
        }
        m_error = std::string("expected '") + c + "'";
        return false;
    }
    static std::string escapePointer(const std::string& key) {
        std::string out;
        for (char c : key) {
            if (c == '~')
                out += "~0";
            else if (c == '/')
                out += "~1";
            else
                out += c;
        }
        return out;
    }
    bool value(json& out, const std::string& pointer, int depth) {
        if (depth > 64) {
            m_error = "nesting deeper than 64 levels";
            return false;
        }
        skipWs();
        m_doc.m_lines[pointer] = m_line;
        if (m_pos >= m_text.size()) {
            m_error = "unexpected end of file";
            return false;
        }
        char c = m_text[m_pos];
        if (c == '{') {
            ++m_pos;
            out = json::object();
            skipWs();
            if (m_pos < m_text.size() && m_text[m_pos] == '}') {
                ++m_pos;
                return true;
            }
            for (;;) {
                skipWs();
                int keyLine = m_line;
                std::string key;
                if (!string(key))
                    return false;
                if (out.contains(key)) {
                    m_error = "duplicate key \"" + key + "\"";
                    return false;
                }
                if (!expect(':'))
                    return false;
                std::string child = pointer + "/" + escapePointer(key);
                json v;
                if (!value(v, child, depth + 1))
                    return false;
                m_doc.m_lines[child] = keyLine;
                out[key] = std::move(v);
                skipWs();
                if (m_pos < m_text.size() && m_text[m_pos] == ',') {
                    ++m_pos;
                    continue;
                }
                return expect('}');
            }
        }
        if (c == '[') {
            ++m_pos;
            out = json::array();
            skipWs();
            if (m_pos < m_text.size() && m_text[m_pos] == ']') {
                ++m_pos;
                return true;
            }
            for (std::size_t i = 0;; ++i) {
                json v;
                if (!value(v, pointer + "/" + std::to_string(i), depth + 1))
                    return false;
                out.push_back(std::move(v));
                skipWs();
                if (m_pos < m_text.size() && m_text[m_pos] == ',') {
                    ++m_pos;
                    continue;
                }
                return expect(']');
            }
        }
        if (c == '"') {
            std::string s;
            if (!string(s))
                return false;
            out = std::move(s);
            return true;
        }
        if (m_text.substr(m_pos, 4) == "true") {
            m_pos += 4;
            out = true;
            return true;
        }
        if (m_text.substr(m_pos, 5) == "false") {
            m_pos += 5;
            out = false;
            return true;
        }
        if (m_text.substr(m_pos, 4) == "null") {
            m_pos += 4;
            out = nullptr;
            return true;
        }
        return number(out);
    }
    bool number(json& out) {
        std::size_t start = m_pos;
        if (m_pos < m_text.size() && m_text[m_pos] == '-')
            ++m_pos;
        bool isFloat = false;
        while (m_pos < m_text.size()) {
            char c = m_text[m_pos];
            if (c >= '0' && c <= '9') {
                ++m_pos;
            } else if (c == '.' || c == 'e' || c == 'E' || ((c == '+' || c == '-') && isFloat)) {
                isFloat = true;
                ++m_pos;
            } else {
                break;
            }
        }
        std::string tok(m_text.substr(start, m_pos - start));
        if (tok.empty() || tok == "-") {
            m_error = "unexpected character '" + std::string(1, m_text[start]) + "'";
            return false;
        }
        try {
            out = json::parse(tok);
        } catch (const std::exception&) {
            m_error = "malformed number '" + tok + "'";
            return false;
        }
        return true;
    }
    bool string(std::string& out) {
        skipWs();
        if (m_pos >= m_text.size() || m_text[m_pos] != '"') {
            m_error = "expected a string in double quotes";
            return false;
        }
        std::size_t start = m_pos++;
        while (m_pos < m_text.size() && m_text[m_pos] != '"') {
            if (m_text[m_pos] == '\\')
                ++m_pos;
            if (m_pos < m_text.size() && m_text[m_pos] == '\n') {
                m_error = "line break inside a string";
                return false;
            }
            ++m_pos;
        }
        if (m_pos >= m_text.size()) {
            m_error = "unterminated string";
            return false;
        }
        ++m_pos;
        try {
            out = json::parse(m_text.substr(start, m_pos - start)).get<std::string>();
        } catch (const std::exception&) {
            m_error = "malformed string escape";
            return false;
        }
        return true;
    }

    std::string_view m_text;
    ConfigDocument& m_doc;
    std::size_t m_pos = 0;
    int m_line = 1;
    std::string m_error;
};

ConfigDocument::ConfigDocument() : m_root(std::make_unique<json>(json::object())) {}
ConfigDocument::~ConfigDocument() = default;
ConfigDocument::ConfigDocument(ConfigDocument&&) noexcept = default;
ConfigDocument& ConfigDocument::operator=(ConfigDocument&&) noexcept = default;

const json& ConfigDocument::root() const {
    return *m_root;
}

int ConfigDocument::lineOf(const std::string& pointer) const {
    auto it = m_lines.find(pointer);
    return it == m_lines.end() ? 0 : it->second;
}

Result<ConfigDocument> ConfigDocument::parse(std::string_view text, std::string fileName) {
    ConfigDocument doc;
    doc.m_fileName = std::move(fileName);
    ConfigJsonParser parser(text, doc);
    auto r = parser.run();
    if (!r)
        return Error{r.error()};
    return doc;
}

Result<ConfigDocument> ConfigDocument::load(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return Error{path + ": cannot open the file"};
    std::ostringstream ss;
    ss << in.rdbuf();
    std::string text = ss.str();
    if (text.size() > 64 * 1024 * 1024)
        return Error{path + ": file larger than 64 MiB"};
    return parse(text, path);
}

std::string ConfigErrors::joined() const {
    std::string out;
    for (auto& m : m_messages) {
        if (!out.empty())
            out += "\n";
        out += m;
    }
    return out;
}

ConfigObject::ConfigObject(const ConfigDocument& doc, std::string pointer, ConfigErrors& errors)
    : m_doc(&doc), m_pointer(std::move(pointer)), m_errors(&errors) {
    const json* j = &doc.root();
    if (!m_pointer.empty()) {
        try {
            j = &doc.root().at(json::json_pointer(m_pointer));
        } catch (const std::exception&) {
            j = nullptr;
        }
    }
    if (j && j->is_object()) {
        m_json = j;
        m_valid = true;
    } else {
        std::ostringstream os;
        os << doc.fileName() << ":" << doc.lineOf(m_pointer) << ": "
           << (m_pointer.empty() ? std::string("document") : m_pointer.substr(1))
           << ": must be a JSON object";
        errors.add(os.str());
    }
}

ConfigObject::~ConfigObject() = default;

static std::string displayPath(const std::string& pointer) {
    std::string p = pointer.empty() ? "" : pointer.substr(1);
    std::replace(p.begin(), p.end(), '/', '.');
    return p;
}

std::string ConfigObject::where(std::string_view key) const {
    std::string ptr = m_pointer + "/" + std::string(key);
    int line = m_doc->lineOf(ptr);
    if (line == 0)
        line = m_doc->lineOf(m_pointer);
    std::ostringstream os;
    os << m_doc->fileName() << ":" << line << ": " << displayPath(ptr);
    return os.str();
}

void ConfigObject::error(std::string_view key, std::string_view message) {
    m_errors->add(where(key) + ": " + std::string(message));
}

bool ConfigObject::has(std::string_view key) const {
    return m_json && m_json->contains(std::string(key));
}

const json* ConfigObject::find(std::string_view key) {
    m_known.insert(std::string(key));
    if (!m_json)
        return nullptr;
    auto it = m_json->find(std::string(key));
    if (it == m_json->end())
        return nullptr;
    return &*it;
}

static std::string fmt(double v) {
    std::ostringstream os;
    os << v;
    return os.str();
}

std::optional<double> ConfigObject::requiredNumber(std::string_view key, double min, double max) {
    const json* j = find(key);
    if (!j) {
        error(key, "required number is missing");
        return std::nullopt;
    }
    if (!j->is_number()) {
        error(key, "must be a number, not " + std::string(j->type_name()));
        return std::nullopt;
    }
    double v = j->get<double>();
    if (!std::isfinite(v) || v < min || v > max) {
        error(key, fmt(v) + " is out of range [" + fmt(min) + ", " + fmt(max) + "]");
        return std::nullopt;
    }
    return v;
}

double ConfigObject::number(std::string_view key, double def, double min, double max) {
    if (!has(key)) {
        m_known.insert(std::string(key));
        return def;
    }
    auto v = requiredNumber(key, min, max);
    return v ? *v : def;
}

std::int64_t ConfigObject::integer(std::string_view key, std::int64_t def, std::int64_t min,
                                   std::int64_t max) {
    const json* j = find(key);
    if (!j)
        return def;
    if (!j->is_number_integer()) {
        error(key, "must be an integer, not " + std::string(j->is_number() ? "a fraction" : j->type_name()));
        return def;
    }
    std::int64_t v =
        j->is_number_unsigned() ? static_cast<std::int64_t>(j->get<std::uint64_t>()) : j->get<std::int64_t>();
    if (v < min || v > max) {
        error(key, std::to_string(v) + " is out of range [" + std::to_string(min) + ", " +
                       std::to_string(max) + "]");
        return def;
    }
    return v;
}

bool ConfigObject::boolean(std::string_view key, bool def) {
    const json* j = find(key);
    if (!j)
        return def;
    if (!j->is_boolean()) {
        error(key, "must be true or false, not " + std::string(j->type_name()));
        return def;
    }
    return j->get<bool>();
}

std::string ConfigObject::string(std::string_view key, const std::string& def) {
    const json* j = find(key);
    if (!j)
        return def;
    if (!j->is_string()) {
        error(key, "must be a string, not " + std::string(j->type_name()));
        return def;
    }
    return j->get<std::string>();
}

std::string ConfigObject::choice(std::string_view key, const std::string& def,
                                 const std::vector<std::string>& allowed) {
    bool present = has(key);
    std::string v = string(key, def);
    if (present && std::find(allowed.begin(), allowed.end(), v) == allowed.end()) {
        std::string list;
        for (auto& a : allowed)
            list += (list.empty() ? "" : ", ") + ("\"" + a + "\"");
        error(key, "\"" + v + "\" is not one of " + list);
        return def;
    }
    return v;
}

std::vector<std::string> ConfigObject::stringList(std::string_view key) {
    std::vector<std::string> out;
    const json* j = find(key);
    if (!j)
        return out;
    if (!j->is_array()) {
        error(key, "must be an array of strings");
        return out;
    }
    for (auto& e : *j) {
        if (!e.is_string()) {
            error(key, "every element must be a string");
            return {};
        }
        out.push_back(e.get<std::string>());
    }
    return out;
}

std::optional<ConfigObject> ConfigObject::object(std::string_view key) {
    const json* j = find(key);
    if (!j)
        return std::nullopt;
    if (!j->is_object()) {
        error(key, "must be an object, not " + std::string(j->type_name()));
        return std::nullopt;
    }
    return ConfigObject(*m_doc, m_pointer + "/" + std::string(key), *m_errors);
}

std::vector<ConfigObject> ConfigObject::objectList(std::string_view key) {
    std::vector<ConfigObject> out;
    const json* j = find(key);
    if (!j)
        return out;
    if (!j->is_array()) {
        error(key, "must be an array of objects");
        return out;
    }
    for (std::size_t i = 0; i < j->size(); ++i)
        out.emplace_back(*m_doc, m_pointer + "/" + std::string(key) + "/" + std::to_string(i), *m_errors);
    return out;
}

const json* ConfigObject::raw(std::string_view key) {
    return find(key);
}

static std::size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
        prev[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        cur[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j)
            cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
        std::swap(prev, cur);
    }
    return prev[b.size()];
}

void ConfigObject::finish() {
    if (!m_json)
        return;
    for (auto it = m_json->begin(); it != m_json->end(); ++it) {
        if (m_known.count(it.key()))
            continue;
        std::string msg = "unknown key \"" + it.key() + "\"";
        std::string best;
        std::size_t bestD = 3;
        for (auto& k : m_known) {
            std::size_t d = editDistance(it.key(), k);
            if (d < bestD) {
                bestD = d;
                best = k;
            }
        }
        if (!best.empty())
            msg += " (did you mean \"" + best + "\"?)";
        error(it.key(), msg);
    }
}

} // namespace ocu
