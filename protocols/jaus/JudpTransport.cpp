#include "protocols/jaus/JudpTransport.h"

#include <boost/asio/ip/address_v4.hpp>
#include <boost/asio/ip/multicast.hpp>
#include <boost/asio/write.hpp>
#include <boost/system/system_error.hpp>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <netinet/in.h>
#include <sys/socket.h>

#include "protocols/common/Log.h"

namespace ocu::jaus {

namespace asio = boost::asio;
using asio::ip::udp;

struct JudpTransport::Receiver {
    explicit Receiver(asio::io_context& io) : socket(io) {}
    udp::socket socket;
    UdpOptions options;
    std::array<std::uint8_t, 65536> buffer{};
    udp::endpoint from;
};

struct JudpTransport::TcpConn {
    explicit TcpConn(asio::io_context& io) : socket(io) {}
    asio::ip::tcp::socket socket;
    JtcpStreamDecoder decoder;
    std::array<std::uint8_t, 16384> buffer{};
    std::deque<Bytes> queue;
    bool writing = false;
    bool connected = false;
    bool versionSent = false;
    bool dead = false;
    std::string peer;
};

JudpTransport::JudpTransport(asio::io_context& io, TransportSettings settings, Counters& counters,
                             const Clock& clock, std::string logCategory)
    : m_io(io), m_cfg(std::move(settings)), m_counters(counters), m_clock(clock),
      m_log(std::move(logCategory)) {}

JudpTransport::~JudpTransport() {
    close();
}

void JudpTransport::setHandlers(MessageHandler onMessage, ErrorHandler onError) {
    m_onMessage = std::move(onMessage);
    m_onError = std::move(onError);
}

namespace {

bool addressInUse(const boost::system::system_error& e) {
    return e.code() == asio::error::address_in_use;
}

// Linux: a socket bound to a wildcard address receives the datagrams of every multicast group joined by any
// socket of the host on its port unless IP_MULTICAST_ALL is off; the unicast socket wants none of them
// (the group socket has them).
void multicastAllOff(udp::socket& s) {
#ifdef IP_MULTICAST_ALL
    int off = 0;
    ::setsockopt(s.native_handle(), IPPROTO_IP, IP_MULTICAST_ALL, &off, sizeof off);
#else
    (void)s;
#endif
}

} // namespace

void JudpTransport::open() {
    m_groupProblem.reset();
    std::optional<GroupSocketProblem> group; // why there is no group socket, once known
    std::uint16_t unicastHeld = 0;           // the configured unicast port, when another process holds it
    try {
        m_unicast = std::make_unique<Receiver>(m_io);
        UdpOptions u;
        u.bindAddress = m_cfg.bindAddress;
        u.port = m_cfg.port;
        u.interfaceAddress = m_cfg.interfaceAddress;
        u.multicastTtl = m_cfg.multicastTtl;
        u.broadcast = !m_cfg.multicast;
        std::string unicastError;
        // The configured port held by another process: an ephemeral port instead (peers learn it from our
        // datagrams, AEP-4818 §4.7.2).
        auto openUnicast = [&] {
            try {
                openUdpSocket(m_unicast->socket, u);
            } catch (const boost::system::system_error& e) {
                if (u.port == 0 || !addressInUse(e))
                    throw;
                boost::system::error_code ec;
                m_unicast->socket.close(ec);
                m_counters.add("transport.port_in_use");
                unicastHeld = u.port;
                unicastError = e.what();
                u.port = 0;
                openUdpSocket(m_unicast->socket, u);
            }
        };
        if (m_cfg.multicast) {
            // Sharing a host: the unicast port is ours alone, so replies meant for us never go
            // to another console or a node manager on the same port (bound without SO_REUSEADDR, which Linux
            // checks at bind time); once bound it allows sharing, so group sockets (ours, other consoles',
            // a node manager's) may use the same port.
            u.reuseAddress = false;
            openUnicast();
            m_unicast->socket.set_option(asio::socket_base::reuse_address(true));
            m_unicast->socket.set_option(asio::ip::multicast::hops(m_cfg.multicastTtl));
            multicastAllOff(m_unicast->socket);
        } else {
            // UDP broadcast mode: broadcasts arrive on this socket, so with its port held by another process
            // the console hears no broadcasts - the same loss as a missing group socket.
            openUnicast();
            if (unicastHeld != 0) {
                GroupSocketProblem p;
                p.group = "broadcast port " + std::to_string(unicastHeld);
                p.port = unicastHeld;
                p.heldByOther = true;
                p.reason = unicastError;
                p.unicastPortHeld = unicastHeld;
                group = std::move(p);
            }
        }
        m_unicast->options = u;
        if (m_cfg.multicast) {
            // The group socket: bound to the group address (not INADDR_ANY) with SO_REUSEADDR, so it shares
            // the port with other JAUS nodes and never receives unicast datagrams meant for another process
            // (Linux delivers a unicast datagram only to sockets bound to its destination or the wildcard).
            m_multicast = std::make_unique<Receiver>(m_io);
            UdpOptions mo;
            mo.bindAddress = m_cfg.multicastGroup;
            mo.port = m_cfg.multicastPort;
            mo.multicastGroup = m_cfg.multicastGroup;
            mo.interfaceAddress = m_cfg.interfaceAddress;
            mo.multicastTtl = m_cfg.multicastTtl;
            try {
                try {
                    openUdpSocket(m_multicast->socket, mo);
                } catch (const boost::system::system_error& e) {
                    // Held by another process: the wildcard would collide with its bind as well.
                    if (addressInUse(e))
                        throw;
                    // Systems that cannot bind a group address: the wildcard, still shared.
                    boost::system::error_code ec;
                    m_multicast->socket.close(ec);
                    mo.bindAddress = "0.0.0.0";
                    openUdpSocket(m_multicast->socket, mo);
                }
                m_multicast->options = mo;
            } catch (const boost::system::system_error& e) {
                // Public JAUS node managers (JTS, FKIE) bind the port without SO_REUSEADDR, and Linux lets a
                // second socket share a UDP port only when both set it; a host may also have no multicast
                // route. Neither stops the console: what is addressed to it comes by unicast to its own port,
                // and it still sends to the group from there (discovery, unknown destinations), so only what
                // others send to the group is missed.
                boost::system::error_code ec;
                m_multicast->socket.close(ec);
                m_multicast.reset();
                GroupSocketProblem p;
                p.group = m_cfg.multicastGroup + ":" + std::to_string(m_cfg.multicastPort);
                p.port = m_cfg.multicastPort;
                p.heldByOther = addressInUse(e);
                p.reason = e.what();
                p.unicastPortHeld = unicastHeld;
                group = std::move(p);
            }
        }
    } catch (const boost::system::system_error& e) {
        close();
        throw std::runtime_error(std::string("JUDP socket: ") + e.what());
    }
    if (m_cfg.jtcpServer) {
        try {
            namespace ip = asio::ip;
            m_acceptor = std::make_unique<ip::tcp::acceptor>(m_io);
            ip::tcp::endpoint ep(ip::make_address_v4(m_cfg.bindAddress), m_cfg.jtcpPort);
            m_acceptor->open(ep.protocol());
            m_acceptor->set_option(asio::socket_base::reuse_address(true));
            m_acceptor->bind(ep);
            m_acceptor->listen();
        } catch (const boost::system::system_error& e) {
            close();
            throw std::runtime_error(std::string("JTCP listen: ") + e.what());
        }
    }
    // One warning for the port held by another process: the group socket's (which names the unicast
    // fallback too), else the unicast port's.
    if (group) {
        group->unicastPort = localPort();
        m_groupProblem = std::move(group);
        m_counters.add("transport.group_socket_missing");
        logWarning(m_log, toText(*m_groupProblem));
    } else if (unicastHeld != 0) {
        logWarning(m_log, "UDP port " + std::to_string(unicastHeld) +
                              " is held by another process (a JAUS node manager or another console):"
                              " using an ephemeral unicast port; peers reply to it");
    }
    m_open = true;
    {
        std::lock_guard lock(m_fastMutex);
        m_fastOpen = true;
    }
    if (m_acceptor)
        startAccept();
    startReceive(*m_unicast);
    if (m_multicast)
        startReceive(*m_multicast);
}

void JudpTransport::close() {
    m_open = false;
    {
        std::lock_guard lock(m_fastMutex);
        m_fastOpen = false;
    }
    boost::system::error_code ec;
    if (m_acceptor)
        m_acceptor->close(ec);
    for (auto& c : m_conns)
        c->socket.close(ec);
    m_conns.clear();
    m_tcpClients.clear();
    m_tcpRoutes.clear();
    if (m_multicast) {
        leaveMulticast(m_multicast->socket, m_multicast->options);
        m_multicast->socket.close(ec);
    }
    if (m_unicast) {
        leaveMulticast(m_unicast->socket, m_unicast->options);
        m_unicast->socket.close(ec);
    }
}

std::uint16_t JudpTransport::localPort() const {
    boost::system::error_code ec;
    if (!m_unicast)
        return 0;
    auto ep = m_unicast->socket.local_endpoint(ec);
    return ec ? 0 : ep.port();
}

std::uint16_t JudpTransport::localTcpPort() const {
    boost::system::error_code ec;
    if (!m_acceptor)
        return 0;
    auto ep = m_acceptor->local_endpoint(ec);
    return ec ? 0 : ep.port();
}

std::size_t JudpTransport::pendingTcpWrites() const {
    std::size_t n = 0;
    for (auto& c : m_conns)
        if (!c->dead)
            n += c->queue.size() + (c->writing ? 1 : 0);
    return n;
}

void JudpTransport::startReceive(Receiver& r) {
    r.socket.async_receive_from(asio::buffer(r.buffer), r.from,
                                [this, &r](boost::system::error_code ec, std::size_t n) {
                                    if (ec == asio::error::operation_aborted || !m_open)
                                        return;
                                    if (!ec)
                                        onDatagram(ByteSpan(r.buffer.data(), n), r.from);
                                    else
                                        m_counters.add("rx.socket_errors");
                                    startReceive(r);
                                });
}

void JudpTransport::onDatagram(ByteSpan data, const Endpoint& from) {
    m_counters.add("rx.datagrams");
    if (m_onRaw)
        m_onRaw(data, from.address().to_string() + ":" + std::to_string(from.port()));
    auto reject = [&](const std::string& err) {
        const std::string reason = rejectReason(err);
        m_counters.add("rx.rejected." + reason);
        // At most one log line per reason and second: a broken or hostile peer must not flood the log.
        const TimePoint t = m_clock.now();
        auto& last = m_lastLog[reason];
        if (last == TimePoint{} || t - last >= std::chrono::seconds(1)) {
            last = t;
            logWarning(m_log, "datagram from " + from.address().to_string() + ":" +
                                  std::to_string(from.port()) + " rejected: " + err);
        }
        if (m_onError)
            m_onError(reason, err);
    };
    auto d = decodeDatagram(data);
    if (!d)
        return reject(d.error());
    if (!d->error.empty())
        reject(d->error);
    const TimePoint now = m_clock.now();
    if (auto n = m_reassembler.expire(now))
        m_counters.add("rx.rejected.fragment_timeout", n);
    for (auto& m : d->messages) {
        const JudpHeader& h = m.header;
        // Learn where this JAUS ID lives (AEP-4818 §4.7.2: dynamic address list from every message).
        if (!h.source.isBroadcast() && h.source.subsystem != 0) {
            if (auto known = m_learned.find(h.source.value()); known != m_learned.end())
                known->second = from;
            else if (m_learned.size() < kMaxLearnedAddresses)
                m_learned.emplace(h.source.value(), from);
            else
                m_counters.add("rx.limited.learned_address");
        }
        if (h.ackNak == AckNak::Ack || h.ackNak == AckNak::Nak) {
            m_counters.add(h.ackNak == AckNak::Ack ? "rx.ack" : "rx.nak");
            continue;
        }
        // Answer ACK requests even when received by multicast: that is how a JTS peer finds us (§2.2).
        if (h.ackNak == AckNak::Request && m_isLocal && !h.destination.isBroadcast() &&
            m_isLocal(h.destination)) {
            rawSend(encodeDatagram(makeAckHeader(h), ByteSpan{}), from);
            m_counters.add("tx.ack");
        }
        deliver(std::move(m), now, reject);
    }
}

void JudpTransport::deliver(JudpMessage m, TimePoint now,
                            const std::function<void(const std::string&)>& reject) {
    const std::uint64_t evictedBefore = m_reassembler.evicted();
    auto r = m_reassembler.feed(std::move(m), now);
    if (m_reassembler.evicted() != evictedBefore) // a partial set made room (per-peer or total bound)
        m_counters.add("rx.rejected.fragment_evicted", m_reassembler.evicted() - evictedBefore);
    if (!r) {
        reject(r.error());
        return;
    }
    if (!*r)
        return;
    const JudpMessage& full = **r;
    if (full.payload.size() < 2) {
        reject("short: message without a message ID");
        return;
    }
    if (m_onMessage)
        m_onMessage(full.header.source, full.header.destination, full.payload);
}

// ---- JTCP ----

void JudpTransport::startAccept() {
    auto c = std::make_shared<TcpConn>(m_io);
    m_acceptor->async_accept(c->socket, [this, c](boost::system::error_code ec) {
        if (!m_open || ec == asio::error::operation_aborted)
            return;
        if (!ec) {
            boost::system::error_code e2;
            auto rep = c->socket.remote_endpoint(e2);
            c->peer = e2 ? "?" : rep.address().to_string() + ":" + std::to_string(rep.port());
            c->connected = true;
            m_conns.insert(c);
            m_counters.add("jtcp.accepted");
            startRead(c);
        }
        startAccept();
    });
}

void JudpTransport::startRead(const TcpPtr& c) {
    c->socket.async_read_some(
        asio::buffer(c->buffer), [this, c](boost::system::error_code ec, std::size_t n) {
            if (!m_open || ec == asio::error::operation_aborted)
                return;
            if (ec)
                return dropConn(c, ec.message());
            if (m_onRaw)
                m_onRaw(ByteSpan(c->buffer.data(), n), c->peer);
            auto msgs = c->decoder.feed(ByteSpan(c->buffer.data(), n));
            if (!msgs) {
                m_counters.add("rx.rejected." + rejectReason(msgs.error()));
                logWarning(m_log, "JTCP stream from " + c->peer + " closed: " + msgs.error());
                return dropConn(c, msgs.error());
            }
            const TimePoint now = m_clock.now();
            auto reject = [&](const std::string& err) {
                m_counters.add("rx.rejected." + rejectReason(err));
                logWarning(m_log, "JTCP message from " + c->peer + " rejected: " + err);
            };
            for (auto& m : *msgs) {
                m_counters.add("rx.jtcp.messages");
                if (!m.header.source.isBroadcast() && m.header.source.subsystem != 0)
                    m_tcpRoutes[m.header.source.value()] = c;
                if (m.header.ackNak == AckNak::Ack || m.header.ackNak == AckNak::Nak)
                    continue;
                deliver(std::move(m), now, reject);
            }
            if (c->decoder.failed()) { // good messages before a bad one in the same read were delivered above
                m_counters.add("rx.rejected." + rejectReason(c->decoder.error()));
                logWarning(m_log, "JTCP stream from " + c->peer + " closed: " + c->decoder.error());
                return dropConn(c, c->decoder.error());
            }
            startRead(c);
        });
}

void JudpTransport::tcpWrite(const TcpPtr& c, Bytes bytes) {
    c->queue.push_back(std::move(bytes));
    if (c->connected && !c->writing)
        flush(c);
}

void JudpTransport::flush(const TcpPtr& c) {
    if (c->queue.empty() || c->dead) {
        c->writing = false;
        return;
    }
    c->writing = true;
    auto data = std::make_shared<Bytes>(std::move(c->queue.front()));
    c->queue.pop_front();
    asio::async_write(c->socket, asio::buffer(*data),
                      [this, c, data](boost::system::error_code ec, std::size_t) {
                          if (!m_open || ec == asio::error::operation_aborted)
                              return;
                          if (ec)
                              return dropConn(c, ec.message());
                          m_counters.add("tx.jtcp.writes");
                          flush(c);
                      });
}

void JudpTransport::dropConn(const TcpPtr& c, const std::string& why) {
    if (c->dead)
        return;
    c->dead = true;
    boost::system::error_code ec;
    c->socket.close(ec);
    m_conns.erase(c);
    for (auto it = m_tcpClients.begin(); it != m_tcpClients.end();)
        it = it->second == c ? m_tcpClients.erase(it) : std::next(it);
    m_counters.add("jtcp.closed");
    logInfo(m_log, "JTCP connection " + c->peer + " closed: " + why);
}

JudpTransport::TcpPtr JudpTransport::tcpRoute(const JausId& dst) {
    if (auto it = m_tcpRoutes.find(dst.value()); it != m_tcpRoutes.end()) {
        if (auto c = it->second.lock(); c && !c->dead)
            return c;
        m_tcpRoutes.erase(it);
    }
    for (std::size_t i = 0; i < m_cfg.staticEndpoints.size(); ++i) {
        const auto& s = m_cfg.staticEndpoints[i];
        if (!s.tcp || s.id.subsystem != dst.subsystem ||
            (s.id.node != 0xFF && dst.node != 0xFF && s.id.node != dst.node) ||
            (s.id.component != 0xFF && dst.component != 0xFF && s.id.component != dst.component))
            continue;
        if (auto it = m_tcpClients.find(i); it != m_tcpClients.end())
            return it->second;
        boost::system::error_code ec;
        auto addr = asio::ip::make_address_v4(s.address, ec);
        if (ec)
            return nullptr;
        auto c = std::make_shared<TcpConn>(m_io);
        c->peer = s.address + ":" + std::to_string(s.port);
        m_tcpClients[i] = c;
        m_conns.insert(c);
        c->socket.async_connect(asio::ip::tcp::endpoint(addr, s.port),
                                [this, c](boost::system::error_code e) {
                                    if (!m_open || e == asio::error::operation_aborted)
                                        return;
                                    if (e)
                                        return dropConn(c, "connect: " + e.message());
                                    c->connected = true;
                                    m_counters.add("jtcp.connected");
                                    startRead(c);
                                    flush(c);
                                });
        return c;
    }
    return nullptr;
}

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
