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
    // `total`, when given, counts everything this set counts as well (e.g. one ISO 23725 link's counters
    // feeding its stack's totals). It must outlive this set.
    explicit Counters(Counters* total = nullptr) : m_total(total) {}
    Counters(const Counters&) = delete;
    Counters& operator=(const Counters&) = delete;

    void add(std::string_view name, std::uint64_t n = 1) {
        {
            std::lock_guard lock(m_mutex);
            auto it = m_values.find(name);
            if (it == m_values.end())
                m_values.emplace(std::string(name), n);
            else
                it->second += n;
        }
        if (m_total)
            m_total->add(name, n);
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
    // Peer input rejected, ignored as implausible or answered no more: rx.rejected.<reason>,
    // rx.implausible.<cause>, rx.limited.<request>, rx.unknown_member, rx.out_of_standard.
    static bool isReject(std::string_view name) {
        for (std::string_view p : {"rx.rejected.", "rx.implausible.", "rx.limited."})
            if (name.substr(0, p.size()) == p)
                return true;
        return name == "rx.unknown_member" || name == "rx.out_of_standard";
    }
    // Every reject counter by reason: its name without the leading "rx." ("rejected.too_short", ...).
    std::map<std::string, std::uint64_t, std::less<>> rejects() const {
        std::lock_guard lock(m_mutex);
        std::map<std::string, std::uint64_t, std::less<>> out;
        for (auto& [k, v] : m_values)
            if (isReject(k))
                out.emplace(k.substr(3), v);
        return out;
    }
    void reset() {
        std::lock_guard lock(m_mutex);
        m_values.clear();
    }

private:
    Counters* m_total = nullptr;
    mutable std::mutex m_mutex;
    std::map<std::string, std::uint64_t, std::less<>> m_values;
};

} // namespace ocu
