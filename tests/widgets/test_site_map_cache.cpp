// The site map's cached static layer: what a view shows after pans (the layer shifted, only strips drawn),
// pass-count changes (only their patch redrawn), a zoom, new ways and the night palette equals, pixel for
// pixel, what a fresh view that never cached anything draws at the same place.
#include "models/FleetModel.h"
#include "models/FleetSelection.h"
#include "models/PassCountLayer.h"
#include "widgets/SiteMapView.h"

#include <QBoxLayout>
#include <QPainter>
#include <QRandomGenerator>
#include <QScreen>
#include <QTest>

using namespace ocu;

namespace {
// Areas (antialiased), sparse roads and lanes with names, or thousands of ways (the dense 1 px path).
SiteMapData siteMap(int ways, QPointF offset = {}) {
    SiteMapData map;
    QRandomGenerator rng(7);
    const char* tasks[] = {"haul", "load", "dump", "park", "compact"};
    MapFeature area;
    area.id = QStringLiteral("pit");
    area.name = QStringLiteral("Pit area");
    area.kind = MapFeatureKind::Area;
    area.defaultTask = QStringLiteral("load");
    area.points = {{-80, -60}, {70, -70}, {90, 50}, {-60, 80}};
    map.features.push_back(area);
    for (int i = 0; i < ways; ++i) {
        MapFeature f;
        f.id = QString::number(i);
        f.name = QStringLiteral("Road %1").arg(i);
        f.kind = i % 10 == 0 ? MapFeatureKind::Lane : MapFeatureKind::Road;
        f.defaultTask = QString::fromLatin1(tasks[i % 5]);
        f.width = i % 3 == 0 ? 6 : 0; // some at their real width
        QPointF p(rng.bounded(300.0) - 150, rng.bounded(300.0) - 150);
        for (int k = 0; k < 6; ++k) {
            f.points.push_back(p + offset);
            p += QPointF(rng.bounded(40.0) - 20, rng.bounded(40.0) - 20);
        }
        map.features.push_back(f);
    }
    return map;
}

struct Differences {
    int pixels = 0;
    int maxChannel = 0;
    QRect where;
};

Differences compare(const QImage& a, const QImage& b) {
    Differences d;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
            const int m = std::max({std::abs(qRed(p) - qRed(q)), std::abs(qGreen(p) - qGreen(q)),
                                    std::abs(qBlue(p) - qBlue(q))});
            if (m > 0) {
                ++d.pixels;
                d.where |= QRect(x, y, 1, 1);
                d.maxChannel = std::max(d.maxChannel, m);
            }
        }
    return d;
}

const QSize kSize(480, 360);

QImage render(SiteMapView& v) {
    QImage img(kSize, QImage::Format_RGB32);
    QPainter p(&img);
    v.paintScene(p, img.size());
    return img;
}

void staticOnly(SiteMapView& v) {
    // Only what the static layer holds (no scale bar or arrow over it, no legend).
    for (auto l : {SiteMapView::LayerMachines, SiteMapView::LayerLabels, SiteMapView::LayerTrails,
                   SiteMapView::LayerOwnPosition, SiteMapView::LayerLegend, SiteMapView::LayerScaleBar,
                   SiteMapView::LayerNorthArrow, SiteMapView::LayerCursor, SiteMapView::LayerMapNames})
        v.setLayerVisible(l, false);
}
} // namespace

class TestSiteMapCache : public QObject {
    Q_OBJECT
private:
    // What a view that never drew before shows at `from`'s place.
    QImage uncached(const SiteMapView& from, const PassCountLayer* pass, bool night = false) {
        SiteMapView fresh;
        fresh.resize(kSize);
        if (night) {
            QPalette dark = fresh.palette();
            dark.setColor(QPalette::Window, QColor(30, 30, 34));
            fresh.setPalette(dark);
        }
        fresh.setSiteMap(from.siteMap());
        fresh.setPassCountLayer(pass);
        staticOnly(fresh);
        fresh.setView(from.center(), from.scale());
        return render(fresh);
    }

    // `tolerance`: pixels that may differ (antialiased 1 px lines that cross a strip's edge: Qt's cosmetic
    // stroker starts their antialiasing where the clip cuts them, a fraction of a pixel's coverage).
    void expectSame(const QImage& cached, const QImage& fresh, const char* what, int tolerance = 0) {
        const Differences d = compare(cached, fresh);
        QVERIFY2(d.pixels <= tolerance, qPrintable(QStringLiteral("%1: %2 pixels differ, by up to %3, in %4")
                                                       .arg(QLatin1String(what))
                                                       .arg(d.pixels)
                                                       .arg(d.maxChannel)
                                                       .arg(QStringLiteral("%1,%2 %3x%4")
                                                                .arg(d.where.x())
                                                                .arg(d.where.y())
                                                                .arg(d.where.width())
                                                                .arg(d.where.height()))));
    }

private slots:
    void pansShiftTheLayerAndMatchAFullRedraw_data() {
        QTest::addColumn<int>("ways");
        QTest::newRow("areas and a few antialiased roads") << 60;
        QTest::newRow("thousands of 1 px ways") << 3000;
    }
    void pansShiftTheLayerAndMatchAFullRedraw() {
        QFETCH(int, ways);
        // Thousands of ways are drawn aliased into the pixels (exact); a few antialiased by QPainter.
        const int antialiased = ways < 1000 ? kSize.width() * kSize.height() / 200 : 0;
        GridPassCountLayer pass({-100, -100}, 0.5, 400, 400);
        pass.fillRect(QRect(40, 60, 120, 90), 3);
        pass.fillRect(QRect(200, 220, 60, 150), 7);
        SiteMapView view;
        view.resize(kSize);
        view.setSiteMap(siteMap(ways));
        view.setPassCountLayer(&pass);
        staticOnly(view);
        view.setView({3.3, -7.1}, 1.7);
        render(view);
        QVERIFY(view.lastFrame().staticRebuilt);
        const QPointF drags[] = {{12, 0}, {0, -9}, {-31, 17}, {5, 5}, {-200, 3}, {0, 150}};
        for (const QPointF& d : drags) {
            view.panByPixels(d);
            const QImage cached = render(view);
            QVERIFY(!view.lastFrame().staticRebuilt); // shifted, only the exposed strips drawn
            QVERIFY(view.lastFrame().staticUpdated);
            expectSame(cached, uncached(view, &pass), "after a pan", antialiased);
        }
        // A pan by a fraction of a pixel cannot shift whole pixels: the layer is redrawn.
        view.panByPixels({0.4, 0});
        const QImage cached = render(view);
        QVERIFY(view.lastFrame().staticRebuilt);
        expectSame(cached, uncached(view, &pass), "after a fractional pan"); // redrawn whole: exact
    }

    void zoomRedrawsTheLayer() {
        SiteMapView view;
        view.resize(kSize);
        view.setSiteMap(siteMap(60));
        staticOnly(view);
        view.setView({0, 0}, 1.5);
        render(view);
        view.zoomBy(1.25, {100, 80});
        const QImage cached = render(view);
        QVERIFY(view.lastFrame().staticRebuilt);
        expectSame(cached, uncached(view, nullptr), "after a zoom");
        render(view);
        QVERIFY(!view.lastFrame().staticRebuilt && !view.lastFrame().staticUpdated); // nothing changed
    }

    void newWaysRedrawTheLayer() {
        SiteMapView view;
        view.resize(kSize);
        view.setSiteMap(siteMap(60));
        staticOnly(view);
        view.setView({0, 0}, 1.5);
        const QImage before = render(view);
        view.setSiteMap(siteMap(60, {25, -10})); // the same ways, moved
        const QImage after = render(view);
        QVERIFY(view.lastFrame().staticRebuilt);
        QVERIFY(compare(before, after).pixels > 1000);
        expectSame(after, uncached(view, nullptr), "after new ways");
    }

    void nightPaletteRedrawsTheLayer() {
        SiteMapView view;
        view.resize(kSize);
        view.setSiteMap(siteMap(60));
        staticOnly(view);
        view.setView({0, 0}, 1.5);
        const QImage day = render(view);
        QPalette dark = view.palette();
        dark.setColor(QPalette::Window, QColor(30, 30, 34));
        view.setPalette(dark);
        QVERIFY(view.isNight());
        const QImage night = render(view);
        QVERIFY(view.lastFrame().staticRebuilt);
        QVERIFY(qGray(night.pixel(2, 2)) < qGray(day.pixel(2, 2)) - 80); // the ground dimmed
        expectSame(night, uncached(view, nullptr, true), "at night");
        view.panByPixels({-14, 6}); // a pan at night dims the strips too
        expectSame(render(view), uncached(view, nullptr, true), "a pan at night",
                   kSize.width() * kSize.height() / 200);
    }

    void passCountChangeRedrawsOnlyItsPatch() {
        GridPassCountLayer pass({-100, -100}, 0.5, 400, 400);
        pass.fillRect(QRect(40, 60, 120, 90), 3);
        SiteMapView view;
        view.resize(kSize);
        view.setSiteMap(siteMap(60));
        view.setPassCountLayer(&pass);
        staticOnly(view);
        view.setView({0, 0}, 1.5);
        view.setPassOverlayFrameBudget(0);
        const QImage before = render(view);
        pass.fillRect(QRect(250, 250, 20, 10), 8); // E 25..35, N 25..30
        view.passCountChanged();
        const QImage after = render(view);
        QVERIFY(!view.lastFrame().staticRebuilt);
        QVERIFY(view.lastFrame().staticUpdated);
        expectSame(after, uncached(view, &pass), "after new passes");
        QVERIFY(compare(before, after).pixels > 50); // the new passes are shown (10 x 5 m, 15 x 7 px)
        // A palette change recolours everything.
        view.setPassPalette(PassPalette::Summary);
        const QImage summary = render(view);
        QVERIFY(view.lastFrame().staticRebuilt);
        QVERIFY(compare(summary, after).pixels > 1000);
    }

    // Hundreds of trails are written straight into the window's backing store, where the map sits in the
    // window (here 40 px right and 30 px down), and nowhere else.
    void trailsAreWrittenIntoTheWindowWhereTheMapIs() {
        FleetModel fleet;
        fleet.setRefreshIntervalMs(0);
        FleetSelection selection(&fleet);
        QWidget window;
        auto* layout = new QVBoxLayout(&window);
        layout->setContentsMargins(40, 30, 0, 0);
        auto* view = new SiteMapView;
        layout->addWidget(view);
        window.resize(440, 330);
        view->setFleet(&fleet, &selection);
        view->setMaxDataFrameRate(0);
        QVector<MachineState> ms;
        for (int i = 0; i < 250; ++i) {
            MachineState m;
            m.id = QStringLiteral("iso23725:T%1").arg(i);
            m.protocol = Protocol::Iso23725;
            m.name = m.id;
            m.hasPosition = true;
            m.link = LinkState::Up;
            m.e = -100;
            m.n = i * 2.0;
            ms.push_back(m);
        }
        for (int k = 0; k <= 50; ++k) { // eastwards from E -100 to E 0
            for (MachineState& m : ms)
                m.e = -100 + 2.0 * k;
            fleet.upsert(ms);
        }
        staticOnly(*view);
        view->setLayerVisible(SiteMapView::LayerTrails, true);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QCOMPARE(view->pos(), QPoint(40, 30));
        view->setView({0, 150}, 1.0); // whole pixels: E -50 is x 150 in the map
        QTest::qWait(50);
        QCoreApplication::processEvents();
        const QImage shot = window.screen()->grabWindow(window.winId()).toImage();
        const QColor trail(0x55, 0x55, 0x88);
        int found = 0;
        QVERIFY(view->lastFrame().trailsIntoTarget); // not into a copy of the static layer
        for (int i = 10; i < 150; i += 10) {         // N 20..280 m: y 280..20
            const QPoint at = view->mapTo(&window, view->worldToScreen({-50, i * 2.0}).toPoint());
            found += shot.pixelColor(at) == trail ? 1 : 0;
            QVERIFY(shot.pixelColor(at + QPoint(0, 1)) != trail); // 1 px high, 2 m apart
        }
        QCOMPARE(found, 14);
        for (int y = 0; y < 30; ++y) // the margin outside the map stays the window's
            for (int x = 0; x < shot.width(); x += 7)
                QVERIFY(shot.pixelColor(x, y) != trail);
    }
};

QTEST_MAIN(TestSiteMapCache)
#include "test_site_map_cache.moc"
