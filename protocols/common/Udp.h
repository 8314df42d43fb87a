#pragma once
// UDP socket set-up shared by the JAUS and OSYRIS transports: unicast, broadcast and multicast with an
// explicit interface. On loopback, multicast needs both join_group(group, 127.0.0.1) and
// outbound_interface(127.0.0.1); without the latter sends follow the default route (toolchain.md §7).
#include <boost/asio/ip/udp.hpp>

#include <cstdint>
#include <string>

namespace ocu {

struct UdpOptions {
    std::string bindAddress = "0.0.0.0"; // local address to bind
    std::uint16_t port = 0;              // 0 = ephemeral
    bool reuseAddress = true;
    std::string multicastGroup;               // empty = no multicast membership
    std::string interfaceAddress = "0.0.0.0"; // interface for join and outbound multicast; 0.0.0.0 = default
    int multicastTtl = 1;
    bool multicastLoop = true;
    bool broadcast = false;
    int receiveBufferBytes = 4 * 1024 * 1024;
};

// Opens and binds a socket per options; throws boost::system::system_error with a message naming what failed.
void openUdpSocket(boost::asio::ip::udp::socket& socket, const UdpOptions& options);
// Leaves the multicast group (IGMP leave) if one was joined; errors are ignored.
void leaveMulticast(boost::asio::ip::udp::socket& socket, const UdpOptions& options);

// Returns a UDP port that is free on 127.0.0.1 right now (for tests and the simulated site).
std::uint16_t findFreeUdpPort();
std::uint16_t findFreeTcpPort();

} // namespace ocu
