// The all-stop frame never waits behind queued frames: WsEndpoint::sendUrgent puts a frame
// after the one being written (a Beast stream writes one message at a time) and ahead of everything else
// queued; urgent frames keep their own order. Over a real loopback WebSocket (service and client endpoints on
// one io_context, 127.0.0.1, free port).
#include <QtTest>

#include <boost/asio/io_context.hpp>

#include "protocols/common/Counters.h"
#include "protocols/common/Log.h"
#include "protocols/iso23725/WsEndpoint.h"

using namespace ocu;
using namespace ocu::iso23725;

namespace {

struct Recorder : WsHandler {
    std::optional<SessionId> session;
    std::vector<std::string> texts;
    void onOpen(SessionId id, const std::string&) override { session = id; }
    void onText(SessionId, std::string text) override { texts.push_back(std::move(text)); }
    void onClose(SessionId, const std::string&) override { session.reset(); }
};

template <class Pred> bool runUntil(boost::asio::io_context& io, Pred p, int ms = 20000) {
    for (int i = 0; i < ms / 10; ++i) {
        if (p())
            return true;
        io.restart();
        io.run_for(std::chrono::milliseconds(10));
    }
    return p();
}

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
};

QTEST_GUILESS_MAIN(TestIsoWsUrgent)
#include "test_iso_ws_urgent.moc"
