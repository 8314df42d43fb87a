// The 2D pass-count overlay's frame budget (docs/decisions/pass-count-frame-budget.md: the map redrawn in <=
// 16 ms at any zoom, also right after the whole job appears or the palette changes). With a budget a frame
// renders only some tiles and stands in for the rest; the frames that follow finish the view, and the
// finished view is pixel for pixel the one a single unbudgeted frame draws. The budget here is a nanosecond,
// so that every frame renders exactly one level-0 tile whatever the machine's speed (the overlay always
// renders at least one).
#include "models/PassCountLayer.h"
#include "widgets/PassCountOverlay.h"
#include "widgets/SiteMapView.h"

#include <QPainter>
#include <QtTest>

using namespace ocu;

namespace {
constexpr double kTiny = 1e-6; // ms

// A long strip of counts: 2,300 x 300 cells at 0.34 m (9 x 2 level-0 tiles), counts 1..9 in bands.
std::unique_ptr<GridPassCountLayer> strip() {
    auto layer = std::make_unique<GridPassCountLayer>(QPointF(100, 200), 0.34, 2300, 300);
    for (int c = 0; c < 2300; c += 7)
        layer->fillRect(QRect(c, (c / 7) % 250, 5, 40), 1 + (c / 7) % 9);
    return layer;
}

const QRectF kScreen(0, 0, 800, 300);

QRectF wholeStrip(const PassCountLayer& l) {
    const double w = l.columns() * l.cellSize();
    return QRectF(l.origin().x(), l.origin().y() - 0.5 * w * 300 / 800 + l.rows() * l.cellSize() / 2, w,
                  w * 300 / 800);
}

QImage frame(PassCountOverlay& o, const PassCountLayer& l, PassPalette pal, PassTarget t, const QRectF& world,
             double budget) {
    QImage img(kScreen.size().toSize(), QImage::Format_ARGB32_Premultiplied);
    img.fill(Qt::white);
    QPainter p(&img);
    o.draw(p, l, pal, t, world, kScreen, budget);
    return img;
}

int coloured(const QImage& img) {
    int n = 0;
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x)
            n += img.pixel(x, y) != qRgb(255, 255, 255);
    return n;
}
} // namespace

class TestPassCountOverlay : public QObject {
    Q_OBJECT
private slots:
    void budgetedFramesFinishAsOneFullFrame() {
        auto layer = strip();
        const QRectF world = wholeStrip(*layer);
        PassCountOverlay full;
        const QImage want = frame(full, *layer, PassPalette::Discrete, {3, 5}, world, 0);
        QCOMPARE(full.stats().pending, 0);
        QVERIFY(coloured(want) > 3000);

        PassCountOverlay o;
        QImage got = frame(o, *layer, PassPalette::Discrete, {3, 5}, world, kTiny);
        const int owed = o.stats().pending;
        QVERIFY2(owed > 0, "a whole-job first frame on a tiny budget owes tiles");
        QCOMPARE(o.stats().standIns, 0); // nothing to stand in with yet
        int frames = 1;
        while (o.stats().pending > 0 && frames < 100) {
            got = frame(o, *layer, PassPalette::Discrete, {3, 5}, world, kTiny);
            QVERIFY(o.stats().tilesRendered >= 1); // every frame makes progress
            ++frames;
        }
        QCOMPARE(o.stats().pending, 0);
        QVERIFY2(frames >= 18, qPrintable(QString("%1 frames").arg(frames))); // one level-0 tile a frame
        QCOMPARE(got, want);
    }

    void paletteChangeKeepsTheOldColoursUntilTheNewAreRendered() {
        auto layer = strip();
        const QRectF world = wholeStrip(*layer);
        PassCountOverlay o;
        QImage before = frame(o, *layer, PassPalette::Discrete, {3, 5}, world, 0);
        PassCountOverlay full;
        const QImage want = frame(full, *layer, PassPalette::Summary, {3, 5}, world, 0);
        QVERIFY(want != before);

        QImage got = frame(o, *layer, PassPalette::Summary, {3, 5}, world, kTiny);
        QVERIFY(o.stats().pending > 0);
        QCOMPARE(o.stats().standIns, o.stats().pending); // every owed tile shows its old colours
        QCOMPARE(coloured(got), coloured(before));       // nothing went blank
        QVERIFY(got != want);
        for (int i = 0; i < 100 && o.stats().pending > 0; ++i)
            got = frame(o, *layer, PassPalette::Summary, {3, 5}, world, kTiny);
        QCOMPARE(o.stats().pending, 0);
        QCOMPARE(got, want);
        // A change of the target is a new colouring too.
        const QImage want2 = frame(full, *layer, PassPalette::Summary, {2, 4}, world, 0);
        got = frame(o, *layer, PassPalette::Summary, {2, 4}, world, kTiny);
        QVERIFY(o.stats().pending > 0 && o.stats().standIns == o.stats().pending);
        for (int i = 0; i < 100 && o.stats().pending > 0; ++i)
            got = frame(o, *layer, PassPalette::Summary, {2, 4}, world, kTiny);
        QCOMPARE(got, want2);
    }

    void zoomingInStandsInWithTheCoarserTiles() {
        auto layer = strip();
        PassCountOverlay o;
        // A cache of 12 tiles: the whole-strip view keeps its coarse tiles, the level-0 tiles they were made
        // from are dropped once they were not drawn for a frame.
        o.setCacheLimit(12 * 256 * 256 * 4);
        frame(o, *layer, PassPalette::Discrete, {3, 5}, wholeStrip(*layer), 0);
        frame(o, *layer, PassPalette::Discrete, {3, 5}, wholeStrip(*layer), 0);
        const int coarse = o.stats().level;
        QVERIFY(coarse >= 1);
        QVERIFY(o.stats().cachedTiles < 12);
        // 200 m across: level 0, its tiles not cached; the coarse ones stand in, enlarged.
        const QRectF near(layer->origin().x() + 100, layer->origin().y(), 200, 75);
        PassCountOverlay full;
        const QImage want = frame(full, *layer, PassPalette::Discrete, {3, 5}, near, 0);
        QImage got = frame(o, *layer, PassPalette::Discrete, {3, 5}, near, kTiny);
        QCOMPARE(o.stats().level, 0);
        QVERIFY(o.stats().pending > 0);
        QCOMPARE(o.stats().standIns, o.stats().pending);
        QVERIFY(coloured(got) > coloured(want) / 2);
        for (int i = 0; i < 100 && o.stats().pending > 0; ++i)
            got = frame(o, *layer, PassPalette::Discrete, {3, 5}, near, kTiny);
        QCOMPARE(got, want);
    }

    void changedCountsShowTheirOldTileUntilRendered() {
        auto layer = strip();
        const QRectF world = wholeStrip(*layer);
        PassCountOverlay o;
        frame(o, *layer, PassPalette::Discrete, {3, 5}, world, 0);
        // A roller passes over the whole strip: every tile changed.
        layer->fillRect(QRect(0, 260, 2300, 30), 4);
        PassCountOverlay full;
        const QImage want = frame(full, *layer, PassPalette::Discrete, {3, 5}, world, 0);
        QImage got = frame(o, *layer, PassPalette::Discrete, {3, 5}, world, kTiny);
        QVERIFY(o.stats().pending > 0);
        QCOMPARE(o.stats().standIns, o.stats().pending);
        for (int i = 0; i < 100 && o.stats().pending > 0; ++i)
            got = frame(o, *layer, PassPalette::Discrete, {3, 5}, world, kTiny);
        QCOMPARE(got, want);
    }

    void theMapViewPaintsOnUntilTheOverlayIsComplete() {
        auto layer = strip();
        SiteMapView view;
        view.resize(800, 300);
        for (auto l : {SiteMapView::LayerMachines, SiteMapView::LayerLabels, SiteMapView::LayerTrails,
                       SiteMapView::LayerOwnPosition, SiteMapView::LayerCursor, SiteMapView::LayerLegend,
                       SiteMapView::LayerScaleBar, SiteMapView::LayerNorthArrow})
            view.setLayerVisible(l, false);
        view.setPassOverlayFrameBudget(kTiny);
        view.setPassCountLayer(layer.get());
        view.setView(wholeStrip(*layer).center(), 800 / wholeStrip(*layer).width());
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        const int framesBefore = view.framesPainted();
        // The view asks for its own frames (nothing else changes) until no tile is owed.
        QTRY_VERIFY_WITH_TIMEOUT(view.framesPainted() > framesBefore && view.passOverlayComplete(), 10000);
        QVERIFY2(view.framesPainted() - framesBefore >= 10,
                 qPrintable(QString("%1 frames").arg(view.framesPainted() - framesBefore)));
        // What is on screen then equals one unbudgeted paint of the same scene.
        const QImage onScreen = view.grab().toImage().convertToFormat(QImage::Format_RGB32);
        QImage direct(view.size(), QImage::Format_RGB32);
        {
            QPainter p(&direct);
            view.paintScene(p, view.size());
        }
        QCOMPARE(onScreen, direct);
        QVERIFY(view.passOverlayComplete());
        // Screenshots wait on the property "screenshotPending" while tiles are owed (app/Screenshot.cpp): a
        // palette change owes every tile again; one synchronous frame renders one of them.
        QVERIFY(!view.property("screenshotPending").toBool());
        view.setPassPalette(PassPalette::Summary);
        view.repaint();
        QVERIFY(!view.passOverlayComplete());
        QVERIFY(view.property("screenshotPending").toBool());
        QTRY_VERIFY_WITH_TIMEOUT(view.passOverlayComplete(), 10000);
        QVERIFY(!view.property("screenshotPending").toBool());
    }

    // The legend lists the counts down the side of a tall map and in one row on a small one (the UGV
    // workspace's map above the drive controls), where nine rows would cover most of it.
    void theLegendIsOneRowOnASmallMap() {
        auto layer = strip();
        SiteMapView view;
        for (auto l : {SiteMapView::LayerMap, SiteMapView::LayerMapNames, SiteMapView::LayerMachines,
                       SiteMapView::LayerLabels, SiteMapView::LayerTrails, SiteMapView::LayerOwnPosition,
                       SiteMapView::LayerScaleBar, SiteMapView::LayerNorthArrow, SiteMapView::LayerCursor})
            view.setLayerVisible(l, false);
        view.setPassCountLayer(layer.get());
        const auto swatch = [](const QImage& img, int count) {
            const QRgb want = passCountDiscreteColor(count).rgb();
            QRect r;
            for (int y = 0; y < img.height(); ++y)
                for (int x = 0; x < img.width(); ++x)
                    if ((img.pixel(x, y) & 0xffffff) == (want & 0xffffff))
                        r |= QRect(x, y, 1, 1);
            return r;
        };
        for (const QSize size : {QSize(800, 600), QSize(800, 200)}) {
            view.resize(size);
            view.setView(QPointF(1e6, 1e6), 1.0); // away from the strip: only the legend has these colours
            QImage img(size, QImage::Format_RGB32);
            img.fill(Qt::white);
            {
                QPainter p(&img);
                view.paintScene(p, size);
            }
            const QRect one = swatch(img, 1), nine = swatch(img, 9);
            QVERIFY(!one.isEmpty() && !nine.isEmpty());
            if (size.height() > 300) { // a column: 9+ below 1
                QCOMPARE(nine.left(), one.left());
                QVERIFY(nine.top() > one.bottom());
            } else { // a row: 9+ right of 1, the legend within the lowest quarter
                QCOMPARE(nine.top(), one.top());
                QVERIFY(nine.left() > one.right());
                QVERIFY2(one.top() > size.height() * 3 / 4 - 30, qPrintable(QString::number(one.top())));
            }
        }
    }
};

QTEST_MAIN(TestPassCountOverlay)
#include "test_pass_count_overlay.moc"
