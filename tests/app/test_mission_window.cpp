// A UGV mission in the whole console on the built-in simulated site, as an operator runs it: planned in the
// Mission panel, uploaded and started with its buttons (through the command gate), running with the driven
// path drawn beside the route on the 2D map at 1366x768 and 1920x1080 (screenshots into OCU_SCREENSHOT_DIR
// when set), in the headless "list"; then the run's flight recording replayed in the replay window, whose
// Mission panel and map show the recorded states and the driven path.
#include "app/HeadlessMonitor.h"
#include "app/MainWindow.h"
#include "app/ReplayRuntime.h"
#include "app/SiteLoader.h"
#include "app/SiteRuntime.h"
#include "app/WorkspaceLayout.h"

#include "models/FleetModel.h"
#include "models/jaus/MissionPlan.h"
#include "models/recording/Recorder.h"
#include "models/recording/Recording.h"
#include "models/recording/ReplayController.h"
#include "widgets/SiteMapView.h"
#include "widgets/jaus/MissionPanel.h"
#include "widgets/jaus/MissionPlanLayer.h"

#include <QBuffer>
#include <QDir>
#include <QDockWidget>
#include <QJsonDocument>
#include <QJsonObject>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace ocu;

namespace {

constexpr quint16 kUgv = 126;

// The machine line of `id` in the headless answer to "list" (its latest).
QJsonObject listed(HeadlessMonitor& mon, QBuffer& out, const QString& id) {
    out.buffer().clear();
    out.seek(0);
    mon.commands().execute(QJsonObject{{"cmd", "list"}});
    QJsonObject line;
    for (const QByteArray& l : out.buffer().split('\n')) {
        const QJsonObject o = QJsonDocument::fromJson(l).object();
        if (o.value("type") == "machine" && o.value("id") == id)
            line = o;
    }
    return line;
}

// The mission the map layer draws for the UGV (an empty one when none).
JausMission drawn(MissionPanel* panel) {
    for (const auto& m : panel->layer()->missions())
        if (m.subsystem == kUgv)
            return m.mission;
    return {};
}

// The map centred on the route at a scale that shows it whole, the Mission panel in front.
void frame(MainWindow& w, MissionPanel* panel, const QVector<MissionWaypoint>& route) {
    QPointF c;
    for (const MissionWaypoint& p : route)
        c += panel->layer()->toEN(p);
    c /= double(route.size());
    if (auto* map = qobject_cast<SiteMapView*>(w.panelWidget(Panel::SiteMap))) {
        map->panByPixels({0, 0}); // as an operator's pan: the start-up fit to the fleet ends
        map->setView(c, w.width() > 1500 ? 9.0 : 6.0);
    }
    w.raisePanel(QStringLiteral("mission"));
}

void save(QWidget& w, const QString& name) {
    const QString dir = qEnvironmentVariable("OCU_SCREENSHOT_DIR");
    if (!dir.isEmpty())
        QVERIFY(w.grab().save(QDir(dir).filePath(name)));
}

} // namespace

class TestMissionWindow : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void runningMissionInTheConsoleAndItsReplay() {
        QSettings().clear();
        QTemporaryDir recordings;
        auto site = loadSite({});
        QVERIFY(site.ok());
        SiteConfig cfg = std::move(site.value());
        cfg.record.dir = recordings.path().toStdString();
        SiteRuntime runtime(cfg);
        runtime.start();
        QBuffer out;
        out.open(QIODevice::ReadWrite);
        HeadlessMonitor* mon = runtime.attachHeadless(&out);
        QString recordingPath;
        {
            MainWindow window;
            runtime.populate(window);
            window.setWorkspace(Workspace::All);
            window.resize(1920, 1080);
            window.show();
            QVERIFY(QTest::qWaitForWindowExposed(&window));
            auto* panel = window.findChild<MissionPanel*>();
            QVERIFY(panel && panel->layer());

            // Where the UGV stands, from the headless list; a route of five legs of 10-15 m around it.
            QJsonObject ugv;
            QTRY_VERIFY_WITH_TIMEOUT(!(ugv = listed(*mon, out, "jaus:126")).isEmpty() && ugv.contains("lat"),
                                     20000);
            const double lat = ugv.value("lat").toDouble(), lon = ugv.value("lon").toDouble();
            const double m = 1.0 / 111'320.0, mLon = m / std::cos(lat * M_PI / 180);
            QVector<MissionWaypoint> route;
            for (auto [n, e] : std::initializer_list<std::pair<double, double>>{
                     {12, 4}, {22, 14}, {14, 27}, {0, 30}, {-8, 16}})
                route.push_back({lat + n * m, lon + e * mLon, 2.0, 1.5});
            panel->setVehicle(kUgv);
            panel->plan()->replace(route, QStringLiteral("test route"));
            QTRY_VERIFY_WITH_TIMEOUT(panel->button(MissionPanel::Action::Upload)->isEnabled(), 20000);
            panel->button(MissionPanel::Action::Upload)->click();
            QTRY_VERIFY2_WITH_TIMEOUT(panel->stateText().startsWith("Uploaded and verified: 5 waypoints"),
                                      qPrintable(panel->stateText()), 20000);
            QTRY_VERIFY_WITH_TIMEOUT(panel->button(MissionPanel::Action::Start)->isEnabled(), 5000);
            panel->button(MissionPanel::Action::Start)->click();
            QTRY_VERIFY2_WITH_TIMEOUT(panel->stateText().startsWith("Running: waypoint"),
                                      qPrintable(panel->stateText()), 20000);

            // The path it drives, drawn beside the route, and the same mission in the headless list.
            QTRY_VERIFY_WITH_TIMEOUT(drawn(panel).drivenPath.size() >= 20, 30000);
            QTRY_VERIFY_WITH_TIMEOUT(drawn(panel).activeIndex >= 3, 60000); // most of the way round
            QCOMPARE(drawn(panel).waypoints, route);
            QCOMPARE(drawn(panel).state, MissionState::Running);
            const QJsonObject mission = listed(*mon, out, "jaus:126").value("mission").toObject();
            QCOMPARE(mission.value("state").toString(), QStringLiteral("running"));
            QCOMPARE(mission.value("waypoints").toInt(), 5);
            QVERIFY(mission.value("active_waypoint").toInt() >= 1);
            QVERIFY(mission.value("path_points").toInt() >= 20);
            frame(window, panel, route);
            QTest::qWait(1000); // on the leg to waypoint 4
            save(window, "mission-running-1920x1080.png");
            window.resize(1366, 768);
            QTest::qWait(300);
            frame(window, panel, route);
            QTest::qWait(500);
            save(window, "mission-running-1366x768.png");
            QVERIFY(drawn(panel).drivenPath.size() >= 20);
            recordingPath = runtime.recorder()->path();
            runtime.recorder()->flush();
        }

        // The run's recording in the replay window: the Mission panel and the map show the recorded mission.
        auto rec = recording::Recording::open(recordingPath);
        QVERIFY(rec);
        FleetModel fleet;
        recording::ReplayController c(rec.get(), &fleet);
        c.seek(rec->endMs());
        MainWindow replay;
        populateReplayWindow(replay, &c);
        replay.setWorkspace(Workspace::All);
        replay.resize(1366, 768);
        replay.show();
        QVERIFY(QTest::qWaitForWindowExposed(&replay));
        auto* panel = qobject_cast<MissionPanel*>(replay.panelWidget(QStringLiteral("mission")));
        QVERIFY2(panel, "the replay's mission panel shows the recorded missions");
        QCOMPARE(panel->vehicle(), kUgv);
        QVERIFY2(panel->stateText().startsWith("Running: waypoint"), qPrintable(panel->stateText()));
        QVERIFY(drawn(panel).drivenPath.size() >= 20);
        QCOMPARE(panel->plan()->size(), 5); // the recorded mission's waypoints in the table
        QVERIFY(!panel->button(MissionPanel::Action::Pause)->isEnabled());
        frame(replay, panel, drawn(panel).waypoints);
        QTest::qWait(300);
        save(replay, "mission-replay-1366x768.png");
        // Back to before the upload: no mission yet.
        c.seek(rec->startMs());
        QTRY_VERIFY(panel->layer()->missions().isEmpty());
        runtime.stop();
    }
};

QTEST_MAIN(TestMissionWindow)
#include "test_mission_window.moc"
