#pragma once
// Test support: an ISO 23725 frame as JSON without its send time, for comparing what a peer received with
// what the research note's tables prescribe, field for field.
#include <nlohmann/json.hpp>

#include <regex>
#include <string>

namespace isosim {

// The frame without "Timestamp", after checking it has the §4.2 form (UTC with milliseconds); null when the
// frame is no JSON object, the string "bad Timestamp" when the time is missing or malformed.
inline nlohmann::json withoutTimestamp(const std::string& frame) {
    nlohmann::json j = nlohmann::json::parse(frame, nullptr, false);
    if (!j.is_object())
        return nlohmann::json();
    static const std::regex ts(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d\.\d{3}Z)");
    if (!j.contains("Timestamp") || !j["Timestamp"].is_string() ||
        !std::regex_match(j["Timestamp"].get<std::string>(), ts))
        return nlohmann::json("bad Timestamp");
    j.erase("Timestamp");
    return j;
}

} // namespace isosim
