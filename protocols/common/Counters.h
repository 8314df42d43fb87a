#pragma once
// Named, thread-safe event counters (received, rejected-with-reason, retransmitted, ...).
// Every rejection of bad input increments one, so operators and tests can see what was dropped.
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <string_view>

namespace ocu {

class Counters {
public:
    void add(std::string_view name, std::uint64_t n = 1) {
        std::lock_guard lock(m_mutex);
        auto it = m_values.find(name);
        if (it == m_values.end())
            m_values.emplace(std::string(name), n);
        else
            it->second += n;
    }
    std::uint64_t get(std::string_view name) const {
        std::lock_guard lock(m_mutex);
        auto it = m_values.find(name);
        return it == m_values.end() ? 0 : it->second;
    }
    std::map<std::string, std::uint64_t, std::less<>> snapshot() const {
        std::lock_guard lock(m_mutex);
        return m_values;
    }
    // Sum of every counter whose name starts with prefix (e.g. "rx.rejected.").
    std::uint64_t sumPrefix(std::string_view prefix) const {
        std::lock_guard lock(m_mutex);
        std::uint64_t s = 0;
        for (auto& [k, v] : m_values)
            if (std::string_view(k).substr(0, prefix.size()) == prefix)
                s += v;
        return s;
    }
    void reset() {
        std::lock_guard lock(m_mutex);
        m_values.clear();
    }

private:
    mutable std::mutex m_mutex;
    std::map<std::string, std::uint64_t, std::less<>> m_values;
};

} // namespace ocu
