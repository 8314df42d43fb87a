// CPU cost of a simulated camera's synthetic view (CameraScene: ground grid in perspective, sky,
// boxes, time code) per frame, at the demo's 640x360 and the benchmark's 1280x720. The H.264 encoding
// (x264enc ultrafast / zerolatency) comes on top and is GStreamer's; the console's decode cost is
// bench_video's.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "sim/jaus/CameraScene.h"

using namespace ocu::sim;

namespace {

void BM_RenderCameraView(benchmark::State& state) {
    const int w = int(state.range(0)), h = int(state.range(1));
    std::vector<std::uint8_t> buf(std::size_t(w * h * 3 / 2));
    I420Frame f{buf.data(), buf.data() + w * h, buf.data() + w * h + w * h / 4, w, w / 2, w / 2, w, h};
    CameraPose pose;
    pose.tilt = -0.05;
    const std::vector<SceneBox> boxes{{12, 4, 0.5}, {20, -6, 0}, {8, 1, 1}};
    std::uint64_t t = 1;
    for (auto _ : state) {
        pose.x += 0.05; // the vehicle drives: every frame differs
        pose.pan = 0.3 * std::sin(double(t) * 0.01);
        renderCameraView(f, pose, boxes, t++);
        benchmark::DoNotOptimize(buf.data());
    }
    state.SetItemsProcessed(state.iterations());
}

} // namespace

BENCHMARK(BM_RenderCameraView)->Args({640, 360})->Args({1280, 720})->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
