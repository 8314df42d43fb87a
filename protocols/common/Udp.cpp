#include "protocols/common/Udp.h"

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/multicast.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/system/system_error.hpp>

namespace ocu {

namespace asio = boost::asio;
using asio::ip::udp;

void openUdpSocket(udp::socket& socket, const UdpOptions& o) {
    auto step = [](const char* what, boost::system::error_code ec) {
        if (ec)
            throw boost::system::system_error(ec, what);
    };
    boost::system::error_code ec;
    socket.open(udp::v4(), ec);
    step("open", ec);
    if (o.reuseAddress) {
        socket.set_option(asio::socket_base::reuse_address(true), ec);
        step("reuse_address", ec);
    }
    if (o.broadcast) {
        socket.set_option(asio::socket_base::broadcast(true), ec);
        step("broadcast", ec);
    }
    if (o.receiveBufferBytes > 0)
        socket.set_option(asio::socket_base::receive_buffer_size(o.receiveBufferBytes), ec); // best effort
    auto bindAddr = asio::ip::make_address_v4(o.bindAddress, ec);
    step("bind address", ec);
    socket.bind(udp::endpoint(bindAddr, o.port), ec);
    step("bind", ec);
    if (!o.multicastGroup.empty()) {
        auto group = asio::ip::make_address_v4(o.multicastGroup, ec);
        step("multicast group address", ec);
        auto iface = asio::ip::make_address_v4(o.interfaceAddress, ec);
        step("interface address", ec);
        socket.set_option(asio::ip::multicast::join_group(group, iface), ec);
        step("join multicast group", ec);
        socket.set_option(asio::ip::multicast::outbound_interface(iface), ec);
        step("multicast outbound interface", ec);
        socket.set_option(asio::ip::multicast::hops(o.multicastTtl), ec);
        step("multicast ttl", ec);
        socket.set_option(asio::ip::multicast::enable_loopback(o.multicastLoop), ec);
        step("multicast loopback", ec);
    } else if (o.interfaceAddress != "0.0.0.0") {
        // Unicast/broadcast sockets may still send to a multicast group (e.g. JAUS from an ephemeral port).
        auto iface = asio::ip::make_address_v4(o.interfaceAddress, ec);
        step("interface address", ec);
        socket.set_option(asio::ip::multicast::outbound_interface(iface), ec);
        step("multicast outbound interface", ec);
        socket.set_option(asio::ip::multicast::hops(o.multicastTtl), ec);
        step("multicast ttl", ec);
    }
}

void leaveMulticast(udp::socket& socket, const UdpOptions& o) {
    if (o.multicastGroup.empty() || !socket.is_open())
        return;
    boost::system::error_code ec;
    auto group = asio::ip::make_address_v4(o.multicastGroup, ec);
    auto iface = asio::ip::make_address_v4(o.interfaceAddress, ec);
    if (!ec)
        socket.set_option(asio::ip::multicast::leave_group(group, iface), ec);
}

std::uint16_t findFreeUdpPort() {
    asio::io_context ctx;
    udp::socket s(ctx, udp::endpoint(asio::ip::address_v4::loopback(), 0));
    return s.local_endpoint().port();
}

std::uint16_t findFreeTcpPort() {
    asio::io_context ctx;
    asio::ip::tcp::acceptor a(ctx, asio::ip::tcp::endpoint(asio::ip::address_v4::loopback(), 0));
    return a.local_endpoint().port();
}

} // namespace ocu
