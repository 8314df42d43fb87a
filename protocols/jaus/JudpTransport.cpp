// Opening and closing the transport: the unicast socket, the multicast group socket and its membership (or
// broadcast reception), the JTCP listener.
#include "protocols/jaus/JudpTransport.h"

#include <boost/asio/ip/address_v4.hpp>
#include <boost/asio/ip/multicast.hpp>
#include <boost/system/system_error.hpp>

#include <stdexcept>

#include <netinet/in.h>
#include <sys/socket.h>

#include "protocols/common/Log.h"
#include "protocols/jaus/JudpTransportSockets.h"

namespace ocu::jaus {

namespace asio = boost::asio;
using asio::ip::udp;

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
        group = openUnicastSocket(unicastHeld);
        if (m_cfg.multicast)
            group = openGroupSocket(unicastHeld);
    } catch (const boost::system::system_error& e) {
        close();
        throw std::runtime_error(std::string("JUDP socket: ") + e.what());
    }
    if (m_cfg.jtcpServer)
        openJtcpServer();
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

std::optional<GroupSocketProblem> JudpTransport::openUnicastSocket(std::uint16_t& unicastHeld) {
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
    std::optional<GroupSocketProblem> group;
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
    return group;
}

std::optional<GroupSocketProblem> JudpTransport::openGroupSocket(std::uint16_t unicastHeld) {
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
        return std::nullopt;
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
        return p;
    }
}

void JudpTransport::openJtcpServer() {
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

} // namespace ocu::jaus
