// bench_sitemap: SiteMapView repaint at 1920x1080 on the offscreen raster engine with the acceptance scene:
// 1,000 machines (12 x 7 m, with full 120-point trails), 5,000 ways (10-point polylines, 1 km²) and a 1 km²
// pass-count layer at 0.34 m cells (2,941² cells).
//  * BM_FullRepaint: everything redrawn, the whole static layer included (what a zoom costs).
//  * BM_PanRepaint: a drag by a few pixels: the cached static layer is shifted, only the exposed strips
//  drawn.
//  * BM_FrameMachinesMoving: the 10 Hz case: machines move, the cached static layer is blitted.
//  * BM_PassCountRecolour: a pass-count change: the changed tiles recoloured, the static layer's patch
//    over them redrawn, then the frame.
// Each reports ms per frame; the acceptance budget is 33 ms for the full repaint.
#include "models/FleetModel.h"
#include "models/FleetSelection.h"
#include "models/PassCountLayer.h"
#ifdef OCU_BENCH_HAVE_PIT
#include "sim/iso23725/PitTerrain.h"
#endif
#include "widgets/MapBackground.h"
#include "widgets/SiteMapView.h"

#include <QApplication>
#include <QImage>
#include <QPainter>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <benchmark/benchmark.h>
#include <cmath>
#include <memory>

using namespace ocu;

namespace {
struct Scene {
    FleetModel fleet;
    FleetSelection selection{&fleet};
    std::unique_ptr<GridPassCountLayer> pass;
    SiteMapView view;
    QImage target{1920, 1080, QImage::Format_ARGB32_Premultiplied};
    QVector<MachineState> machines;
    int tick = 0;

    Scene() {
        fleet.setRefreshIntervalMs(0);
        QRandomGenerator rng(42);
        SiteMapData map;
        const char* tasks[] = {"haul", "load", "dump", "park", "compact"};
        for (int i = 0; i < 5000; ++i) {
            MapFeature f;
            f.id = QString::number(i);
            f.name = QStringLiteral("Way %1").arg(i);
            f.kind = i % 10 == 0 ? MapFeatureKind::Lane : MapFeatureKind::Road;
            f.defaultTask = QString::fromLatin1(tasks[i % 5]);
            f.width = 0; // centre lines: the widths of 5,000 roads are drawn only when zoomed in
            QPointF p(rng.bounded(1000.0) - 500, rng.bounded(1000.0) - 500);
            for (int k = 0; k < 10; ++k) {
                f.points.push_back(p);
                p += QPointF(rng.bounded(24.0) - 12, rng.bounded(24.0) - 12);
            }
            map.features.push_back(f);
        }
        // 1 km² at 0.34 m (TRex cell size): 2941 x 2941 cells, with passes on half of it.
        pass = std::make_unique<GridPassCountLayer>(QPointF(-500, -500), 0.34, 2941, 2941);
        for (int i = 0; i < 400; ++i) {
            const int c = int(rng.bounded(2800)), r = int(rng.bounded(2800));
            pass->fillRect(QRect(c, r, 40 + int(rng.bounded(200)), 40 + int(rng.bounded(200))),
                           1 + int(rng.bounded(9)));
        }
        for (int i = 0; i < 1000; ++i) {
            MachineState m;
            m.id = QStringLiteral("iso23725:T%1").arg(i);
            m.protocol = Protocol::Iso23725;
            m.name = QStringLiteral("T%1").arg(i);
            m.type = QStringLiteral("haul truck");
            m.link = LinkState::Up;
            m.hasPosition = true;
            m.e = rng.bounded(1000.0) - 500;
            m.n = rng.bounded(1000.0) - 500;
            m.headingDeg = rng.bounded(360.0);
            m.length = 12;
            m.width = 7;
            m.stop = i % 50 == 0 ? StopState::Stopped : StopState::None;
            m.mode = ModeCategory::Autonomous;
            m.health = HealthLevel::Ok;
            machines.push_back(m);
        }
        view.resize(1920, 1080);
        view.setFleet(&fleet, &selection);
        view.setSiteMap(map);
        view.setPassCountLayer(pass.get());
        // Full trails: 120 points per machine (one per metre travelled, the default trail length).
        for (int k = 0; k < 125; ++k)
            move(1.5);
        view.setView({0, 0}, 1080.0 / 1000.0); // the whole square kilometre on screen
    }
    void move(double metres) {
        ++tick;
        for (MachineState& m : machines) {
            const double h = m.headingDeg * M_PI / 180;
            m.e += std::sin(h) * metres;
            m.n += std::cos(h) * metres;
            if (std::abs(m.e) > 495 || std::abs(m.n) > 495) // turn back at the edge: all stay in view
                m.headingDeg = std::fmod(m.headingDeg + 180, 360);
        }
        fleet.upsert(machines);
    }
    void paint() {
        QPainter p(&target);
        view.paintScene(p, target.size());
    }
};

Scene& scene() {
    static Scene s;
    return s;
}
} // namespace

static void BM_FullRepaint(benchmark::State& state) {
    Scene& s = scene();
    s.paint(); // pass-count colour image built once
    for (auto _ : state) {
        // A different scale each time (a zoom): the whole static layer is redrawn. (A pan no longer redraws
        // it: BM_PanRepaint.)
        s.view.setView({0, 0}, s.view.scale() == 1.08 ? 1.08 * (1 + 1e-9) : 1.08);
        s.paint();
        if (!s.view.lastFrame().staticRebuilt)
            state.SkipWithError("static layer was not rebuilt");
    }
    state.counters["machines"] = s.view.lastFrame().machinesDrawn;
    state.counters["ways"] = s.view.lastFrame().featuresDrawn;
}
BENCHMARK(BM_FullRepaint)->Unit(benchmark::kMillisecond)->MinTime(2.0);

static void BM_PanRepaint(benchmark::State& state) {
    Scene& s = scene();
    s.view.setView({0, 0}, 1.08);
    s.paint();
    int k = 0;
    for (auto _ : state) {
        const double sign = (k++ / 8) % 2 ? -1 : 1; // to and fro, the whole square kilometre stays in view
        s.view.panByPixels(QPointF(7 * sign, -3 * sign));
        s.paint();
        if (s.view.lastFrame().staticRebuilt || !s.view.lastFrame().staticUpdated)
            state.SkipWithError("the static layer was not shifted");
    }
    s.view.setView({0, 0}, 1.08);
}
BENCHMARK(BM_PanRepaint)->Unit(benchmark::kMillisecond)->MinTime(2.0);

static void BM_FrameMachinesMoving(benchmark::State& state) {
    Scene& s = scene();
    s.paint();
    for (auto _ : state) {
        state.PauseTiming();
        s.move(0.3);
        state.ResumeTiming();
        s.paint();
    }
    state.counters["static_rebuilt"] = s.view.lastFrame().staticRebuilt ? 1 : 0;
}
BENCHMARK(BM_FrameMachinesMoving)->Unit(benchmark::kMillisecond)->MinTime(2.0);

// Components of the cached frame: 0 = static blit + overlays only, 1 = + machines, 2 = + trails.
static void BM_FrameComponents(benchmark::State& state) {
    Scene& s = scene();
    const int what = int(state.range(0));
    s.view.setLayerVisible(SiteMapView::LayerMachines, what >= 1);
    s.view.setLayerVisible(SiteMapView::LayerTrails, what >= 2);
    s.paint();
    for (auto _ : state)
        s.paint();
    s.view.setLayerVisible(SiteMapView::LayerMachines, true);
    s.view.setLayerVisible(SiteMapView::LayerTrails, true);
}
BENCHMARK(BM_FrameComponents)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->MinTime(1.0);

static void BM_PassCountRecolour(benchmark::State& state) {
    Scene& s = scene();
    int k = 0;
    for (auto _ : state) {
        s.pass->setCount(k % 2941, 100, 3 + k % 3); // one new pass: revision bump
        ++k;
        s.view.passCountChanged();
        s.paint();
    }
}
BENCHMARK(BM_PassCountRecolour)->Unit(benchmark::kMillisecond)->MinTime(2.0);

#ifdef OCU_BENCH_HAVE_PIT
// The simulated pit as an operator sees it at 1920x1080 — 1,000 haul trucks (SVG symbols at the
// minimum legible size, decluttered name labels, trails), the pit's roads and areas with their names, and the
// pit's hillshade as background raster (GDAL-warped tile pyramid).
//  * BM_FullRepaintSite: scale changed every frame, so the static layer (background tiles, roads, areas) is
//    redrawn too: what a zoom costs. Budget 16 ms, aim 8 ms.
//  * BM_FrameSite: trucks moved, static layer cached (the 10 Hz case).
namespace {
struct SiteScene {
    FleetModel fleet;
    FleetSelection selection{&fleet};
    SiteMapView view;
    QImage target{1920, 1080, QImage::Format_ARGB32_Premultiplied};
    QVector<MachineState> machines;
    QTemporaryDir dir;
    int labelsPlaced = 0;

    SiteScene() {
        fleet.setRefreshIntervalMs(0);
        const ocu::sim::PitLayout layout{2, 2, {48.2085, 11.4702, 480.0}};
        const ocu::sim::PitMap pit = ocu::sim::generatePitMap(layout, 0);
        const auto files = ocu::sim::writePitTerrain(pit, layout.origin, dir.path().toStdString());
        if (!files.error.empty())
            qFatal("pit terrain: %s", files.error.c_str());
        const auto bg = MapBackground::load(QString::fromStdString(files.hillshade), GeoFrame(layout.origin));
        if (!bg.background)
            qFatal("background: %s", qPrintable(bg.error));
        SiteMapData map;
        for (const auto& [id, way] : pit.map.ways) {
            MapFeature f;
            f.id = QString::number(id);
            f.name = QString::fromStdString(way.name());
            f.kind = way.kind == ocu::iso23725::WayKind::Area   ? MapFeatureKind::Area
                     : way.kind == ocu::iso23725::WayKind::Lane ? MapFeatureKind::Lane
                                                                : MapFeatureKind::Road;
            f.defaultTask = QString::fromStdString(way.defaultTask()).toLower();
            f.width = f.kind == MapFeatureKind::Area ? 0 : 12;
            for (auto n : way.nodes)
                f.points.push_back({pit.map.nodes.at(n).enu.e, pit.map.nodes.at(n).enu.n});
            map.features.push_back(f);
        }
        QRandomGenerator rng(19);
        for (int i = 0; i < 1000; ++i) {
            MachineState m;
            m.id = QStringLiteral("iso23725:T%1").arg(i, 4, 10, QLatin1Char('0'));
            m.protocol = Protocol::Iso23725;
            m.name = QStringLiteral("HT%1").arg(i, 4, 10, QLatin1Char('0'));
            m.type = QStringLiteral("haul truck");
            m.link = LinkState::Up;
            m.hasPosition = true;
            m.e = rng.bounded(1100.0) - 550;
            m.n = rng.bounded(1100.0) - 650;
            m.headingDeg = rng.bounded(360.0);
            m.length = 12;
            m.width = 7;
            m.stop = i % 50 == 0 ? StopState::Stopped : StopState::None;
            m.mode = ModeCategory::Autonomous;
            m.health = i % 97 == 0 ? HealthLevel::Fault : HealthLevel::Ok;
            machines.push_back(m);
        }
        view.resize(1920, 1080);
        view.setFleet(&fleet, &selection);
        view.setGeoFrame(GeoFrame(layout.origin));
        view.setSiteMap(map);
        view.setBackground(bg.background);
        for (int k = 0; k < 125; ++k)
            move(1.5);
        selection.setCurrent(machines[500].id);
        view.setView({0, -150}, 1080.0 / 1250.0); // the pit and its dumps on screen
    }
    void move(double metres) {
        for (MachineState& m : machines) {
            const double h = m.headingDeg * M_PI / 180;
            m.e += std::sin(h) * metres;
            m.n += std::cos(h) * metres;
            if (std::abs(m.e) > 550 || m.n > 450 || m.n < -750)
                m.headingDeg = std::fmod(m.headingDeg + 180, 360);
        }
        fleet.upsert(machines);
    }
    void paint() {
        QPainter p(&target);
        view.paintScene(p, target.size());
        labelsPlaced = int(view.labelPlacements().size());
    }
};

SiteScene& siteScene() {
    static SiteScene s;
    return s;
}
} // namespace

static void BM_FullRepaintSite(benchmark::State& state) {
    SiteScene& s = siteScene();
    s.paint(); // symbol and label caches warm, as after the first second on screen
    const double scale = 1080.0 / 1250.0;
    for (auto _ : state) {
        s.view.setView({0, -150}, s.view.scale() == scale ? scale * (1 + 1e-9) : scale);
        s.paint();
        if (!s.view.lastFrame().staticRebuilt)
            state.SkipWithError("static layer was not rebuilt");
    }
    state.counters["machines"] = s.view.lastFrame().machinesDrawn;
    state.counters["labels"] = s.labelsPlaced;
}
BENCHMARK(BM_FullRepaintSite)->Unit(benchmark::kMillisecond)->MinTime(2.0);

static void BM_FrameSite(benchmark::State& state) {
    SiteScene& s = siteScene();
    s.paint();
    for (auto _ : state) {
        state.PauseTiming();
        s.move(0.3);
        state.ResumeTiming();
        s.paint();
    }
    state.counters["labels"] = s.labelsPlaced;
}
BENCHMARK(BM_FrameSite)->Unit(benchmark::kMillisecond)->MinTime(2.0);
#endif

int main(int argc, char** argv) {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
