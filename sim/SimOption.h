#pragma once
// A command-line option of ocu-sim that a protocol's simulator module adds (--ugvs N): its names, help text
// and how its value goes into the site configuration's simulation section. No Qt: ocu-sim turns these into
// its parser's options.
#include "protocols/site/SiteConfig.h"

#include <charconv>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

namespace ocu::sim {

struct SimOption {
    std::vector<std::string> names; // without the dashes; the last one is named in error messages
    std::string valueName;          // empty: a switch, which takes no value
    std::string description;
    // Puts the value (empty for a switch) into config; returns what is wrong with it, or an empty string.
    std::function<std::string(const std::string& value, SiteConfig& config)> apply;
};

// An integer option in 0..max.
inline std::string intOption(const std::string& name, const std::string& value, int& target, int max) {
    int v = 0;
    const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), v);
    if (ec != std::errc() || end != value.data() + value.size() || v < 0 || v > max)
        return "--" + name + " must be an integer 0.." + std::to_string(max);
    target = v;
    return {};
}

// A number option in min..max (the message names the range as given).
inline std::string numberOption(const std::string& name, const std::string& value, double& target, double min,
                                double max, const std::string& range) {
    char* end = nullptr;
    const double v = std::strtod(value.c_str(), &end);
    if (value.empty() || end != value.c_str() + value.size() || !(v >= min && v <= max))
        return "--" + name + " must be a number " + range;
    target = v;
    return {};
}

} // namespace ocu::sim
