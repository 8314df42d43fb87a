#pragma once
// In-memory "radio" for OSYRIS stations driven by a FakeClock: per-link loss, duplication, reordering
// (extra delay), latency, and range-limited links computed from the nodes' true positions.
#include "protocols/common/Bytes.h"
#include "protocols/common/Clock.h"

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <queue>
#include <random>
#include <utility>
#include <vector>

namespace ocu::sim::osyris {

struct LinkProfile {
    double loss = 0;
    double duplicate = 0;
    double reorder = 0; // probability of an extra delay of up to reorderDelayMs
    double latencyMs = 2;
    double reorderDelayMs = 250;
    bool operator==(const LinkProfile&) const = default;
};

class SimNetwork {
public:
    using Deliver = std::function<void(ocu::ByteSpan)>;
    using Position = std::function<std::optional<std::pair<double, double>>()>;

    SimNetwork(const ocu::Clock& clock, std::uint32_t seed = 1) : m_clock(clock), m_rng(seed) {}

    int addNode(Deliver deliver, Position position = {});
    void setDeliver(int node, Deliver deliver); // e.g. after a station restart; empty = node down
    void setDefaultLink(const LinkProfile& p) { m_default = p; }
    void setLink(int from, int to, const LinkProfile& p) { m_links[{from, to}] = p; }
    void clearLinks() { m_links.clear(); }
    // Nodes farther apart than this (both positions known) do not hear each other; 0 = unlimited.
    void setRange(double metres) { m_range = metres; }
    // Observer called once per send with the receivers whose copy was lost (tests measure recovery cost).
    using Tap = std::function<void(int from, const ocu::Bytes& datagram, const std::vector<int>& lostAt)>;
    void setTap(Tap tap) { m_tap = std::move(tap); }
    // Multicast from node: every other node may receive it.
    void send(int from, const ocu::Bytes& datagram);
    // Delivers every datagram due by now.
    void deliverDue();

    struct Stats {
        std::uint64_t sent = 0, copies = 0, lost = 0, duplicated = 0, delayed = 0, outOfRange = 0,
                      delivered = 0;
    };
    const Stats& stats() const { return m_stats; }
    bool inRange(int a, int b) const;

private:
    struct Pending {
        ocu::TimePoint due;
        std::uint64_t seq;
        int to;
        std::shared_ptr<const ocu::Bytes> data;
        bool operator>(const Pending& o) const { return due != o.due ? due > o.due : seq > o.seq; }
    };
    const LinkProfile& link(int from, int to) const;

    const ocu::Clock& m_clock;
    std::mt19937 m_rng;
    std::vector<Deliver> m_deliver;
    std::vector<Position> m_position;
    LinkProfile m_default;
    std::map<std::pair<int, int>, LinkProfile> m_links;
    double m_range = 0;
    std::priority_queue<Pending, std::vector<Pending>, std::greater<>> m_queue;
    std::uint64_t m_seq = 0;
    Stats m_stats;
    Tap m_tap;
};

} // namespace ocu::sim::osyris
