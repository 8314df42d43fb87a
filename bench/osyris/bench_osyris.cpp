// bench_osyris: CmPos decode rate and pass-count ingest rate (>= 5 M/s and >= 1 M/s);
// the cost of pass-count snapshots on the io thread and of the GUI's read of one.
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

// The same ingest on the io thread while snapshots are published for the GUI every `arg` positions (the
// previous snapshot kept alive, as the GUI holds it): after each snapshot the first write to a tile copies
// it. Live, the station publishes at most every 100 ms, i.e. every few to few hundred positions; 10 is the
// worst case.
void BM_PassCountIngestPublishing(benchmark::State& state) {
    const auto every = static_cast<std::size_t>(state.range(0));
    auto track = rollerTrack(200000, 0.30);
    PassCountSettings s;
    std::size_t snapshots = 0;
    for (auto _ : state) {
        state.PauseTiming();
        PassCountGrid g(s);
        std::shared_ptr<const PassCountSnapshot> held;
        state.ResumeTiming();
        for (std::size_t i = 0; i < track.size(); ++i) {
            g.addPosition(1, track[i]);
            if ((i + 1) % every == 0) {
                held = g.snapshot();
                ++snapshots;
            }
        }
        benchmark::DoNotOptimize(held);
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * track.size()));
    state.counters["snapshots"] = benchmark::Counter(double(snapshots) / double(state.iterations()));
    state.SetLabel("0.30 m between positions, a snapshot every " + std::to_string(every) + " positions");
}
BENCHMARK(BM_PassCountIngestPublishing)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

// A 3-million-cell job (~2,970 tiles): lanes 1.5 m apart over ~600 m x 600 m, every cell counted once.
void fillJob(PassCountGrid& g) {
    const double side = 54 * kTileSize * g.settings().cellSize;
    std::uint32_t slot = 0;
    for (double y = 0.75; y < side; y += 1.5) {
        for (double x = 0; x <= side; x += 0.5) {
            CmPos p;
            p.x = static_cast<float>(x);
            p.y = static_cast<float>(y);
            p.dx = 1.5f;
            p.flags = kPosValid | kPosAccuracyHigh | kPosVibrating | kPosForward;
            p.slot = slot++;
            g.addPosition(1, p);
        }
        g.addPosition(1, CmPos{.slot = slot++}); // not usable: ends the traversal, no sweep across the turn
    }
}

// One publication on a 3-million-cell job (~2,970 tiles of 32 x 32), all on the io thread: the snapshot (one
// pointer per tile, sorted) plus the writes since the previous one into `arg` tiles (2 positions per tile;
// the first write to each copies the tile the previous snapshot holds). Arg 0 = the snapshot alone.
void BM_PassCountSnapshot3M(benchmark::State& state) {
    PassCountSettings s;
    s.minMove = 0;
    PassCountGrid g(s);
    fillJob(g);
    const auto tilesTouched = static_cast<int>(state.range(0));
    auto held = g.snapshot();
    std::uint8_t machine = 2;
    for (auto _ : state) {
        // Writes into `tilesTouched` tiles spread over the job (a 1 m run in each), as a Beat's worth of
        // positions from a few rollers would; each first write copies a tile the previous snapshot holds.
        for (int k = 0; k < tilesTouched; ++k) {
            const double x = (k * 7 % 54) * kTileSize * s.cellSize + 2,
                         y = (k * 13 % 54) * kTileSize * s.cellSize + 2;
            CmPos a;
            a.x = static_cast<float>(x);
            a.y = static_cast<float>(y);
            a.dx = 1.0f;
            a.flags = kPosValid | kPosAccuracyHigh | kPosVibrating | kPosForward;
            CmPos b = a;
            b.x = static_cast<float>(x + 1);
            b.slot = 1;
            g.addPosition(machine, a); // a new traversal starts here (far from this machine's last position)
            g.addPosition(machine, b);
            machine = static_cast<std::uint8_t>(machine == 250 ? 2 : machine + 1);
        }
        held = g.snapshot();
        benchmark::DoNotOptimize(held);
    }
    state.SetLabel(std::to_string(held->tiles().size()) + " tiles, " + std::to_string(tilesTouched) +
                   " changed per publication");
}
BENCHMARK(BM_PassCountSnapshot3M)->Arg(0)->Arg(16)->Arg(128)->Unit(benchmark::kMicrosecond);

// The GUI's read of the whole 3-million-cell job into one buffer (what the 2D map's colour image and the 3D
// raster are built from): arg 1 = from a snapshot (row segments copied tile by tile, no lock), arg 0 = the
// grid's own cell-by-cell reader (the path the GUI used before, then under the io thread's lock).
void BM_PassCountRead3M(benchmark::State& state) {
    PassCountSettings s;
    s.minMove = 0;
    PassCountGrid g(s);
    fillJob(g);
    auto snap = g.snapshot();
    const CellBox e = snap->extent();
    const int cols = e.cx1 - e.cx0 + 1, rows = e.cy1 - e.cy0 + 1;
    std::vector<PassCount> out(std::size_t(cols) * std::size_t(rows));
    for (auto _ : state) {
        if (state.range(0))
            snap->countsInRect(e.cx0, e.cy0, cols, rows, out.data());
        else
            g.countsInRect(e.cx0, e.cy0, cols, rows, out.data());
        benchmark::DoNotOptimize(out.data());
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * cols * rows);
    state.SetLabel(std::to_string(cols) + " x " + std::to_string(rows) + " cells");
}
BENCHMARK(BM_PassCountRead3M)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
