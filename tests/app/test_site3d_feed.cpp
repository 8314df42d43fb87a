// The 3D view's pass-count surface is coloured like the 2D map, cell for cell: the texture handed to VTK
// holds passCountColor(count, palette, target) of the 2D map's palette and target for every counted cell
// (and is transparent where nothing was counted), it follows the operator's palette and target changes, and
// the 2D map painted over the same layer shows the same colour at every cell's centre. The texture is read
// back from the renderer (exact), not from rendered pixels.
#include "app/Site3DFeed.h"
#include "models/FleetModel.h"
#include "models/PassCountLayer.h"
#include "widgets/SiteMapView.h"
#include "widgets/view3d/Site3DView.h"
#include "widgets/view3d/SiteSceneRenderer.h"

#include <QPainter>
#include <QtTest>

using namespace ocu;

namespace {
constexpr int kCols = 14, kRows = 3;

// Counts 0..13 along each row (row 1 shifted by one, row 2 by two): every palette step, 9+ and no data.
int countAt(int col, int row) {
    return (col + row) % kCols;
}

QString texelsDiffer(const SiteSceneRenderer& r, PassPalette palette, PassTarget target) {
    const auto size = r.passTextureSize();
    if (size[0] != kCols || size[1] != kRows)
        return QStringLiteral("texture %1 x %2").arg(size[0]).arg(size[1]);
    for (int row = 0; row < kRows; ++row)
        for (int col = 0; col < kCols; ++col) {
            const auto t = r.passTexel(col, row); // row 0 = south in both
            const int n = countAt(col, row);
            if (n == 0) {
                if (t[3] != 0)
                    return QStringLiteral("cell %1,%2 without passes is drawn").arg(col).arg(row);
                continue;
            }
            const QColor want = passCountColor(n, palette, target);
            if (t[0] != want.red() || t[1] != want.green() || t[2] != want.blue() || t[3] != 255)
                return QStringLiteral("cell %1,%2 (%3 passes): 3D %4,%5,%6,%7, 2D palette %8")
                    .arg(col)
                    .arg(row)
                    .arg(n)
                    .arg(t[0])
                    .arg(t[1])
                    .arg(t[2])
                    .arg(t[3])
                    .arg(want.name());
        }
    return {};
}
} // namespace

class TestSite3DFeed : public QObject {
    Q_OBJECT
private slots:
    void passCountColoursEqualTheMap() {
        GridPassCountLayer layer(QPointF(-20, 10), 0.5, kCols, kRows);
        for (int row = 0; row < kRows; ++row)
            for (int col = 0; col < kCols; ++col)
                layer.setCount(col, row, countAt(col, row));
        FleetModel fleet;
        Site3DView view;
        view.resize(640, 480);
        Site3DFeed feed(&view, &fleet, nullptr);
        feed.setPassCountLayer(&layer);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        const SiteSceneRenderer& r = view.sceneRenderer();

        // The default is the 2D map's default: the 9-step discrete palette, target 3-5.
        SiteMapView map;
        QCOMPARE(feed.passPalette(), map.passPalette());
        QCOMPARE(feed.passTarget().min, map.passTarget().min);
        QCOMPARE(feed.passTarget().max, map.passTarget().max);
        QTRY_COMPARE_WITH_TIMEOUT(texelsDiffer(r, PassPalette::Discrete, map.passTarget()), QString(), 10000);
        // The 3D legend is the 2D one: 1 ... 8, 9+ in the same colours.
        const auto& legend = r.scene().legend;
        QCOMPARE(legend.size(), std::size_t(9));
        for (int c = 1; c <= 9; ++c) {
            const QColor want = passCountColor(c, PassPalette::Discrete, map.passTarget());
            const Rgb got = legend[std::size_t(c - 1)].colour;
            QCOMPARE(QColor(got.r, got.g, got.b), want);
        }
        QCOMPARE(legend.back().label, QStringLiteral("9+"));

        // Cell for cell against the 2D map painted over the same layer (pass counts only).
        map.setPassCountLayer(&layer);
        for (SiteMapView::Layer l :
             {SiteMapView::LayerMap, SiteMapView::LayerMapNames, SiteMapView::LayerMachines,
              SiteMapView::LayerLabels, SiteMapView::LayerTrails, SiteMapView::LayerOwnPosition,
              SiteMapView::LayerLegend, SiteMapView::LayerScaleBar, SiteMapView::LayerNorthArrow,
              SiteMapView::LayerCursor})
            map.setLayerVisible(l, false);
        const QSize size(800, 200);
        map.resize(size);
        map.setView(QPointF(-20 + kCols * 0.25, 10 + kRows * 0.25), 50.0); // 25 px per cell
        auto checkMap = [&](PassPalette palette) -> QString {
            QImage img(size, QImage::Format_ARGB32_Premultiplied);
            img.fill(Qt::white);
            QPainter p(&img);
            map.paintScene(p, size);
            p.end();
            for (int row = 0; row < kRows; ++row)
                for (int col = 0; col < kCols; ++col) {
                    const int n = countAt(col, row);
                    if (n == 0)
                        continue;
                    const QPoint px =
                        map.worldToScreen(QPointF(-20 + (col + 0.5) * 0.5, 10 + (row + 0.5) * 0.5)).toPoint();
                    const auto t = r.passTexel(col, row);
                    const QColor on2d = img.pixelColor(px);
                    if (on2d != QColor(t[0], t[1], t[2]))
                        return QStringLiteral("cell %1,%2 (%3 passes): 2D %4, 3D %5 (palette %6)")
                            .arg(col)
                            .arg(row)
                            .arg(n)
                            .arg(on2d.name(), QColor(t[0], t[1], t[2]).name())
                            .arg(int(palette));
                }
            return {};
        };
        QCOMPARE(checkMap(PassPalette::Discrete), QString());

        // The operator picks the summary palette and another target: both views follow.
        const PassTarget target{2, 4};
        map.setPassPalette(PassPalette::Summary);
        map.setPassTarget(target);
        feed.setPassPalette(PassPalette::Summary);
        feed.setPassTarget(target);
        QTRY_COMPARE_WITH_TIMEOUT(texelsDiffer(r, PassPalette::Summary, target), QString(), 10000);
        QCOMPARE(checkMap(PassPalette::Summary), QString());
        QCOMPARE(r.scene().legend.size(), std::size_t(3));
        // Back to the per-count palette with the same counts (no new revision of the layer): recoloured.
        feed.setPassPalette(PassPalette::Discrete);
        QTRY_COMPARE_WITH_TIMEOUT(texelsDiffer(r, PassPalette::Discrete, target), QString(), 10000);

        // New counts are pushed in the current palette.
        layer.setCount(0, 0, 7);
        feed.passCountChanged();
        QTRY_VERIFY_WITH_TIMEOUT(r.passTexel(0, 0)[3] == 255, 10000);
        const QColor seven = passCountColor(7, PassPalette::Discrete, target);
        const auto t = r.passTexel(0, 0);
        QCOMPARE(QColor(t[0], t[1], t[2]), seven);
    }
};

QTEST_MAIN(TestSite3DFeed)
#include "test_site3d_feed.moc"
