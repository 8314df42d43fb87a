// The 3D view draws only while it is visible and never faster than the data arrive. The panel
// sits in a tab behind another one (as in the console's default layout) while the fleet keeps moving; its
// render counter (VTK StartEvent of the scene's renderer) must not move until the tab is raised.
#include "app/Site3DFeed.h"
#include "models/FleetModel.h"
#include "widgets/view3d/Site3DView.h"
#include "widgets/view3d/SiteSceneRenderer.h"

#include <QDockWidget>
#include <QLabel>
#include <QMainWindow>
#include <QTabWidget>
#include <QtTest>

using namespace ocu;

namespace {
QVector<MachineState> fleetAt(int step) {
    QVector<MachineState> out;
    for (int i = 0; i < 50; ++i) {
        MachineState m;
        m.id = QStringLiteral("iso23725:HT%1").arg(i);
        m.protocol = Protocol::Iso23725;
        m.name = QStringLiteral("HT%1").arg(i);
        m.type = QStringLiteral("HaulTruck");
        m.link = LinkState::Up;
        m.lastDataMs = QDateTime::currentMSecsSinceEpoch();
        m.hasPosition = true;
        m.e = i * 12.0 + step;
        m.n = (i % 7) * 15.0;
        m.headingDeg = 90;
        out.push_back(m);
    }
    return out;
}
} // namespace

class TestView3dVisibility : public QObject {
    Q_OBJECT
private slots:
    void hiddenViewDoesNotRender() {
        FleetModel fleet;
        QTabWidget tabs;
        tabs.resize(800, 600);
        tabs.addTab(new QLabel(QStringLiteral("2D map stand-in")), QStringLiteral("2D"));
        auto* view = new Site3DView;
        tabs.addTab(view, QStringLiteral("3D"));
        Site3DFeed feed(view, &fleet, nullptr);
        tabs.show();
        QVERIFY(QTest::qWaitForWindowExposed(&tabs));
        QVERIFY(!view->isVisible());

        // The fleet moves for a while with the 3D tab hidden: nothing is prepared, nothing is drawn.
        for (int step = 0; step < 10; ++step) {
            fleet.upsert(fleetAt(step));
            QTest::qWait(60);
        }
        QCOMPARE(view->renderCount(), std::uint64_t(0));
        QCOMPARE(feed.machinePushCount(), 0);

        // Raised: the current state is drawn.
        tabs.setCurrentIndex(1);
        QTRY_VERIFY_WITH_TIMEOUT(view->renderCount() > 0, 20000);
        QCOMPARE(feed.machinePushCount(), 1); // the moves made while hidden, pushed once
        QTRY_COMPARE_WITH_TIMEOUT(view->sceneRenderer().scene().machines.size(), std::size_t(50), 5000);

        // No new data: no new frames (at most the data rate, here zero).
        QTest::qWait(100); // let the frame of the show settle
        const std::uint64_t idle = view->renderCount();
        QTest::qWait(500);
        QCOMPARE(view->renderCount(), idle);

        // Machines are type-specific shapes with decluttered name labels.
        QCOMPARE(view->sceneRenderer().machine(QStringLiteral("iso23725:HT3"))->shape,
                 MachineShape::HaulTruck);
        const std::vector<QRectF> labels = view->sceneRenderer().nameLabelRects();
        QVERIFY(labels.size() >= 5);
        QVERIFY(labels.size() <= 40);
        for (std::size_t i = 0; i < labels.size(); ++i)
            for (std::size_t j = i + 1; j < labels.size(); ++j)
                QVERIFY2(!labels[i].intersects(labels[j]), "two 3D name labels overlap");

        // New data: drawn again.
        fleet.upsert(fleetAt(20));
        QTRY_VERIFY_WITH_TIMEOUT(view->renderCount() > idle, 20000);

        // Hidden again: more data, no more frames.
        tabs.setCurrentIndex(0);
        QTRY_VERIFY(!view->isVisible());
        QTest::qWait(100);
        const std::uint64_t hidden = view->renderCount();
        const int pushes = feed.machinePushCount();
        for (int step = 21; step < 30; ++step) {
            fleet.upsert(fleetAt(step));
            QTest::qWait(60);
        }
        QCOMPARE(view->renderCount(), hidden);
        QCOMPARE(feed.machinePushCount(), pushes);
    }

    // The console's layout: the 3D panel is a dock tabified behind the 2D map's dock. Such a dock stays
    // isVisible() with nothing of it on screen and gets no hide event; the feed must still prepare nothing.
    void dockTabBehindAnotherPreparesNothing() {
        FleetModel fleet;
        QMainWindow win;
        win.resize(800, 600);
        auto* front = new QDockWidget(QStringLiteral("2D"), &win);
        front->setWidget(new QLabel(QStringLiteral("2D map stand-in")));
        auto* back = new QDockWidget(QStringLiteral("3D"), &win);
        auto* view = new Site3DView;
        back->setWidget(view);
        win.addDockWidget(Qt::LeftDockWidgetArea, front);
        win.addDockWidget(Qt::LeftDockWidgetArea, back);
        win.tabifyDockWidget(front, back);
        front->raise();
        Site3DFeed feed(view, &fleet, nullptr);
        win.show();
        QVERIFY(QTest::qWaitForWindowExposed(&win));
        for (int step = 0; step < 10; ++step) {
            fleet.upsert(fleetAt(step));
            QTest::qWait(60);
        }
        QVERIFY(view->visibleRegion().isEmpty());
        QCOMPARE(feed.machinePushCount(), 0);
        QCOMPARE(view->renderCount(), std::uint64_t(0));
        // Raised: the current state goes out once and is drawn.
        back->raise();
        QTRY_VERIFY_WITH_TIMEOUT(feed.machinePushCount() >= 1, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(view->renderCount() > 0, 20000);
        QTRY_COMPARE_WITH_TIMEOUT(view->sceneRenderer().scene().machines.size(), std::size_t(50), 5000);
        // Behind the 2D map again: moves are not prepared.
        front->raise();
        QTRY_VERIFY(view->visibleRegion().isEmpty());
        QTest::qWait(150);
        const int pushes = feed.machinePushCount();
        for (int step = 21; step < 30; ++step) {
            fleet.upsert(fleetAt(step));
            QTest::qWait(60);
        }
        QCOMPARE(feed.machinePushCount(), pushes);
    }
};

QTEST_MAIN(TestView3dVisibility)
#include "test_view3d_visibility.moc"
