#pragma once
// WebSocket transport for ISO 23725 (research note §2): client (default) or service role, ws:// or wss://,
// one text frame = one JSON container or one XML map chunk. Boost.Beast stays inside WsEndpoint.cpp.
// Every callback runs on the io_context's thread; every method must be called on that thread.
#include "protocols/iso23725/WsUrl.h"

#include "protocols/common/Clock.h"
#include "protocols/common/Counters.h"
#include "protocols/common/Result.h"

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace boost::asio {
class io_context;
}

namespace ocu::iso23725 {

enum class WsRole { Client, Service };

struct WsTlsOptions {
    std::string caFile; // client: CA to verify the service; service: CA for client certificates (mutual TLS)
    std::string certFile; // client: optional client certificate; service: server certificate chain (wss)
    std::string keyFile;
    bool verifyHostname = true; // client: check the certificate names the URL's host (RFC 2818)
};

struct WsOptions {
    WsRole role = WsRole::Client;
    // Client: URL to connect to; service: URL to listen on (host and port; port 0 = any free port).
    std::string url;
    WsTlsOptions tls;
    std::chrono::milliseconds pingInterval{5000}; // [I] §2: ping every 5 s
    std::chrono::milliseconds deadAfter{15000};   // [I] §2: dead after 15 s without any frame
    std::chrono::milliseconds backoffMin{1000};   // [I] §2: reconnect 1, 2, 4 ... 30 s
    std::chrono::milliseconds backoffMax{30000};
    double backoffJitter = 0.2; // +-20 %
    std::chrono::milliseconds connectTimeout{5000};
    std::size_t maxFrameBytes = 16u * 1024u * 1024u;
    // Outgoing bytes a session may hold queued (not yet taken by the socket). Beyond it the peer is not
    // reading: the session is closed as overloaded (counter "ws.tx.overloaded", the reason in onClose) and
    // the client reconnects, instead of memory growing without bound. Urgent frames (the all-stop) are never
    // refused by it.
    std::size_t maxQueueBytes = 32u * 1024u * 1024u;
    std::string
        subprotocol; // Sec-WebSocket-Protocol offered (client) / accepted (service); none by default (Q1)
};

using SessionId = std::uint64_t;

class WsHandler {
public:
    virtual ~WsHandler() = default;
    virtual void onOpen(SessionId id, const std::string& peer) = 0;
    virtual void onText(SessionId id, std::string text) = 0;
    virtual void onClose(SessionId id, const std::string& reason) = 0;
    // A binary frame (§2: ignored; counted in rx.rejected.binary by the transport): for the operator's
    // events.
    virtual void onBinaryFrame(SessionId id, std::size_t bytes) {
        (void)id;
        (void)bytes;
    }
    // Connection attempts that failed before a session opened (client), with the next retry delay.
    virtual void onConnectFailed(const std::string& reason, std::chrono::milliseconds retryIn) {
        (void)reason;
        (void)retryIn;
    }
};

class WsEndpoint {
public:
    // counters: "ws.rx.frames", "ws.tx.frames", "ws.rx.close.<code>" (close frames received, by code),
    // "rx.rejected.binary", "rx.rejected.too_big", "ws.connect.failed", "ws.dead" ... are added there.
    // Keepalive deadlines (ping, dead link) are measured on `clock`, which must outlive the endpoint.
    WsEndpoint(boost::asio::io_context& io, WsOptions options, WsHandler& handler, Counters& counters,
               Clock& clock = SteadyClock::instance());
    ~WsEndpoint();
    WsEndpoint(const WsEndpoint&) = delete;
    WsEndpoint& operator=(const WsEndpoint&) = delete;

    // Client: starts connecting (and reconnecting); service: binds and listens. Error for a bad URL, TLS
    // files or an address in use.
    Result<bool> start();
    // Closes every session and stops reconnecting; no callback after this returns. Drops the TCP connections
    // at once (the peer sees 1006): use shutdown() when the io thread can run a little longer.
    void stop();
    // Orderly end (RFC 6455 §7.1.2, close code 1001 "going away" per §7.4.1): stops reconnecting, sends a
    // close frame on every open session, and calls done() on the io thread once every session has finished
    // its closing handshake or `grace` has passed (then the connection is dropped). No WsHandler callback
    // after this returns; done() runs exactly once.
    void shutdown(std::chrono::milliseconds grace, std::function<void()> done);
    // Queues one text frame; false when the session is not open.
    bool send(SessionId id, std::string text);
    // A text frame ahead of the queued ones (the all-stop: never behind telemetry), after the frame being
    // written; false when the session is not open.
    bool sendUrgent(SessionId id, std::string text);
    // Binary frame (never used by ISO 23725 itself: for fault-injection tests of the peer's tolerance).
    bool sendBinary(SessionId id, std::string data);
    void close(SessionId id, const std::string& reason);
    std::uint16_t localPort() const; // service role, after start()
    std::size_t queuedBytes() const; // across sessions (outgoing frames not yet written)
    std::size_t openSessions() const;
    const WsOptions& options() const;

    struct Impl;

private:
    std::shared_ptr<Impl> m_impl;
};

} // namespace ocu::iso23725
