#pragma once
// The ISO 23725 codec's validating JSON reader (internal to MessageDecoder.cpp): Obj reads one JSON object
// and names "<path>.<Member>" in every error it throws (DecodeError), applies the tolerances of InferredRules
// (aliases, numeric strings, case-insensitive enumerations, timestamp repair) with a warning each, and
// reports the members it did not consume. Header-only so the decoder inlines it as before the split.
#include "protocols/iso23725/InferredRules.h"
#include "protocols/iso23725/Messages.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

namespace ocu::iso23725::detail {

using nlohmann::json;

struct DecodeError {
    std::string message;
};

inline const char* typeName(const json& v) {
    switch (v.type()) {
    case json::value_t::null:
        return "null";
    case json::value_t::boolean:
        return "boolean";
    case json::value_t::string:
        return "string";
    case json::value_t::array:
        return "array";
    case json::value_t::object:
        return "object";
    case json::value_t::binary:
        return "binary";
    case json::value_t::discarded:
        return "invalid";
    default:
        return "number";
    }
}

inline std::string joinSet(const std::vector<std::string_view>& set) {
    std::string s;
    for (auto v : set) {
        if (!s.empty())
            s += ", ";
        s += v;
    }
    return s;
}

struct Ctx {
    const InferredRules& rules;
    std::vector<std::string>& warnings;
};

// Reads one JSON object, naming "<path>.<Member>" in every error, and remembers which keys it consumed.
class Obj {
public:
    Obj(const json& j, std::string path, Ctx& ctx) : m_j(j), m_path(std::move(path)), m_ctx(ctx) {
        if (!j.is_object())
            fail("", std::string("expected an object, got ") + typeName(j));
    }
    // Hot path (one per message): a literal path needs no allocation.
    Obj(const json& j, const char* path, Ctx& ctx) : m_j(j), m_literal(path), m_ctx(ctx) {
        if (!j.is_object())
            fail("", std::string("expected an object, got ") + typeName(j));
    }

    std::string path() const { return m_literal ? std::string(m_literal) : m_path; }

    [[noreturn]] void fail(std::string_view key, const std::string& what) const {
        throw DecodeError{key.empty() ? path() + ": " + what : path() + "." + std::string(key) + ": " + what};
    }

    // Finds key (or an accepted alias); nullptr when absent.
    const json* find(std::string_view key, std::string_view alias = {}) {
        see(key);
        if (const json* v = lookup(key)) {
            ++m_found;
            return v;
        }
        if (!alias.empty()) {
            see(alias);
            if (m_ctx.rules.acceptAliases) {
                if (const json* a = lookup(alias)) {
                    ++m_found;
                    m_ctx.warnings.push_back(path() + ": alias '" + std::string(alias) + "' accepted for '" +
                                             std::string(key) + "'");
                    return a;
                }
            }
        }
        return nullptr;
    }
    const json& need(std::string_view key, std::string_view alias = {}) {
        const json* v = find(key, alias);
        if (!v)
            fail(key, "required member missing");
        return *v;
    }

    std::string str(std::string_view key) { return asString(key, need(key)); }
    std::optional<std::string> optStr(std::string_view key) {
        const json* v = find(key);
        if (!v || v->is_null())
            return std::nullopt;
        return asString(key, *v);
    }
    std::string asString(std::string_view key, const json& v) const {
        if (!v.is_string())
            fail(key, std::string("expected a string, got ") + typeName(v));
        return v.get<std::string>();
    }

    Guid guid(std::string_view key, std::string_view alias = {}) { return asGuid(key, need(key, alias)); }
    std::optional<Guid> nullableGuid(std::string_view key, bool required) {
        const json* v = required ? &need(key) : find(key);
        if (!v || v->is_null())
            return std::nullopt;
        return asGuid(key, *v);
    }
    Guid asGuid(std::string_view key, const json& v) const {
        if (!v.is_string())
            fail(key, std::string("expected a GUID string, got ") + typeName(v));
        const auto& s = v.get_ref<const std::string&>();
        if (!isGuid(s))
            fail(key, "malformed GUID '" + s + "'");
        Guid g = s;
        std::transform(g.begin(), g.end(), g.begin(), [](unsigned char c) { return std::tolower(c); });
        return g;
    }

    bool boolean(std::string_view key) {
        const json& v = need(key);
        if (!v.is_boolean())
            fail(key, std::string("expected a boolean, got ") + typeName(v));
        return v.get<bool>();
    }
    std::optional<bool> optBool(std::string_view key) {
        const json* v = find(key);
        if (!v || v->is_null())
            return std::nullopt;
        if (!v->is_boolean())
            fail(key, std::string("expected a boolean, got ") + typeName(*v));
        return v->get<bool>();
    }

    // Numbers: null = unavailable (§4.2.3) when nullable; numeric strings tolerated per InferredRules.
    std::optional<double> number(std::string_view key, bool required, bool nullable,
                                 std::string_view alias = {}) {
        const json* v = required ? &need(key, alias) : find(key, alias);
        if (!v)
            return std::nullopt;
        return asNumber(key, *v, nullable);
    }
    std::optional<double> asNumber(std::string_view key, const json& v, bool nullable) const {
        if (v.is_number())
            return v.get<double>();
        if (v.is_null()) {
            if (!nullable)
                fail(key, "must not be null");
            return std::nullopt;
        }
        if (v.is_string() && m_ctx.rules.acceptNumericStrings) {
            const auto& s = v.get_ref<const std::string&>();
            double d = 0;
            auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), d);
            if (ec == std::errc() && p == s.data() + s.size() && std::isfinite(d)) {
                m_ctx.warnings.push_back(path() + "." + std::string(key) + ": number sent as a string");
                return d;
            }
        }
        fail(key, std::string("expected a number, got ") + typeName(v));
    }
    std::optional<std::int64_t> integer(std::string_view key, bool required, bool nullable) {
        const json* v = required ? &need(key) : find(key);
        if (!v)
            return std::nullopt;
        return asInteger(key, *v, nullable);
    }
    std::optional<std::int64_t> asInteger(std::string_view key, const json& v, bool nullable) const {
        if (v.is_number_integer())
            return v.get<std::int64_t>();
        if (v.is_number_float() && !m_ctx.rules.acceptNumericStrings)
            fail(key, "expected an integer, got a decimal");
        auto d = asNumber(key, v, nullable);
        if (!d)
            return std::nullopt;
        if (std::fabs(*d) > 9.0e18)
            fail(key, "integer out of range");
        return static_cast<std::int64_t>(std::llround(*d));
    }
    std::int64_t reqInt(std::string_view key) { return *integer(key, true, false); }

    std::string enumeration(std::string_view key, const std::vector<std::string_view>& set) {
        return asEnum(key, need(key), set);
    }
    std::optional<std::string> optEnum(std::string_view key, const std::vector<std::string_view>& set) {
        const json* v = find(key);
        if (!v || v->is_null())
            return std::nullopt;
        return asEnum(key, *v, set);
    }
    std::string asEnum(std::string_view key, const json& v, const std::vector<std::string_view>& set) const {
        if (!v.is_string())
            fail(key, std::string("expected an enumeration string, got ") + typeName(v));
        const auto& s = v.get_ref<const std::string&>();
        for (auto e : set)
            if (e == s)
                return s;
        if (m_ctx.rules.caseInsensitiveEnums)
            for (auto e : set)
                if (e.size() == s.size() && std::equal(e.begin(), e.end(), s.begin(), [](char a, char b) {
                        return std::tolower(static_cast<unsigned char>(a)) ==
                               std::tolower(static_cast<unsigned char>(b));
                    }))
                    return std::string(e);
        fail(key, "'" + s + "' is not one of " + joinSet(set));
    }

    Timestamp timestamp(std::string_view key) { return asTimestamp(key, need(key)); }
    std::optional<Timestamp> optTimestamp(std::string_view key) {
        const json* v = find(key);
        if (!v || v->is_null())
            return std::nullopt;
        return asTimestamp(key, *v);
    }
    Timestamp asTimestamp(std::string_view key, const json& v) const {
        if (!v.is_string())
            fail(key, std::string("expected an ISO 8601 timestamp string, got ") + typeName(v));
        Timestamp t{v.get<std::string>(), std::nullopt};
        bool repaired = false;
        t.unixMs = parseTimestamp(t.text, m_ctx.rules.repairTimestamps, &repaired);
        if (!t.unixMs)
            fail(key, "malformed timestamp '" + t.text + "'");
        if (repaired)
            m_ctx.warnings.push_back(path() + "." + std::string(key) + ": malformed timestamp '" + t.text +
                                     "' repaired");
        return t;
    }

    // An array that must not be null (ISO: "can be empty but not null").
    const json& array(std::string_view key, std::string_view alias = {}) {
        const json& v = need(key, alias);
        return asArray(key, v);
    }
    const json* optArray(std::string_view key, std::string_view alias = {}) {
        const json* v = find(key, alias);
        if (!v)
            return nullptr;
        return &asArray(key, *v);
    }
    const json& asArray(std::string_view key, const json& v) const {
        if (!v.is_array())
            fail(key, v.is_null() ? std::string("must be an array (may be empty, not null)")
                                  : std::string("expected an array, got ") + typeName(v));
        return v;
    }
    std::string item(std::string_view key, std::size_t i) const {
        return path() + "." + std::string(key) + "[" + std::to_string(i) + "]";
    }

    // Unknown members are kept (returned) and reported, never fatal (§4.2).
    json extras() const {
        json out; // null unless there are unknown members (no allocation on the hot path)
        if (m_j.size() == m_found)
            return out; // every key present was consumed (looked-up names are distinct)
        for (auto it = m_j.begin(); it != m_j.end(); ++it) {
            if (seen(it.key()))
                continue;
            out[it.key()] = it.value();
            m_ctx.warnings.push_back(path() + ": unknown member '" + it.key() + "' kept");
        }
        return out;
    }

    // Hot messages: one pass over the object resolves these keys, instead of one map lookup per key.
    void prefetch(std::initializer_list<std::string_view> keys) {
        m_npk = 0;
        for (auto k : keys)
            if (m_npk < m_pk.size()) {
                m_pk[m_npk] = k;
                m_pv[m_npk++] = nullptr;
            }
        for (auto it = m_j.begin(); it != m_j.end(); ++it) {
            const std::string& key = it.key();
            for (std::size_t i = 0; i < m_npk; ++i)
                if (m_pk[i].size() == key.size() && m_pk[i] == key) {
                    m_pv[i] = &*it;
                    break;
                }
        }
    }

private:
    const json* lookup(std::string_view key) const {
        for (std::size_t i = 0; i < m_npk; ++i)
            if (m_pk[i] == key)
                return m_pv[i];
        auto it = m_j.find(key);
        return it == m_j.end() ? nullptr : &*it;
    }
    void see(std::string_view k) {
        if (m_nSeen < m_seen.size())
            m_seen[m_nSeen++] = k;
        else
            m_more.push_back(k);
    }
    bool seen(std::string_view k) const {
        for (std::size_t i = 0; i < m_nSeen; ++i)
            if (m_seen[i] == k)
                return true;
        return std::find(m_more.begin(), m_more.end(), k) != m_more.end();
    }

    const json& m_j;
    const char* m_literal = nullptr;
    std::string m_path;
    Ctx& m_ctx;
    std::array<std::string_view, 16> m_seen;
    std::size_t m_nSeen = 0;
    std::size_t m_found = 0;
    std::array<std::string_view, 16> m_pk;
    std::array<const json*, 16> m_pv{};
    std::size_t m_npk = 0;
    std::vector<std::string_view> m_more;
};

} // namespace ocu::iso23725::detail
