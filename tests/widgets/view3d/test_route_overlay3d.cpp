// The selected truck's route in the 3D view (RouteOverlay3D), headless (offscreen platform,
// EGL). The drawn polyline follows the path on the terrain (1.5 m above it, no segment longer than 10 m), the
// view shows it in the route colour where there was ground before, and an empty path takes it away again.
#include "tests/widgets/view3d/SyntheticSite.h"
#include "widgets/view3d/RouteOverlay3D.h"
#include "widgets/view3d/Site3DView.h"
#include "widgets/view3d/SiteSceneRenderer.h"

#include <QtTest>

#include <cmath>

using namespace ocu;
using namespace ocu::testsite;

namespace {
QString describe(QRgb p) {
    return QStringLiteral("(%1,%2,%3)").arg(qRed(p)).arg(qGreen(p)).arg(qBlue(p));
}
// The overlay's purple (0.56, 0.14, 0.67), unlit: not the brown terrain, the grey road or the green area.
bool isRoutePurple(QRgb p) {
    return qRed(p) > 100 && qBlue(p) > 130 && qGreen(p) < 80 && qBlue(p) > qRed(p);
}
} // namespace

class TestRouteOverlay3d : public QObject {
    Q_OBJECT
private slots:
    void routeDrawnOnTheTerrainAndRemoved() {
        Site3DView view;
        view.resize(640, 480);
        view.setScene(makeSite());
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        SiteSceneRenderer& scene = view.sceneRenderer();
        auto* overlay = new RouteOverlay3D(&view);
        QImage before = view.grab().toImage(); // the first render sets the camera

        // Open ground north of the road: from (-80, 60) east to (20, 60), then north to (20, 80).
        const QVector<QPointF> path{{-80.0, 60.0}, {20.0, 60.0}, {20.0, 80.0}};
        const double probeE = -30.0, probeN = 60.0;
        const auto probe =
            scene.project(probeE, probeN, scene.terrainHeight(probeE, probeN) + RouteOverlay3D::kLift);
        QVERIFY(probe);
        const QPointF offset(view.viewWidget()->mapTo(&view, QPoint(0, 0)));
        const QPoint at = (*probe + offset).toPoint();
        QVERIFY2(isTerrain(before.pixel(at)), qPrintable(describe(before.pixel(at))));

        overlay->setPath(path);
        const QVector<QVector3D> pts = overlay->drawnPoints();
        // 100 m in 10 m steps plus 20 m in 10 m steps: 11 + 2 points, ends where the path ends.
        QCOMPARE(pts.size(), 13);
        QCOMPARE(QPointF(pts.front().x(), pts.front().y()), path.front());
        QCOMPARE(QPointF(pts.back().x(), pts.back().y()), path.back());
        for (int i = 0; i < pts.size(); ++i) {
            const double ground = scene.terrainHeight(pts[i].x(), pts[i].y());
            QVERIFY2(std::abs(pts[i].z() - (ground + RouteOverlay3D::kLift)) < 1e-3,
                     qPrintable(
                         QStringLiteral("point %1 at %2 m, ground %3 m").arg(i).arg(pts[i].z()).arg(ground)));
            if (i > 0)
                QVERIFY(QLineF(pts[i - 1].toPointF(), pts[i].toPointF()).length() <=
                        RouteOverlay3D::kStep + 1e-6);
        }
        QImage shown = view.grab().toImage();
        QVERIFY2(isRoutePurple(shown.pixel(at)), qPrintable(describe(shown.pixel(at))));

        overlay->setPath({});
        QVERIFY(overlay->drawnPoints().isEmpty());
        QImage after = view.grab().toImage();
        QVERIFY2(isTerrain(after.pixel(at)), qPrintable(describe(after.pixel(at))));
    }
};

QTEST_MAIN(TestRouteOverlay3d)
#include "test_route_overlay3d.moc"
