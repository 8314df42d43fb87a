// 3D site view throughput: 1,000 machines moving (10 Hz position updates from the fleet), rendered through
// the headless EGL path at 1280x800 including the read-back into a QImage (what the offscreen panel shows).
// Each benchmark iteration is one displayed frame; "fps" is frames per second of wall time.
#include "widgets/view3d/EglOffscreenRenderer.h"
#include "widgets/view3d/SiteSceneRenderer.h"

#include <QGuiApplication>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>

using namespace ocu;

namespace {

constexpr int kMachines = 1000;

Scene3D makeScene() {
    Scene3D s;
    for (int i = 0; i <= 40; ++i)
        for (int j = 0; j <= 40; ++j) {
            const double e = -1000.0 + 50.0 * i, n = -1000.0 + 50.0 * j;
            s.terrain.points.push_back({e, n, 15.0 * std::sin(e / 300.0) * std::cos(n / 250.0)});
        }
    for (int k = 0; k < 20; ++k) {
        Way3D road;
        road.points = {
            {-950.0, -950.0 + 100.0 * k, 0}, {0.0, -900.0 + 100.0 * k, 0}, {950.0, -950.0 + 100.0 * k, 0}};
        road.width = 12.0;
        s.ways.push_back(road);
    }
    // A 1 km x 0.5 km pass-count patch at 1 m cells (500,000 cells), TRex summary colours.
    PassCountRaster& r = s.passCount;
    r.originE = -500.0;
    r.originN = -250.0;
    r.cellSize = 1.0;
    r.cols = 1000;
    r.rows = 500;
    r.rgba.resize(static_cast<std::size_t>(r.cols) * r.rows * 4);
    for (std::size_t c = 0; c < static_cast<std::size_t>(r.cols) * r.rows; ++c) {
        const int passes = static_cast<int>(c % 7);
        const Rgb col = passes < 3 ? Rgb{30, 144, 255} : passes <= 5 ? Rgb{154, 205, 50} : Rgb{255, 0, 0};
        r.rgba[c * 4] = col.r;
        r.rgba[c * 4 + 1] = col.g;
        r.rgba[c * 4 + 2] = col.b;
        r.rgba[c * 4 + 3] = passes == 0 ? 0 : 255;
    }
    for (int i = 0; i < kMachines; ++i) {
        Machine3D m;
        m.id = QStringLiteral("M%1").arg(i);
        m.e = -900.0 + 60.0 * (i % 30);
        m.n = -900.0 + 55.0 * (i / 30);
        m.length = 12.0;
        m.width = 6.0;
        m.height = 5.0;
        m.colour = {static_cast<std::uint8_t>(i * 37 % 256), 160, static_cast<std::uint8_t>(i * 91 % 256)};
        s.machines.push_back(m);
    }
    return s;
}

void moveMachines(std::vector<Machine3D>& machines, int tick) {
    for (std::size_t i = 0; i < machines.size(); ++i) {
        Machine3D& m = machines[i];
        const double a = 0.05 * tick + static_cast<double>(i);
        m.e += std::cos(a) * 1.5;
        m.n += std::sin(a) * 1.5;
        m.headingDeg = std::fmod(90.0 - a * 57.2958, 360.0);
    }
}

// Every frame applies a fresh update of all 1,000 machines (worst case: updates arrive faster than 10 Hz).
void BM_UpdateAndRenderEvery(benchmark::State& state) {
    SiteSceneRenderer scene;
    scene.setScene(makeScene());
    EglOffscreenRenderer egl;
    if (!egl.initialize()) {
        state.SkipWithError(egl.errorString().toUtf8().constData());
        return;
    }
    std::vector<Machine3D> machines = scene.scene().machines;
    const QSize size(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
    egl.render(scene, size); // first frame builds shaders and buffers
    int tick = 0;
    for (auto _ : state) {
        moveMachines(machines, ++tick); // the renderer puts them on the terrain
        scene.updateMachines(machines);
        QImage img = egl.render(scene, size);
        benchmark::DoNotOptimize(img.constBits());
    }
    state.counters["fps"] =
        benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["rebuilds"] = static_cast<double>(scene.sceneBuildCount());
}
BENCHMARK(BM_UpdateAndRenderEvery)
    ->Args({1280, 800})
    ->Args({800, 600})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime() // CPU column = all threads (llvmpipe rasterises on worker threads)
    ->UseRealTime();

// The fast path alone: applying one 10 Hz update of 1,000 machines (no rendering).
void BM_UpdateMachinesOnly(benchmark::State& state) {
    SiteSceneRenderer scene;
    scene.setScene(makeScene());
    std::vector<Machine3D> machines = scene.scene().machines;
    int tick = 0;
    for (auto _ : state) {
        moveMachines(machines, ++tick); // the renderer puts them on the terrain
        scene.updateMachines(machines);
    }
}
BENCHMARK(BM_UpdateMachinesOnly)->Unit(benchmark::kMicrosecond);

// A new pass-count picture for the 1 km² grid of the OSYRIS anchor (0.34 m cells: 2941 x 2941 = 8.6 M cells),
// applied and rendered: the texture refill and upload path.
void BM_PassCount8MCellsUpdateAndRender(benchmark::State& state) {
    SiteSceneRenderer scene;
    scene.setScene(makeScene());
    EglOffscreenRenderer egl;
    if (!egl.initialize()) {
        state.SkipWithError(egl.errorString().toUtf8().constData());
        return;
    }
    PassCountRaster r;
    r.originE = -500.0;
    r.originN = -500.0;
    r.cellSize = 0.34;
    r.cols = r.rows = 2941;
    r.rgba.assign(static_cast<std::size_t>(r.cols) * r.rows * 4, 200);
    scene.setPassCount(r, {});
    egl.render(scene, QSize(1280, 800));
    std::uint8_t v = 0;
    for (auto _ : state) {
        r.rgba[0] = ++v; // a new revision
        scene.setPassCount(r, {});
        QImage img = egl.render(scene, QSize(1280, 800));
        benchmark::DoNotOptimize(img.constBits());
    }
}
BENCHMARK(BM_PassCount8MCellsUpdateAndRender)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

} // namespace

int main(int argc, char** argv) {
    qputenv("QT_QPA_PLATFORM", "offscreen"); // headless: no X server needed
    QGuiApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
