// The WebSocket keepalive (research note §2 [I]: dead after 15 s without any frame) decided on the endpoint's
// Clock: with a FakeClock, 16 s of a silent peer are declared dead within a fraction of a real second, and
// 14 s are not. Over a real loopback socket whose peer completes the opening handshake and then stays silent.
#include "tests/support/IoContextWaits.h"
#include <QtTest>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/write.hpp>

#include "protocols/common/Clock.h"
#include "protocols/common/Counters.h"
#include "protocols/common/Log.h"
#include "protocols/iso23725/WsEndpoint.h"

using namespace ocu;
using namespace ocu::iso23725;

namespace {

struct Recorder : WsHandler {
    std::optional<SessionId> session;
    std::string closeReason;
    void onOpen(SessionId id, const std::string&) override { session = id; }
    void onText(SessionId, std::string) override {}
    void onClose(SessionId, const std::string& reason) override {
        session.reset();
        closeReason = reason;
    }
};

using ocu::testing::runUntil;

} // namespace

class TestIsoWsKeepAlive : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { setLogThreshold(LogLevel::Error); }

    void silentPeerIsDeadAfterDeadAfterOnTheFakeClock() {
        namespace asio = boost::asio;
        asio::io_context io;
        Counters counters;
        FakeClock clock;
        Recorder ahs;
        WsOptions so;
        so.role = WsRole::Service;
        so.url = "ws://127.0.0.1:0/";
        // The timer wakes at least this often in real time to look at the (fake) time left.
        so.pingInterval = std::chrono::milliseconds(50);
        so.deadAfter = std::chrono::seconds(15);
        WsEndpoint service(io, so, ahs, counters, clock);
        QVERIFY(service.start());
        // The peer: an RFC 6455 §4.1 opening handshake by hand, then silence (no pong to any ping).
        asio::io_context peerIo;
        asio::ip::tcp::socket peer(peerIo);
        peer.connect({asio::ip::make_address_v4("127.0.0.1"), service.localPort()});
        const std::string upgrade = "GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\n"
                                    "Connection: Upgrade\r\nSec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n"
                                    "Sec-WebSocket-Version: 13\r\n\r\n";
        asio::write(peer, asio::buffer(upgrade));
        QVERIFY(runUntil(
            io, [&] { return ahs.session.has_value(); }, 5000));

        clock.advance(std::chrono::seconds(14));
        QVERIFY(!runUntil(
            io, [&] { return !ahs.session; }, 300)); // 14 s of silence: still alive
        QCOMPARE(counters.get("ws.dead"), std::uint64_t(0));

        clock.advance(std::chrono::seconds(2));
        QVERIFY2(runUntil(
                     io, [&] { return !ahs.session; }, 2000),
                 "16 s of fake silence did not end the link");
        QCOMPARE(counters.get("ws.dead"), std::uint64_t(1));
        QCOMPARE(ahs.closeReason, std::string("link dead: no frame for 16000 ms"));
        service.stop();
    }
};

QTEST_GUILESS_MAIN(TestIsoWsKeepAlive)
#include "test_iso_ws_keepalive.moc"
