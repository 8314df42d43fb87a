// The mission plan editor on the 2D map (mouse and keyboard), the map's "Go here", and the mission panel:
// its table, files and commands through the MissionCommands seam, and each mission state a fake JAUS bridge
// reports, with the driven path drawn beside the planned route.
#include "models/FleetContext.h"
#include "models/FleetModel.h"
#include "models/FleetSelection.h"
#include "models/jaus/JausVehicleBridge.h"
#include "models/jaus/MissionGeoJson.h"
#include "models/jaus/MissionPlan.h"
#include "tests/widgets/jaus/FakeJausBridge.h"
#include "widgets/SiteMapView.h"
#include "widgets/jaus/MissionCommands.h"
#include "widgets/jaus/MissionGateCommands.h"
#include "widgets/jaus/MissionPanel.h"
#include "widgets/jaus/MissionPlanEditor.h"
#include "widgets/jaus/MissionPlanLayer.h"
#include "widgets/jaus/MissionPlanTableModel.h"

#include <QApplication>
#include <QLabel>
#include <QMap>
#include <QMenu>
#include <QMouseEvent>
#include <QPainter>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableView>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

using namespace ocu;

namespace {

const GeoPoint kOrigin{48.137, 11.575, 500};

using ocu::testing::FakeJausBridge;

// The sending seam, recording each call as the JAUS module's implementation would send it.
class RecordingCommands final : public MissionCommands {
public:
    QStringList calls;
    QVector<MissionWaypoint> uploaded;
    MissionWaypoint goal;
    void upload(const QString& id, const QVector<MissionWaypoint>& w) override {
        calls << "upload " + id;
        uploaded = w;
    }
    void start(const QString& id, int from) override {
        calls << QStringLiteral("start %1 %2").arg(id).arg(from);
    }
    void pause(const QString& id) override { calls << "pause " + id; }
    void resume(const QString& id) override { calls << "resume " + id; }
    void abort(const QString& id) override { calls << "abort " + id; }
    void goTo(const QString& id, const MissionWaypoint& w) override {
        calls << "goto " + id;
        goal = w;
    }
};

JausVehicle ugv(quint16 id) {
    JausVehicle v;
    v.subsystem = id;
    v.callSign = QStringLiteral("UGV-%1").arg(id);
    v.link = JausLink::Up;
    v.controlledByUs = true;
    JausPlatform p;
    p.maxForwardSpeed = 2.0;
    p.front = 1.0;
    p.back = 0.5;
    v.platform = p;
    JausGlobalPose pose;
    pose.lat = kOrigin.lat;
    pose.lon = kOrigin.lon;
    v.globalPose = pose;
    return v;
}

void mouse(QWidget* w, QEvent::Type type, QPointF pos, Qt::MouseButton button = Qt::LeftButton,
           Qt::KeyboardModifiers mods = Qt::NoModifier) {
    const Qt::MouseButtons held =
        type == QEvent::MouseButtonRelease ? Qt::NoButton : Qt::MouseButtons(button);
    QMouseEvent e(type, pos, w->mapToGlobal(pos), type == QEvent::MouseMove ? Qt::NoButton : button, held,
                  mods);
    QApplication::sendEvent(w, &e);
}
void click(QWidget* w, QPointF pos) {
    mouse(w, QEvent::MouseButtonPress, pos);
    mouse(w, QEvent::MouseButtonRelease, pos);
}
void drag(QWidget* w, QPointF from, QPointF to, int steps = 5) {
    mouse(w, QEvent::MouseButtonPress, from);
    for (int i = 1; i <= steps; ++i)
        mouse(w, QEvent::MouseMove, from + (to - from) * (double(i) / steps));
    mouse(w, QEvent::MouseButtonRelease, to);
}

struct Rig {
    Rig() : selection(&fleet) {
        bridge.report(ugv(1));
        bridge.report(ugv(2));
        map.setGeoFrame(GeoFrame(kOrigin));
        map.resize(800, 600);
        map.show();
        map.setView({0, 0}, 2.0); // 2 px per metre: 400 m x 300 m
        panel = new MissionPanel(&bridge, &selection);
        panel->attachMap(&map, GeoFrame(kOrigin));
        panel->setVehicle(1);
        panel->resize(600, 700);
        panel->show();
    }
    ~Rig() { delete panel; }
    MissionPlan* plan() const { return panel->plan(); }
    MissionPlanLayer* layer() const { return panel->layer(); }
    // The waypoint's place on the map (px).
    QPointF at(int i) const { return map.worldToScreen(layer()->toEN(plan()->at(i))); }
    void report(MissionState state, int active = -1) {
        JausVehicle v = bridge.vehicles.value(1);
        v.mission.state = state;
        v.mission.waypoints = plan()->waypoints();
        v.mission.activeIndex = active;
        bridge.report(v);
    }
    FakeJausBridge bridge;
    FleetModel fleet;
    FleetSelection selection;
    SiteMapView map;
    MissionPanel* panel = nullptr;
};

bool near(QPointF a, QPointF b, double px = 0.5) {
    return std::hypot(a.x() - b.x(), a.y() - b.y()) <= px;
}

} // namespace

class TestMissionPanel : public QObject {
    Q_OBJECT
private slots:
    void clicksAddDragMovesLegInsertsAndKeysDelete() {
        Rig r;
        click(&r.map, {100, 100}); // not editing: the map's own click, no waypoint
        QCOMPARE(r.plan()->size(), 0);
        r.panel->button(MissionPanel::Action::Edit)->click();
        QVERIFY(r.panel->editor()->isEditing());
        click(&r.map, {100, 100});
        click(&r.map, {300, 100});
        click(&r.map, {300, 300});
        QCOMPARE(r.plan()->size(), 3);
        QVERIFY(near(r.at(0), {100, 100}));
        QVERIFY(near(r.at(2), {300, 300}));
        // The platform's defaults: half of 2 m/s, one vehicle length of 1.5 m.
        QCOMPARE(r.plan()->at(0).speed, 1.0);
        QCOMPARE(r.plan()->at(0).tolerance, 1.5);
        QCOMPARE(r.panel->table()->model()->rowCount(), 3);

        // Drag the second waypoint: one undo step for the whole drag.
        const int steps = r.plan()->undoStack()->count();
        drag(&r.map, {300, 100}, {350, 150});
        QVERIFY(near(r.at(1), {350, 150}));
        QCOMPARE(r.plan()->undoStack()->count(), steps + 1);
        QCOMPARE(r.plan()->size(), 3);

        // A click on the leg between the first two inserts a waypoint there.
        const QPointF mid = (r.at(0) + r.at(1)) / 2;
        click(&r.map, mid);
        QCOMPARE(r.plan()->size(), 4);
        QVERIFY(near(r.at(1), mid, 1.0));
        QCOMPARE(r.panel->editor()->selected(), 1);

        // A drag on the ground pans the map and adds nothing.
        const QPointF centre = r.map.center();
        drag(&r.map, {600, 500}, {560, 500});
        QCOMPARE(r.plan()->size(), 4);
        QVERIFY(std::abs(r.map.center().x() - (centre.x() + 20)) < 0.01);

        // Keyboard: Delete removes the selected waypoint, Ctrl+Z brings it back, Ctrl+Shift+Z removes it
        // again.
        r.map.setFocus();
        QTest::keyClick(&r.map, Qt::Key_Delete);
        QCOMPARE(r.plan()->size(), 3);
        QTest::keyClick(&r.map, Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(r.plan()->size(), 4);
        QTest::keyClick(&r.map, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QCOMPARE(r.plan()->size(), 3);
        // Page Down selects the next, Shift+Right moves it 10 px, Insert adds one after it.
        r.panel->editor()->select(0);
        QTest::keyClick(&r.map, Qt::Key_PageDown);
        QCOMPARE(r.panel->editor()->selected(), 1);
        const QPointF before = r.at(1);
        QTest::keyClick(&r.map, Qt::Key_Right, Qt::ShiftModifier);
        QVERIFY(near(r.at(1), before + QPointF(10, 0)));
        QTest::keyClick(&r.map, Qt::Key_Insert);
        QCOMPARE(r.plan()->size(), 4);
        QCOMPARE(r.panel->editor()->selected(), 2);
        // Esc ends editing; the button follows.
        QTest::keyClick(&r.map, Qt::Key_Escape);
        QVERIFY(!r.panel->editor()->isEditing());
        QVERIFY(!r.panel->button(MissionPanel::Action::Edit)->isChecked());
        click(&r.map, {500, 500});
        QCOMPARE(r.plan()->size(), 4);
    }

    void contextMenuOffersGoHereThroughTheSeam() {
        Rig r;
        QMenu none;
        r.panel->editor()->addContextActions(&none, {200, 200});
        QVERIFY(!none.findChild<QAction*>("mission-go-here")); // nothing sends without the seam
        RecordingCommands commands;
        r.panel->setCommands(&commands);
        QMenu menu;
        r.panel->editor()->addContextActions(&menu, {200, 200});
        auto* go = menu.findChild<QAction*>("mission-go-here");
        QVERIFY(go);
        QVERIFY(go->text().contains("UGV-1"));
        go->trigger();
        QCOMPARE(commands.calls, QStringList{"goto jaus:1"});
        QVERIFY(near(r.map.worldToScreen(r.layer()->toEN(commands.goal)), {200, 200}));
        QCOMPARE(commands.goal.speed, 1.0);
        // While editing: add here, and delete over a waypoint.
        r.panel->editor()->setEditing(true);
        QMenu edit;
        r.panel->editor()->addContextActions(&edit, {250, 250});
        edit.findChild<QAction*>("mission-add")->trigger();
        QCOMPARE(r.plan()->size(), 1);
        QMenu del;
        r.panel->editor()->addContextActions(&del, r.at(0));
        del.findChild<QAction*>("mission-delete")->trigger();
        QCOMPARE(r.plan()->size(), 0);
    }

    void commandsGoThroughTheSeamByState() {
        Rig r;
        RecordingCommands commands;
        r.panel->setCommands(&commands);
        using A = MissionPanel::Action;
        QVERIFY(!r.panel->button(A::Upload)->isEnabled()); // nothing planned
        r.plan()->append(r.plan()->makeWaypoint(48.1372, 11.5752));
        r.plan()->append(r.plan()->makeWaypoint(48.1374, 11.5755));
        QVERIFY(r.panel->button(A::Upload)->isEnabled());
        QVERIFY(!r.panel->button(A::Start)->isEnabled());
        r.panel->button(A::Upload)->click();
        QCOMPARE(commands.calls.last(), QString("upload jaus:1"));
        QCOMPARE(commands.uploaded, r.plan()->waypoints());
        r.report(MissionState::Uploaded);
        QVERIFY(r.panel->button(A::Start)->isEnabled());
        r.panel->findChild<QSpinBox*>()->setValue(2);
        r.panel->button(A::Start)->click();
        QCOMPARE(commands.calls.last(), QString("start jaus:1 1"));
        r.report(MissionState::Running, 1);
        QVERIFY(r.panel->button(A::Pause)->isEnabled());
        QVERIFY(!r.panel->button(A::Resume)->isEnabled());
        QVERIFY(!r.panel->button(A::Upload)->isEnabled());
        r.panel->button(A::Pause)->click();
        QCOMPARE(commands.calls.last(), QString("pause jaus:1"));
        r.report(MissionState::Paused, 1);
        r.panel->button(A::Resume)->click();
        QCOMPARE(commands.calls.last(), QString("resume jaus:1"));
        r.panel->button(A::Abort)->click();
        QCOMPARE(commands.calls.last(), QString("abort jaus:1"));
        // A plan changed after the upload is not started: upload again first.
        r.report(MissionState::Uploaded);
        r.plan()->append(r.plan()->makeWaypoint(48.1376, 11.5757));
        QVERIFY(!r.panel->button(A::Start)->isEnabled());
        QVERIFY(r.panel->stateText().contains("differs"));
        // Not ours: nothing is offered.
        JausVehicle v = r.bridge.vehicles.value(1);
        v.mission.state = MissionState::Running;
        v.mission.ours = false;
        r.bridge.report(v);
        QVERIFY(!r.panel->button(A::Pause)->isEnabled());
        QVERIFY(!r.panel->button(A::Abort)->isEnabled());
        QCOMPARE(commands.calls.size(), 5);
    }

    // The JAUS module's seam: typed commands through the command gate to the vehicle's bridge.
    void theGateSeamSendsTypedCommands() {
        Rig r;
        FleetContext ctx;
        ctx.addBridge(&r.bridge);
        r.panel->setCommands(new MissionGateCommands(ctx.gate(), r.panel));
        r.plan()->append(r.plan()->makeWaypoint(48.1372, 11.5752));
        r.plan()->append(r.plan()->makeWaypoint(48.1374, 11.5755));
        r.panel->button(MissionPanel::Action::Upload)->click();
        QTRY_COMPARE(r.bridge.commands.size(), 1);
        const auto* upload = std::get_if<MissionUpload>(&r.bridge.commands[0]);
        QVERIFY(upload);
        QCOMPARE(upload->id, QString("jaus:1"));
        QCOMPARE(upload->waypoints, r.plan()->waypoints());
        r.report(MissionState::Uploaded);
        r.panel->button(MissionPanel::Action::Start)->click();
        QTRY_COMPARE(r.bridge.commands.size(), 2);
        QCOMPARE(std::get<MissionStart>(r.bridge.commands[1]), (MissionStart{"jaus:1", 0}));
        QMenu menu;
        r.panel->editor()->addContextActions(&menu, {200, 200});
        menu.findChild<QAction*>("mission-go-here")->trigger();
        QTRY_COMPARE(r.bridge.commands.size(), 3);
        QVERIFY(std::holds_alternative<GoTo>(r.bridge.commands[2]));
    }

    void withoutTheSeamNothingIsSent() {
        Rig r;
        r.plan()->append(r.plan()->makeWaypoint(48.1372, 11.5752));
        r.report(MissionState::Uploaded);
        using A = MissionPanel::Action;
        for (A a : {A::Upload, A::Start, A::Pause, A::Resume, A::Abort})
            QVERIFY(!r.panel->button(a)->isEnabled());
        auto labels = r.panel->findChildren<QLabel*>();
        QVERIFY(std::any_of(labels.begin(), labels.end(),
                            [](QLabel* l) { return l->isVisible() && l->text().contains("not available"); }));
        QVERIFY(r.panel->button(A::Save)->isEnabled()); // the plan itself works
    }

    void panelShowsEachState_data() {
        QTest::addColumn<int>("state");
        QTest::addColumn<int>("active");
        QTest::addColumn<QString>("reason");
        QTest::addColumn<QString>("says");
        QTest::newRow("none") << int(MissionState::None) << -1 << ""
                              << "Planned: 3 waypoints, not uploaded";
        QTest::newRow("uploading") << int(MissionState::Uploading) << -1 << ""
                                   << "Uploading 3 waypoints";
        QTest::newRow("uploaded") << int(MissionState::Uploaded) << -1 << ""
                                  << "Uploaded and verified: 3 waypoints";
        QTest::newRow("running") << int(MissionState::Running) << 1 << ""
                                 << "Running: waypoint 2 of 3, 120 m to go, ETA 1 min 40 s";
        QTest::newRow("paused") << int(MissionState::Paused) << 1 << ""
                                << "Paused at waypoint 2 of 3";
        QTest::newRow("completed") << int(MissionState::Completed) << 2 << ""
                                   << "Completed: 3 waypoints";
        QTest::newRow("aborted") << int(MissionState::Aborted) << 0 << ""
                                 << "Aborted at waypoint 1 of 3";
        QTest::newRow("emergency")
            << int(MissionState::StoppedByEmergency) << 2 << ""
            << "Stopped by emergency at waypoint 3 of 3; clearing the emergency does not "
               "restart it";
        QTest::newRow("lost") << int(MissionState::Lost) << -1 << "link down"
                              << "Unknown, last seen at waypoint 2 of 3 (link down)";
        QTest::newRow("rejected") << int(MissionState::Rejected) << -1 << "element 2: invalid waypoint"
                                  << "Rejected: element 2: invalid waypoint";
    }
    void panelShowsEachState() {
        QFETCH(int, state);
        QFETCH(int, active);
        QFETCH(QString, reason);
        QFETCH(QString, says);
        Rig r;
        for (int i = 0; i < 3; ++i)
            r.plan()->append(r.plan()->makeWaypoint(48.1372 + i * 1e-4, 11.5752));
        JausVehicle v = r.bridge.vehicles.value(1);
        v.mission.state = MissionState(state);
        if (v.mission.state != MissionState::None)
            v.mission.waypoints = r.plan()->waypoints();
        v.mission.activeIndex = active;
        v.mission.lastSeenIndex = 1;
        v.mission.reason = reason;
        if (v.mission.state == MissionState::Running) {
            v.mission.distanceToGoM = 120;
            v.mission.etaS = 100;
        }
        r.bridge.report(v);
        QVERIFY2(r.panel->stateText().startsWith(says), qPrintable(r.panel->stateText()));
        QVERIFY(!r.panel->stateText().contains("differs"));
    }

    void drivenPathIsDrawnBesideTheRoute() {
        Rig r;
        JausVehicle v = r.bridge.vehicles.value(2);
        v.mission.state = MissionState::Running;
        v.mission.activeIndex = 1;
        const GeoFrame frame(kOrigin);
        for (int i = 0; i < 3; ++i) {
            const GeoPoint g = frame.toGeodetic({i * 40.0, 40.0, 0});
            v.mission.waypoints << MissionWaypoint{g.lat, g.lon, 1, 1};
        }
        for (int i = 0; i <= 10; ++i) {
            const GeoPoint g = frame.toGeodetic({i * 4.0, -40.0, 0});
            v.mission.drivenPath << qMakePair(g.lat, g.lon);
        }
        v.mission.pathSource = QStringLiteral("pose trail");
        r.bridge.report(v);
        QCOMPARE(r.layer()->missions().size(), 1);
        QCOMPARE(r.layer()->missions()[0].subsystem, quint16(2));
        QImage img(800, 600, QImage::Format_ARGB32_Premultiplied);
        img.fill(Qt::white);
        {
            QPainter p(&img);
            r.map.paintScene(p, img.size());
        }
        const QColor driven = MissionPlanLayer::missionColour(2).darker(140);
        const QPoint onPath = r.map.worldToScreen({20, -40}).toPoint();
        QCOMPARE(QColor(img.pixel(onPath)).name(), driven.name());
        const QPoint onRoute = r.map.worldToScreen({20, 40}).toPoint();
        QVERIFY(QColor(img.pixel(onRoute)) != QColor(Qt::white) ||
                QColor(img.pixel(onRoute + QPoint(2, 0))) != QColor(Qt::white)); // dashed
        // The vehicle's report without a mission takes it off the map.
        v.mission = JausMission{};
        r.bridge.report(v);
        QVERIFY(r.layer()->missions().isEmpty());
    }

    void filesFromThePanel() {
        Rig r;
        QTemporaryDir dir;
        r.plan()->append(r.plan()->makeWaypoint(48.1372, 11.5752));
        r.plan()->append(r.plan()->makeWaypoint(48.1374, 11.5755));
        const QVector<MissionWaypoint> saved = r.plan()->waypoints();
        const QString path = dir.filePath("m.geojson");
        QCOMPARE(r.panel->saveFile(path), QString());
        r.plan()->replace({}, "clear");
        QCOMPARE(r.panel->openFile(path), QString());
        QCOMPARE(r.plan()->waypoints(), saved);
        // A bad file: the message names it and the plan stays.
        QFile bad(dir.filePath("bad.geojson"));
        QVERIFY(bad.open(QIODevice::WriteOnly));
        bad.write("{ not json");
        bad.close();
        QVERIFY(!r.panel->openFile(bad.fileName()).isEmpty());
        QVERIFY(r.panel->messageText().contains("bad.geojson"));
        QCOMPARE(r.plan()->waypoints(), saved);
        QVERIFY(!r.panel->importFile(dir.filePath("none.gpx")).isEmpty());
        QCOMPARE(r.plan()->waypoints(), saved);
        // Import: the vehicle's defaults for speed and tolerance.
        QFile gpx(dir.filePath("r.gpx"));
        QVERIFY(gpx.open(QIODevice::WriteOnly));
        gpx.write("<?xml version=\"1.0\"?><gpx version=\"1.1\" creator=\"t\" "
                  "xmlns=\"http://www.topografix.com/GPX/1/1\">\n"
                  "<rte><rtept lat=\"48.1371\" lon=\"11.5751\"/><rtept lat=\"48.1373\" "
                  "lon=\"11.5753\"/><rtept lat=\"48.1375\" lon=\"11.5751\"/></rte></gpx>");
        gpx.close();
        QCOMPARE(r.panel->importFile(gpx.fileName()), QString());
        QCOMPARE(r.plan()->size(), 3);
        QCOMPARE(r.plan()->at(2).speed, 1.0);
        r.plan()->undo();
        QCOMPARE(r.plan()->waypoints(), saved);
    }

    void tableEditsAreUndoSteps() {
        Rig r;
        r.plan()->append(r.plan()->makeWaypoint(48.1372, 11.5752));
        QAbstractItemModel* m = r.panel->table()->model();
        QVERIFY(m->setData(m->index(0, MissionPlanTableModel::Speed), 2.5, Qt::EditRole));
        QCOMPARE(r.plan()->at(0).speed, 2.5);
        QVERIFY(!m->setData(m->index(0, MissionPlanTableModel::Tolerance), -1, Qt::EditRole));
        QVERIFY(!m->setData(m->index(0, MissionPlanTableModel::Latitude), 91, Qt::EditRole));
        QVERIFY(m->setData(m->index(0, MissionPlanTableModel::Longitude), 11.5, Qt::EditRole));
        QCOMPARE(r.plan()->at(0).lon, 11.5);
        QCOMPARE(m->index(0, MissionPlanTableModel::Longitude).data().toString(), QString("11.5000000"));
        QApplication::setActiveWindow(r.panel);
        QVERIFY(QTest::qWaitForWindowActive(r.panel));
        r.panel->table()->setFocus();
        QTest::keyClick(r.panel->table(), Qt::Key_Z, Qt::ControlModifier); // the panel's shortcut
        QCOMPARE(r.plan()->at(0).lon, 11.5752);
        QCOMPARE(r.plan()->at(0).speed, 2.5); // one step back only
    }

    void eachVehicleHasItsOwnPlanAndTheSelectionChoosesIt() {
        Rig r;
        r.plan()->append(r.plan()->makeWaypoint(48.1372, 11.5752));
        r.panel->setVehicle(2);
        QCOMPARE(r.plan()->size(), 0);
        QCOMPARE(r.layer()->plan(), r.plan());
        r.panel->setVehicle(1);
        QCOMPARE(r.plan()->size(), 1);
        QSignalSpy route(r.panel, &MissionPanel::planRouteChanged);
        r.plan()->append(r.plan()->makeWaypoint(48.1374, 11.5752));
        QTRY_COMPARE(route.size(), 1); // the 3D route, coalesced
        QCOMPARE(route.last().at(0).value<QVector<MissionWaypoint>>().size(), 2);
    }
};

QTEST_MAIN(TestMissionPanel)
#include "test_mission_panel.moc"
