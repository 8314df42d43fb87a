// A UGV's mission in the flight recorder: a run (upload, waypoints, pause, a sliding PathReporter window, a
// path that starts over, completion) reported by a fake JAUS bridge is recorded as the console records it
// (MissionRecordFeed on the bridge, Recorder attached to the context), replayed through the replay
// controller, and the mission panel and its map layer show at every instant the states and the driven path
// the live console had; seeks back and forth, a slice and the JSON-lines export keep them.
#include "models/FleetContext.h"
#include "models/FleetModel.h"
#include "models/FleetSelection.h"
#include "models/jaus/JausVehicleBridge.h"
#include "models/jaus/MissionJson.h"
#include "models/jaus/MissionRecordFeed.h"
#include "models/jaus/MissionReplayBridge.h"
#include "models/recording/Recorder.h"
#include "models/recording/Recording.h"
#include "models/recording/ReplayController.h"
#include "tests/widgets/jaus/FakeJausBridge.h"
#include "widgets/SiteMapView.h"
#include "widgets/jaus/MissionPanel.h"
#include "widgets/jaus/MissionPlanLayer.h"

#include <QFile>
#include <QJsonDocument>
#include <QMap>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <limits>

using namespace ocu;

namespace {

const GeoPoint kOrigin{48.137, 11.575, 500};

using ocu::testing::FakeJausBridge;

QVector<MissionWaypoint> route() {
    QVector<MissionWaypoint> w;
    for (int i = 0; i < 5; ++i)
        w.push_back({kOrigin.lat + 0.0001 * i, kOrigin.lon + 0.00013 * i * i, 1.5, 0.8});
    return w;
}

QPair<double, double> pathPoint(int i) {
    return {kOrigin.lat + 0.00002 * i + 1e-9 * (i % 7), kOrigin.lon + 0.000011 * i};
}

QVector<QPair<double, double>> pathRange(int from, int to) {
    QVector<QPair<double, double>> p;
    for (int i = from; i < to; ++i)
        p << pathPoint(i);
    return p;
}

MachineState machine(quint16 sub, const QPair<double, double>& at) {
    MachineState m;
    m.id = JausVehicleBridge::machineId(sub);
    m.protocol = Protocol::Jaus;
    m.name = QStringLiteral("UGV-%1").arg(sub);
    m.type = QStringLiteral("UGV");
    m.link = LinkState::Up;
    m.hasPosition = true;
    m.lat = at.first;
    m.lon = at.second;
    const EnuPoint e = GeoFrame(kOrigin).toLocal({at.first, at.second, kOrigin.alt});
    m.e = e.e;
    m.n = e.n;
    return m;
}

} // namespace

class TestMissionRecording : public QObject {
    Q_OBJECT

    // The missions the live console had, by record time and vehicle.
    struct Live {
        qint64 t;
        quint16 sub;
        JausMission mission;
    };

private slots:
    void recordJsonRoundTripsEveryField() {
        JausMission before;
        JausMission m;
        m.state = MissionState::Lost;
        m.waypoints = route();
        m.global = true;
        m.activeIndex = 2;
        m.lastSeenIndex = 2;
        m.distanceToGoM = 12.25;
        m.etaS = 8.5;
        m.ours = false;
        m.reason = QStringLiteral("link down");
        m.drivenPath = pathRange(0, 40);
        m.pathSource = QStringLiteral("path reporter");
        JausMission back = before;
        QVERIFY(applyMissionRecord(back, encodeMissionRecord(before, m)));
        QCOMPARE(back, m);
        // A sliding window (10 dropped, 3 added) is written as such, not whole.
        JausMission slid = m;
        slid.drivenPath = pathRange(10, 43);
        const QByteArray rec = encodeMissionRecord(m, slid);
        QVERIFY(rec.contains("\"path_drop\":10"));
        QVERIFY(!rec.contains("\"waypoints\""));
        QVERIFY(rec.size() < 400);
        QVERIFY(applyMissionRecord(back, rec));
        QCOMPARE(back, slid);
        // Malformed records change nothing.
        for (const QByteArray& bad : {QByteArray("{"), QByteArray("{\"state\":\"flying\"}"),
                                      QByteArray("{\"state\":\"running\",\"path_drop\":999,\"path_add\":[]}"),
                                      QByteArray("{\"state\":\"running\",\"path\":[1]}")}) {
            JausMission same = slid;
            QVERIFY(!applyMissionRecord(same, bad));
            QCOMPARE(same, slid);
        }
        // The headless fields.
        const QJsonObject o = missionJson(m);
        QCOMPARE(o.value("state").toString(), QStringLiteral("lost"));
        QCOMPARE(o.value("waypoints").toInt(), 5);
        QCOMPARE(o.value("active_waypoint").toInt(), 3);
        QCOMPARE(o.value("last_seen_waypoint").toInt(), 3);
        QCOMPARE(o.value("distance_to_go_m").toDouble(), 12.25);
        QCOMPARE(o.value("path_points").toInt(), 40);
        QCOMPARE(o.value("ours").toBool(), false);
    }

    void progressIsRecordedAtMostOncePerInterval() {
        FakeJausBridge bridge;
        bridge.ident = {}; // a console that may command nothing: the recording is read, never sent
        auto* feed = new MissionRecordFeed(&bridge, 60000);
        QSignalSpy records(&bridge, &FleetBridge::detailRecorded);
        JausVehicle v;
        v.subsystem = 7;
        bridge.report(v); // no mission: nothing
        QCOMPARE(records.size(), 0);
        v.mission.state = MissionState::Running;
        v.mission.waypoints = route();
        v.mission.activeIndex = 0;
        bridge.report(v);
        QCOMPARE(records.size(), 1);
        for (int i = 1; i <= 20; ++i) { // the pose moves: progress only, within the interval
            v.mission.drivenPath = pathRange(0, i);
            v.mission.distanceToGoM = 100.0 - i;
            bridge.report(v);
        }
        QCOMPARE(records.size(), 1);
        v.mission.activeIndex = 1; // a new waypoint: at once, with the progress so far
        bridge.report(v);
        QCOMPARE(records.size(), 2);
        v.mission.drivenPath = pathRange(0, 25);
        bridge.report(v);
        QCOMPARE(records.size(), 2);
        feed->flush();
        QCOMPARE(records.size(), 3);
        JausMission back;
        for (const auto& r : records) {
            QCOMPARE(r.at(0).toString(), QStringLiteral("jaus:7"));
            QCOMPARE(r.at(1).toString(), missionRecordKind());
            QVERIFY(applyMissionRecord(back, r.at(2).toByteArray()));
        }
        QCOMPARE(back, v.mission);
    }

    void recordedRunReplaysItsStatesAndPath() {
        QTemporaryDir dir;
        auto clock = std::make_shared<ManualModelClock>(1'800'000'000'000);
        FleetContext ctx;
        ctx.fleet()->setClock(clock);
        auto* bridge = new FakeJausBridge;
        bridge->ident = {};
        bridge->setClock(clock);
        ctx.addBridge(bridge);
        new MissionRecordFeed(bridge, 0); // every change: the test compares every instant
        recording::Recorder recorder;
        recording::RecorderOptions o;
        o.path = dir.filePath("run.sqlite");
        o.clock = clock;
        o.originLat = kOrigin.lat;
        o.originLon = kOrigin.lon;
        o.originAlt = kOrigin.alt;
        QCOMPARE(recorder.start(o), QString());
        recorder.attach(&ctx);

        // The run: UGV 126 uploads, runs five waypoints with its pose trail, is paused and resumed, and
        // completes; UGV 127's PathReporter window slides, then its path starts over, and it is lost.
        QVector<Live> live;
        JausVehicle a, b;
        a.subsystem = 126;
        b.subsystem = 127;
        auto step = [&](JausVehicle& v, auto change) {
            clock->advance(250);
            change(v.mission);
            bridge->publishMachine(machine(v.subsystem, v.mission.drivenPath.isEmpty()
                                                            ? QPair<double, double>{kOrigin.lat, kOrigin.lon}
                                                            : v.mission.drivenPath.back()));
            bridge->flushPending();
            bridge->report(v);
            live.push_back({clock->nowMs(), v.subsystem, v.mission});
        };
        step(a, [](JausMission& m) {
            m.state = MissionState::Uploading;
            m.waypoints = route();
        });
        step(a, [](JausMission& m) { m.state = MissionState::Uploaded; });
        for (int k = 0; k < 5; ++k)
            for (int i = 0; i < 6; ++i)
                step(a, [&](JausMission& m) {
                    m.state = k == 2 && i >= 2 && i < 4 ? MissionState::Paused : MissionState::Running;
                    m.activeIndex = k;
                    m.drivenPath = pathRange(0, k * 6 + i + 1);
                    m.pathSource = QStringLiteral("pose trail");
                    m.distanceToGoM = 200.0 - (k * 6 + i) * 6.5;
                    m.etaS = m.distanceToGoM.value() / 1.5;
                });
        step(a, [](JausMission& m) {
            m.state = MissionState::Completed;
            m.activeIndex = -1;
            m.distanceToGoM.reset();
            m.etaS.reset();
        });
        step(b, [](JausMission& m) {
            m.state = MissionState::Running;
            m.global = true;
            m.waypoints = route().mid(1, 3);
            m.activeIndex = 0;
            m.pathSource = QStringLiteral("path reporter");
        });
        for (int i = 0; i < 12; ++i) // a window of at most 20 points
            step(b, [&](JausMission& m) { m.drivenPath = pathRange(std::max(0, i * 4 - 20), i * 4 + 4); });
        step(b, [](JausMission& m) { m.drivenPath = pathRange(500, 503); }); // it starts over
        step(b, [](JausMission& m) {
            m.state = MissionState::Lost;
            m.lastSeenIndex = 0;
            m.activeIndex = -1;
            m.reason = QStringLiteral("link down");
        });
        clock->advance(1000);
        recorder.flush();
        recorder.stop();

        auto rec = recording::Recording::open(o.path);
        QVERIFY(rec);
        const auto details =
            rec->details(missionRecordKind(), std::numeric_limits<qint64>::min(), rec->endMs());
        QCOMPARE(details.size(), live.size());
        QVector<MissionReplayBridge::Record> records;
        for (const auto& d : details)
            records.push_back({d.t, d.machine, d.data});

        // The replay as the console builds it: the replayed fleet, the panel and its map layer on the bridge.
        FleetModel fleet;
        recording::ReplayController controller(rec.get(), &fleet);
        MissionReplayBridge vehicles(records, &fleet);
        connect(&controller, &recording::ReplayController::positionChanged, &vehicles,
                &MissionReplayBridge::setTime);
        FleetSelection selection(&fleet);
        SiteMapView map;
        map.setFleet(&fleet, &selection);
        map.setGeoFrame(GeoFrame(kOrigin));
        MissionPanel panel(&vehicles, &selection);
        panel.attachMap(&map, GeoFrame(kOrigin));

        // The picture at an instant: each vehicle's latest mission up to it.
        auto expectedAt = [&](qint64 t) {
            QHash<quint16, JausMission> out;
            for (const Live& l : live)
                if (l.t <= t)
                    out[l.sub] = l.mission;
            return out;
        };
        auto check = [&](qint64 t) {
            const auto want = expectedAt(t);
            for (quint16 sub : {quint16(126), quint16(127)}) {
                const auto v = vehicles.subsystem(sub);
                QCOMPARE(v ? v->mission : JausMission{}, want.value(sub));
            }
            // The layer draws what the live one drew: route and driven path per vehicle with a mission.
            QVector<MissionPlanLayer::VehicleMission> drawn = panel.layer()->missions();
            QCOMPARE(drawn.size(), want.size());
            for (const auto& d : drawn)
                QCOMPARE(d.mission, want.value(d.subsystem));
        };
        // Forwards through every instant, then seeks back and forth.
        for (const Live& l : live) {
            controller.moveTo(l.t);
            check(l.t);
        }
        for (int i : {40, 3, 29, 0, 47, 12}) {
            controller.seek(live[i].t);
            check(live[i].t);
        }
        QCOMPARE(vehicles.malformed(), 0);

        // The panel in words: the selected UGV's recorded state and its driven path.
        selection.setCurrent(QStringLiteral("jaus:126"));
        controller.seek(live[2 + 2 * 6 + 2].t); // paused on waypoint 3
        QVERIFY2(panel.stateText().startsWith("Paused at waypoint 3 of 5"), qPrintable(panel.stateText()));
        QVERIFY(panel.stateText().contains("driven path from the pose trail"));
        controller.seek(live[2 + 3 * 6 + 1].t);
        QVERIFY2(panel.stateText().startsWith("Running: waypoint 4 of 5"), qPrintable(panel.stateText()));
        controller.seek(rec->endMs());
        selection.setCurrent(QStringLiteral("jaus:127"));
        QVERIFY2(panel.stateText().startsWith("Unknown, last seen at waypoint 1 of 3"),
                 qPrintable(panel.stateText()));
        QVERIFY(!panel.button(MissionPanel::Action::Resume)->isEnabled());

        // A slice from the middle replays the same picture (its records before the window kept), and the
        // JSON lines carry the records.
        const qint64 mid = live[30].t;
        QVERIFY(rec->exportSlice(dir.filePath("slice.sqlite"), mid, rec->endMs()));
        auto slice = recording::Recording::open(dir.filePath("slice.sqlite"));
        QVERIFY(slice);
        QVector<MissionReplayBridge::Record> sliced;
        for (const auto& d : slice->details(missionRecordKind(), std::numeric_limits<qint64>::min(), mid))
            sliced.push_back({d.t, d.machine, d.data});
        MissionReplayBridge fromSlice(sliced, nullptr);
        fromSlice.setTime(mid);
        QCOMPARE(fromSlice.subsystem(126)->mission, expectedAt(mid).value(126));
        QFile jsonl(dir.filePath("run.jsonl"));
        QVERIFY(jsonl.open(QIODevice::WriteOnly));
        QVERIFY(rec->exportJsonLines(&jsonl, rec->startMs(), rec->endMs()));
        jsonl.close();
        QVERIFY(jsonl.open(QIODevice::ReadOnly));
        int detailLines = 0;
        for (const QByteArray& line : jsonl.readAll().split('\n')) {
            const QJsonObject j = QJsonDocument::fromJson(line).object();
            if (j.value("type").toString() == "detail") {
                ++detailLines;
                QCOMPARE(j.value("kind").toString(), missionRecordKind());
                QVERIFY(j.value("data").toObject().contains("state"));
            }
        }
        QCOMPARE(detailLines, live.size());
    }
};

QTEST_MAIN(TestMissionRecording)
#include "test_mission_recording.moc"
