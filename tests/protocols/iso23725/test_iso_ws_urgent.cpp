// The all-stop frame never waits behind queued frames: WsEndpoint::sendUrgent puts a frame
// after the one being written (a Beast stream writes one message at a time) and ahead of everything else
// queued; urgent frames keep their own order. Over a real loopback WebSocket (service and client endpoints on
// one io_context, 127.0.0.1, free port).
#include "tests/support/IoContextWaits.h"
#include <QtTest>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/write.hpp>

#include "protocols/common/Counters.h"
#include "protocols/common/Log.h"
#include "protocols/iso23725/WsEndpoint.h"

using namespace ocu;
using namespace ocu::iso23725;

namespace {

struct Recorder : WsHandler {
    std::optional<SessionId> session;
    std::vector<std::string> texts;
    std::string closeReason;
    void onOpen(SessionId id, const std::string&) override { session = id; }
    void onText(SessionId, std::string text) override { texts.push_back(std::move(text)); }
    void onClose(SessionId, const std::string& reason) override {
        session.reset();
        closeReason = reason;
    }
};

using ocu::testing::runUntil;

} // namespace

class TestIsoWsUrgent : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { setLogThreshold(LogLevel::Warning); }

    void urgentFrameOvertakesQueuedFrames() {
        boost::asio::io_context io;
        Counters counters;
        Recorder ahs, fms;
        WsOptions so;
        so.role = WsRole::Service;
        so.url = "ws://127.0.0.1:0/";
        WsEndpoint service(io, so, ahs, counters);
        QVERIFY(service.start());
        WsOptions co;
        co.url = "ws://127.0.0.1:" + std::to_string(service.localPort()) + "/";
        WsEndpoint client(io, co, fms, counters);
        QVERIFY(client.start());
        QVERIFY(runUntil(io, [&] { return fms.session && ahs.session; }));

        // Telemetry-sized frames queue up (no io run in between: nothing is written yet but the first).
        constexpr int kQueued = 50;
        const std::string bulk(64 * 1024, 'x');
        for (int i = 0; i < kQueued; ++i)
            QVERIFY(client.send(*fms.session, "bulk " + std::to_string(i) + " " + bulk));
        QVERIFY(client.sendUrgent(*fms.session, "{\"ModeAllStop\":\"Apply\"}"));
        QVERIFY(client.sendUrgent(*fms.session, "{\"ModeAllStop\":\"Remove\"}"));
        QVERIFY(runUntil(io, [&] { return int(ahs.texts.size()) == kQueued + 2; }));
        QVERIFY(ahs.texts[0].rfind("bulk 0 ", 0) == 0); // was being written already
        QCOMPARE(ahs.texts[1], std::string("{\"ModeAllStop\":\"Apply\"}"));
        QCOMPARE(ahs.texts[2], std::string("{\"ModeAllStop\":\"Remove\"}"));
        for (int i = 1; i < kQueued; ++i) // the rest in their order, none lost
            QVERIFY(ahs.texts[std::size_t(i) + 2].rfind("bulk " + std::to_string(i) + " ", 0) == 0);
        client.stop();
        service.stop();
    }

    // A peer that completes the opening handshake and then never reads: the session's write queue stays
    // within maxQueueBytes (plus the frame that would cross it), and the session is closed as overloaded with
    // the reason and a counter, instead of memory growing with every frame.
    void queueOfAPeerThatDoesNotReadIsBounded() {
        namespace asio = boost::asio;
        asio::io_context io;
        Counters counters;
        Recorder ahs;
        WsOptions so;
        so.role = WsRole::Service;
        so.url = "ws://127.0.0.1:0/";
        so.maxQueueBytes = 1024 * 1024;
        WsEndpoint service(io, so, ahs, counters);
        QVERIFY(service.start());
        // The peer: an RFC 6455 §4.1 opening handshake by hand, then silence.
        asio::io_context peerIo;
        asio::ip::tcp::socket peer(peerIo);
        peer.open(asio::ip::tcp::v4());
        peer.set_option(asio::socket_base::receive_buffer_size(4096));
        peer.connect({asio::ip::make_address_v4("127.0.0.1"), service.localPort()});
        const std::string upgrade = "GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\n"
                                    "Connection: Upgrade\r\nSec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n"
                                    "Sec-WebSocket-Version: 13\r\n\r\n";
        asio::write(peer, asio::buffer(upgrade));
        QVERIFY(runUntil(io, [&] { return ahs.session.has_value(); }));
        const SessionId id = *ahs.session;
        const std::string frame(256 * 1024, 'p');
        std::size_t maxQueued = 0;
        int sent = 0;
        while (ahs.session && sent < 400) { // 100 MB at most: far beyond any loopback socket buffer
            service.send(id, frame);
            ++sent;
            maxQueued = std::max(maxQueued, service.queuedBytes());
            io.restart();
            io.run_for(std::chrono::milliseconds(2));
        }
        QVERIFY2(!ahs.session, "the session stayed open although the peer never read");
        QVERIFY(maxQueued <= so.maxQueueBytes);
        QCOMPARE(counters.get("ws.tx.overloaded"), std::uint64_t(1));
        QVERIFY2(ahs.closeReason.find("overloaded") != std::string::npos, ahs.closeReason.c_str());
        QCOMPARE(service.queuedBytes(), std::size_t(0));
    }
};

QTEST_GUILESS_MAIN(TestIsoWsUrgent)
#include "test_iso_ws_urgent.moc"
