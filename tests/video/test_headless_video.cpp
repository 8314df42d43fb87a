// Headless video status: {"cmd":"video_status"} lists each JAUS vehicle's announced cameras,
// idle until played; {"cmd":"video_play"} decodes one, and the status then reports what is actually decoded
// (state, resolution, fps, frame age from the time code); {"cmd":"video_stop"} ends it. Simulated UGV with
// its cameras on loopback.
#include "app/HeadlessMonitor.h"
#include "app/modules/JausVideoHeadless.h"
#include "models/FleetContext.h"
#include "models/bridges/JausBridge.h"
#include "protocols/jaus/JausStack.h"
#include "sim/jaus/JausDemo.h"

#include <QBuffer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QtTest>

using namespace ocu;
using namespace ocu::jaus;

namespace {
QJsonObject run(HeadlessMonitor& mon, const char* line) {
    return QJsonDocument::fromJson(mon.handleLine(QByteArray(line))).object();
}
QJsonObject stream(const QJsonObject& status, int vehicle, int index) {
    const QJsonArray vehicles = status[QStringLiteral("vehicles")].toArray();
    if (vehicle >= vehicles.size())
        return {};
    const QJsonArray streams = vehicles.at(vehicle).toObject()[QStringLiteral("streams")].toArray();
    return index < streams.size() ? streams.at(index).toObject() : QJsonObject{};
}
} // namespace

class TestHeadlessVideo : public QObject {
    Q_OBJECT
private slots:
    void statusReportsWhatIsDecoded() {
        sim::JausDemoOptions o;
        o.count = 1;
        o.video = true;
        sim::JausDemo demo(o);
        JausConfig c;
        c.subsystemId = 200;
        c.callSign = "OCU-HEADLESS";
        demo.configure(c);
        FleetContext ctx;
        JausBridge bridge(c, GeoFrame(o.origin));
        ctx.addBridge(&bridge);
        QCOMPARE(bridge.start(), QString());
        QBuffer out;
        out.open(QIODevice::WriteOnly);
        HeadlessMonitor* mon = HeadlessMonitor::attach(&ctx, &out);
        JausVideoHeadless video(&bridge);
        video.registerIn(mon->commands());

        // The endpoints come from Digital Resource Discovery first, the pan-tilt mount from the Visual
        // Sensor and Pan Tilt services a little later (under load, seconds later): wait for both.
        QTRY_VERIFY_WITH_TIMEOUT(
            stream(run(*mon, R"({"cmd":"video_status"})"), 0, 1).contains(QStringLiteral("url")) &&
                stream(run(*mon, R"({"cmd":"video_status"})"), 0, 0)[QStringLiteral("pan_tilt")].toBool(),
            30000);
        QJsonObject st = run(*mon, R"({"cmd":"video_status","req":3})");
        QCOMPARE(st[QStringLiteral("type")].toString(), QStringLiteral("result"));
        QCOMPARE(st[QStringLiteral("req")].toInt(), 3);
        QVERIFY(st[QStringLiteral("ok")].toBool());
        QCOMPARE(stream(st, 0, 0)[QStringLiteral("state")].toString(), QStringLiteral("idle"));
        QVERIFY(!stream(st, 0, 0).contains(QStringLiteral("fps"))); // nothing decoded, nothing claimed
        QVERIFY(stream(st, 0, 0)[QStringLiteral("pan_tilt")].toBool());

        const QJsonObject play = run(*mon, R"({"cmd":"video_play","id":"jaus:126","sensor":1001})");
        QVERIFY2(play[QStringLiteral("ok")].toBool(), qPrintable(play[QStringLiteral("message")].toString()));
        QTRY_VERIFY_WITH_TIMEOUT(
            stream(run(*mon, R"({"cmd":"video_status"})"), 0, 1)[QStringLiteral("frames")].toInt() >= 10,
            30000);
        st = run(*mon, R"({"cmd":"video_status","id":"jaus:126"})");
        const QJsonObject rear = stream(st, 0, 1);
        QCOMPARE(rear[QStringLiteral("sensor")].toInt(), 1001);
        QCOMPARE(rear[QStringLiteral("state")].toString(), QStringLiteral("playing"));
        QCOMPARE(rear[QStringLiteral("width")].toInt(), o.videoWidth);
        QCOMPARE(rear[QStringLiteral("height")].toInt(), o.videoHeight);
        QVERIFY(rear[QStringLiteral("fps")].toDouble() > 0);
        QVERIFY(rear.contains(QStringLiteral("frame_age_ms")));
        QCOMPARE(rear[QStringLiteral("age_source")].toString(), QStringLiteral("timecode"));
        QCOMPARE(stream(st, 0, 0)[QStringLiteral("state")].toString(), QStringLiteral("idle"));

        // Unknown vehicle or camera: a clear refusal.
        QVERIFY(!run(*mon, R"({"cmd":"video_play","id":"jaus:999"})")[QStringLiteral("ok")].toBool());
        QVERIFY(!run(*mon, R"({"cmd":"video_play","id":"iso23725:x"})")[QStringLiteral("ok")].toBool());
        QVERIFY(
            !run(*mon, R"({"cmd":"video_play","id":"jaus:126","sensor":5})")[QStringLiteral("ok")].toBool());

        QVERIFY(run(*mon, R"({"cmd":"video_stop"})")[QStringLiteral("ok")].toBool());
        QCOMPARE(stream(run(*mon, R"({"cmd":"video_status"})"), 0, 1)[QStringLiteral("state")].toString(),
                 QStringLiteral("idle"));
        bridge.stop();
    }
};

QTEST_MAIN(TestHeadlessVideo)
#include "test_headless_video.moc"
