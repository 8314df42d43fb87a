// SiteMapView offscreen: pixels of machines, pass-count overlay and roads at their projected positions;
// selection shared with the fleet list; pan/zoom/follow.
#include "models/FleetFilterProxy.h"
#include "models/FleetModel.h"
#include "models/FleetSelection.h"
#include "models/PassCountLayer.h"
#include "widgets/FleetListWidget.h"
#include "widgets/SiteMapView.h"

#include <QItemSelectionModel>
#include <QPainter>
#include <QSignalSpy>
#include <QTableView>
#include <QTest>

using namespace ocu;

namespace {
MachineState machine(const QString& id, double e, double n, double heading = 0) {
    MachineState m;
    m.id = id;
    m.protocol = protocolOfId(id);
    m.name = id;
    m.type = QStringLiteral("haul truck");
    m.link = LinkState::Up;
    m.hasPosition = true;
    m.e = e;
    m.n = n;
    m.headingDeg = heading;
    m.length = 10;
    m.width = 5;
    m.stop = StopState::None;
    m.health = HealthLevel::Ok;
    m.mode = ModeCategory::Manual;
    return m;
}

bool near(QColor a, QColor b, int tol = 6) {
    return std::abs(a.red() - b.red()) <= tol && std::abs(a.green() - b.green()) <= tol &&
           std::abs(a.blue() - b.blue()) <= tol;
}

QString describe(QColor c) {
    return c.name();
}
} // namespace

class TestSiteMap : public QObject {
    Q_OBJECT
private:
    FleetModel* fleet = nullptr;
    FleetSelection* selection = nullptr;
    GridPassCountLayer* pass = nullptr;

private slots:
    void init() {
        fleet = new FleetModel(this);
        fleet->setRefreshIntervalMs(0);
        selection = new FleetSelection(fleet, this);
        pass = new GridPassCountLayer({-100, -100}, 1.0, 200, 200);
        pass->fillRect(QRect(50, 50, 10, 10), 4); // E,N in [-50,-40)
    }
    void cleanup() {
        delete selection;
        delete fleet;
        delete pass;
    }

    void screenshotShowsRoadsMachinesAndPassCounts() {
        MachineState ok = machine(QStringLiteral("jaus:1"), 20, 0);
        MachineState stopped = machine(QStringLiteral("iso23725:T2"), -20, 0, 90);
        stopped.stop = StopState::Stopped;
        MachineState autonomous = machine(QStringLiteral("osyris:3"), 0, -20);
        autonomous.mode = ModeCategory::Autonomous;
        fleet->upsert({ok, stopped, autonomous});

        SiteMapData map;
        map.features.push_back({QStringLiteral("r1"),
                                QStringLiteral("Haul road"),
                                MapFeatureKind::Road,
                                QStringLiteral("haul"),
                                true,
                                {{-100, 30}, {100, 30}},
                                8});
        SiteMapView view;
        view.resize(800, 600);
        view.setFleet(fleet, selection);
        view.setSiteMap(map);
        view.setPassCountLayer(pass);
        view.setLayerVisible(SiteMapView::LayerCursor, false);
        view.setView({0, 0}, 4.0);
        const QImage img = view.grab().toImage();
        QCOMPARE(img.size(), QSize(800, 600));

        // Machine jaus:1 (heading north): 12 px behind its centre is inside its 40x20 px footprint.
        QPointF c = view.worldToScreen({20, 0});
        QColor px = img.pixelColor(c.toPoint() + QPoint(0, 12));
        QVERIFY2(near(px, statusColor(StatusCategory::Ok)), qPrintable(describe(px)));
        // Stopped machine heading east: 12 px behind is to the west of its centre; it is red.
        c = view.worldToScreen({-20, 0});
        px = img.pixelColor(c.toPoint() + QPoint(-12, 0));
        QVERIFY2(near(px, statusColor(StatusCategory::FaultOrStopped)), qPrintable(describe(px)));
        c = view.worldToScreen({0, -20});
        px = img.pixelColor(c.toPoint() + QPoint(0, 12));
        QVERIFY2(near(px, statusColor(StatusCategory::Autonomous)), qPrintable(describe(px)));

        // Pass-count patch: 4 passes in the discrete TRex palette (olive).
        const QPoint patch = view.worldToScreen({-45, -45}).toPoint();
        px = img.pixelColor(patch);
        QVERIFY2(near(px, passCountDiscreteColor(4), 0), qPrintable(describe(px)));
        // Outside the patch: no overlay (background).
        px = img.pixelColor(view.worldToScreen({-60, -60}).toPoint());
        QVERIFY2(!near(px, passCountDiscreteColor(4), 30), qPrintable(describe(px)));

        // The road (8 m wide, 32 px): 6 px off its centre line is road surface in the haul colour.
        const QPoint road = view.worldToScreen({50, 30}).toPoint() + QPoint(0, 6);
        px = img.pixelColor(road);
        QVERIFY2(near(px, taskColor(QStringLiteral("haul")).lighter(150)), qPrintable(describe(px)));

        // Summary palette: 4 passes is within the 3-5 target (YellowGreen).
        view.setPassPalette(PassPalette::Summary);
        const QImage img2 = view.grab().toImage();
        px = img2.pixelColor(patch);
        QVERIFY2(near(px, passCountSummaryColor(4, {3, 5}), 0), qPrintable(describe(px)));
        view.setPassTarget({5, 8});
        px = view.grab().toImage().pixelColor(patch);
        QVERIFY2(near(px, QColor(0x1E, 0x90, 0xFF), 0), qPrintable(describe(px)));

        // Pass-count edits show after passCountChanged().
        pass->fillRect(QRect(50, 50, 10, 10), 12);
        view.passCountChanged();
        px = view.grab().toImage().pixelColor(patch);
        QVERIFY2(near(px, QColor(0xFF, 0, 0), 0), qPrintable(describe(px)));

        // Layer switch: machines off -> the footprint pixel is no longer green.
        view.setLayerVisible(SiteMapView::LayerMachines, false);
        c = view.worldToScreen({20, 0});
        px = view.grab().toImage().pixelColor(c.toPoint() + QPoint(0, 12));
        QVERIFY2(!near(px, statusColor(StatusCategory::Ok), 20), qPrintable(describe(px)));
    }

    void staleMachineTurnsGreyOnTheMap() {
        auto clock = std::make_shared<ManualModelClock>(10'000'000);
        fleet->setClock(clock);
        MachineState m = machine(QStringLiteral("jaus:9"), 0, 0);
        m.lastDataMs = clock->nowMs();
        fleet->upsert({m});
        SiteMapView view;
        view.resize(400, 300);
        view.setFleet(fleet, selection);
        view.setView({0, 0}, 4.0);
        QImage img = view.grab().toImage();
        QPoint p = view.worldToScreen({0, 0}).toPoint() + QPoint(0, 12);
        QVERIFY(near(img.pixelColor(p), statusColor(StatusCategory::Ok)));
        clock->advance(10000);
        fleet->refresh();
        img = view.grab().toImage();
        // Stale: the symbol turns grey and is drawn faded.
        QVERIFY2(img.pixelColor(p).hsvSaturation() < 40 &&
                     !near(img.pixelColor(p), statusColor(StatusCategory::Ok), 40),
                 qPrintable(describe(img.pixelColor(p))));
    }

    // Repaints caused by data are coalesced to the capped rate; the operator's own actions
    // repaint at once.
    void dataRepaintsAreCoalescedToTheCappedRate() {
        fleet->upsert({machine(QStringLiteral("jaus:1"), 0, 0)});
        SiteMapView view;
        view.resize(400, 300);
        view.setFleet(fleet, selection);
        view.setView({0, 0}, 2.0);
        QCOMPARE(view.maxDataFrameRate(), 10.0); // the default: the fastest data rate
        view.setMaxDataFrameRate(1.0 / 3600);    // one data-driven frame an hour: none during this test
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        QTRY_VERIFY(view.framesPainted() > 0);
        QCoreApplication::processEvents();
        const int f0 = view.framesPainted();
        for (int i = 1; i <= 30; ++i) {
            fleet->upsert({machine(QStringLiteral("jaus:1"), i, 0)});
            QCoreApplication::processEvents();
        }
        QCOMPARE(view.framesPainted(), f0);
        // A zoom (the operator) paints at once, and shows the latest data.
        view.zoomBy(1.25, {200, 150});
        QTRY_COMPARE(view.framesPainted(), f0 + 1);
        // No cap: the pending frame is painted, and every later change paints.
        view.setMaxDataFrameRate(0);
        QTRY_VERIFY(view.framesPainted() > f0 + 1);
        QCoreApplication::processEvents();
        const int f1 = view.framesPainted();
        fleet->upsert({machine(QStringLiteral("jaus:1"), 50, 0)});
        QTRY_VERIFY(view.framesPainted() > f1);
    }

    // Hundreds of trails are rasterised straight into a copy of the static layer; they are where
    // the machines drove, and the static layer itself stays clean (they vanish with their machines).
    void manyTrailsAreDrawnWhereTheMachinesDrove() {
        SiteMapView view;
        view.resize(400, 600);
        view.setFleet(fleet, selection); // trails are collected from here on
        QVector<MachineState> ms;
        for (int i = 0; i < 250; ++i)
            ms.push_back(machine(QStringLiteral("iso23725:T%1").arg(i), -100, i * 2.0, 90));
        for (int k = 0; k <= 50; ++k) { // eastwards from E -100 to E 0
            for (MachineState& m : ms)
                m.e = -100 + 2.0 * k;
            fleet->upsert(ms);
        }
        view.setLayerVisible(SiteMapView::LayerMachines, false); // nothing on top of the trails
        view.setView({0, 249}, 1.0);                             // whole pixels: E -50 is x 150
        QImage img(400, 600, QImage::Format_RGB32);
        auto paint = [&] {
            QPainter p(&img);
            view.paintScene(p, img.size());
        };
        paint();
        const QColor trail(0x55, 0x55, 0x88);
        for (int i : {0, 1, 100, 249}) {
            const QPoint at = view.worldToScreen({-50, i * 2.0}).toPoint();
            QCOMPARE(img.pixelColor(at), trail);
            QVERIFY2(img.pixelColor(at + QPoint(0, 1)) != trail, qPrintable(describe(img.pixelColor(at))));
            // Only where the machine drove: not ahead of it.
            QVERIFY(img.pixelColor(view.worldToScreen({30, i * 2.0}).toPoint()) != trail);
        }
        QStringList ids;
        for (const MachineState& m : ms)
            ids << m.id;
        fleet->remove(ids);
        paint();
        QVERIFY(img.pixelColor(view.worldToScreen({-50, 0}).toPoint()) != trail);
    }

    void selectionIsSharedBetweenListAndMap() {
        fleet->upsert({machine(QStringLiteral("jaus:1"), 20, 0), machine(QStringLiteral("jaus:2"), -20, 0)});
        SiteMapView view;
        view.resize(600, 400);
        FleetListWidget list(fleet, selection);
        view.setFleet(fleet, selection);
        view.setView({0, 0}, 4.0);
        view.show();
        list.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));

        // Click on the map selects in the list.
        QTest::mouseClick(&view, Qt::LeftButton, {}, view.worldToScreen({-20, 0}).toPoint());
        QCOMPARE(selection->currentId(), QStringLiteral("jaus:2"));
        QModelIndexList rows = list.tableView()->selectionModel()->selectedRows();
        QCOMPARE(rows.size(), 1);
        QCOMPARE(rows[0].data(FleetModel::IdRole).toString(), QStringLiteral("jaus:2"));

        // Selecting in the list selects on the map (the map draws a selection ring in gold).
        const QModelIndex first =
            list.proxy()->mapFromSource(fleet->index(fleet->rowOf(QStringLiteral("jaus:1")), 0));
        list.tableView()->selectionModel()->setCurrentIndex(first, QItemSelectionModel::ClearAndSelect |
                                                                       QItemSelectionModel::Rows);
        QCOMPARE(selection->currentId(), QStringLiteral("jaus:1"));
        QCOMPARE(selection->selectedIds(), QStringList{QStringLiteral("jaus:1")});
        const QImage img = view.grab().toImage();
        const QPointF c = view.worldToScreen({20, 0});
        // The 10 x 5 m symbol is 40 x 20 px; the ring is at half its diagonal + 7 px = 29.4 px.
        bool gold = false;
        for (int dx = 26; dx <= 30; ++dx)
            gold = gold || near(img.pixelColor(c.toPoint() + QPoint(dx, 0)), QColor(0xff, 0xd7, 0x00), 40);
        QVERIFY(gold);

        // Ctrl-click adds to the selection; clicking empty ground clears it.
        QTest::mouseClick(&view, Qt::LeftButton, Qt::ControlModifier, view.worldToScreen({-20, 0}).toPoint());
        QCOMPARE(selection->selectedIds().size(), 2);
        QCOMPARE(list.tableView()->selectionModel()->selectedRows().size(), 2);
        QTest::mouseClick(&view, Qt::LeftButton, {}, QPoint(5, 5));
        QVERIFY(selection->selectedIds().isEmpty());
        QVERIFY(list.tableView()->selectionModel()->selectedRows().isEmpty());
    }

    void panZoomFollowAndCursor() {
        fleet->upsert({machine(QStringLiteral("jaus:1"), 100, 50)});
        SiteMapView view;
        view.resize(600, 400);
        view.setFleet(fleet, selection);
        view.setView({0, 0}, 2.0);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        // Wheel zoom keeps the world point under the cursor.
        const QPointF anchor(450, 100);
        const QPointF before = view.screenToWorld(anchor);
        QWheelEvent wheel(anchor, view.mapToGlobal(anchor), QPoint(), QPoint(0, 120), Qt::NoButton,
                          Qt::NoModifier, Qt::NoScrollPhase, false);
        QCoreApplication::sendEvent(&view, &wheel);
        QCOMPARE(view.scale(), 2.5);
        const QPointF after = view.screenToWorld(anchor);
        QVERIFY(std::abs(before.x() - after.x()) < 1e-9 && std::abs(before.y() - after.y()) < 1e-9);
        // Keyboard: + zooms, arrows pan.
        QTest::keyClick(&view, Qt::Key_Plus);
        QCOMPARE(view.scale(), 3.75);
        const QPointF c0 = view.center();
        QTest::keyClick(&view, Qt::Key_Right);
        QVERIFY(view.center().x() > c0.x());
        // Mouse drag pans.
        const QPointF c1 = view.center();
        QTest::mousePress(&view, Qt::LeftButton, {}, QPoint(300, 200));
        QMouseEvent move(QEvent::MouseMove, QPointF(340, 200), view.mapToGlobal(QPointF(340, 200)),
                         Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
        QCoreApplication::sendEvent(&view, &move);
        QTest::mouseRelease(&view, Qt::LeftButton, {}, QPoint(340, 200));
        QVERIFY(std::abs((c1.x() - view.center().x()) - 40 / view.scale()) < 1e-6);
        // Follow: the view centres on the current machine and stays on it as it moves.
        selection->setCurrent(QStringLiteral("jaus:1"));
        view.setFollow(true);
        QCOMPARE(view.center(), QPointF(100, 50));
        fleet->upsert({machine(QStringLiteral("jaus:1"), 130, 70)});
        QCOMPARE(view.center(), QPointF(130, 70));
        // A manual pan ends following.
        QTest::keyClick(&view, Qt::Key_Left);
        QVERIFY(!view.isFollowing());
        // Cursor coordinates: local and WGS84 (site origin at 48N 11E).
        view.setGeoFrame(GeoFrame({48.0, 11.0, 0}));
        QSignalSpy cursor(&view, &SiteMapView::cursorMoved);
        const QPoint at = view.worldToScreen({0, 111.2}).toPoint();
        QMouseEvent hover(QEvent::MouseMove, QPointF(at), view.mapToGlobal(QPointF(at)), Qt::NoButton,
                          Qt::NoButton, Qt::NoModifier);
        QCoreApplication::sendEvent(&view, &hover);
        QCOMPARE(cursor.count(), 1);
        QVERIFY(std::abs(cursor.at(0).at(1).toDouble() - 48.001) < 0.0001);
        QVERIFY(std::abs(cursor.at(0).at(2).toDouble() - 11.0) < 0.0001);
    }

    void levelOfDetailAndCulling() {
        QVector<MachineState> many;
        for (int i = 0; i < 500; ++i)
            many.push_back(machine(QStringLiteral("jaus:%1").arg(i), (i % 25) * 40.0, (i / 25) * 40.0));
        fleet->upsert(many);
        SiteMapView view;
        view.resize(400, 300);
        view.setFleet(fleet, selection);
        view.setView({0, 0}, 0.2); // 10 m machines would be 2 px: drawn at the legible minimum
        QImage img = view.grab().toImage();
        QCOMPARE(view.lastFrame().machinesDrawn, 500);
        const QPoint p = view.worldToScreen({400, 400}).toPoint();
        QVERIFY(!near(img.pixelColor(p), QColor(0xf4, 0xf1, 0xea))); // a symbol, not the empty map
        view.setView({0, 0}, 5.0); // zoomed in: only the few near the origin
        view.grab();
        QVERIFY(view.lastFrame().machinesDrawn < 10);
        QVERIFY(view.lastFrame().staticRebuilt);
        view.grab();
        QVERIFY(!view.lastFrame().staticRebuilt); // static layer cached while the view is unchanged
    }
};

QTEST_MAIN(TestSiteMap)
#include "test_site_map.moc"
