#pragma once
// JUDP over Boost.Asio (AS5669A, AEP-4818 §4.7): unicast socket (port 3794 or ephemeral) plus multicast
// reception (239.255.0.1 by default) or UDP broadcast; dynamic JAUS-ID -> endpoint learning from every
// datagram, an optional static table, ACK answering (also for multicast-received requests, jaus-wire.md
// §2.2), fragmentation and reassembly. Runs on the owner's io_context; not thread-safe (call from that
// thread).
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/ip/udp.hpp>
#include <boost/asio/steady_timer.hpp>

#include <array>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "protocols/common/Clock.h"
#include "protocols/common/Counters.h"
#include "protocols/common/Udp.h"
#include "protocols/jaus/JausConfig.h"
#include "protocols/jaus/JausOutput.h"
#include "protocols/jaus/JausTypes.h"
#include "protocols/jaus/JudpCodec.h"

namespace ocu::jaus {

// Network fault injection (simulated UGV, AEP-4818 §10 item 24): applied to outgoing datagrams.
struct NetFaults {
    double loss = 0;      // probability 0..1 of dropping a datagram
    Duration delay{};     // added latency
    bool reorder = false; // swap every other pair of datagrams
};

// One datagram routed and encoded ahead of time on the io thread, sent later from any thread
// (JudpTransport::sendPlanned): the STOP ALL path leaves from the operator's thread without waiting for the
// io thread to wake up (docs/decisions/stop-from-callers-thread.md).
struct PlannedDatagram {
    Bytes datagram; // one message, encoded with sequence number 0: sendPlanned writes the real one
    std::vector<boost::asio::ip::udp::endpoint> to;
    bool operator==(const PlannedDatagram&) const = default;
};

class JudpTransport {
public:
    using MessageHandler = std::function<void(const JausId& src, const JausId& dst, ByteSpan payload)>;
    using ErrorHandler = std::function<void(const std::string& reason, const std::string& text)>;

    JudpTransport(boost::asio::io_context& io, TransportSettings settings, Counters& counters,
                  const Clock& clock, std::string logCategory);
    ~JudpTransport();
    JudpTransport(const JudpTransport&) = delete;
    JudpTransport& operator=(const JudpTransport&) = delete;

    // Opens the sockets; throws std::runtime_error naming what failed. A group socket that cannot be opened
    // (its port held by another process without SO_REUSEADDR, the group not joinable) is not a failure:
    // the transport runs without it (groupSocketProblem) and says so in one log warning.
    void open();
    void close();
    void setHandlers(MessageHandler onMessage, ErrorHandler onError);
    // The flight recorder's record.raw: every datagram and every JTCP read as received (peer "address:port"),
    // before any check.
    using RawHandler = std::function<void(ByteSpan data, const std::string& peer)>;
    void setRawHandler(RawHandler onRaw) { m_onRaw = std::move(onRaw); }
    // Which destination IDs are ours (for ACK answering).
    void setLocalIds(std::function<bool(const JausId&)> isLocal) { m_isLocal = std::move(isLocal); }

    // Returns empty when the message was handed to a socket (or queued on a JTCP connection), else why not.
    std::string send(const JausId& src, const JausId& dst, const Bytes& payload, SendOptions options);
    std::string endpointOf(const JausId& id) const;
    // Io thread: the datagram send() would emit for this message, when it is exactly one UDP datagram sent
    // without side effects (no JTCP route, no fragmentation, no unknown destination, no fault injection);
    // otherwise nullopt and the message must go through send().
    std::optional<PlannedDatagram> plan(const JausId& src, const JausId& dst, const Bytes& payload,
                                        SendOptions options) const;
    // Any thread: takes src's next sequence number (shared with send(), so numbers stay unique and
    // consecutive) and hands the datagram to the unicast socket without blocking. Empty when every
    // endpoint's socket took it, else why not (nothing is retried here: the caller sends through the io
    // thread instead). Sequence numbers of datagrams not taken are spent, as for a failed send().
    std::string sendPlanned(const JausId& src, const PlannedDatagram& planned);
    std::uint16_t localPort() const;
    // Why the last open() runs without a group socket (nothing is received from the group, or in broadcast
    // mode from the broadcast port); nullopt when it has one. Io thread (or before the io thread runs).
    const std::optional<GroupSocketProblem>& groupSocketProblem() const { return m_groupProblem; }
    // JAUS IDs whose address was learned from their traffic (AEP-4818 §4.7.2), at most kMaxLearnedAddresses
    // (a bound against address floods): an ID first heard when the table is full is not learned
    // (rx.limited.learned_address; it is still reached by the static table, JTCP or multicast), so a peer
    // inventing source IDs can neither grow the table nor push out the addresses of the vehicles already
    // known. Io thread.
    static constexpr std::size_t kMaxLearnedAddresses = 1024;
    std::size_t learnedAddresses() const { return m_learned.size(); }
    std::uint16_t localTcpPort() const; // JTCP server port, 0 when not listening
    // JTCP bytes still queued or being written (stop() waits for the releases to leave).
    std::size_t pendingTcpWrites() const;
    void setFaults(NetFaults f) { m_faults = f; }

private:
    using Endpoint = boost::asio::ip::udp::endpoint;
    struct Receiver;
    struct TcpConn;
    using TcpPtr = std::shared_ptr<TcpConn>;

    // open(), in steps: the unicast socket (its problem in broadcast mode, where it receives the broadcasts),
    // the group socket (its problem, when there is none) and the JTCP listener (throws).
    std::optional<GroupSocketProblem> openUnicastSocket(std::uint16_t& unicastHeld);
    std::optional<GroupSocketProblem> openGroupSocket(std::uint16_t unicastHeld);
    void openJtcpServer();
    void startReceive(Receiver& r);
    void onDatagram(ByteSpan data, const Endpoint& from);
    std::optional<Endpoint> resolve(const JausId& dst) const;
    Endpoint broadcastEndpoint() const;
    std::vector<Endpoint>
    staticUdpEndpoints(const JausId& dst) const; // UDP static entries of dst's subsystem
    void transmit(Bytes datagram, const Endpoint& to);
    bool rawSend(const Bytes& datagram, const Endpoint& to);
    bool hasTcpRoute(const JausId& dst) const;
    // The first of n consecutive sequence numbers of src (any thread).
    std::uint16_t takeSequence(const JausId& src, std::size_t n);
    void deliver(JudpMessage m, TimePoint now, const std::function<void(const std::string&)>& reject);
    // JTCP (AS5669A; AEP-4818 §4.7.1: static address list, port 3794)
    void startAccept();
    void startRead(const TcpPtr& c);
    void tcpWrite(const TcpPtr& c, Bytes bytes);
    void flush(const TcpPtr& c);
    void dropConn(const TcpPtr& c, const std::string& why);
    TcpPtr tcpRoute(const JausId& dst);

    boost::asio::io_context& m_io;
    TransportSettings m_cfg;
    Counters& m_counters;
    const Clock& m_clock;
    std::string m_log;
    std::unique_ptr<Receiver> m_unicast;
    std::unique_ptr<Receiver> m_multicast; // the group socket; null without one (m_groupProblem says why)
    std::optional<GroupSocketProblem> m_groupProblem;
    MessageHandler m_onMessage;
    ErrorHandler m_onError;
    RawHandler m_onRaw;
    std::function<bool(const JausId&)> m_isLocal;
    std::map<std::uint32_t, Endpoint> m_learned;
    std::mutex m_sequenceMutex;                        // send() on the io thread, sendPlanned() anywhere
    std::map<std::uint32_t, std::uint16_t> m_sequence; // per source component
    // sendPlanned() on another thread never uses a closed (or reused) descriptor: close() takes this first.
    std::mutex m_fastMutex;
    bool m_fastOpen = false; // under m_fastMutex
    Reassembler m_reassembler;
    NetFaults m_faults;
    std::mt19937 m_rng{12345};
    std::optional<std::pair<Bytes, Endpoint>> m_held; // reorder fault
    std::map<std::string, TimePoint> m_lastLog;
    bool m_open = false;
    std::string m_lastSendError; // of the send() in progress (synchronous UDP sends)
    std::unique_ptr<boost::asio::ip::tcp::acceptor> m_acceptor;
    std::set<TcpPtr> m_conns;
    std::map<std::uint32_t, std::weak_ptr<TcpConn>> m_tcpRoutes; // learned from JTCP traffic
    std::map<std::size_t, TcpPtr> m_tcpClients;                  // by static-table index
};

} // namespace ocu::jaus
