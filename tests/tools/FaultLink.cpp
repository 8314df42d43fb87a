#include "tests/tools/FaultLink.h"

#include <algorithm>
#include <cstdlib>
#include <sstream>

namespace ocu::tools {

FaultProfile parseFaultProfile(const std::string& text, std::string& error) {
    FaultProfile p;
    std::istringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        if (item.empty())
            continue;
        const auto eq = item.find('=');
        if (eq == std::string::npos) {
            error = "fault \"" + item + "\" has no value (name=value)";
            return p;
        }
        const std::string name = item.substr(0, eq);
        const std::string valueText = item.substr(eq + 1);
        char* end = nullptr;
        const double v = std::strtod(valueText.c_str(), &end);
        if (valueText.empty() || *end != '\0' || v < 0) {
            error = "fault \"" + name + "\": \"" + valueText + "\" is not a number ≥ 0";
            return p;
        }
        const bool probability = name == "loss" || name == "dup" || name == "reorder";
        if (probability && v > 1) {
            error = "fault \"" + name + "\" is a probability (0 … 1)";
            return p;
        }
        if (name == "loss")
            p.loss = v;
        else if (name == "dup")
            p.duplicate = v;
        else if (name == "reorder")
            p.reorder = v;
        else if (name == "delay")
            p.delayMs = int(v);
        else if (name == "jitter")
            p.jitterMs = int(v);
        else if (name == "rate")
            p.rateBitsPerS = v;
        else if (name == "queue")
            p.queueLimitMs = int(v);
        else {
            error = "unknown fault \"" + name + "\" (loss, dup, reorder, delay, jitter, rate, queue)";
            return p;
        }
    }
    if (p.jitterMs > p.delayMs) {
        error = "jitter must not exceed delay";
        return p;
    }
    return p;
}

FaultLink::FaultLink(FaultProfile profile, std::uint64_t seed) : m_profile(profile), m_random(seed) {}

bool FaultLink::chance(double p) {
    if (p <= 0)
        return false;
    return std::uniform_real_distribution<double>(0.0, 1.0)(m_random) < p;
}

FaultLink::Clock::duration FaultLink::delayFor() {
    int ms = m_profile.delayMs;
    if (m_profile.jitterMs > 0)
        ms += std::uniform_int_distribution<int>(-m_profile.jitterMs, m_profile.jitterMs)(m_random);
    return std::chrono::milliseconds(std::max(ms, 0));
}

std::vector<FaultLink::Clock::time_point> FaultLink::offer(std::size_t bytes, Clock::time_point now) {
    ++m_counters.in;
    if (m_partitioned) {
        ++m_counters.partitioned;
        return {};
    }
    if (chance(m_profile.loss)) {
        ++m_counters.lost;
        return {};
    }
    // The rate limit first (the frame leaves the sender's queue), then the path's delay, as netem's rate.
    Clock::time_point onLine = now;
    if (m_profile.rateBitsPerS > 0) {
        const Clock::time_point start = std::max(now, m_lineFreeAt);
        if (start - now > std::chrono::milliseconds(m_profile.queueLimitMs)) {
            ++m_counters.overflow;
            return {};
        }
        const double seconds = double(bytes) * 8.0 / m_profile.rateBitsPerS;
        m_lineFreeAt =
            start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
        onLine = m_lineFreeAt;
    }
    Clock::time_point at = onLine + delayFor();
    if (chance(m_profile.reorder)) {
        ++m_counters.reordered;
        at += std::chrono::milliseconds(
            std::uniform_int_distribution<int>(m_profile.reorderMinMs, m_profile.reorderMaxMs)(m_random));
    }
    std::vector<Clock::time_point> out{at};
    if (chance(m_profile.duplicate)) {
        ++m_counters.duplicated;
        out.push_back(at + std::chrono::milliseconds(1));
    }
    m_counters.sent += out.size();
    return out;
}

} // namespace ocu::tools
