#include "protocols/osyris/OsyrisTransport.h"

#include "protocols/common/Udp.h"

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/udp.hpp>
#include <boost/asio/steady_timer.hpp>

#include <array>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <random>
#include <stdexcept>
#include <vector>

namespace ocu::osyris {

namespace asio = boost::asio;
using asio::ip::udp;

struct OsyrisTransport::Impl {
    Impl(asio::io_context& c, Counters& k) : io(c), counters(k), socket(c) {}

    void receiveNext() {
        socket.async_receive_from(asio::buffer(rxBuf), sender,
                                  [this](boost::system::error_code ec, std::size_t n) {
                                      if (ec == asio::error::operation_aborted || !socket.is_open())
                                          return;
                                      if (!ec)
                                          deliver(n);
                                      receiveNext();
                                  });
    }

    void deliver(std::size_t n) {
        std::uniform_real_distribution<double> u(0, 1);
        if (imp.loss > 0 && u(rng) < imp.loss) {
            counters.add("rx.impaired.lost");
            return;
        }
        int times = (imp.duplicate > 0 && u(rng) < imp.duplicate) ? 2 : 1;
        if (times == 2)
            counters.add("rx.impaired.duplicated");
        if (imp.reorder > 0 && u(rng) < imp.reorder) {
            counters.add("rx.impaired.delayed");
            Bytes copy(rxBuf.begin(), rxBuf.begin() + static_cast<std::ptrdiff_t>(n));
            auto t = std::make_shared<asio::steady_timer>(io);
            t->expires_after(std::chrono::milliseconds(imp.delayMs));
            t->async_wait([this, t, copy = std::move(copy), times](boost::system::error_code e) {
                if (!e && open)
                    for (int i = 0; i < times; ++i)
                        onDatagram(copy);
            });
            return;
        }
        for (int i = 0; i < times; ++i)
            onDatagram(ByteSpan(rxBuf.data(), n));
    }

    asio::io_context& io;
    Counters& counters;
    udp::socket socket;
    UdpOptions options;
    std::vector<udp::endpoint> destinations;
    std::array<std::uint8_t, 65536> rxBuf{};
    udp::endpoint sender;
    DatagramHandler onDatagram;
    RxImpairment imp;
    std::mt19937 rng{1};
    bool open = false;
    std::mutex fastMutex; // sendFromAnyThread never uses a closed (or reused) descriptor
    bool fastOpen = false;
};

OsyrisTransport::OsyrisTransport(asio::io_context& io, Counters& counters)
    : m_impl(std::make_unique<Impl>(io, counters)) {}

OsyrisTransport::~OsyrisTransport() {
    close();
}

void OsyrisTransport::open(const OsyrisConfig& cfg) {
    auto& o = m_impl->options;
    // Multicast: bind the group address, so only the group's datagrams arrive and nothing listens on other
    // addresses; unicast: the interface; broadcast needs the wildcard.
    o.bindAddress = cfg.addressing == Addressing::Multicast ? cfg.group
                    : cfg.addressing == Addressing::Unicast ? cfg.interfaceAddress
                                                            : std::string("0.0.0.0");
    o.port = cfg.port;
    o.interfaceAddress = cfg.interfaceAddress;
    o.multicastTtl = cfg.multicastTtl;
    o.broadcast = cfg.addressing == Addressing::Broadcast;
    o.multicastGroup = cfg.addressing == Addressing::Multicast ? cfg.group : "";
    std::vector<udp::endpoint> destinations;
    try {
        openUdpSocket(m_impl->socket, o);
        destinations.emplace_back(asio::ip::make_address_v4(cfg.group), cfg.port);
    } catch (const std::exception& e) {
        boost::system::error_code ec;
        m_impl->socket.close(ec);
        throw std::runtime_error(std::string("OSYRIS socket: ") + e.what());
    }
    for (const auto& peer : cfg.unicastPeers) {
        auto colon = peer.rfind(':');
        std::string ip = colon == std::string::npos ? peer : peer.substr(0, colon);
        int port = colon == std::string::npos ? cfg.port : std::atoi(peer.c_str() + colon + 1);
        boost::system::error_code ec;
        auto addr = asio::ip::make_address_v4(ip, ec);
        if (ec || port <= 0 || port > 65535) {
            leaveMulticast(m_impl->socket, o);
            m_impl->socket.close(ec);
            throw std::runtime_error("OSYRIS unicast peer '" + peer + "' is not ip:port");
        }
        destinations.emplace_back(addr, static_cast<std::uint16_t>(port));
    }
    m_impl->destinations = std::move(destinations);
    m_impl->open = true;
    std::lock_guard lock(m_impl->fastMutex);
    m_impl->fastOpen = true;
}

void OsyrisTransport::startReceive(DatagramHandler onDatagram) {
    m_impl->onDatagram = std::move(onDatagram);
    if (m_impl->open)
        m_impl->receiveNext();
}

bool OsyrisTransport::send(const Bytes& datagram) {
    if (!m_impl->open)
        return false;
    bool ok = !m_impl->destinations.empty();
    for (const auto& ep : m_impl->destinations) {
        boost::system::error_code ec;
        m_impl->socket.send_to(asio::buffer(datagram), ep, 0, ec);
        if (ec) {
            m_impl->counters.add("tx.error");
            m_lastError = ec.message();
            ok = false;
        }
    }
    return ok;
}

bool OsyrisTransport::sendFromAnyThread(const Bytes& datagram, std::string* why, std::size_t* taken) {
    if (taken)
        *taken = 0;
    std::lock_guard lock(m_impl->fastMutex);
    if (!m_impl->fastOpen || m_impl->destinations.empty()) {
        if (why)
            *why = "the OSYRIS socket is closed";
        return false;
    }
    const int fd = m_impl->socket.native_handle();
    bool ok = true;
    for (const auto& ep : m_impl->destinations) {
        // The kernel's sendto is thread-safe; MSG_DONTWAIT: a full socket buffer is a refusal, never a wait.
        const ssize_t n = ::sendto(fd, datagram.data(), datagram.size(), MSG_DONTWAIT, ep.data(),
                                   static_cast<socklen_t>(ep.size()));
        if (n != static_cast<ssize_t>(datagram.size())) {
            m_impl->counters.add("tx.error");
            if (why)
                *why = n < 0 ? std::strerror(errno) : "short write";
            ok = false;
        } else if (taken) {
            ++*taken;
        }
    }
    return ok;
}

void OsyrisTransport::close() {
    if (!m_impl->open)
        return;
    {
        std::lock_guard lock(m_impl->fastMutex);
        m_impl->fastOpen = false;
    }
    m_impl->open = false;
    boost::system::error_code ec;
    leaveMulticast(m_impl->socket, m_impl->options); // IGMP leave
    m_impl->socket.close(ec);
}

bool OsyrisTransport::isOpen() const {
    return m_impl->open;
}

void OsyrisTransport::setImpairment(const RxImpairment& imp) {
    m_impl->imp = imp;
    m_impl->rng.seed(imp.seed);
}

std::uint16_t OsyrisTransport::localPort() const {
    boost::system::error_code ec;
    auto ep = m_impl->socket.local_endpoint(ec);
    return ec ? 0 : ep.port();
}

} // namespace ocu::osyris
