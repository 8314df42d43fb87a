// The 3D panel headless: offscreen platform, DISPLAY unset. It must never create a QOpenGLWidget, and a
// grab() of the window (what `--screenshot --view 3d` saves) must contain terrain, road and machines.
#include "tests/widgets/view3d/SyntheticSite.h"
#include "widgets/view3d/Site3DView.h"
#include "widgets/view3d/SiteSceneRenderer.h"

#include <QOpenGLWidget>
#include <QSignalSpy>
#include <QToolBar>
#include <QtTest>

#include <cmath>

using namespace ocu;
using namespace ocu::testsite;

namespace {
QString describe(QRgb p) {
    return QStringLiteral("(%1,%2,%3)").arg(qRed(p)).arg(qGreen(p)).arg(qBlue(p));
}
QRgb pixelAt(const QImage& img, QPointF p) {
    return img.pixel(static_cast<int>(p.x()), static_cast<int>(p.y()));
}
} // namespace

class TestView3dPanel : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        QCOMPARE(QGuiApplication::platformName(), QStringLiteral("offscreen"));
        QVERIFY(qEnvironmentVariable("DISPLAY").isEmpty());
    }

    void grabShowsTheSceneWithoutOpenGLWidget() {
        Site3DView view;
        QCOMPARE(view.backend(), Site3DView::Backend::OffscreenImage);
        QVERIFY(view.findChildren<QOpenGLWidget*>().isEmpty());
        view.resize(800, 600);
        view.setScene(makeSite());
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        QVERIFY2(view.statusMessage().isEmpty(), qPrintable(view.statusMessage()));

        const QImage shot = view.grab().toImage(); // paints the canvas, which renders through EGL
        const QPointF offset(view.viewWidget()->mapTo(&view, QPoint(0, 0)));
        SiteSceneRenderer& scene = view.sceneRenderer();
        const Machine3D m1 = *scene.machine(QStringLiteral("M1"));
        const Machine3D m2 = *scene.machine(QStringLiteral("M2"));
        const auto p1 = scene.project(m1.e, m1.n, m1.u + m1.height);
        const auto p2 = scene.project(m2.e, m2.n, m2.u + m2.height);
        const auto road = scene.project(-60.0, 0.0, scene.terrainHeight(-60.0, 0.0));
        const auto ground = scene.project(-70.0, 60.0, scene.terrainHeight(-70.0, 60.0));
        QVERIFY(p1 && p2 && road && ground);
        QVERIFY2(isMagenta(pixelAt(shot, *p1 + offset)), qPrintable(describe(pixelAt(shot, *p1 + offset))));
        QVERIFY2(isCyan(pixelAt(shot, *p2 + offset)), qPrintable(describe(pixelAt(shot, *p2 + offset))));
        QVERIFY2(isRoadGrey(pixelAt(shot, *road + offset)),
                 qPrintable(describe(pixelAt(shot, *road + offset))));
        QVERIFY2(isTerrain(pixelAt(shot, *ground + offset)),
                 qPrintable(describe(pixelAt(shot, *ground + offset))));
        if (const QString dump = qEnvironmentVariable("OCU_VIEW3D_DUMP"); !dump.isEmpty())
            shot.save(dump + QStringLiteral("/panel_offscreen.png"));

        // The legend overlay (top-right of the canvas) shows the pass-count colours: find the red swatch.
        const QRect legendArea(offset.toPoint() + QPoint(view.viewWidget()->width() - 160, 0),
                               QSize(160, 120));
        bool redSwatch = false;
        for (int y = legendArea.top(); y < legendArea.bottom() && !redSwatch; ++y)
            for (int x = legendArea.left(); x < legendArea.right() && !redSwatch; ++x)
                redSwatch = shot.pixel(x, y) == qRgb(255, 0, 0);
        QVERIFY(redSwatch);
    }

    void clickPicksAndUpdatesAreThrottledButShown() {
        Site3DView view;
        view.resize(640, 480);
        view.setScene(makeSite());
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        view.grab();
        SiteSceneRenderer& scene = view.sceneRenderer();
        const Machine3D m2 = *scene.machine(QStringLiteral("M2"));
        const auto p2 = scene.project(m2.e, m2.n, m2.u + m2.height);
        QVERIFY(p2);
        QSignalSpy picked(&view, &Site3DView::machinePicked);
        QTest::mouseClick(view.viewWidget(), Qt::LeftButton, Qt::NoModifier, p2->toPoint());
        QCOMPARE(picked.count(), 1);
        QCOMPARE(picked.at(0).at(0).toString(), QStringLiteral("M2"));
        QCOMPARE(view.selectedMachine(), QStringLiteral("M2"));

        // Move M2 through the fast path; the next grab shows it at the new place.
        std::vector<Machine3D> machines = scene.scene().machines;
        machines[1].e = 60.0;
        machines[1].n = -70.0;
        machines[1].u = groundU(60.0, -70.0);
        const auto builds = scene.sceneBuildCount();
        view.updateMachines(machines);
        QCOMPARE(scene.sceneBuildCount(), builds);
        const QImage shot = view.grab().toImage();
        const QPointF offset(view.viewWidget()->mapTo(&view, QPoint(0, 0)));
        const Machine3D placed = *scene.machine(QStringLiteral("M2"));
        const auto moved = scene.project(60.0, -70.0, placed.u + placed.height);
        QVERIFY(moved);
        QVERIFY2(isCyan(pixelAt(shot, *moved + offset)),
                 qPrintable(describe(pixelAt(shot, *moved + offset))));
    }

    // A double-click selects in every view: in the 3D panel too, and the camera follows it.
    void doubleClickSelectsAndFollows() {
        Site3DView view;
        view.resize(640, 480);
        view.setScene(makeSite());
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        view.grab();
        SiteSceneRenderer& scene = view.sceneRenderer();
        const Machine3D m2 = *scene.machine(QStringLiteral("M2"));
        const auto p2 = scene.project(m2.e, m2.n, m2.u + m2.height);
        QVERIFY(p2);
        QCOMPARE(view.cameraMode(), CameraMode::FreeOrbit);
        QSignalSpy picked(&view, &Site3DView::machinePicked);
        QSignalSpy activated(&view, &Site3DView::machineActivated);
        QTest::mouseDClick(view.viewWidget(), Qt::LeftButton, Qt::NoModifier, p2->toPoint());
        QVERIFY(picked.count() >= 1);
        QCOMPARE(picked.last().at(0).toString(), QStringLiteral("M2"));
        QCOMPARE(activated.count(), 1);
        QCOMPARE(activated.at(0).at(0).toString(), QStringLiteral("M2"));
        QCOMPARE(view.selectedMachine(), QStringLiteral("M2"));
        QCOMPARE(view.cameraMode(), CameraMode::FollowSelected);
        // A double-click on bare ground selects nothing new.
        view.setCameraMode(CameraMode::FreeOrbit);
        view.grab();
        const auto ground = scene.project(-70.0, 60.0, scene.terrainHeight(-70.0, 60.0));
        QVERIFY(ground);
        QVERIFY(scene.pick(ground->x(), ground->y()).isEmpty());
        QTest::mouseDClick(view.viewWidget(), Qt::LeftButton, Qt::NoModifier, ground->toPoint());
        QCOMPARE(activated.count(), 1);
        QCOMPARE(view.cameraMode(), CameraMode::FreeOrbit);
    }

    void dragOrbitsAndWheelZoomsInTheImageView() {
        Site3DView view;
        view.resize(640, 480);
        view.setScene(makeSite());
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        view.grab();
        SiteSceneRenderer& scene = view.sceneRenderer();
        QWidget* canvas = view.viewWidget();
        const Machine3D m1 = *scene.machine(QStringLiteral("M1"));
        const Machine3D m2 = *scene.machine(QStringLiteral("M2"));
        auto at = [&](const Machine3D& m) { return scene.project(m.e, m.n, m.u + m.height); };
        auto drag = [&](QPoint from, QPoint to) {
            QMouseEvent press(QEvent::MouseButtonPress, from, canvas->mapToGlobal(from), Qt::LeftButton,
                              Qt::LeftButton, Qt::NoModifier);
            QApplication::sendEvent(canvas, &press);
            for (int i = 1; i <= 10; ++i) {
                const QPoint p = from + (to - from) * i / 10;
                QMouseEvent move(QEvent::MouseMove, p, canvas->mapToGlobal(p), Qt::NoButton, Qt::LeftButton,
                                 Qt::NoModifier);
                QApplication::sendEvent(canvas, &move);
            }
            QMouseEvent release(QEvent::MouseButtonRelease, to, canvas->mapToGlobal(to), Qt::LeftButton,
                                Qt::NoButton, Qt::NoModifier);
            QApplication::sendEvent(canvas, &release);
        };
        const auto before = at(m1);
        QVERIFY(before);
        QSignalSpy picked(&view, &Site3DView::machinePicked);
        drag(QPoint(320, 240), QPoint(440, 240)); // a quarter-degree per pixel: 30 degrees of azimuth
        QCOMPARE(picked.count(), 0);              // a drag is not a click
        const auto after = at(m1);
        QVERIFY(after);
        QVERIFY2(std::hypot(after->x() - before->x(), after->y() - before->y()) > 20.0,
                 qPrintable(QStringLiteral("M1 moved only from %1,%2 to %3,%4")
                                .arg(before->x())
                                .arg(before->y())
                                .arg(after->x())
                                .arg(after->y())));
        // The picture follows the camera: M1 is drawn where it now projects.
        const QImage shot = view.grab().toImage();
        const QPointF offset(canvas->mapTo(&view, QPoint(0, 0)));
        QVERIFY2(isMagenta(pixelAt(shot, *after + offset)),
                 qPrintable(describe(pixelAt(shot, *after + offset))));

        // Dragging far up or down stops short of the poles: the view never flips over (up stays up).
        // (as the GL widget's VTK trackball: dragging down raises the camera)
        drag(QPoint(320, 20), QPoint(320, 470));
        drag(QPoint(320, 20), QPoint(320, 470));
        QVERIFY2(scene.viewElevationDeg() > 88.0 && scene.viewElevationDeg() < 89.5,
                 qPrintable(QString::number(scene.viewElevationDeg())));
        drag(QPoint(320, 470), QPoint(320, 20));
        drag(QPoint(320, 470), QPoint(320, 20));
        QVERIFY2(scene.viewElevationDeg() > 4.5 && scene.viewElevationDeg() < 6.0,
                 qPrintable(QString::number(scene.viewElevationDeg())));

        // Wheel towards the screen zooms in: the two machines move apart on screen.
        scene.resetCamera();
        auto spread = [&] {
            const auto a = at(m1), b = at(m2);
            return std::hypot(a->x() - b->x(), a->y() - b->y());
        };
        const double wide = spread();
        QWheelEvent wheel(QPointF(320, 240), canvas->mapToGlobal(QPointF(320, 240)), QPoint(), QPoint(0, 360),
                          Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(canvas, &wheel);
        QVERIFY2(spread() > wide * 1.25, qPrintable(QStringLiteral("%1 -> %2").arg(wide).arg(spread())));

        // Top-down stays north-up: a drag does not turn it.
        view.setCameraMode(CameraMode::TopDown);
        const auto top = at(m1);
        drag(QPoint(320, 240), QPoint(440, 300));
        QCOMPARE(*at(m1), *top);
    }

    void topDownIsNorthUpAndRenderImageHasTheRequestedSize() {
        Site3DView view;
        view.resize(640, 480);
        view.setScene(makeSite());
        QSignalSpy modes(&view, &Site3DView::cameraModeChanged);
        view.setCameraMode(CameraMode::TopDown);
        QCOMPARE(modes.count(), 1);
        const QImage img = view.renderImage(QSize(500, 500));
        QCOMPARE(img.size(), QSize(500, 500));
        SiteSceneRenderer& scene = view.sceneRenderer();
        const auto north = scene.project(0.0, 50.0, scene.terrainHeight(0.0, 50.0));
        const auto south = scene.project(0.0, -50.0, scene.terrainHeight(0.0, -50.0));
        const auto east = scene.project(50.0, 0.0, scene.terrainHeight(50.0, 0.0));
        QVERIFY(north && south && east);
        QVERIFY(north->y() < south->y() - 100.0);
        QVERIFY(qAbs(north->x() - south->x()) < 3.0);
        QVERIFY(east->x() > 250.0 + 50.0);
        const Machine3D m1 = *scene.machine(QStringLiteral("M1"));
        const auto p1 = scene.project(m1.e, m1.n, m1.u + m1.height);
        QVERIFY(p1);
        QVERIFY2(isMagenta(pixelAt(img, *p1)), qPrintable(describe(pixelAt(img, *p1))));
    }

    void showsAClearMessageWhenNothingCanRender() {
        qputenv("OCU_VIEW3D_NO_EGL", "1");
        Site3DView view;
        qunsetenv("OCU_VIEW3D_NO_EGL");
        QVERIFY(view.findChildren<QOpenGLWidget*>().isEmpty());
        QVERIFY2(view.statusMessage().contains(QStringLiteral("DISPLAY")), qPrintable(view.statusMessage()));
        view.resize(400, 300);
        view.setScene(makeSite());
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        const QImage shot = view.grab().toImage();
        const QPoint inCanvas = view.viewWidget()->mapTo(&view, QPoint(5, 5));
        QCOMPARE(shot.pixel(inCanvas), qRgb(60, 60, 60)); // the message panel, not a crash or a black hole
        QCOMPARE(view.renderImage(QSize(100, 100)).isNull(), true);
    }
};

QTEST_MAIN(TestView3dPanel)
#include "test_view3d_panel.moc"
