#include "protocols/common/Bytes.h"
#include "protocols/common/Clock.h"
#include "protocols/common/ConfigReader.h"
#include "protocols/common/Counters.h"
#include "protocols/common/GeoFrame.h"
#include "protocols/common/IoThread.h"
#include "protocols/common/PosePlausibility.h"

#include <QtTest>

#include <cmath>
#include <future>
#include <limits>

using namespace ocu;

class TestCommon : public QObject {
    Q_OBJECT
private slots:
    void bytesRoundTrip() {
        Bytes b;
        ByteWriter w(b);
        w.u8(0x02);
        w.u16(0x1234);
        w.u32(0xA1B2C3D4);
        w.i32(-2);
        w.f64(1.5);
        w.fixedString("AB", 4);
        QCOMPARE(b.size(), std::size_t(1 + 2 + 4 + 4 + 8 + 4));
        QCOMPARE(b[1], std::uint8_t(0x34)); // little-endian
        QCOMPARE(b[2], std::uint8_t(0x12));
        ByteReader r(b);
        QCOMPARE(r.u8(), std::uint8_t(2));
        QCOMPARE(r.u16(), std::uint16_t(0x1234));
        QCOMPARE(r.u32(), 0xA1B2C3D4u);
        QCOMPARE(r.i32(), -2);
        QCOMPARE(r.f64(), 1.5);
        QCOMPARE(QString::fromStdString(r.fixedString(4)), QString("AB"));
        QVERIFY(r.ok());
        QVERIFY(r.atEnd());
        r.u8();
        QVERIFY(!r.ok()); // reading past the end fails, never crashes
        QCOMPARE(r.u32(), 0u);
    }
    void scaledIntegers() {
        // JSIDL: latitude -90..90 in int32 range as uint32 raw.
        auto raw = scaleToInt<std::uint16_t>(0.0, -10.0, 10.0);
        QCOMPARE(raw, std::uint16_t(32768)); // rounded to nearest
        double back = intToScale<std::uint16_t>(raw, -10.0, 10.0);
        QVERIFY(std::abs(back) < 20.0 / 65535.0);
        QCOMPARE(scaleToInt<std::uint8_t>(-50, -10, 10), std::uint8_t(0));
        QCOMPARE(scaleToInt<std::uint8_t>(50, -10, 10), std::uint8_t(255));
    }
    void fakeClock() {
        FakeClock c;
        auto t0 = c.now();
        c.advance(std::chrono::milliseconds(1500));
        QCOMPARE(std::chrono::duration_cast<std::chrono::milliseconds>(c.now() - t0).count(), 1500);
    }
    void counters() {
        Counters c;
        c.add("rx.rejected.short");
        c.add("rx.rejected.version", 2);
        c.add("rx.ok");
        QCOMPARE(c.get("rx.rejected.version"), 2u);
        QCOMPARE(c.sumPrefix("rx.rejected."), 3u);
        QCOMPARE(c.get("missing"), 0u);
    }
    void ioThreadPostAndCall() {
        IoThread t("test-io");
        t.start();
        int v = t.call([&] {
            Q_ASSERT(t.onThread());
            return 42;
        });
        QCOMPARE(v, 42);
        t.stop();
        t.stop(); // idempotent
    }
    void ioThreadWatchdogSeesABlockedLoop() {
        // The heartbeat stamps every turn; a handler that blocks the loop makes the age grow
        // past the watchdog's 1 s, and it falls back once the loop turns again.
        IoThread t("test-watchdog");
        QCOMPARE(t.sinceLastTurn().count(), 0); // not running
        t.start();
        QTRY_VERIFY_WITH_TIMEOUT(t.sinceLastTurn() < std::chrono::milliseconds(1000), 10000);
        std::promise<void> latch;
        std::shared_future<void> released = latch.get_future().share();
        t.post([released] { released.wait_for(std::chrono::seconds(120)); });
        QTRY_VERIFY_WITH_TIMEOUT(t.sinceLastTurn() > std::chrono::milliseconds(1000), 20000);
        latch.set_value();
        QTRY_VERIFY_WITH_TIMEOUT(t.sinceLastTurn() < std::chrono::milliseconds(1000), 20000);
        t.stop();
        QCOMPARE(t.sinceLastTurn().count(), 0);
        // A restart keeps one heartbeat (the old wait is cancelled, not doubled) and turns again.
        t.start();
        QTRY_VERIFY_WITH_TIMEOUT(t.sinceLastTurn() < std::chrono::milliseconds(1000), 10000);
        t.stop();
    }
    void poseGateCausesAndRateLimitedWarnings() {
        // The first rule broken, counted per peer, one warning per
        // peer and cause every 30 s.
        PoseGate g; // defaults: 50 km, 30 m/s, 50 m slack
        const TimePoint t0 = TimePoint{} + std::chrono::hours(1);
        QVERIFY(g.check("a", 100, 200, 5, 10.0, t0).ok());
        auto v = g.check("a", std::nan(""), 0, 0, std::nullopt, t0);
        QCOMPARE(v.fault, PoseFault::NonFinite);
        QVERIFY(v.warn);
        QCOMPARE(v.peerCount, std::uint64_t(1));
        QCOMPARE(g.check("a", 0, 0, 0, std::numeric_limits<double>::infinity(), t0).fault,
                 PoseFault::NonFinite);
        QCOMPARE(g.check("a", 1e30, 0, 0, std::nullopt, t0).fault, PoseFault::OutsideExtent);
        QCOMPARE(g.check("a", 40000, 40000, 0, std::nullopt, t0).fault, PoseFault::OutsideExtent); // 56.6 km
        QCOMPARE(g.check("a", 0, 0, 60000, std::nullopt, t0).fault, PoseFault::OutsideExtent);
        v = g.check("a", 100, 200, 0, 31.0, t0);
        QCOMPARE(v.fault, PoseFault::Speed);
        QVERIFY(v.warn);
        v = g.check("a", 100, 200, 0, -40.0, t0 + std::chrono::seconds(1));
        QCOMPARE(v.fault, PoseFault::Speed);
        QVERIFY(!v.warn); // the same cause within 30 s: counted, not warned
        QCOMPARE(v.peerCount, std::uint64_t(7));
        QVERIFY(g.check("a", 100, 200, 0, -40.0, t0 + std::chrono::seconds(31)).warn);
        QCOMPARE(QString(nameFor(PoseFault::Jump)), QStringLiteral("jump"));
        // Another peer has its own count and its own warnings.
        v = g.check("b", 1e9, 0, 0, std::nullopt, t0);
        QVERIFY(v.warn);
        QCOMPARE(v.peerCount, std::uint64_t(1));
        QCOMPARE(g.peerCount("a"), std::uint64_t(8));
        // Limits from the site configuration.
        PoseGate narrow(PoseLimits{1000, 5, 10});
        QCOMPARE(narrow.check("x", 1500, 0, 0, std::nullopt, t0).fault, PoseFault::OutsideExtent);
        QCOMPARE(narrow.check("x", 0, 0, 0, 6.0, t0).fault, PoseFault::Speed);
    }
    void poseGateBoundsJumpsAndReanchors() {
        PoseGate g;
        const TimePoint t0 = TimePoint{} + std::chrono::hours(1);
        QVERIFY(g.check("m", 0, 0, 0, std::nullopt, t0).ok());
        // 10 s later: up to 30 m/s x 10 s + 50 m = 350 m away is plausible, 400 m is a jump.
        QVERIFY(g.check("m", 340, 0, 0, std::nullopt, t0 + std::chrono::seconds(10)).ok());
        QCOMPARE(g.check("m", 740, 0, 0, std::nullopt, t0 + std::chrono::seconds(20)).fault, PoseFault::Jump);
        auto v = g.check("m", 640, 0, 0, std::nullopt, t0 + std::chrono::seconds(20));
        QVERIFY(v.ok()); // measured from the last good pose (340 m at 10 s): 300 m in 10 s
        QCOMPARE(g.check("m", 5000, 0, 0, std::nullopt, t0 + std::chrono::seconds(21)).fault,
                 PoseFault::Jump);
        // The jumps do not move the reference: a pose next to the last good one is fine.
        QVERIFY(g.check("m", 700, 0, 0, std::nullopt, t0 + std::chrono::seconds(22)).ok());
        // Three poses in a row that agree with each other far away: the machine is there (re-anchored), so
        // one wrong first pose cannot pin a machine forever.
        QCOMPARE(g.check("m", 20000, 0, 0, std::nullopt, t0 + std::chrono::seconds(23)).fault,
                 PoseFault::Jump);
        QCOMPARE(g.check("m", 20010, 0, 0, std::nullopt, t0 + std::chrono::seconds(24)).fault,
                 PoseFault::Jump);
        QVERIFY(g.check("m", 20020, 0, 0, std::nullopt, t0 + std::chrono::seconds(25)).ok());
        QVERIFY(g.check("m", 20030, 0, 0, std::nullopt, t0 + std::chrono::seconds(26)).ok());
        // Scattered wild poses never agree, so they never re-anchor.
        for (int i = 0; i < 10; ++i)
            QCOMPARE(g.check("m", (i % 2 ? -1 : 1) * 30000.0, 0, 0, std::nullopt,
                             t0 + std::chrono::seconds(27 + i))
                         .fault,
                     PoseFault::Jump);
        // Bounded state: the least recently seen peer is forgotten beyond kMaxPeers.
        for (std::size_t i = 0; i < PoseGate::kMaxPeers + 10; ++i)
            g.check("p" + std::to_string(i), 0, 0, 0, std::nullopt, t0);
        QCOMPARE(g.peers(), PoseGate::kMaxPeers);
        QCOMPARE(g.peerCount("m"), std::uint64_t(0)); // "m" was the oldest
    }
    void configLinesAndUnknownKeys() {
        const char* text = "{\n"
                           "  \"origin\": {\n"
                           "    \"latitude\": 123,\n"
                           "    \"longitdue\": 7.0\n"
                           "  }\n"
                           "}\n";
        auto doc = ConfigDocument::parse(text, "site.json");
        QVERIFY(doc.ok());
        ConfigErrors errors;
        ConfigObject root(*doc, "", errors);
        auto origin = root.object("origin");
        QVERIFY(origin.has_value());
        origin->requiredNumber("latitude", -90, 90);
        origin->number("longitude", 0, -180, 180);
        origin->finish();
        root.finish();
        QCOMPARE(int(errors.messages().size()), 2);
        QCOMPARE(QString::fromStdString(errors.messages()[0]),
                 QString("site.json:3: origin.latitude: 123 is out of range [-90, 90]"));
        QCOMPARE(
            QString::fromStdString(errors.messages()[1]),
            QString(
                "site.json:4: origin.longitdue: unknown key \"longitdue\" (did you mean \"longitude\"?)"));
    }
    void configSyntaxErrorNamesLine() {
        auto doc = ConfigDocument::parse("{\n \"a\": 1,\n \"b\": tru\n}", "x.json");
        QVERIFY(!doc.ok());
        QVERIFY2(QString::fromStdString(doc.error()).startsWith("x.json:3: JSON syntax error"),
                 doc.error().c_str());
        auto dup = ConfigDocument::parse("{\"a\":1,\"a\":2}", "d.json");
        QVERIFY(!dup.ok());
        QVERIFY(QString::fromStdString(dup.error()).contains("duplicate key"));
    }
    void configTypes() {
        auto doc =
            ConfigDocument::parse(R"({"port": "3794", "rate": 2.5, "mode": "fast", "on": 1})", "t.json");
        QVERIFY(doc.ok());
        ConfigErrors errors;
        ConfigObject root(*doc, "", errors);
        QCOMPARE(root.integer("port", 7, 0, 65535), std::int64_t(7));
        QCOMPARE(root.integer("rate", 1, 0, 10), std::int64_t(1)); // fraction where integer expected
        QCOMPARE(QString::fromStdString(root.choice("mode", "slow", {"slow", "normal"})), QString("slow"));
        QCOMPARE(root.boolean("on", false), false);
        root.finish();
        QCOMPARE(int(errors.messages().size()), 4);
        QVERIFY(QString::fromStdString(errors.joined()).contains("port: must be an integer, not string"));
        QVERIFY(
            QString::fromStdString(errors.joined()).contains("\"fast\" is not one of \"slow\", \"normal\""));
    }
    void geoFrameRoundTrip() {
        GeoFrame f({48.0, 11.0, 500.0});
        auto enu = f.toLocal({48.001, 11.001, 500.0});
        QVERIFY(std::abs(enu.n - 111.2) < 0.5);
        QVERIFY(std::abs(enu.e - 74.5) < 0.5);
        auto g = f.toGeodetic(enu);
        QVERIFY(std::abs(g.lat - 48.001) < 1e-9);
        QVERIFY(std::abs(g.lon - 11.001) < 1e-9);
    }
};

QTEST_GUILESS_MAIN(TestCommon)
#include "test_common.moc"
