#include "sim/osyris/SimNetwork.h"

#include <cmath>

namespace ocu::sim::osyris {

int SimNetwork::addNode(Deliver deliver, Position position) {
    m_deliver.push_back(std::move(deliver));
    m_position.push_back(std::move(position));
    return static_cast<int>(m_deliver.size()) - 1;
}

void SimNetwork::setDeliver(int node, Deliver deliver) {
    m_deliver.at(static_cast<std::size_t>(node)) = std::move(deliver);
}

const LinkProfile& SimNetwork::link(int from, int to) const {
    auto it = m_links.find({from, to});
    return it == m_links.end() ? m_default : it->second;
}

bool SimNetwork::inRange(int a, int b) const {
    if (m_range <= 0)
        return true;
    auto& pa = m_position[static_cast<std::size_t>(a)];
    auto& pb = m_position[static_cast<std::size_t>(b)];
    if (!pa || !pb)
        return true;
    auto x = pa(), y = pb();
    if (!x || !y)
        return true;
    return std::hypot(x->first - y->first, x->second - y->second) <= m_range;
}

void SimNetwork::send(int from, const ocu::Bytes& datagram) {
    ++m_stats.sent;
    auto data = std::make_shared<const ocu::Bytes>(datagram);
    std::uniform_real_distribution<double> u(0, 1);
    auto now = m_clock.now();
    std::vector<int> lostAt;
    for (int to = 0; to < static_cast<int>(m_deliver.size()); ++to) {
        if (to == from)
            continue;
        if (!inRange(from, to)) {
            ++m_stats.outOfRange;
            continue;
        }
        const auto& l = link(from, to);
        ++m_stats.copies;
        if (u(m_rng) < l.loss) {
            ++m_stats.lost;
            lostAt.push_back(to);
            continue;
        }
        int copies = u(m_rng) < l.duplicate ? 2 : 1;
        if (copies == 2)
            ++m_stats.duplicated;
        for (int c = 0; c < copies; ++c) {
            double ms = l.latencyMs;
            if (u(m_rng) < l.reorder) {
                ms += u(m_rng) * l.reorderDelayMs;
                ++m_stats.delayed;
            }
            auto due = now + std::chrono::duration_cast<ocu::Duration>(
                                 std::chrono::duration<double, std::milli>(ms));
            m_queue.push({due, m_seq++, to, data});
        }
    }
    if (m_tap)
        m_tap(from, datagram, lostAt);
}

void SimNetwork::deliverDue() {
    auto now = m_clock.now();
    while (!m_queue.empty() && m_queue.top().due <= now) {
        Pending p = m_queue.top();
        m_queue.pop();
        auto& d = m_deliver[static_cast<std::size_t>(p.to)];
        if (d) {
            ++m_stats.delivered;
            d(*p.data);
        }
    }
}

} // namespace ocu::sim::osyris
