// The only translation unit with Boost.Beast (~12 s to compile): keep it that way.
#include "protocols/iso23725/WsEndpoint.h"

#include "protocols/iso23725/LinkTiming.h"

#include "protocols/common/Log.h"
#include "protocols/iso23725/LogCategory.h"

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/ssl.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/ssl.hpp>
#include <boost/beast/websocket.hpp>
#include <boost/beast/websocket/ssl.hpp>

#include <openssl/ssl.h>

#include <cmath>
#include <deque>
#include <map>
#include <random>

namespace ocu::iso23725 {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;
namespace ssl = asio::ssl;
using tcp = asio::ip::tcp;
using beast::error_code;

namespace {

class SessionBase {
public:
    virtual ~SessionBase() = default;
    virtual void send(std::string text, bool binary = false, bool urgent = false) = 0;
    virtual void close(const std::string& reason) = 0;
    // Close frame with 1001, then teardown when the handshake ends or after `grace`; done() once.
    virtual void goAway(std::chrono::milliseconds grace, std::function<void()> done) = 0;
    virtual std::size_t queuedBytes() const = 0;
};

} // namespace

struct WsEndpoint::Impl : std::enable_shared_from_this<WsEndpoint::Impl> {
    Impl(asio::io_context& io, WsOptions o, WsHandler& h, Counters& c, Clock& clk)
        : io(io), options(std::move(o)), handler(&h), counters(c), clock(clk), reconnectTimer(io),
          acceptor(io), sslCtx(ssl::context::tls),
          backoff(options.backoffMin, options.backoffMax, options.backoffJitter) {}

    asio::io_context& io;
    WsOptions options;
    WsHandler* handler; // null after stop(): late completions must not call back
    Counters& counters;
    Clock& clock; // every keepalive decision is measured on it
    WsUrl url;
    asio::steady_timer reconnectTimer;
    tcp::acceptor acceptor;
    ssl::context sslCtx;
    std::map<SessionId, std::shared_ptr<SessionBase>> sessions;
    SessionId nextId = 1;
    ReconnectBackoff backoff;
    bool stopped = false;
    tcp::resolver::results_type resolvedCache;

    Result<bool> setupTls();
    void connect();
    void scheduleReconnect(const std::string& reason);
    void accept();
    template <class Ws> void startSession(std::shared_ptr<Ws> ws, std::string peer, bool client);
    void opened(SessionId id, std::shared_ptr<SessionBase> s, const std::string& peer) {
        sessions[id] = std::move(s);
        backoff.reset();
        counters.add("ws.sessions.opened");
        if (handler)
            handler->onOpen(id, peer);
    }
    void closed(SessionId id, const std::string& reason) {
        if (!sessions.erase(id))
            return;
        counters.add("ws.sessions.closed");
        if (handler)
            handler->onClose(id, reason);
        if (!stopped && options.role == WsRole::Client)
            scheduleReconnect(reason);
    }
};

namespace {

using PlainWs = websocket::stream<beast::tcp_stream>;
using TlsWs = websocket::stream<beast::ssl_stream<beast::tcp_stream>>;

template <class Ws>
class Session final : public SessionBase, public std::enable_shared_from_this<Session<Ws>> {
public:
    Session(std::shared_ptr<WsEndpoint::Impl> ep, std::shared_ptr<Ws> ws, SessionId id)
        : m_ep(std::move(ep)), m_ws(std::move(ws)), m_id(id), m_timer(m_ep->io),
          m_keepAlive(m_ep->options.pingInterval, m_ep->options.deadAfter) {}

    void run() {
        m_ws->read_message_max(m_ep->options.maxFrameBytes);
        m_ws->auto_fragment(false);
        m_ws->binary(false);
        m_keepAlive.start(m_ep->clock.now());
        std::weak_ptr<Session> weak = this->shared_from_this();
        m_ws->control_callback([weak](websocket::frame_type, beast::string_view) {
            if (auto s = weak.lock())
                s->m_keepAlive.received(s->m_ep->clock.now());
        });
        read();
        tick();
    }

    void send(std::string text, bool binary, bool urgent) override {
        if (m_closing)
            return;
        if (!urgent && m_queuedBytes + text.size() > m_ep->options.maxQueueBytes) {
            m_ep->counters.add("ws.tx.overloaded");
            std::string msg = "the peer does not read: " + std::to_string(m_queuedBytes) +
                              " bytes queued and the write queue limit is " +
                              std::to_string(m_ep->options.maxQueueBytes) +
                              ": connection closed as overloaded";
            logWarning(kLog, msg);
            fail(msg);
            return;
        }
        m_queuedBytes += text.size();
        if (urgent) {
            // Ahead of every queued frame but the one being written (a Beast stream writes one message at a
            // time) and earlier urgent ones.
            auto at = m_queue.begin() + (m_writing && !m_queue.empty() ? 1 : 0);
            while (at != m_queue.end() && at->urgent)
                ++at;
            m_queue.insert(at, Item{std::move(text), false, binary, true});
        } else {
            m_queue.push_back(Item{std::move(text), false, binary});
        }
        if (!m_writing)
            write();
    }

    void close(const std::string& reason) override { fail(reason); }
    void goAway(std::chrono::milliseconds grace, std::function<void()> done) override {
        if (m_closing) {
            if (done)
                done();
            return;
        }
        m_closing = true; // no new writes; a write in progress finishes before Beast sends the close frame
        m_goAwayDone = std::move(done);
        auto self = this->shared_from_this();
        m_timer.cancel();
        m_timer.expires_after(grace);
        m_timer.async_wait([self](error_code ec) {
            if (ec != asio::error::operation_aborted)
                self->teardown("close handshake timed out");
        });
        m_ws->async_close(websocket::close_reason(websocket::close_code::going_away, "FMS shutting down"),
                          [self](error_code ec) { self->teardown(ec ? ec.message() : "closed (1001)"); });
    }
    std::size_t queuedBytes() const override { return m_queuedBytes; }

private:
    struct Item {
        std::string text;
        bool ping;
        bool binary = false;
        bool urgent = false;
    };

    void read() {
        m_ws->async_read(m_buffer,
                         [self = this->shared_from_this()](error_code ec, std::size_t) { self->onRead(ec); });
    }
    void onRead(error_code ec) {
        if (ec) {
            // Counted even when a failed write closed the session first (Beast fails pending writes while it
            // sends the 1009 close of an oversized frame).
            if (ec == websocket::error::message_too_big) {
                m_ep->counters.add("rx.rejected.too_big");
                std::string msg = "incoming frame larger than the maximum of " +
                                  std::to_string(m_ep->options.maxFrameBytes) +
                                  " bytes: connection closed (1009)";
                logWarning(kLog, msg);
                fail(msg);
            } else if (ec == websocket::error::closed) {
                m_ep->counters.add("ws.rx.close." + std::to_string(m_ws->reason().code));
                fail("closed by peer (" + std::to_string(m_ws->reason().code) + ")");
            } else {
                fail(ec.message());
            }
            return;
        }
        m_keepAlive.received(m_ep->clock.now());
        m_ep->counters.add("ws.rx.frames");
        if (!m_ws->got_text()) {
            // §2: binary frames are logged and ignored; the link stays up.
            m_ep->counters.add("rx.rejected.binary");
            logWarning(kLog, "binary frame of " + std::to_string(m_buffer.size()) + " bytes ignored");
            if (m_ep->handler)
                m_ep->handler->onBinaryFrame(m_id, m_buffer.size());
        } else if (m_ep->handler) {
            std::string text = beast::buffers_to_string(m_buffer.data());
            m_buffer.consume(m_buffer.size());
            m_ep->handler->onText(m_id, std::move(text));
            if (m_closing)
                return;
        }
        m_buffer.consume(m_buffer.size());
        read();
    }

    void write() {
        if (m_queue.empty() || m_closing) {
            m_writing = false;
            return;
        }
        m_writing = true;
        auto self = this->shared_from_this();
        if (m_queue.front().ping) {
            m_ws->async_ping({}, [self](error_code ec) { self->onWrite(ec, 0); });
        } else {
            m_ws->binary(m_queue.front().binary);
            m_ws->async_write(asio::buffer(m_queue.front().text),
                              [self](error_code ec, std::size_t n) { self->onWrite(ec, n); });
        }
    }
    void onWrite(error_code ec, std::size_t) {
        if (ec == websocket::error::closed) {
            // The read side is closing the stream (peer close or an oversized frame answered with 1009): let
            // the pending read report the real reason.
            m_writing = false;
            return;
        }
        if (ec) {
            fail("write failed: " + ec.message());
            return;
        }
        if (!m_queue.front().ping) {
            m_queuedBytes -= m_queue.front().text.size();
            m_ep->counters.add("ws.tx.frames");
        }
        m_queue.pop_front();
        write();
    }

    // Keepalive [I] §2: the timing decisions are KeepAlive's (LinkTiming.h), on the endpoint's Clock; the
    // timer only sleeps until they are due, for the time the Clock says is left (it may be a test's
    // FakeClock).
    void tick() {
        m_timer.expires_after(std::max(Duration::zero(), m_keepAlive.deadline() - m_ep->clock.now()));
        m_timer.async_wait([self = this->shared_from_this()](error_code ec) {
            if (ec || self->m_closing)
                return;
            const auto now = self->m_ep->clock.now();
            switch (self->m_keepAlive.poll(now)) {
            case KeepAlive::Action::Dead: {
                self->m_ep->counters.add("ws.dead");
                auto silent =
                    std::chrono::duration_cast<std::chrono::milliseconds>(self->m_keepAlive.silentFor(now));
                self->fail("link dead: no frame for " + std::to_string(silent.count()) + " ms");
                return;
            }
            case KeepAlive::Action::SendPing:
                self->m_queue.push_back(Item{{}, true, false});
                if (!self->m_writing)
                    self->write();
                break;
            case KeepAlive::Action::None:
                break;
            }
            self->tick();
        });
    }

    void teardown(const std::string& reason) {
        if (m_tornDown)
            return;
        m_tornDown = true;
        m_timer.cancel();
        error_code ignored;
        beast::get_lowest_layer(*m_ws).socket().shutdown(tcp::socket::shutdown_both, ignored);
        beast::get_lowest_layer(*m_ws).close();
        m_ep->closed(m_id, reason);
        if (auto done = std::move(m_goAwayDone))
            done();
    }

    void fail(const std::string& reason) {
        if (m_closing)
            return;
        m_closing = true;
        m_timer.cancel();
        error_code ignored;
        beast::get_lowest_layer(*m_ws).socket().shutdown(tcp::socket::shutdown_both, ignored);
        beast::get_lowest_layer(*m_ws).close();
        m_ep->closed(m_id, reason);
    }

    std::shared_ptr<WsEndpoint::Impl> m_ep;
    std::shared_ptr<Ws> m_ws;
    SessionId m_id;
    asio::steady_timer m_timer;
    beast::flat_buffer m_buffer;
    std::deque<Item> m_queue;
    std::size_t m_queuedBytes = 0;
    bool m_writing = false;
    bool m_closing = false;
    bool m_tornDown = false;
    std::function<void()> m_goAwayDone;
    KeepAlive m_keepAlive;
};

template <class Ws> void setHandshakeOptions(Ws& ws, const WsOptions& o, bool client) {
    websocket::stream_base::timeout t{};
    t.handshake_timeout = std::chrono::seconds(10);
    t.idle_timeout = websocket::stream_base::none();
    t.keep_alive_pings = false;
    ws.set_option(t);
    if (!o.subprotocol.empty()) {
        std::string proto = o.subprotocol;
        if (client)
            ws.set_option(websocket::stream_base::decorator([proto](websocket::request_type& req) {
                req.set(beast::http::field::sec_websocket_protocol, proto);
            }));
        else
            ws.set_option(websocket::stream_base::decorator([proto](websocket::response_type& res) {
                res.set(beast::http::field::sec_websocket_protocol, proto);
            }));
    }
}

} // namespace

Result<bool> WsEndpoint::Impl::setupTls() {
    if (!url.tls)
        return true;
    // Which file was being loaded, so the operator's message names it (a bare OpenSSL error does not).
    std::string what = "TLS options";
    try {
        const auto& t = options.tls;
        sslCtx.set_options(ssl::context::default_workarounds | ssl::context::no_sslv2 |
                           ssl::context::no_sslv3 | ssl::context::no_tlsv1 | ssl::context::no_tlsv1_1);
        const std::string keyFile = t.keyFile.empty() ? t.certFile : t.keyFile;
        if (options.role == WsRole::Client) {
            what = "CA file " + t.caFile + " (tls.ca)";
            if (!t.caFile.empty())
                sslCtx.load_verify_file(t.caFile);
            else
                sslCtx.set_default_verify_paths();
            sslCtx.set_verify_mode(ssl::verify_peer);
            if (!t.certFile.empty()) {
                what = "certificate file " + t.certFile + " (tls.cert)";
                sslCtx.use_certificate_chain_file(t.certFile);
                what = "key file " + keyFile + " (tls.key)";
                sslCtx.use_private_key_file(keyFile, ssl::context::pem);
            }
        } else {
            if (t.certFile.empty())
                return makeError("wss service needs a certificate file (tls.cert)");
            what = "certificate file " + t.certFile + " (tls.cert)";
            sslCtx.use_certificate_chain_file(t.certFile);
            what = "key file " + keyFile + " (tls.key)";
            sslCtx.use_private_key_file(keyFile, ssl::context::pem);
            if (!t.caFile.empty()) {
                what = "CA file " + t.caFile + " (tls.ca)";
                sslCtx.load_verify_file(t.caFile);
                sslCtx.set_verify_mode(ssl::verify_peer | ssl::verify_fail_if_no_peer_cert);
            }
        }
    } catch (const std::exception& e) {
        return makeError("TLS setup failed: " + what + ": " + e.what());
    }
    return true;
}

template <class Ws> void WsEndpoint::Impl::startSession(std::shared_ptr<Ws> ws, std::string peer, bool) {
    SessionId id = nextId++;
    auto s = std::make_shared<Session<Ws>>(shared_from_this(), ws, id);
    opened(id, s, peer);
    s->run();
}

void WsEndpoint::Impl::scheduleReconnect(const std::string& reason) {
    if (stopped)
        return;
    auto delay = backoff.next();
    if (handler && sessions.empty())
        handler->onConnectFailed(reason, delay);
    reconnectTimer.expires_after(delay);
    reconnectTimer.async_wait([self = shared_from_this()](error_code ec) {
        if (!ec && !self->stopped)
            self->connect();
    });
}

void WsEndpoint::Impl::connect() {
    auto self = shared_from_this();
    auto resolver = std::make_shared<tcp::resolver>(io);
    resolver->async_resolve(
        url.host, std::to_string(url.port), [self, resolver](error_code ec, tcp::resolver::results_type res) {
            if (self->stopped)
                return;
            if (ec) {
                self->counters.add("ws.connect.failed");
                self->scheduleReconnect("resolve " + self->url.host + ": " + ec.message());
                return;
            }
            auto onConnected = [self](auto ws, auto afterTcp) {
                beast::get_lowest_layer(*ws).expires_after(self->options.connectTimeout);
                beast::get_lowest_layer(*ws).async_connect(
                    self->resolvedCache, [self, ws, afterTcp](error_code ec, const tcp::endpoint&) {
                        if (self->stopped)
                            return;
                        if (ec) {
                            self->counters.add("ws.connect.failed");
                            self->scheduleReconnect("connect " + self->url.host + ":" +
                                                    std::to_string(self->url.port) + ": " + ec.message());
                            return;
                        }
                        // Each frame leaves when written, as on the service side (accept): with Nagle's
                        // algorithm (RFC 896) a small frame such as the all-stop waits while an earlier small
                        // segment is unacknowledged, up to the peer's delayed ACK (RFC 1122 §4.2.3.2: 40 ms
                        // on Linux).
                        error_code ignored;
                        beast::get_lowest_layer(*ws).socket().set_option(tcp::no_delay(true), ignored);
                        afterTcp(ws);
                    });
            };
            self->resolvedCache = res;
            auto wsHandshake = [self](auto ws) {
                beast::get_lowest_layer(*ws).expires_never();
                setHandshakeOptions(*ws, self->options, true);
                std::string hostHeader = self->url.host + ":" + std::to_string(self->url.port);
                ws->async_handshake(hostHeader, self->url.target, [self, ws](error_code ec) {
                    if (self->stopped)
                        return;
                    if (ec) {
                        self->counters.add("ws.connect.failed");
                        self->scheduleReconnect("WebSocket handshake: " + ec.message());
                        return;
                    }
                    self->startSession(ws, self->url.host + ":" + std::to_string(self->url.port), true);
                });
            };
            if (!self->url.tls) {
                auto ws = std::make_shared<PlainWs>(self->io);
                onConnected(ws, wsHandshake);
            } else {
                auto ws = std::make_shared<TlsWs>(self->io, self->sslCtx);
                auto& sslStream = ws->next_layer();
                if (!SSL_set_tlsext_host_name(sslStream.native_handle(), self->url.host.c_str())) {
                    // not fatal: SNI is a courtesy; IP literals have none
                }
                // Chain verification always; the RFC 2818 name check unless disabled. Failures are logged
                // with the certificate and the reason, so a site can tell a wrong CA from a wrong host name.
                sslStream.set_verify_callback([self, check = ssl::host_name_verification(self->url.host)](
                                                  bool preverified, ssl::verify_context& vc) {
                    X509_STORE_CTX* x = vc.native_handle();
                    int depth = X509_STORE_CTX_get_error_depth(x);
                    char subject[256] = "?";
                    if (X509* cert = X509_STORE_CTX_get_current_cert(x))
                        X509_NAME_oneline(X509_get_subject_name(cert), subject, sizeof subject);
                    if (!preverified) {
                        logWarning(kLog, std::string("TLS: certificate ") + subject + " (depth " +
                                             std::to_string(depth) + ") rejected: " +
                                             X509_verify_cert_error_string(X509_STORE_CTX_get_error(x)));
                        return false;
                    }
                    if (depth > 0 || !self->options.tls.verifyHostname)
                        return true;
                    if (check(preverified, vc))
                        return true;
                    X509_STORE_CTX_set_error(x, X509_V_ERR_HOSTNAME_MISMATCH);
                    logWarning(kLog, std::string("TLS: certificate ") + subject + " does not name host '" +
                                         self->url.host + "'");
                    return false;
                });
                onConnected(ws, [self, wsHandshake](std::shared_ptr<TlsWs> ws) {
                    ws->next_layer().async_handshake(
                        ssl::stream_base::client, [self, ws, wsHandshake](error_code ec) {
                            if (self->stopped)
                                return;
                            if (ec) {
                                self->counters.add("ws.connect.failed");
                                self->counters.add("ws.tls.failed");
                                self->scheduleReconnect("TLS handshake: " + ec.message());
                                return;
                            }
                            wsHandshake(ws);
                        });
                });
            }
        });
}

void WsEndpoint::Impl::accept() {
    acceptor.async_accept([self = shared_from_this()](error_code ec, tcp::socket sock) {
        if (self->stopped)
            return;
        if (ec) {
            logWarning(kLog, "accept failed: " + ec.message());
            self->accept();
            return;
        }
        error_code ignored;
        std::string peer = sock.remote_endpoint(ignored).address().to_string();
        sock.set_option(tcp::no_delay(true), ignored);
        auto wsAccept = [self, peer](auto ws) {
            setHandshakeOptions(*ws, self->options, false);
            ws->async_accept([self, ws, peer](error_code ec) {
                if (self->stopped)
                    return;
                if (ec) {
                    self->counters.add("ws.accept.failed");
                    logWarning(kLog, "WebSocket accept from " + peer + " failed: " + ec.message());
                    return;
                }
                self->startSession(ws, peer, false);
            });
        };
        if (!self->url.tls) {
            wsAccept(std::make_shared<PlainWs>(std::move(sock)));
        } else {
            auto ws = std::make_shared<TlsWs>(std::move(sock), self->sslCtx);
            beast::get_lowest_layer(*ws).expires_after(std::chrono::seconds(10));
            ws->next_layer().async_handshake(
                ssl::stream_base::server, [self, ws, peer, wsAccept](error_code ec) {
                    if (self->stopped)
                        return;
                    if (ec) {
                        self->counters.add("ws.tls.failed");
                        logWarning(kLog, "TLS handshake from " + peer + " failed: " + ec.message());
                        return;
                    }
                    beast::get_lowest_layer(*ws).expires_never();
                    wsAccept(ws);
                });
        }
        self->accept();
    });
}

WsEndpoint::WsEndpoint(asio::io_context& io, WsOptions options, WsHandler& handler, Counters& counters,
                       Clock& clock)
    : m_impl(std::make_shared<Impl>(io, std::move(options), handler, counters, clock)) {}

WsEndpoint::~WsEndpoint() {
    stop();
}

Result<bool> WsEndpoint::start() {
    auto& d = *m_impl;
    auto u = parseWsUrl(d.options.url);
    if (!u)
        return makeError(u.error());
    d.url = *u;
    d.stopped = false;
    if (auto t = d.setupTls(); !t)
        return t;
    if (d.options.role == WsRole::Client) {
        d.connect();
        return true;
    }
    try {
        error_code ec;
        auto addr = asio::ip::make_address(d.url.host == "localhost" ? "127.0.0.1" : d.url.host, ec);
        if (ec)
            return makeError("service URL host '" + d.url.host + "' must be an IP address to listen on");
        tcp::endpoint ep(addr, d.url.port);
        d.acceptor.open(ep.protocol());
        d.acceptor.set_option(asio::socket_base::reuse_address(true));
        d.acceptor.bind(ep);
        d.acceptor.listen();
    } catch (const std::exception& e) {
        return makeError("cannot listen on " + d.options.url + ": " + e.what());
    }
    d.accept();
    return true;
}

void WsEndpoint::stop() {
    if (!m_impl || m_impl->stopped)
        return;
    auto& d = *m_impl;
    d.stopped = true;
    d.reconnectTimer.cancel();
    error_code ignored;
    d.acceptor.close(ignored);
    auto sessions = d.sessions;
    d.handler = nullptr;
    for (auto& [id, s] : sessions)
        s->close("stopped");
    d.sessions.clear();
}

void WsEndpoint::shutdown(std::chrono::milliseconds grace, std::function<void()> done) {
    auto& d = *m_impl;
    if (d.stopped) {
        if (done)
            done();
        return;
    }
    d.stopped = true;
    d.reconnectTimer.cancel();
    error_code ignored;
    d.acceptor.close(ignored);
    auto sessions = std::move(d.sessions);
    d.sessions.clear();
    d.handler = nullptr;
    if (sessions.empty()) {
        if (done)
            done();
        return;
    }
    auto left = std::make_shared<std::size_t>(sessions.size());
    auto all = std::make_shared<std::function<void()>>(std::move(done));
    for (auto& [id, s] : sessions)
        s->goAway(grace, [left, all] {
            if (--*left == 0 && *all)
                (*all)();
        });
}

bool WsEndpoint::send(SessionId id, std::string text) {
    auto it = m_impl->sessions.find(id);
    if (it == m_impl->sessions.end())
        return false;
    it->second->send(std::move(text));
    return true;
}

bool WsEndpoint::sendUrgent(SessionId id, std::string text) {
    auto it = m_impl->sessions.find(id);
    if (it == m_impl->sessions.end())
        return false;
    it->second->send(std::move(text), false, true);
    return true;
}

bool WsEndpoint::sendBinary(SessionId id, std::string data) {
    auto it = m_impl->sessions.find(id);
    if (it == m_impl->sessions.end())
        return false;
    it->second->send(std::move(data), true);
    return true;
}

void WsEndpoint::close(SessionId id, const std::string& reason) {
    auto it = m_impl->sessions.find(id);
    if (it != m_impl->sessions.end())
        it->second->close(reason);
}

std::uint16_t WsEndpoint::localPort() const {
    error_code ec;
    auto ep = m_impl->acceptor.local_endpoint(ec);
    return ec ? 0 : ep.port();
}

std::size_t WsEndpoint::queuedBytes() const {
    std::size_t n = 0;
    for (auto& [id, s] : m_impl->sessions)
        n += s->queuedBytes();
    return n;
}

std::size_t WsEndpoint::openSessions() const {
    return m_impl->sessions.size();
}
const WsOptions& WsEndpoint::options() const {
    return m_impl->options;
}

} // namespace ocu::iso23725
