#pragma once
// Sets of slot numbers as sorted, disjoint, inclusive intervals (ribbon holdings, gaps, requests).
#include <algorithm>
#include <cstdint>
#include <iterator>
#include <map>
#include <utility>
#include <vector>

namespace ocu::osyris {

struct SlotRange {
    std::uint32_t from = 0;
    std::uint32_t to = 0; // inclusive
    std::uint64_t size() const { return std::uint64_t(to) - from + 1; }
    bool operator==(const SlotRange&) const = default;
};

class IntervalSet {
public:
    bool empty() const { return m_map.empty(); }
    void clear() { m_map.clear(); }
    std::uint64_t count() const {
        std::uint64_t n = 0;
        for (auto& [a, b] : m_map)
            n += std::uint64_t(b) - a + 1;
        return n;
    }
    std::uint32_t min() const { return m_map.begin()->first; }
    std::uint32_t max() const { return std::prev(m_map.end())->second; }

    bool contains(std::uint32_t s) const {
        auto it = m_map.upper_bound(s);
        if (it == m_map.begin())
            return false;
        --it;
        return s <= it->second;
    }
    bool containsAll(std::uint32_t a, std::uint32_t b) const {
        auto it = m_map.upper_bound(a);
        if (it == m_map.begin())
            return false;
        --it;
        return b <= it->second;
    }

    void insert(std::uint32_t a, std::uint32_t b) {
        if (a > b)
            return;
        std::uint64_t lo = a, hi = b;
        auto it = m_map.upper_bound(a);
        if (it != m_map.begin()) {
            auto p = std::prev(it);
            if (std::uint64_t(p->second) + 1 >= lo)
                it = p;
        }
        while (it != m_map.end() && it->first <= hi + 1) {
            lo = std::min<std::uint64_t>(lo, it->first);
            hi = std::max<std::uint64_t>(hi, it->second);
            it = m_map.erase(it);
        }
        m_map.emplace(static_cast<std::uint32_t>(lo), static_cast<std::uint32_t>(hi));
    }
    void insert(std::uint32_t s) { insert(s, s); }

    void erase(std::uint32_t a, std::uint32_t b) {
        if (a > b)
            return;
        auto it = m_map.upper_bound(a);
        if (it != m_map.begin())
            --it;
        std::vector<std::pair<std::uint32_t, std::uint32_t>> add;
        while (it != m_map.end() && it->first <= b) {
            auto [x, y] = *it;
            if (y < a) {
                ++it;
                continue;
            }
            it = m_map.erase(it);
            if (x < a)
                add.emplace_back(x, a - 1);
            if (y > b)
                add.emplace_back(b + 1, y);
        }
        for (auto& [x, y] : add)
            m_map.emplace(x, y);
    }
    void erase(std::uint32_t s) { erase(s, s); }

    // Intervals of this set inside [a, b].
    std::vector<SlotRange> intersect(std::uint32_t a, std::uint32_t b) const {
        std::vector<SlotRange> out;
        auto it = m_map.upper_bound(a);
        if (it != m_map.begin())
            --it;
        for (; it != m_map.end() && it->first <= b; ++it) {
            if (it->second < a)
                continue;
            out.push_back({std::max(a, it->first), std::min(b, it->second)});
        }
        return out;
    }
    // Slots of [a, b] missing from this set.
    std::vector<SlotRange> gaps(std::uint32_t a, std::uint32_t b) const {
        std::vector<SlotRange> out;
        if (a > b)
            return out;
        std::uint64_t next = a;
        for (auto& r : intersect(a, b)) {
            if (r.from > next)
                out.push_back({static_cast<std::uint32_t>(next), r.from - 1});
            next = std::uint64_t(r.to) + 1;
        }
        if (next <= b)
            out.push_back({static_cast<std::uint32_t>(next), b});
        return out;
    }
    std::vector<SlotRange> ranges() const {
        std::vector<SlotRange> out;
        for (auto& [a, b] : m_map)
            out.push_back({a, b});
        return out;
    }

private:
    std::map<std::uint32_t, std::uint32_t> m_map;
};

} // namespace ocu::osyris
