// bench_osyris: CmPos decode rate and pass-count ingest rate (issue 5 acceptance: >= 5 M/s and >= 1 M/s).
#include "protocols/osyris/OsyrisCodec.h"
#include "protocols/osyris/PassCountGrid.h"

#include <benchmark/benchmark.h>

#include <cmath>

using namespace ocu;
using namespace ocu::osyris;

namespace {

CmPos samplePos(std::uint32_t slot) {
    CmPos p;
    p.numPos = slot;
    p.x = 1234.5f;
    p.y = -87.25f;
    p.z = 101.f;
    p.yaw = -1.57f;
    p.flags = kPosValid | kPosForward | kPosVibrating | kPosAccuracyHigh;
    p.dx = 2.1f;
    p.speed = 1.2;
    p.time = unixMillisToFileTime(1763683200000);
    p.slot = slot;
    return p;
}

void BM_CmPosDecode(benchmark::State& state) {
    Bytes b;
    encodePos(b, 1, 1, samplePos(7));
    for (auto _ : state) {
        auto m = decodeMessage(b);
        benchmark::DoNotOptimize(m);
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}
BENCHMARK(BM_CmPosDecode);

void BM_CmPosDecodeDatagram(benchmark::State& state) {
    Bytes d;
    for (std::uint32_t i = 0; i < 19; ++i) // 19 x 73 = 1387 bytes <= MaxLen 1400
        encodePos(d, 1, 1, samplePos(i), state.range(0) ? Checksum::Crc16 : Checksum::None);
    Checksum cs = state.range(0) ? Checksum::Crc16 : Checksum::None;
    for (auto _ : state) {
        auto r = decodeDatagram(d, cs);
        benchmark::DoNotOptimize(r);
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * 19);
}
BENCHMARK(BM_CmPosDecodeDatagram)->Arg(0)->Arg(1);

void BM_CmPosEncode(benchmark::State& state) {
    Bytes b;
    b.reserve(128);
    auto p = samplePos(3);
    for (auto _ : state) {
        b.clear();
        encodePos(b, 1, 1, p);
        benchmark::DoNotOptimize(b.data());
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}
BENCHMARK(BM_CmPosEncode);

// A roller doing 40 m forward/backward passes on 8 lanes, one position every `spacing` metres.
std::vector<CmPos> rollerTrack(std::size_t n, double spacing) {
    std::vector<CmPos> out;
    out.reserve(n);
    double L = 40;
    std::size_t perPass = static_cast<std::size_t>(L / spacing);
    for (std::size_t i = 0; i < n; ++i) {
        std::size_t pass = i / perPass, k = i % perPass;
        bool fwd = pass % 2 == 0;
        CmPos p = samplePos(static_cast<std::uint32_t>(i));
        double along = fwd ? k * spacing : L - k * spacing;
        p.x = static_cast<float>(1000 + along);
        p.y = static_cast<float>(200 + double((pass / 6) % 8) * 1.8 + 0.2 * std::sin(along * 0.2));
        p.flags = kPosValid | kPosAccuracyHigh | kPosVibrating | (fwd ? kPosForward : kPosBackward);
        out.push_back(p);
    }
    return out;
}

void BM_PassCountIngest(benchmark::State& state) {
    double spacing = static_cast<double>(state.range(0)) / 100.0;
    auto track = rollerTrack(200000, spacing);
    PassCountSettings s; // 0.34 m cells
    for (auto _ : state) {
        state.PauseTiming();
        PassCountGrid g(s);
        state.ResumeTiming();
        for (auto& p : track)
            g.addPosition(1, p);
        benchmark::DoNotOptimize(g.nextSlot(1));
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * track.size()));
    state.SetLabel("2.1 m drum, 0.34 m cells, " + std::to_string(spacing) + " m between positions");
}
BENCHMARK(BM_PassCountIngest)->Arg(30)->Arg(60)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
