#pragma once
// Strict reading of the site configuration (JSON). Every value read names its key; unknown keys,
// wrong types and out-of-range values are errors that name the key path and the line in the file,
// never a silent default (docs/site-config.md).
#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "protocols/common/Result.h"

namespace ocu {

// A parsed JSON document that remembers the line of every value (by JSON pointer, "/jaus/port").
class ConfigDocument {
public:
    ConfigDocument();
    ~ConfigDocument();
    ConfigDocument(ConfigDocument&&) noexcept;
    ConfigDocument& operator=(ConfigDocument&&) noexcept;

    static Result<ConfigDocument> parse(std::string_view text, std::string fileName = "<config>");
    static Result<ConfigDocument> load(const std::string& path);

    const nlohmann::json& root() const;
    const std::string& fileName() const { return m_fileName; }
    int lineOf(const std::string& pointer) const; // 0 when unknown

private:
    friend class ConfigJsonParser;
    std::unique_ptr<nlohmann::json> m_root;
    std::map<std::string, int> m_lines;
    std::string m_fileName;
};

class ConfigErrors {
public:
    void add(std::string message) { m_messages.push_back(std::move(message)); }
    bool empty() const { return m_messages.empty(); }
    const std::vector<std::string>& messages() const { return m_messages; }
    std::string joined() const;

private:
    std::vector<std::string> m_messages;
};

// One JSON object of the document. Each accessor records the key as known; finish() reports the rest.
class ConfigObject {
public:
    ConfigObject(const ConfigDocument& doc, std::string pointer, ConfigErrors& errors);
    ConfigObject(const ConfigObject&) = default;
    ~ConfigObject();

    bool valid() const { return m_valid; }
    bool has(std::string_view key) const;
    const std::string& pointer() const { return m_pointer; }

    double number(std::string_view key, double def, double min, double max);
    std::optional<double> requiredNumber(std::string_view key, double min, double max);
    std::int64_t integer(std::string_view key, std::int64_t def, std::int64_t min, std::int64_t max);
    bool boolean(std::string_view key, bool def);
    std::string string(std::string_view key, const std::string& def);
    // A string that must be one of allowed (message lists them).
    std::string choice(std::string_view key, const std::string& def, const std::vector<std::string>& allowed);
    std::vector<std::string> stringList(std::string_view key);
    std::optional<ConfigObject> object(std::string_view key);
    std::vector<ConfigObject> objectList(std::string_view key);
    // The raw JSON of a key (for sections parsed elsewhere); marks the key known.
    const nlohmann::json* raw(std::string_view key);

    // Reports every key that no accessor asked for, with a suggestion when a known key is close.
    void finish();
    // Adds an error located at key (for cross-field checks done by callers).
    void error(std::string_view key, std::string_view message);

private:
    const nlohmann::json* find(std::string_view key);
    std::string where(std::string_view key) const;

    const ConfigDocument* m_doc;
    std::string m_pointer;
    ConfigErrors* m_errors;
    const nlohmann::json* m_json = nullptr;
    std::set<std::string, std::less<>> m_known;
    bool m_valid = false;
};

} // namespace ocu
