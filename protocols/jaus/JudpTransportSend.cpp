// Sending: routing to learned, static, broadcast or JTCP endpoints, fragmentation, sequence numbers, network
// fault injection, and the planned datagrams of the stop path.
#include "protocols/jaus/JudpTransport.h"

#include <boost/asio/ip/address_v4.hpp>
#include <boost/asio/steady_timer.hpp>

#include <cerrno>
#include <cstring>

#include <sys/socket.h>

#include "protocols/common/Log.h"
#include "protocols/jaus/JudpTransportSockets.h"

namespace ocu::jaus {

namespace asio = boost::asio;

std::optional<JudpTransport::Endpoint> JudpTransport::resolve(const JausId& dst) const {
    if (auto it = m_learned.find(dst.value()); it != m_learned.end())
        return it->second;
    for (auto& s : m_cfg.staticEndpoints) {
        if (s.id.matches(dst) ||
            (s.id.subsystem == dst.subsystem && (s.id.node == 0xFF || s.id.node == dst.node) &&
             (s.id.component == 0xFF || s.id.component == dst.component))) {
            boost::system::error_code ec;
            auto a = asio::ip::make_address_v4(s.address, ec);
            if (!ec)
                return Endpoint(a, s.port);
        }
    }
    // Components of one node usually share a node manager / socket.
    for (auto& [k, ep] : m_learned) {
        JausId id = JausId::fromValue(k);
        if (id.subsystem == dst.subsystem && id.node == dst.node)
            return ep;
    }
    return std::nullopt;
}

std::vector<JudpTransport::Endpoint> JudpTransport::staticUdpEndpoints(const JausId& dst) const {
    std::vector<Endpoint> out;
    for (auto& s : m_cfg.staticEndpoints) {
        if (s.tcp || s.id.subsystem != dst.subsystem)
            continue;
        if (dst.node != 0xFF && s.id.node != 0xFF && s.id.node != dst.node)
            continue;
        boost::system::error_code ec;
        auto a = asio::ip::make_address_v4(s.address, ec);
        if (!ec)
            out.emplace_back(a, s.port);
    }
    return out;
}

JudpTransport::Endpoint JudpTransport::broadcastEndpoint() const {
    boost::system::error_code ec;
    if (m_cfg.multicast)
        return Endpoint(asio::ip::make_address_v4(m_cfg.multicastGroup, ec), m_cfg.multicastPort);
    return Endpoint(asio::ip::make_address_v4(m_cfg.broadcastAddress, ec), m_cfg.multicastPort);
}

std::string JudpTransport::endpointOf(const JausId& id) const {
    if (auto it = m_tcpRoutes.find(id.value()); it != m_tcpRoutes.end())
        if (auto c = it->second.lock(); c && !c->dead)
            return "tcp:" + c->peer;
    auto ep = resolve(id);
    if (!ep)
        return {};
    return ep->address().to_string() + ":" + std::to_string(ep->port());
}

std::string JudpTransport::send(const JausId& src, const JausId& dst, const Bytes& payload, SendOptions o) {
    if (!m_open)
        return "the JAUS transport is closed";
    JudpHeader h;
    h.priority = o.priority;
    h.ackNak = o.ackRequest ? AckNak::Request : AckNak::None;
    h.source = src;
    h.destination = dst;
    // A destination within one subsystem (ss.255.255) may be reached through its static endpoint.
    if (!dst.isBroadcast() || dst.subsystem != 0xFFFF) {
        if (auto c = tcpRoute(dst)) {
            h.ackNak = AckNak::None; // TCP is reliable
            const std::size_t n = fragmentPayload(h, payload, m_cfg.maxFragmentPayload).size();
            h.sequence = takeSequence(src, n);
            auto frags = fragmentPayload(h, payload, m_cfg.maxFragmentPayload);
            for (auto& f : frags) {
                tcpWrite(c, encodeJtcp(f.header, f.payload, !c->versionSent));
                c->versionSent = true;
            }
            m_counters.add("tx.jtcp.messages");
            return {};
        }
    }
    Endpoint to;
    if (dst.isBroadcast() && dst.subsystem != 0xFFFF) {
        // Static endpoints of that subsystem get it unicast (AEP-4818 §4.7.1), not the group.
        if (auto eps = staticUdpEndpoints(dst); !eps.empty()) {
            h.broadcast = BroadcastFlag::Local;
            h.ackNak = AckNak::None;
            auto frags = fragmentPayload(h, payload, m_cfg.maxFragmentPayload);
            if (frags.size() > 1)
                return "a broadcast may not be fragmented";
            frags[0].header.sequence = takeSequence(src, 1);
            m_lastSendError.clear();
            for (auto& ep : eps)
                transmit(encodeDatagram(frags[0].header, frags[0].payload), ep);
            return m_lastSendError;
        }
    }
    if (dst.isBroadcast()) {
        h.broadcast = dst.subsystem == 0xFFFF ? BroadcastFlag::Global : BroadcastFlag::Local;
        h.ackNak = AckNak::None; // no ACKs for wildcard destinations (JTS JuniorMgr::sendto)
        to = broadcastEndpoint();
    } else if (auto ep = resolve(dst)) {
        to = *ep;
    } else {
        // Unknown address: broadcast with an ACK request so the ACK reveals the peer (JTS JuniorRTE, §2.2).
        h.broadcast = BroadcastFlag::Global;
        h.ackNak = AckNak::Request;
        to = broadcastEndpoint();
        m_counters.add("tx.unknown_destination");
    }
    const std::size_t nfrag = fragmentPayload(h, payload, m_cfg.maxFragmentPayload).size();
    if (nfrag > 1 && h.broadcast != BroadcastFlag::None) {
        m_counters.add("tx.refused.broadcast_too_large");
        logWarning(m_log, "refusing to broadcast a message larger than one fragment");
        return "a broadcast may not be fragmented";
    }
    h.sequence = takeSequence(src, nfrag);
    auto frags = fragmentPayload(h, payload, m_cfg.maxFragmentPayload);
    m_lastSendError.clear();
    for (auto& f : frags)
        transmit(encodeDatagram(f.header, f.payload), to);
    return m_lastSendError;
}

void JudpTransport::transmit(Bytes datagram, const Endpoint& to) {
    if (m_faults.loss > 0 && std::uniform_real_distribution<double>(0, 1)(m_rng) < m_faults.loss) {
        m_counters.add("tx.fault.dropped");
        return;
    }
    auto out = [this](Bytes d, const Endpoint& e) {
        if (m_faults.delay > Duration::zero()) {
            auto t = std::make_shared<asio::steady_timer>(m_io, m_faults.delay);
            t->async_wait([this, t, d = std::move(d), e](boost::system::error_code ec) {
                if (!ec && m_open)
                    rawSend(d, e);
            });
        } else {
            rawSend(d, e);
        }
    };
    if (m_faults.reorder) {
        if (!m_held) {
            m_held = std::make_pair(std::move(datagram), to);
            return;
        }
        auto held = std::move(*m_held);
        m_held.reset();
        out(std::move(datagram), to); // the newer one first
        out(std::move(held.first), held.second);
        return;
    }
    out(std::move(datagram), to);
}

std::uint16_t JudpTransport::takeSequence(const JausId& src, std::size_t n) {
    std::lock_guard lock(m_sequenceMutex);
    std::uint16_t& seq = m_sequence[src.value()];
    const std::uint16_t first = seq;
    seq = std::uint16_t(seq + n);
    return first;
}

bool JudpTransport::hasTcpRoute(const JausId& dst) const {
    if (auto it = m_tcpRoutes.find(dst.value()); it != m_tcpRoutes.end())
        if (auto c = it->second.lock(); c && !c->dead)
            return true;
    for (const auto& s : m_cfg.staticEndpoints)
        if (s.tcp && s.id.subsystem == dst.subsystem &&
            (s.id.node == 0xFF || dst.node == 0xFF || s.id.node == dst.node) &&
            (s.id.component == 0xFF || dst.component == 0xFF || s.id.component == dst.component))
            return true;
    return false;
}

std::optional<PlannedDatagram> JudpTransport::plan(const JausId& src, const JausId& dst, const Bytes& payload,
                                                   SendOptions o) const {
    // The same routing as send(), minus everything with side effects or more than one datagram.
    if (!m_open || m_faults.loss > 0 || m_faults.delay > Duration::zero() || m_faults.reorder)
        return std::nullopt;
    if (payload.size() > (m_cfg.maxFragmentPayload ? m_cfg.maxFragmentPayload : kMaxFragmentPayload))
        return std::nullopt;
    if ((!dst.isBroadcast() || dst.subsystem != 0xFFFF) && hasTcpRoute(dst))
        return std::nullopt;
    JudpHeader h;
    h.priority = o.priority;
    h.ackNak = o.ackRequest ? AckNak::Request : AckNak::None;
    h.source = src;
    h.destination = dst;
    PlannedDatagram p;
    if (dst.isBroadcast() && dst.subsystem != 0xFFFF) {
        if (auto eps = staticUdpEndpoints(dst); !eps.empty()) {
            h.broadcast = BroadcastFlag::Local;
            h.ackNak = AckNak::None;
            p.to = std::move(eps);
        }
    }
    if (p.to.empty()) {
        if (dst.isBroadcast()) {
            h.broadcast = dst.subsystem == 0xFFFF ? BroadcastFlag::Global : BroadcastFlag::Local;
            h.ackNak = AckNak::None;
            p.to.push_back(broadcastEndpoint());
        } else if (auto ep = resolve(dst)) {
            p.to.push_back(*ep);
        } else {
            return std::nullopt; // unknown address: send() broadcasts with an ACK request and counts it
        }
    }
    h.sequence = 0;
    auto frags = fragmentPayload(h, payload, m_cfg.maxFragmentPayload);
    if (frags.size() != 1)
        return std::nullopt;
    p.datagram = encodeDatagram(frags[0].header, frags[0].payload);
    return p;
}

std::string JudpTransport::sendPlanned(const JausId& src, const PlannedDatagram& planned) {
    if (planned.datagram.size() < 1 + kMessageOverhead || planned.to.empty())
        return "nothing planned";
    std::lock_guard lock(m_fastMutex);
    if (!m_fastOpen || !m_unicast)
        return "the JAUS transport is closed";
    // The sequence number closes the message (AS5669A JUDP header: ... payload, sequence number), little
    // endian like every JUDP field.
    Bytes d = planned.datagram;
    const std::uint16_t seq = takeSequence(src, 1);
    d[d.size() - 2] = std::uint8_t(seq & 0xFF);
    d[d.size() - 1] = std::uint8_t(seq >> 8);
    const int fd = m_unicast->socket.native_handle();
    std::string why;
    for (const auto& ep : planned.to) {
        // The kernel's sendto is thread-safe; MSG_DONTWAIT: a full socket buffer is a refusal, never a wait.
        const ssize_t n =
            ::sendto(fd, d.data(), d.size(), MSG_DONTWAIT, ep.data(), static_cast<socklen_t>(ep.size()));
        if (n != static_cast<ssize_t>(d.size())) {
            m_counters.add("tx.errors");
            why = "send to " + ep.address().to_string() + ":" + std::to_string(ep.port()) +
                  " failed: " + (n < 0 ? std::strerror(errno) : "short write");
        } else {
            m_counters.add("tx.datagrams");
        }
    }
    if (why.empty())
        m_counters.add("tx.planned");
    return why;
}

bool JudpTransport::rawSend(const Bytes& datagram, const Endpoint& to) {
    boost::system::error_code ec;
    m_unicast->socket.send_to(asio::buffer(datagram), to, 0, ec);
    if (ec) {
        m_counters.add("tx.errors");
        m_lastSendError = "send to " + to.address().to_string() + ":" + std::to_string(to.port()) +
                          " failed: " + ec.message();
        logDebug(m_log, m_lastSendError);
        return false;
    }
    m_counters.add("tx.datagrams");
    return true;
}

} // namespace ocu::jaus
