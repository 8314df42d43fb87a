#include "protocols/common/Bytes.h"
#include "protocols/common/Clock.h"
#include "protocols/common/ConfigReader.h"
#include "protocols/common/Counters.h"
#include "protocols/common/GeoFrame.h"
#include "protocols/common/IoThread.h"

#include <QtTest>

#include <future>

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
        // Issue 14 §3: the heartbeat stamps every turn; a handler that blocks the loop makes the age grow
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
