#pragma once
// The socket records behind JudpTransport (its UDP receivers and JTCP connections), shared by the files that
// implement it: JudpTransport.cpp (opening and closing), JudpTransportReceive.cpp, JudpTransportSend.cpp and
// JudpTransportJtcp.cpp. Not for use outside them.
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/ip/udp.hpp>

#include <array>
#include <deque>
#include <string>

#include "protocols/jaus/JudpTransport.h"

namespace ocu::jaus {

struct JudpTransport::Receiver {
    explicit Receiver(boost::asio::io_context& io) : socket(io) {}
    boost::asio::ip::udp::socket socket;
    UdpOptions options;
    std::array<std::uint8_t, 65536> buffer{};
    boost::asio::ip::udp::endpoint from;
};

struct JudpTransport::TcpConn {
    explicit TcpConn(boost::asio::io_context& io) : socket(io) {}
    boost::asio::ip::tcp::socket socket;
    JtcpStreamDecoder decoder;
    std::array<std::uint8_t, 16384> buffer{};
    std::deque<Bytes> queue;
    bool writing = false;
    bool connected = false;
    bool versionSent = false;
    bool dead = false;
    std::string peer;
};

} // namespace ocu::jaus
