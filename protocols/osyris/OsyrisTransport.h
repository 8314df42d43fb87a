#pragma once
// OSYRIS over UDP (seed 004 §3, §7): one socket for multicast (bound to the group address, IGMP join and
// outbound multicast on the configured interface), broadcast (wildcard bind) or unicast (interface bind),
// the receive loop, and sends to the group/peer address plus any extra unicast peers. A receive-side
// impairment (loss, duplication, reordering on the real socket) serves tests and demos. Runs on the owner's
// io_context; not thread-safe (call from that thread once open() returned), except sendFromAnyThread.
#include "protocols/osyris/OsyrisConfig.h"

#include "protocols/common/Bytes.h"
#include "protocols/common/Counters.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace boost::asio {
class io_context;
}

namespace ocu::osyris {

// Receive-side impairment for tests and demos (loss, duplication, reordering on a real socket).
struct RxImpairment {
    double loss = 0;      // probability a datagram is dropped
    double duplicate = 0; // probability it is delivered twice
    double reorder = 0;   // probability it is held back by delayMs
    int delayMs = 150;
    std::uint32_t seed = 1;
};

class OsyrisTransport {
public:
    using DatagramHandler = std::function<void(ByteSpan datagram)>;

    // counters receives tx.error and rx.impaired.*; it must outlive the transport.
    OsyrisTransport(boost::asio::io_context& io, Counters& counters);
    ~OsyrisTransport();
    OsyrisTransport(const OsyrisTransport&) = delete;
    OsyrisTransport& operator=(const OsyrisTransport&) = delete;

    // Opens and binds the socket, joins the group and resolves the destinations. Throws std::runtime_error
    // with a message for the operator ("OSYRIS socket: ...", "OSYRIS unicast peer '...' is not ip:port").
    void open(const OsyrisConfig& cfg);
    // Starts the receive loop; every datagram (after the impairment) goes to onDatagram on the io thread.
    void startReceive(DatagramHandler onDatagram);
    // Sends to every destination; failures count as tx.error.
    // True when every destination took the datagram (it is on the wire), false on a socket error or closed.
    bool send(const Bytes& datagram);
    // Any thread (the STOP fast path): hands the datagram to the socket for every destination without
    // blocking. True when every destination took it; otherwise false with the reason in *why (the caller
    // sends through the io thread instead). Safe against a concurrent close().
    // *taken counts the destinations that took it.
    bool sendFromAnyThread(const Bytes& datagram, std::string* why, std::size_t* taken = nullptr);
    // Why the last failed send failed (socket error text).
    const std::string& lastError() const { return m_lastError; }
    // IGMP leave and close; impaired datagrams still held back are dropped.
    void close();
    bool isOpen() const;
    void setImpairment(const RxImpairment& imp);
    std::uint16_t localPort() const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
    std::string m_lastError;
};

} // namespace ocu::osyris
