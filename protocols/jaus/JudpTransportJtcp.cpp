// JTCP (AS5669A; AEP-4818 §4.7.1: static address list, port 3794): accepted and outgoing connections,
// their reads and write queues.
#include "protocols/jaus/JudpTransport.h"

#include <boost/asio/ip/address_v4.hpp>
#include <boost/asio/write.hpp>

#include "protocols/common/Log.h"
#include "protocols/jaus/JudpTransportSockets.h"

namespace ocu::jaus {

namespace asio = boost::asio;

std::size_t JudpTransport::pendingTcpWrites() const {
    std::size_t n = 0;
    for (auto& c : m_conns)
        if (!c->dead)
            n += c->queue.size() + (c->writing ? 1 : 0);
    return n;
}

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

} // namespace ocu::jaus
