// Symbols, labels and navigation of the 2D map, offscreen: machine symbols (SVG per type, true size vs
// minimum size), label decluttering checked from the view's own placement data, road labels along their road,
// follow, edge indicators, the start-up fit that keeps including machines, zoom to selection/area, hover,
// double-click.
#include "models/FleetModel.h"
#include "models/FleetSelection.h"
#include "widgets/MapSymbols.h"
#include "widgets/SiteMapView.h"

#include <QFile>
#include <QImage>
#include <QPainter>
#include <QRandomGenerator>
#include <QSignalSpy>
#include <QSvgRenderer>
#include <QTest>

using namespace ocu;

namespace {
MachineState machine(const QString& id, double e, double n, double heading = 0,
                     const QString& type = QStringLiteral("haul truck")) {
    MachineState m;
    m.id = id;
    m.protocol = protocolOfId(id);
    m.name = id.section(QLatin1Char(':'), 1);
    m.type = type;
    m.link = LinkState::Up;
    m.hasPosition = true;
    m.e = e;
    m.n = n;
    m.headingDeg = heading;
    m.length = 12;
    m.width = 7;
    m.stop = StopState::None;
    m.health = HealthLevel::Ok;
    m.mode = ModeCategory::Manual;
    return m;
}

MapFeature road(const QString& id, const QString& name, QVector<QPointF> pts, double width = 10) {
    MapFeature f;
    f.id = id;
    f.name = name;
    f.kind = MapFeatureKind::Road;
    f.defaultTask = QStringLiteral("haul");
    f.points = std::move(pts);
    f.width = width;
    return f;
}

MapFeature area(const QString& id, const QString& name, QRectF r) {
    MapFeature f;
    f.id = id;
    f.name = name;
    f.kind = MapFeatureKind::Area;
    f.defaultTask = QStringLiteral("load");
    f.points = {r.topLeft(), r.topRight(), r.bottomRight(), r.bottomLeft(), r.topLeft()};
    return f;
}

void paint(SiteMapView& v, QSize size = {1366, 768}) {
    QImage img(size, QImage::Format_ARGB32_Premultiplied);
    QPainter p(&img);
    v.paintScene(p, size);
}

// Every pair of placed labels: none may overlap (rects touching at an edge do not intersect).
int overlaps(const QVector<MapLabelLayout::Placed>& placed, QString* what) {
    int bad = 0;
    for (int i = 0; i < placed.size(); ++i)
        for (int j = i + 1; j < placed.size(); ++j)
            if (placed[i].rect.intersects(placed[j].rect)) {
                if (what && bad == 0)
                    *what = placed[i].text + QStringLiteral(" / ") + placed[j].text;
                ++bad;
            }
    return bad;
}
} // namespace

class TestSiteMapSymbols : public QObject {
    Q_OBJECT
    FleetModel* fleet = nullptr;
    FleetSelection* selection = nullptr;

private slots:
    void init() {
        fleet = new FleetModel(this);
        fleet->setRefreshIntervalMs(0);
        selection = new FleetSelection(fleet, this);
    }
    void cleanup() {
        delete selection;
        delete fleet;
    }

    void everyTypeHasAValidSvg() {
        for (int s = 0; s < kMachineSymbolCount; ++s) {
            const QString path = QStringLiteral(":/symbols/%1.svg").arg(symbolName(MachineSymbol(s)));
            MapSymbolCache cache; // registers the resources
            QFile f(path);
            QVERIFY2(f.open(QIODevice::ReadOnly), qPrintable(path));
            const QByteArray svg = f.readAll();
            QVERIFY2(svg.contains("#00ff01"), "the state colour placeholder is missing");
            QSvgRenderer r(svg);
            QVERIFY2(r.isValid(), qPrintable(path));
        }
        QCOMPARE(symbolForType(QStringLiteral("haul truck")), MachineSymbol::HaulTruck);
        QCOMPARE(symbolForType(QStringLiteral("UGV")), MachineSymbol::Ugv);
        QCOMPARE(symbolForType(QStringLiteral("roller")), MachineSymbol::Roller);
        QCOMPARE(symbolForType(QStringLiteral("paver")), MachineSymbol::Paver);
        QCOMPARE(symbolForType(QStringLiteral("Shovel")), MachineSymbol::Loader);
        QCOMPARE(symbolForType(QStringLiteral("LightVehicle")), MachineSymbol::LightVehicle);
        QCOMPARE(symbolForType(QStringLiteral("zeppelin")), MachineSymbol::Unknown);
    }

    void symbolsTrueSizeWhenZoomedInMinimumWhenOut() {
        // 12 x 7 m at 10 px/m: true size.
        QCOMPARE(MapSymbolCache::footprintPx(12, 7, 10), QSizeF(70, 120));
        // At 0.5 px/m the truck would be 6 px long: drawn at the legible minimum, proportions kept.
        const QSizeF small = MapSymbolCache::footprintPx(12, 7, 0.5);
        QCOMPARE(small.height(), MapSymbolCache::kMinLengthPx);
        QVERIFY(small.width() >= MapSymbolCache::kMinWidthPx);
        // The cached image is coloured by state and rotated: north-up vs east-up differ, and a fault is red.
        MapSymbolCache cache;
        SymbolStyle ok{MachineSymbol::HaulTruck, StatusCategory::Ok, SymbolRing::None, false};
        SymbolStyle fault{MachineSymbol::HaulTruck, StatusCategory::FaultOrStopped, SymbolRing::None, false};
        const QImage north = cache.image({14, 24}, 0, ok, 1), east = cache.image({14, 24}, 90, ok, 1);
        QVERIFY(!north.isNull() && !east.isNull());
        QVERIFY(north != east);
        const QImage red = cache.image({14, 24}, 0, fault, 1);
        const QPoint mid(red.width() / 2, red.height() / 2 - 4); // on the dump body
        QCOMPARE(QColor(red.pixel(mid)).rgb() & 0xffffff,
                 statusColor(StatusCategory::FaultOrStopped).rgb() & 0xffffff);
        QCOMPARE(QColor(north.pixel(mid)).rgb() & 0xffffff, statusColor(StatusCategory::Ok).rgb() & 0xffffff);
        // Same style again: from the cache, not rendered again.
        const int renders = cache.renders();
        cache.image({14, 24}, 1, ok, 1); // same 5° heading bucket
        QCOMPARE(cache.renders(), renders);
    }

    void thousandMachinesLabelsNeverOverlap() {
        QVector<MachineState> ms;
        QRandomGenerator rng(7);
        for (int i = 0; i < 1000; ++i)
            ms.push_back(machine(QStringLiteral("iso23725:T%1").arg(i), rng.bounded(800.0) - 400,
                                 rng.bounded(800.0) - 400, rng.bounded(360.0)));
        ms[10].stop = StopState::Stopped;
        fleet->upsert(ms);
        SiteMapData map;
        // The two ramp lanes 12 m apart: their names used to be drawn over each other.
        QVector<QPointF> down, up;
        for (int k = 0; k <= 10; ++k) {
            down.push_back({-6.0, 200 - 50.0 * k});
            up.push_back({6.0, -300 + 50.0 * k});
        }
        map.features << road(QStringLiteral("1"), QStringLiteral("Main ramp down"), down)
                     << road(QStringLiteral("2"), QStringLiteral("Main ramp up"), up)
                     << area(QStringLiteral("3"), QStringLiteral("Pit 1 shovel 1"),
                             QRectF(-300, -300, 80, 80));
        SiteMapView v;
        v.setFleet(fleet, selection);
        v.setSiteMap(map);
        selection->setCurrent(QStringLiteral("iso23725:T500"));
        for (double scale : {0.6, 1.2, 3.0, 8.0}) {
            v.setView({0, 0}, scale);
            for (QSize size : {QSize(1366, 768), QSize(1920, 1080)}) {
                paint(v, size);
                const auto& placed = v.labelPlacements();
                QVERIFY2(placed.size() > 10, qPrintable(QString::number(placed.size())));
                QString what;
                QVERIFY2(overlaps(placed, &what) == 0,
                         qPrintable(QStringLiteral("scale %1: %2").arg(scale).arg(what)));
                for (const auto& l : placed)
                    QVERIFY(QRectF(QPointF(0, 0), QSizeF(size)).contains(l.rect));
                // The current machine's label has the first choice: it is always placed when in view.
                const MachineState* cur = fleet->machine(QStringLiteral("iso23725:T500"));
                if (QRectF(QPointF(0, 0), QSizeF(size))
                        .adjusted(80, 40, -80, -40)
                        .contains(v.worldToScreen({cur->e, cur->n}))) {
                    bool found = false;
                    for (const auto& l : placed)
                        found = found || l.text == QLatin1String("T500");
                    QVERIFY2(found, "the selected machine's label yielded");
                }
            }
        }
    }

    // Text drawn by an overlay (the dispatch route's label, the compaction design's station labels) is
    // reserved with the view: the machines' labels of that frame keep clear of it, and still get placed
    // elsewhere.
    void overlayTextIsKeptClearOfMachineLabels() {
        struct TextOverlay : SiteMapOverlay {
            QRectF rect;
            void paintOverlay(QPainter& p, const SiteMapView& view) override {
                p.fillRect(rect, Qt::magenta);
                view.reserveLabelArea(rect);
            }
        } overlay;
        QVector<MachineState> ms;
        for (int i = 0; i < 20; ++i)
            ms.push_back(machine(QStringLiteral("iso23725:T%1").arg(i), -100 + 10.0 * i, 0));
        fleet->upsert(ms);
        SiteMapView v;
        v.setFleet(fleet, selection);
        v.setView({0, 0}, 4.0);
        paint(v);
        QRectF where; // where T10's label goes without the overlay
        for (const auto& l : v.labelPlacements())
            if (l.text == QLatin1String("T10"))
                where = l.rect;
        QVERIFY(!where.isEmpty());
        overlay.rect = where.adjusted(-20, -6, 20, 6);
        v.addOverlay(&overlay);
        paint(v);
        QCOMPARE(v.reservedLabelAreas().size(), 1);
        bool t10 = false;
        for (const auto& l : v.labelPlacements()) {
            QVERIFY2(!l.rect.intersects(overlay.rect), qPrintable(l.text));
            t10 = t10 || l.text == QLatin1String("T10");
        }
        QVERIFY(t10); // moved, not dropped
    }

    void rampLaneNamesDoNotOverlapAndFollowTheRoad() {
        SiteMapData map;
        QVector<QPointF> down, up, diag;
        for (int k = 0; k <= 10; ++k) {
            down.push_back({-6.0, 200 - 50.0 * k});
            up.push_back({6.0, -300 + 50.0 * k});
            diag.push_back({300 + 20.0 * k, -300 + 20.0 * k}); // south-west to north-east
        }
        map.features << road(QStringLiteral("1"), QStringLiteral("Main ramp down"), down)
                     << road(QStringLiteral("2"), QStringLiteral("Main ramp up"), up)
                     << road(QStringLiteral("3"), QStringLiteral("Crusher road"), diag);
        SiteMapView v;
        v.setFleet(fleet, selection);
        v.setSiteMap(map);
        v.setView({150, -50}, 1.0);
        paint(v);
        QStringList names;
        for (const auto& l : v.labelPlacements()) {
            QCOMPARE(l.kind, MapLabelLayout::Kind::Road);
            names << l.text;
            if (l.text == QLatin1String("Crusher road"))
                QVERIFY2(std::abs(l.angleDeg + 45) < 3,
                         qPrintable(QString::number(l.angleDeg))); // up-right on screen
            else
                QVERIFY2(std::abs(std::abs(l.angleDeg) - 90) < 3, qPrintable(QString::number(l.angleDeg)));
        }
        // Both lanes are named, at different places along the ramp, without overlap.
        QVERIFY2(names.contains(QStringLiteral("Main ramp down")) &&
                     names.contains(QStringLiteral("Main ramp up")),
                 qPrintable(names.join(',')));
        QCOMPARE(overlaps(v.labelPlacements(), nullptr), 0);
    }

    // A road name is drawn after the machines: it keeps off a machine symbol on the road and moves along it.
    void roadNamesKeepOffMachineSymbols() {
        SiteMapData map;
        QVector<QPointF> diag;
        for (int k = 0; k <= 10; ++k)
            diag.push_back({-100 + 20.0 * k, -100 + 20.0 * k});
        map.features << road(QStringLiteral("3"), QStringLiteral("Crusher road"), diag);
        SiteMapView v;
        v.setFleet(fleet, selection);
        v.setSiteMap(map);
        v.setView({0, 0}, 3.0);
        v.setLayerVisible(SiteMapView::LayerLabels, false); // machine names elsewhere would hide the effect
        paint(v);
        QCOMPARE(v.labelPlacements().size(), 1);
        const QRectF first = v.labelPlacements().front().rect;
        // A truck right where the name was.
        const QPointF at = v.screenToWorld(first.center());
        fleet->upsert({machine(QStringLiteral("iso23725:T1"), at.x(), at.y(), 45)});
        paint(v);
        const QPointF c = v.worldToScreen(at);
        const QSizeF fp = MapSymbolCache::footprintPx(12, 7, v.scale());
        const double r = std::max(fp.width(), fp.height()) / 2;
        const QRectF symbol(c - QPointF(r, r), QSizeF(2 * r, 2 * r));
        QCOMPARE(v.labelPlacements().size(), 1); // still named, further along the road
        QVERIFY2(!v.labelPlacements().front().rect.intersects(symbol),
                 qPrintable(QStringLiteral("label at %1,%2")
                                .arg(v.labelPlacements().front().rect.x())
                                .arg(v.labelPlacements().front().rect.y())));
    }

    void followKeepsSelectedMachineInView() {
        fleet->upsert({machine(QStringLiteral("jaus:1"), 0, 0), machine(QStringLiteral("jaus:2"), 50, 50)});
        SiteMapView v;
        v.resize(800, 600);
        v.setFleet(fleet, selection);
        v.setView({0, 0}, 2.0);
        paint(v, {800, 600});
        selection->setCurrent(QStringLiteral("jaus:2"));
        v.setFollow(true);
        QVERIFY(!v.isAutoFitting());
        const QRectF view(0, 0, 800, 600);
        for (int step = 1; step <= 20; ++step) {
            const MachineState m = machine(QStringLiteral("jaus:2"), 50 + step * 400.0, 50 - step * 250.0);
            fleet->upsert({m});
            paint(v, {800, 600});
            QVERIFY2(view.contains(v.worldToScreen({m.e, m.n})), qPrintable(QString::number(step)));
        }
        // The other machine is now far off: indicated at the edge.
        QVERIFY(!v.edgeIndicators().isEmpty());
        // Panning by hand ends following.
        v.panByPixels({30, 0});
        QVERIFY(!v.isFollowing());
    }

    void machinesOutsideTheViewAreIndicatedAtTheEdge() {
        fleet->upsert({machine(QStringLiteral("jaus:1"), 0, 0), machine(QStringLiteral("jaus:2"), 5000, 0),
                       machine(QStringLiteral("jaus:3"), 0, 3000),
                       machine(QStringLiteral("jaus:4"), 10, 3300)});
        MachineState stopped = machine(QStringLiteral("jaus:5"), -4000, -10);
        stopped.stop = StopState::Stopped;
        fleet->upsert({stopped});
        SiteMapView v;
        v.resize(1000, 800);
        v.setFleet(fleet, selection);
        v.setView({0, 0}, 1.0);
        paint(v, {1000, 800});
        const auto& edges = v.edgeIndicators();
        QCOMPARE(edges.size(), 3); // east, north (two machines grouped), west
        int total = 0;
        bool east = false, north = false, west = false;
        for (const auto& e : edges) {
            total += e.count;
            if (e.pos.x() > 950 && std::abs(e.angleDeg) < 2 && e.firstId == QLatin1String("jaus:2"))
                east = true;
            if (e.pos.y() < 50 && std::abs(e.angleDeg + 90) < 2 && e.count == 2)
                north = true;
            if (e.pos.x() < 50 && e.worst == StatusCategory::FaultOrStopped)
                west = true;
        }
        QCOMPARE(total, 4);
        QVERIFY(east && north && west);
        // Clicking the east arrow brings that machine into view.
        for (const auto& e : edges)
            if (e.firstId == QLatin1String("jaus:2")) {
                QTest::mouseClick(&v, Qt::LeftButton, {}, e.pos.toPoint());
                break;
            }
        QVERIFY(QRectF(0, 0, 1000, 800).contains(v.worldToScreen({5000, 0})));
    }

    void startUpFitKeepsIncludingMachinesUntilOperatorTakesOver() {
        SiteMapView v;
        v.resize(1000, 800);
        v.setFleet(fleet, selection);
        SiteMapData map;
        map.features << area(QStringLiteral("a"), QStringLiteral("Pit"), QRectF(-100, -100, 200, 200));
        v.setSiteMap(map);
        QVERIFY(v.isAutoFitting());
        fleet->upsert({machine(QStringLiteral("iso23725:A"), 2000, 1500)});
        QVERIFY(QRectF(0, 0, 1000, 800).contains(v.worldToScreen({2000, 1500})));
        QVERIFY(QRectF(0, 0, 1000, 800).contains(v.worldToScreen({-100, -100})));
        fleet->upsert({machine(QStringLiteral("iso23725:B"), -3000, -800)});
        QVERIFY(QRectF(0, 0, 1000, 800).contains(v.worldToScreen({-3000, -800})));
        // A machine without a fix (0°/0° is thousands of km away) does not shrink the site to a dot.
        fleet->upsert({machine(QStringLiteral("iso23725:C"), 4.0e6, -5.2e6)});
        QVERIFY(v.scale() > 0.05);
        // The operator zooms with the wheel: the view is theirs from now on.
        QWheelEvent wheel(QPointF(500, 400), v.mapToGlobal(QPointF(500, 400)), {}, QPoint(0, 120),
                          Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(&v, &wheel);
        QVERIFY(!v.isAutoFitting());
        const double scale = v.scale();
        const QPointF centre = v.center();
        fleet->upsert({machine(QStringLiteral("iso23725:D"), 9000, 9000)});
        QCOMPARE(v.scale(), scale);
        QCOMPARE(v.center(), centre);
        v.refitIfAuto(); // what the site does when the map changes: no jump either
        QCOMPARE(v.scale(), scale);
    }

    void zoomToSelectionAreaAndFleet() {
        fleet->upsert({machine(QStringLiteral("jaus:1"), 0, 0), machine(QStringLiteral("jaus:2"), 600, 0),
                       machine(QStringLiteral("jaus:3"), 2000, 2000)});
        SiteMapData map;
        map.features << area(QStringLiteral("load1"), QStringLiteral("Shovel 1"), QRectF(1000, 1000, 100, 50))
                     << area(QStringLiteral("aoz"), QStringLiteral("AOZ"), QRectF(-500, -500, 3000, 3000));
        SiteMapView v;
        v.resize(1000, 800);
        v.setFleet(fleet, selection);
        v.setSiteMap(map);
        selection->select({QStringLiteral("jaus:1"), QStringLiteral("jaus:2")}, QStringLiteral("jaus:1"));
        v.zoomToSelection();
        QVERIFY(!v.isAutoFitting());
        const QRectF view(0, 0, 1000, 800);
        QVERIFY(view.contains(v.worldToScreen({0, 0})) && view.contains(v.worldToScreen({600, 0})));
        QVERIFY(!view.contains(v.worldToScreen({2000, 2000})));
        QVERIFY(v.zoomToArea(QStringLiteral("load1")));
        QVERIFY(view.contains(v.worldToScreen({1000, 1000})) && view.contains(v.worldToScreen({1100, 1050})));
        QVERIFY(v.scale() > 5); // 100 m across 1000 px, with a margin
        QVERIFY(!v.zoomToArea(QStringLiteral("nope")));
        // The innermost area under a pixel.
        QCOMPARE(v.areaAt(v.worldToScreen({1050, 1025})), QStringLiteral("load1"));
        v.setView({0, 0}, 0.2);
        QCOMPARE(v.areaAt(v.worldToScreen({0, 0})), QStringLiteral("aoz"));
        v.zoomToFleet();
        for (QPointF p : {QPointF(0, 0), QPointF(600, 0), QPointF(2000, 2000)})
            QVERIFY(view.contains(v.worldToScreen(p)));
    }

    void hoverShowsCardDoubleClickSelects() {
        fleet->upsert({machine(QStringLiteral("jaus:7"), 0, 0, 0, QStringLiteral("UGV")),
                       machine(QStringLiteral("jaus:8"), 80, 0, 0, QStringLiteral("roller"))});
        SiteMapView v;
        v.resize(800, 600);
        v.setFleet(fleet, selection);
        v.setView({0, 0}, 2.0);
        v.show();
        QVERIFY(QTest::qWaitForWindowExposed(&v));
        const QPoint at = v.worldToScreen({80, 0}).toPoint();
        QTest::mouseMove(&v, at);
        QTRY_COMPARE(v.hoveredMachine(), QStringLiteral("jaus:8"));
        // The card is painted next to the cursor (white box with text, not the plain map).
        QImage img(800, 600, QImage::Format_ARGB32_Premultiplied);
        {
            QPainter p(&img);
            v.paintScene(p, img.size());
        }
        int white = 0;
        for (int y = at.y() + 22; y < at.y() + 60; ++y)
            for (int x = at.x() + 22; x < at.x() + 120; ++x)
                white += QColor(img.pixel(x, y)).lightness() > 245 ? 1 : 0;
        QVERIFY2(white > 1500, qPrintable(QString::number(white)));
        QSignalSpy activated(&v, &SiteMapView::machineActivated);
        QTest::mouseDClick(&v, Qt::LeftButton, {}, v.worldToScreen({0, 0}).toPoint());
        QCOMPARE(selection->currentId(), QStringLiteral("jaus:7"));
        QCOMPARE(activated.size(), 1);
    }
};

QTEST_MAIN(TestSiteMapSymbols)
#include "test_site_map_symbols.moc"
