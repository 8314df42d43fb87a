// The dispatch panel and the route on the 2D map, with a hand-made dispatch source and a fake
// bridge behind a real CommandGate. The keyboard path (F6 to the truck asking for work, Alt+D destination,
// Ctrl+Enter assign, re-assign and reset asking first, Alt+R), what reaches the gate and the per-target
// result shown; picking the destination by clicking an area on the map (selection untouched); the route's
// geometry over a known map, and that the map draws it.
#include "models/AlarmModel.h"
#include "models/AutoDispatcher.h"
#include "models/CommandGate.h"
#include "models/FleetModel.h"
#include "models/FleetSelection.h"
#include "models/testing/FakeDispatchSource.h"
#include "models/testing/FakeFleetBridge.h"
#include "widgets/SiteMapView.h"
#include "widgets/dispatch/CachedTextDelegate.h"
#include "widgets/dispatch/DispatchPanel.h"
#include "widgets/dispatch/RouteOverlay2D.h"

#include <QComboBox>
#include <QHeaderView>
#include <QJsonArray>
#include <QLabel>
#include <QPainter>
#include <QPushButton>
#include <QSplitter>
#include <QTableView>
#include <QtTest>

using namespace ocu;

namespace {

DispatchTruck truck(const QString& n) {
    DispatchTruck t;
    t.id = QStringLiteral("iso23725:") + n;
    t.link = QStringLiteral("ahs");
    t.name = n;
    t.stateKnown = true;
    t.custodian = QStringLiteral("FMS");
    t.wayId = 1;
    return t;
}

const QString kLink = QStringLiteral("ahs");

// A known map: the park area west of the origin, road 1 east to (100,0), road 2 drawn from (100,100) down to
// (100,0) (against the driving direction), the crusher area around (100,150), the shovel far east.
SiteMapData knownMap() {
    SiteMapData map;
    auto feature = [](qint64 way, MapFeatureKind kind, QVector<QPointF> pts, const QString& task = {}) {
        MapFeature f;
        f.id = kLink + QLatin1Char('/') + QString::number(way);
        f.kind = kind;
        f.points = std::move(pts);
        f.defaultTask = task;
        return f;
    };
    map.features << feature(30, MapFeatureKind::Area, {{-60, -10}, {-40, -10}, {-40, 10}, {-60, 10}}, "park");
    map.features << feature(1, MapFeatureKind::Road, {{0, 0}, {100, 0}});
    map.features << feature(2, MapFeatureKind::Road, {{100, 100}, {100, 50}, {100, 0}});
    map.features << feature(20, MapFeatureKind::Area, {{90, 140}, {110, 140}, {110, 160}, {90, 160}}, "dump");
    map.features << feature(10, MapFeatureKind::Area, {{300, -10}, {320, -10}, {320, 10}, {300, 10}}, "load");
    map.revision = 1;
    return map;
}

struct Rig {
    Rig() {
        gate.addBridge(&bridge);
        src.setAreas({{kLink, 10, QStringLiteral("Shovel A"), QStringLiteral("Load")},
                      {kLink, 20, QStringLiteral("Crusher"), QStringLiteral("Offload")},
                      {kLink, 30, QStringLiteral("Park 1"), QStringLiteral("Park")}});
        DispatchTruck t2 = truck("T2");
        t2.needsAssignment = true;
        DispatchTruck t3 = truck("T3");
        t3.assignmentId = QStringLiteral("a3");
        t3.assignmentStatus = QStringLiteral("Active");
        t3.task = QStringLiteral("Offload");
        t3.destinationId = 20;
        t3.destinationName = QStringLiteral("Crusher");
        t3.wayId = 30;
        src.routes.insert(t3.id, DispatchRoute{kLink, {30, 1, 2, 20}, 200.0, {}, false});
        src.setTrucks({truck("T1"), t2, t3});
        for (const char* n : {"T1", "T2", "T3"}) {
            MachineState m;
            m.id = QStringLiteral("iso23725:") + QLatin1String(n);
            m.protocol = Protocol::Iso23725;
            m.name = QLatin1String(n);
            fleet.upsert({m});
        }
        panel.setConfirm([this](const QString& title, const QString&) {
            questions << title;
            return answer;
        });
        panel.resize(1100, 420);
        panel.show();
        QApplication::setActiveWindow(&panel);
    }
    AlarmModel alarms;
    CommandGate gate{&alarms};
    FakeFleetBridge bridge{Protocol::Iso23725};
    FleetModel fleet;
    FleetSelection selection{&fleet};
    FakeDispatchSource src;
    DispatchPanel panel{&src, &gate, &selection};
    QStringList questions;
    bool answer = true;

    QVector<FakeFleetBridge::Call> calls(const QString& name) const {
        QVector<FakeFleetBridge::Call> out;
        for (const auto& c : bridge.calls())
            if (c.name == name)
                out << c;
        return out;
    }
};

} // namespace

class TestDispatchPanel : public QObject {
    Q_OBJECT
private slots:
    // The table's delegate draws what a text cell shows — the text (elided when the column is narrow), the
    // background and foreground roles, the selection — and lays each distinct text out once.
    void cachedTextDelegatePaintsCells() {
        FakeDispatchSource src;
        QVector<DispatchTruck> trucks;
        for (int i = 0; i < 30; ++i) {
            DispatchTruck t = truck(QStringLiteral("T%1").arg(i, 2, 10, QLatin1Char('0')));
            t.productionState = i % 2 ? QStringLiteral("Hauling") : QStringLiteral("Loading");
            t.needsAssignment = i == 1;
            trucks << t;
        }
        src.setTrucks(trucks, false);
        DispatchPanel panel(&src, nullptr, nullptr);
        panel.resize(1200, 600);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        QTableView* table = panel.table();
        auto* delegate = qobject_cast<CachedTextDelegate*>(table->itemDelegate());
        QVERIFY(delegate);
        table->clearSelection();
        table->setCurrentIndex({});
        const QImage img = table->viewport()->grab().toImage();
        // Row 0 (not selected, no cue): the truck cell has dark text pixels on the light base.
        const QRect name = table->visualRect(panel.model()->index(0, DispatchModel::ColTruck));
        const QRect prod = table->visualRect(panel.model()->index(0, DispatchModel::ColProduction));
        auto inkIn = [&](const QRect& r) {
            int ink = 0;
            for (int y = r.top(); y <= r.bottom(); ++y)
                for (int x = r.left(); x <= r.right(); ++x)
                    ink += qGray(img.pixel(x, y)) < 128;
            return ink;
        };
        QVERIFY(inkIn(name) > 10);
        QVERIFY(inkIn(prod) > 10);
        // Row 1 asks for work: its cells have the amber background of the cue.
        const QRect cue = table->visualRect(panel.model()->index(1, DispatchModel::ColMode));
        QCOMPARE(QColor(img.pixel(cue.right() - 2, cue.center().y())), QColor(0xff, 0xd5, 0x4f));
        // 30 names + a handful of shared texts ("Loading", "Hauling", "FMS", "—"...) laid out, not 30 x 10.
        QVERIFY2(delegate->cachedTexts() < 60, qPrintable(QString::number(delegate->cachedTexts())));
        const int cached = delegate->cachedTexts();
        table->viewport()->repaint();
        QCOMPARE(delegate->cachedTexts(), cached); // a repaint lays nothing out again
        // A narrow column: the text is elided, not cut or overflowing into the next cell.
        table->setColumnWidth(DispatchModel::ColAssignment, 40);
        table->viewport()->grab(); // paints
        const QRect a = table->visualRect(panel.model()->index(1, DispatchModel::ColAssignment));
        const QRect next = table->visualRect(panel.model()->index(1, DispatchModel::ColTask));
        QVERIFY(a.width() <= 41 && next.left() > a.right());
        QVERIFY(delegate->cachedTexts() > cached); // the elided "NEEDS ASSIGNMENT" is its own layout
    }

    // A laptop's side column (600 px): the queues go below the trucks and neither table scrolls sideways,
    // their columns elided (the truck's name whole); wide again, the queues are beside the trucks at their
    // columns' widths.
    void narrowPanelTablesDoNotScrollSideways() {
        Rig r;
        QVERIFY(QTest::qWaitForWindowExposed(&r.panel));
        auto* split = r.panel.findChild<QSplitter*>();
        QVERIFY(split);
        const int truckWidth = r.panel.table()->columnWidth(DispatchModel::ColTruck);
        const auto fits = [&] {
            for (QTableView* t : {r.panel.table(), r.panel.queueTable()})
                if (t->horizontalHeader()->length() > t->viewport()->width())
                    return false;
            return true;
        };
        r.panel.resize(600, 420);
        QTRY_COMPARE(split->orientation(), Qt::Vertical);
        QTRY_VERIFY(fits());
        QCOMPARE(r.panel.table()->columnWidth(DispatchModel::ColTruck), truckWidth);
        QVERIFY(r.panel.table()->columnWidth(DispatchModel::ColAssignment) <
                r.panel.table()->fontMetrics().horizontalAdvance(QStringLiteral("NEEDS ASSIGNMENT")));
        r.panel.resize(1800, 420);
        QTRY_COMPARE(split->orientation(), Qt::Horizontal);
        QTRY_VERIFY(fits());
        QTRY_VERIFY(r.panel.table()->columnWidth(DispatchModel::ColAssignment) >
                    r.panel.table()->fontMetrics().horizontalAdvance(QStringLiteral("NEEDS ASSIGNMENT")));
    }

    // The automatic dispatcher's switch in the panel: hidden without one; switching on asks
    // first (No leaves it off); on, the line says so and what it did last; the state follows a switch from
    // elsewhere (the headless command); off stops it.
    void autoDispatchSwitch() {
        Rig r;
        QVERIFY(!r.panel.autoButton()->isVisible());
        AutoDispatcher dispatcher(&r.src, &r.gate);
        r.panel.setAutoDispatcher(&dispatcher);
        QVERIFY(r.panel.autoButton()->isVisible());
        QVERIFY(!r.panel.autoLabel()->isVisible());
        r.answer = false;
        r.panel.autoButton()->click();
        QCOMPARE(r.questions.size(), 1);
        QVERIFY(!dispatcher.isOn());
        QVERIFY(!r.panel.autoButton()->isChecked());
        r.answer = true;
        r.panel.autoButton()->click();
        QVERIFY(dispatcher.isOn());
        QVERIFY(r.panel.autoButton()->isChecked());
        QVERIFY(r.panel.autoButton()->text().contains(QStringLiteral("ON")));
        // T1 (no task) and T2 (asks for work) go to the only shovel; the line shows the last one.
        QTRY_VERIFY(r.calls(QStringLiteral("assign")).size() == 2);
        QTRY_VERIFY2(r.panel.autoLabel()->text().contains(QStringLiteral("Auto dispatch ON — last:")) &&
                         r.panel.autoLabel()->text().contains(QStringLiteral("Load at Shovel A")),
                     qPrintable(r.panel.autoLabel()->text()));
        QVERIFY(r.panel.autoLabel()->isVisible());
        // Switched off elsewhere (the headless command): the panel follows.
        dispatcher.setOn(false, QStringLiteral("headless"));
        QVERIFY(!r.panel.autoButton()->isChecked());
        QVERIFY(r.panel.autoLabel()->text().contains(QStringLiteral("Auto dispatch OFF (headless)")));
        QCOMPARE(r.questions.size(), 2); // switching off never asks
    }

    void keyboardPath() {
        Rig r;
        QVERIFY(QTest::qWaitForWindowActive(&r.panel));
        QCOMPARE(r.panel.model()->rowCount(), 3);
        QVERIFY(r.panel.toolTip().contains(QStringLiteral("F6")));
        // The cue: one truck asks for work; F6 goes to it.
        QVERIFY(r.panel.findChild<QLabel*>(QStringLiteral("label-needs-assignment"))
                    ->text()
                    .contains(QStringLiteral("1 truck")));
        r.panel.table()->setFocus();
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_F6);
        QCOMPARE(r.panel.currentTruck(), QStringLiteral("iso23725:T2"));
        QCOMPARE(r.selection.currentId(), QStringLiteral("iso23725:T2")); // the map and 3D follow the table
        // Alt+D: the destination list; Down picks the crusher, whose task (Offload) comes with it.
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_D, Qt::AltModifier);
        QCOMPARE(QApplication::focusWidget(), r.panel.destinationBox());
        QCOMPARE(r.panel.destinationBox()->currentText(), QStringLiteral("Shovel A — Load"));
        QCOMPARE(r.panel.taskBox()->currentText(), QStringLiteral("Load"));
        QTest::keyClick(r.panel.destinationBox(), Qt::Key_Down);
        QCOMPARE(r.panel.destinationBox()->currentText(), QStringLiteral("Crusher — Offload"));
        QCOMPARE(r.panel.taskBox()->currentText(), QStringLiteral("Offload"));
        // Ctrl+Enter: assign through the gate (no question: the truck has no task).
        QVERIFY(r.panel.assignButton()->isEnabled());
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_Return, Qt::ControlModifier);
        QTRY_COMPARE(r.calls(QStringLiteral("assign")).size(), 1);
        QVERIFY(r.questions.isEmpty());
        const auto call = r.calls(QStringLiteral("assign")).first();
        QCOMPARE(call.id, QStringLiteral("iso23725:T2"));
        const QJsonObject task = call.args.value(QStringLiteral("tasks")).toArray().first().toObject();
        QCOMPARE(task.value(QStringLiteral("task")).toString(), QStringLiteral("Offload"));
        QCOMPARE(task.value(QStringLiteral("destination")).toInt(), 20);
        QTRY_VERIFY(r.panel.resultLabel()->text().contains(QStringLiteral("T2: sent")));
        // The truck's answer follows on the same line.
        DispatchTruck t2 = truck("T2");
        t2.requestedAssignmentId = task.value(QStringLiteral("assignment_id")).toString();
        t2.lastResponse = QStringLiteral("Rejected");
        t2.lastResponseDetail = QStringLiteral("destination 20 is closed");
        r.src.setTrucks({t2});
        QVERIFY(r.panel.resultLabel()->text().contains(QStringLiteral("Rejected: destination 20 is closed")));

        // Down to T3 (it has an Active task): re-assigning asks first; "No" sends nothing.
        r.panel.table()->setFocus();
        QTest::keyClick(r.panel.table(), Qt::Key_Down);
        QCOMPARE(r.panel.currentTruck(), QStringLiteral("iso23725:T3"));
        QCOMPARE(r.panel.assignButton()->text(), QStringLiteral("Re-&assign"));
        r.answer = false;
        QTest::keyClick(r.panel.table(), Qt::Key_Return, Qt::ControlModifier);
        QCOMPARE(r.questions.size(), 1);
        QVERIFY(r.questions.first().contains(QStringLiteral("Re-assign T3")));
        QTest::qWait(50);
        QCOMPARE(r.calls(QStringLiteral("assign")).size(), 1);
        r.answer = true;
        QTest::keyClick(r.panel.table(), Qt::Key_Return, Qt::ControlModifier);
        QTRY_COMPARE(r.calls(QStringLiteral("assign")).size(), 2);
        QCOMPARE(r.calls(QStringLiteral("assign")).last().id, QStringLiteral("iso23725:T3"));
        // Alt+R: reset, after the question.
        QVERIFY(r.panel.resetButton()->isEnabled());
        QTest::keyClick(r.panel.table(), Qt::Key_R, Qt::AltModifier);
        QTRY_COMPARE(r.questions.size(), 3); // a button's mnemonic clicks it after a short animation
        QTRY_COMPARE(r.calls(QStringLiteral("reset_assignment")).size(), 1);
        QCOMPARE(r.calls(QStringLiteral("reset_assignment")).first().id, QStringLiteral("iso23725:T3"));
        QTRY_VERIFY(r.panel.resultLabel()->text().contains(QStringLiteral("Reset T3: T3: sent")));

        // A truck the source refuses: the controls say why and Assign is disabled.
        r.src.refusals.insert(QStringLiteral("iso23725:T1"),
                              QStringLiteral("assignment refused: T1 is dispatched by the AHS"));
        QTest::keyClick(r.panel.table(), Qt::Key_Home, Qt::ControlModifier);
        QCOMPARE(r.panel.currentTruck(), QStringLiteral("iso23725:T1"));
        QVERIFY(!r.panel.assignButton()->isEnabled());
        QVERIFY(r.panel.refusalLabel()->isVisible());
        QVERIFY(r.panel.refusalLabel()->text().contains(QStringLiteral("dispatched by the AHS")));
    }

    void pickDestinationOnTheMap() {
        Rig r;
        SiteMapView map;
        map.setFleet(&r.fleet, &r.selection);
        // Not shown (the panel stays the active window for its shortcuts): sized by one paint.
        map.resize(800, 600);
        map.setSiteMap(knownMap());
        map.setView(QPointF(100, 50), 2.0);
        {
            QImage img(800, 600, QImage::Format_ARGB32_Premultiplied);
            QPainter p(&img);
            map.paintScene(p, img.size());
        }
        r.panel.setMap(&map);
        r.panel.setCurrentTruck(QStringLiteral("iso23725:T1"));
        r.selection.setCurrent(QStringLiteral("iso23725:T1"));
        QVERIFY(QTest::qWaitForWindowActive(&r.panel));
        // Alt+M: pick on the map; the map takes a click on an area and leaves the selection alone.
        r.panel.table()->setFocus();
        QTest::keyClick(r.panel.table(), Qt::Key_M, Qt::AltModifier);
        QTRY_VERIFY(r.panel.pickButton()->isChecked());
        QVERIFY(map.isAreaPicking());
        QSignalSpy clicked(&map, &SiteMapView::areaClicked);
        const QPoint crusher = map.worldToScreen(QPointF(100, 150)).toPoint();
        QCOMPARE(map.areaAt(crusher), QStringLiteral("ahs/20"));
        QTest::mouseClick(&map, Qt::LeftButton, {}, crusher);
        QCOMPARE(clicked.size(), 1);
        QCOMPARE(r.panel.destinationBox()->currentText(), QStringLiteral("Crusher — Offload"));
        QCOMPARE(r.panel.taskBox()->currentText(), QStringLiteral("Offload"));
        QVERIFY(!r.panel.pickButton()->isChecked());
        QVERIFY(!map.isAreaPicking());
        QCOMPARE(r.selection.currentId(), QStringLiteral("iso23725:T1"));
        QCOMPARE(r.panel.currentTruck(), QStringLiteral("iso23725:T1"));
        // Esc cancels a pick.
        QTest::keyClick(r.panel.table(), Qt::Key_M, Qt::AltModifier);
        QTRY_VERIFY(map.isAreaPicking());
        QTest::keyClick(r.panel.table(), Qt::Key_Escape);
        QVERIFY(!map.isAreaPicking());
        // Outside the pick mode a click on an area selects as before (nothing emitted).
        QTest::mouseClick(&map, Qt::LeftButton, {}, crusher);
        QCOMPARE(clicked.size(), 1);
    }

    void routeGeometryOverAKnownMap() {
        const SiteMapData map = knownMap();
        QVector<qint64> missing;
        // Park area (centroid), road 1 as drawn, road 2 turned to continue at (100,0), crusher centroid.
        const QVector<QPointF> path = routePath(map, kLink, {30, 1, 2, 20}, &missing);
        QCOMPARE(path, QVector<QPointF>({{-50, 0}, {0, 0}, {100, 0}, {100, 50}, {100, 100}, {100, 150}}));
        QVERIFY(missing.isEmpty());
        // A route starting on a road turns it toward the next way; unknown ways are reported, not drawn.
        QCOMPARE(routePath(map, kLink, {2, 1, 77}, &missing),
                 QVector<QPointF>({{100, 100}, {100, 50}, {100, 0}, {0, 0}}));
        QCOMPARE(missing, QVector<qint64>({77}));
        QVERIFY(routePath(map, QStringLiteral("other"), {1, 2}).isEmpty());

        // The panel draws the current truck's route on the map, and a preview for a truck without a task.
        Rig r;
        SiteMapView view;
        view.setFleet(&r.fleet, &r.selection);
        view.setSiteMap(map);
        view.setView(QPointF(100, 50), 2.0);
        view.setLayerVisible(SiteMapView::LayerLegend, false);
        r.panel.setMap(&view);
        QSignalSpy routed(&r.panel, &DispatchPanel::routeChanged);
        r.panel.setCurrentTruck(QStringLiteral("iso23725:T3"));
        QVERIFY(!routed.isEmpty());
        QCOMPARE(routed.last()[1].value<QVector<qint64>>(), QVector<qint64>({30, 1, 2, 20}));
        QCOMPARE(r.panel.routeOverlay()->path(), path);
        QVERIFY(!r.panel.routeOverlay()->isPreview());
        QImage img(800, 600, QImage::Format_ARGB32_Premultiplied);
        img.fill(Qt::white);
        {
            QPainter p(&img);
            view.paintScene(p, img.size());
        }
        const QColor onRoute = img.pixelColor(view.worldToScreen(QPointF(50, 0)).toPoint());
        QVERIFY2(onRoute.red() > 100 && onRoute.blue() > 130 && onRoute.green() < 80,
                 qPrintable(onRoute.name()));
        // The line is kept in the map's cached static layer: the next frame draws it without redrawing
        // the layer, and the same pixels are there.
        const QImage first = img.copy();
        img.fill(Qt::white);
        {
            QPainter p(&img);
            view.paintScene(p, img.size());
        }
        QVERIFY(!view.lastFrame().staticRebuilt);
        QCOMPARE(img, first);
        // T1 has no task: the route it would drive to the chosen destination, dashed.
        r.src.previews.insert(QStringLiteral("iso23725:T1/10"),
                              DispatchRoute{kLink, {1, 10}, 300, {}, false});
        r.panel.setCurrentTruck(QStringLiteral("iso23725:T1"));
        QCOMPARE(r.panel.destinationBox()->currentText(), QStringLiteral("Shovel A — Load"));
        // Only while the panel is in front of the dispatcher (another workspace's map shows no preview).
        r.panel.hide();
        QTRY_VERIFY(r.panel.routeOverlay()->path().isEmpty());
        r.panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&r.panel));
        QTRY_VERIFY(r.panel.routeOverlay()->isPreview());
        QCOMPARE(r.panel.routeOverlay()->path(), QVector<QPointF>({{0, 0}, {100, 0}, {310, 0}}));
        // Another route redraws the layer: the old line (road 2, north of x=100) is gone, the new one there.
        {
            QPainter p(&img);
            view.paintScene(p, img.size());
        }
        QVERIFY(view.lastFrame().staticRebuilt);
        const QColor oldLine = img.pixelColor(view.worldToScreen(QPointF(100, 120)).toPoint());
        QVERIFY2(oldLine.green() > 150, qPrintable(oldLine.name()));
        const QColor newLine = img.pixelColor(view.worldToScreen(QPointF(200, 0)).toPoint());
        QVERIFY2(newLine.red() > 100 && newLine.blue() > 130 && newLine.green() < 80,
                 qPrintable(newLine.name()));
    }
};

QTEST_MAIN(TestDispatchPanel)
#include "test_dispatch_panel.moc"
