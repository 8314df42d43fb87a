// A UGV's mission run recorded as the console records it (a JAUS bridge's reports and mission events,
// MissionRecordFeed, the Recorder on the context), then replayed: the headless replay prints the mission's
// states in the UGV's machine lines and the mission events as the live monitor did, and its "list" answers
// with the mission at the replay time; the replay window's 3D view draws the planned route in the vehicle's
// colour and the path driven in another tone, as the live console does through the same hook.
#include "app/HeadlessMonitor.h"
#include "app/HeadlessReplay.h"
#include "app/MainWindow.h"
#include "app/ReplayRuntime.h"
#include "app/Screenshot.h"
#include "app/modules/JausMission3D.h"

#include "models/FleetContext.h"
#include "models/FleetModel.h"
#include "models/FleetSelection.h"
#include "models/jaus/MissionPlan.h"
#include "models/jaus/MissionRecordFeed.h"
#include "models/recording/Recorder.h"
#include "models/recording/Recording.h"
#include "models/recording/ReplayController.h"
#include "tests/widgets/jaus/FakeJausBridge.h"
#include "widgets/jaus/MissionPanel.h"
#include "widgets/jaus/MissionPlanLayer.h"
#ifdef OCU_HAVE_OCU_VIEW3D
#include "widgets/view3d/RouteOverlay3D.h"
#include "widgets/view3d/Site3DView.h"
#endif

#include <QBuffer>
#include <QDir>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

using namespace ocu;
using ocu::testing::FakeJausBridge;

namespace {

const GeoPoint kOrigin{48.137, 11.575, 500};
const QString kUgv = QStringLiteral("jaus:126");

QVector<MissionWaypoint> route() {
    QVector<MissionWaypoint> w;
    for (int i = 0; i < 5; ++i)
        w.push_back({kOrigin.lat + 0.0001 * i, kOrigin.lon + 0.00013 * i * i, 1.5, 0.8});
    return w;
}

QVector<QPair<double, double>> path(int points) {
    QVector<QPair<double, double>> p;
    for (int i = 0; i < points; ++i)
        p << qMakePair(kOrigin.lat + 0.00002 * i, kOrigin.lon + 0.000011 * i);
    return p;
}

MachineState machine(const QPair<double, double>& at) {
    MachineState m;
    m.id = kUgv;
    m.protocol = Protocol::Jaus;
    m.name = QStringLiteral("UGV-126");
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

QList<QJsonObject> lines(const QByteArray& text) {
    QList<QJsonObject> out;
    for (const QByteArray& l : text.split('\n'))
        if (!l.trimmed().isEmpty())
            out << QJsonDocument::fromJson(l).object();
    return out;
}

} // namespace

class TestMissionReplay : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;
    QString m_path;
    qint64 m_pausedAt = 0;  // paused at waypoint 3
    qint64 m_runningAt = 0; // running to waypoint 5 with 24 points driven

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
        recordRun();
    }

    // The headless replay: the mission's states in the UGV's lines in the order they happened, the mission
    // events among them, and "list" at a replay time.
    void headlessReplayPrintsTheMissionStates() {
        auto rec = recording::Recording::open(m_path);
        QVERIFY(rec);
        FleetModel fleet;
        recording::ReplayController c(rec.get(), &fleet);
        c.seek(rec->startMs());
        QBuffer out;
        out.open(QIODevice::ReadWrite);
        HeadlessReplay replay(&c, &out);
        replay.runToEnd();
        QStringList states, events;
        QList<int> active;
        for (const QJsonObject& o : lines(out.buffer())) {
            if (o.value("type") == "event" && o.value("machine") == kUgv)
                events << o.value("text").toString();
            if (o.value("type") != "machine" || o.value("id") != kUgv || !o.contains("mission"))
                continue;
            const QJsonObject m = o.value("mission").toObject();
            if (states.isEmpty() || states.last() != m.value("state").toString())
                states << m.value("state").toString();
            if (m.contains("active_waypoint") &&
                (active.isEmpty() || active.last() != m["active_waypoint"].toInt()))
                active << m.value("active_waypoint").toInt();
        }
        QCOMPARE(states, (QStringList{"uploading", "uploaded", "running", "paused", "running", "completed"}));
        QCOMPARE(active, (QList<int>{1, 2, 3, 4, 5}));
        QCOMPARE(events, (QStringList{"UGV-126: mission uploading", "UGV-126: mission uploaded",
                                      "UGV-126: mission running", "UGV-126: mission paused",
                                      "UGV-126: mission running", "UGV-126: mission completed"}));

        // "list" answers from the replayed state at the replay time, backwards and forwards.
        auto listed = [&] {
            out.buffer().clear();
            out.seek(0);
            replay.monitor().commands().execute(QJsonObject{{"cmd", "list"}});
            for (const QJsonObject& o : lines(out.buffer()))
                if (o.value("type") == "machine" && o.value("id") == kUgv)
                    return o.value("mission").toObject();
            return QJsonObject{};
        };
        c.seek(m_pausedAt);
        QJsonObject m = listed();
        QCOMPARE(m.value("state").toString(), QStringLiteral("paused"));
        QCOMPARE(m.value("active_waypoint").toInt(), 3);
        QCOMPARE(m.value("waypoints").toInt(), 5);
        c.seek(m_runningAt);
        m = listed();
        QCOMPARE(m.value("state").toString(), QStringLiteral("running"));
        QCOMPARE(m.value("active_waypoint").toInt(), 5);
        QCOMPARE(m.value("path_points").toInt(), 24);
        c.seek(rec->startMs());
        QVERIFY(listed().isEmpty()); // before the upload: no mission field
    }

#ifdef OCU_HAVE_OCU_VIEW3D
    // The replay window's 3D view: the recorded route in the vehicle's colour, the path driven darker.
    void replayWindowDrawsTheRouteIn3D() {
        auto rec = recording::Recording::open(m_path);
        QVERIFY(rec);
        FleetModel fleet;
        recording::ReplayController c(rec.get(), &fleet);
        c.seek(m_runningAt);
        MainWindow window;
        populateReplayWindow(window, &c);
        auto* view3d = qobject_cast<Site3DView*>(window.panelWidget(Panel::Site3D));
        QVERIFY(view3d);
        checkOverlays(view3d, 5, 24);
        if (const QString dir = qEnvironmentVariable("OCU_SCREENSHOT_DIR"); !dir.isEmpty()) {
            window.resize(1366, 768);
            window.show();
            QVERIFY(QTest::qWaitForWindowExposed(&window));
            QTest::qWait(1500);
            QCOMPARE(
                saveScreenshot(window, QStringLiteral("3d"), QDir(dir).filePath("mission-replay-3d.png")),
                QString());
        }
        c.seek(rec->startMs()); // no mission yet: no path driven (the table keeps the recorded plan)
        auto* driven = view3d->findChild<RouteOverlay3D*>(drivenPath3DName());
        QTRY_VERIFY(driven->drawnPoints().isEmpty());
    }

    // Live, through the same hook on the live mission panel: the same drawing.
    void liveConsoleDrawsTheSame() {
        FakeJausBridge bridge;
        FleetModel fleet;
        FleetSelection selection(&fleet);
        MainWindow window;
        auto* view3d = new Site3DView;
        window.setPanelWidget(Panel::Site3D, view3d);
        auto* panel = new MissionPanel(&bridge, &selection);
        window.setPanelWidget(QStringLiteral("mission"), panel);
        attachMissionRoutes3D(window, panel, GeoFrame(kOrigin));
        JausVehicle v;
        v.subsystem = 126;
        v.mission.state = MissionState::Running;
        v.mission.waypoints = route();
        v.mission.activeIndex = 4;
        v.mission.drivenPath = path(24);
        bridge.report(v);
        panel->setVehicle(126);
        panel->plan()->replace(route(), QStringLiteral("route"));
        checkOverlays(view3d, 5, 24);
    }
#endif

private:
#ifdef OCU_HAVE_OCU_VIEW3D
    // Both overlays drawn: the route through its waypoints, the path through its points (long legs are split
    // to follow the ground, so at least as many points).
    void checkOverlays(Site3DView* view3d, int waypoints, int pathPoints) {
        auto* planned = view3d->findChild<RouteOverlay3D*>(plannedRoute3DName());
        auto* driven = view3d->findChild<RouteOverlay3D*>(drivenPath3DName());
        QVERIFY(planned && driven);
        QTRY_VERIFY(planned->drawnPoints().size() >= waypoints);
        QTRY_VERIFY(driven->drawnPoints().size() >= pathPoints);
        const QColor c = MissionPlanLayer::missionColour(126);
        const QVector3D want(float(c.redF()), float(c.greenF()), float(c.blueF()));
        QVERIFY((planned->colour() - want).length() < 1e-3);
        QVERIFY((driven->colour() - want).length() > 0.05); // distinct from the route
        QVERIFY(driven->width() < planned->width());
        const EnuPoint last = GeoFrame(kOrigin).toLocal({route().back().lat, route().back().lon, 0});
        QVERIFY(std::abs(planned->drawnPoints().back().x() - last.e) < 0.01);
        QVERIFY(std::abs(planned->drawnPoints().back().y() - last.n) < 0.01);
    }
#endif

    // UGV 126 uploads, runs five waypoints (paused on the third), completes; each state change is a mission
    // event as the JAUS stack raises it.
    void recordRun() {
        auto clock = std::make_shared<ManualModelClock>(1'800'000'000'000);
        FleetContext ctx;
        ctx.fleet()->setClock(clock);
        auto* bridge = new FakeJausBridge;
        bridge->ident = {};
        bridge->setClock(clock);
        ctx.addBridge(bridge);
        new MissionRecordFeed(bridge, 0); // every change: the test knows the picture at each instant
        recording::Recorder recorder;
        recording::RecorderOptions o;
        o.path = m_dir.filePath("run.sqlite");
        o.clock = clock;
        o.originLat = kOrigin.lat;
        o.originLon = kOrigin.lon;
        o.originAlt = kOrigin.alt;
        QCOMPARE(recorder.start(o), QString());
        recorder.attach(&ctx);
        JausVehicle v;
        v.subsystem = 126;
        auto step = [&](auto change, qint64 afterMs = 1100) {
            clock->advance(afterMs);
            const MissionState before = v.mission.state;
            change(v.mission);
            bridge->publishMachine(machine(v.mission.drivenPath.isEmpty()
                                               ? qMakePair(kOrigin.lat, kOrigin.lon)
                                               : v.mission.drivenPath.back()));
            if (v.mission.state != before) {
                FleetEvent e = makeEvent(EventSeverity::Info, EventKind::Info, kUgv,
                                         "UGV-126: mission " + toText(v.mission.state), "jaus");
                e.timeMs = clock->nowMs();
                bridge->publishEvent(e);
            }
            bridge->flushPending();
            bridge->report(v);
            QCoreApplication::processEvents();
        };
        step(
            [](JausMission& m) {
                m.state = MissionState::Uploading;
                m.waypoints = route();
            },
            1150);
        // Verified 40 ms later: within one 100 ms step of the headless replay, still a line of its own.
        step([](JausMission& m) { m.state = MissionState::Uploaded; }, 40);
        for (int k = 0; k < 5; ++k)
            for (int i = 0; i < 4; ++i) {
                step([&](JausMission& m) {
                    m.state = k == 2 && i >= 2 ? MissionState::Paused : MissionState::Running;
                    m.activeIndex = k;
                    m.drivenPath = path(k * 5 + i + 1);
                    m.pathSource = QStringLiteral("pose trail");
                    m.distanceToGoM = 100.0 - (k * 4 + i) * 5;
                });
                if (k == 2 && i == 3)
                    m_pausedAt = clock->nowMs();
                if (k == 4 && i == 3)
                    m_runningAt = clock->nowMs();
            }
        step([](JausMission& m) {
            m.state = MissionState::Completed;
            m.activeIndex = -1;
            m.distanceToGoM.reset();
        });
        clock->advance(1000);
        recorder.flush();
        recorder.stop();
        m_path = o.path;
    }
};

QTEST_MAIN(TestMissionReplay)
#include "test_mission_replay.moc"
