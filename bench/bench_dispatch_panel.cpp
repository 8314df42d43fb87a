// bench_dispatch_panel: the GUI-thread cost of one dispatch update for 1,000 haul
// trucks.
//  * BM_DispatchUpdate/N: N of the 1,000 trucks change (production state, payload, way, assignment status
//    in turn) and are announced in one trucksChanged batch, as IsoBridge delivers them; measured: the
//    DispatchModel update (one dataChanged), the queue model rebuild, the panel's cue/controls/route update
//    and the repaint of the whole panel (grab() into a pixmap at 1920x1080: both tables, every visible cell,
//    ETAs from cached routes). Routes come from the source precomputed (routing itself: bench_iso23725
//    BM_Route20kWays); the model asks again only for visible rows whose way changed.
//  * BM_DispatchUpdateRepaint/N/H/full: the same update, then the repaint of the tables: full = 1 both
//    viewports entirely (every visible cell), full = 0 what the event loop repaints (the changed cells).
//  * BM_DispatchModelOnly/N: the model and queue update without painting.
#include "models/testing/FakeDispatchSource.h"
#include "widgets/dispatch/DispatchPanel.h"

#include <QApplication>
#include <QPaintEvent>
#include <QPixmap>
#include <QTableView>
#include <benchmark/benchmark.h>

using namespace ocu;

namespace {

constexpr int kTrucks = 1000;
constexpr int kAreas = 24;
const QStringList kStates{QStringLiteral("Driving"), QStringLiteral("Queued"),  QStringLiteral("Spotting"),
                          QStringLiteral("Loading"), QStringLiteral("Hauling"), QStringLiteral("Dumping")};
const QStringList kStatus{QStringLiteral("Pending"), QStringLiteral("Active"), QStringLiteral("Completed")};

DispatchTruck makeTruck(int i, int tick) {
    DispatchTruck t;
    t.id = QStringLiteral("iso23725:%1").arg(i, 4, 10, QLatin1Char('0'));
    t.link = QStringLiteral("ahs");
    t.name = QStringLiteral("HT%1").arg(i, 4, 10, QLatin1Char('0'));
    t.stateKnown = true;
    t.custodian = i % 17 == 0 ? QStringLiteral("AHS") : QStringLiteral("FMS");
    t.needsAssignment = (i + tick) % 50 == 0;
    t.autonomyMode = QStringLiteral("Autonomous");
    t.assignmentId = QStringLiteral("a-%1-%2").arg(i).arg(tick / 4);
    t.assignmentStatus = kStatus[(i + tick / 4) % kStatus.size()];
    t.task = (i + tick / 4) % 2 ? QStringLiteral("Load") : QStringLiteral("Offload");
    t.destinationId = 1000 + (i % kAreas);
    t.destinationName = QStringLiteral("Area %1").arg(i % kAreas);
    t.productionState = kStates[(i + tick) % kStates.size()];
    t.wayId = 1 + (i + tick) % 400;
    t.productionSinceMs = 1'700'000'000'000 + tick * 100;
    t.payloadTonnes = (i + tick) % 3 ? std::optional<double>(180.0 + (i + tick) % 40) : std::nullopt;
    return t;
}

struct Rig {
    Rig() {
        QVector<DispatchArea> areas;
        for (int a = 0; a < kAreas; ++a)
            areas << DispatchArea{QStringLiteral("ahs"), 1000 + a, QStringLiteral("Area %1").arg(a),
                                  a % 2 ? QStringLiteral("Offload") : QStringLiteral("Load")};
        src.setAreas(areas);
        QVector<DispatchTruck> trucks;
        for (int i = 0; i < kTrucks; ++i) {
            trucks << makeTruck(i, 0);
            src.routes.insert(
                trucks.back().id,
                DispatchRoute{QStringLiteral("ahs"), {1, 2, 3, 1000 + i % kAreas}, 850.0, {}, false});
        }
        src.setTrucks(trucks);
        panel.resize(1920, 1080);
        panel.show();
        QCoreApplication::processEvents();
        panel.setCurrentTruck(trucks[3].id);
    }
    // N trucks change (a rolling window so every row changes over time), announced as one batch.
    void update(int n) {
        QVector<DispatchTruck> batch;
        batch.reserve(n);
        for (int k = 0; k < n; ++k)
            batch << makeTruck((next + k) % kTrucks, tick);
        next = (next + n) % kTrucks;
        ++tick;
        src.setTrucks(batch);
    }
    FakeDispatchSource src;
    DispatchPanel panel{&src, nullptr, nullptr};
    int next = 0;
    int tick = 1;
};

Rig* g_rig = nullptr;
Rig& rig() {
    if (!g_rig)
        g_rig = new Rig;
    return *g_rig;
}

} // namespace

static void BM_DispatchUpdate(benchmark::State& state) {
    Rig& r = rig();
    const int n = int(state.range(0));
    for (auto _ : state) {
        r.update(n);
        const QPixmap frame = r.panel.grab();
        benchmark::DoNotOptimize(frame.cacheKey());
    }
    state.counters["trucks"] = kTrucks;
    state.counters["changed"] = n;
}
BENCHMARK(BM_DispatchUpdate)->Arg(1000)->Arg(100)->Unit(benchmark::kMillisecond)->MinTime(2.0);

namespace {
// Counts the paint events of a widget and the pixels they covered, to show what a repaint really drew.
struct PaintCounter : QObject {
    int paints = 0;
    qint64 pixels = 0;
    bool eventFilter(QObject*, QEvent* e) override {
        if (e->type() == QEvent::Paint) {
            ++paints;
            for (const QRect& rc : static_cast<QPaintEvent*>(e)->region())
                pixels += qint64(rc.width()) * rc.height();
        }
        return false;
    }
};
} // namespace

// BM_DispatchUpdateRepaint/N/H/full: the update, then the repaint.
//  full = 1: both tables' viewports repainted entirely (synchronous repaint()): every visible cell drawn, the
//            upper bound of an update (every visible cell changed, or the panel was exposed).
//  full = 0: what the event loop repaints for this update: the posted update requests are processed, so the
//            cells the model announced as changed (dataChanged) are drawn, as on the operator's screen.
// The panel is 1920 px wide and H px high.
static void BM_DispatchUpdateRepaint(benchmark::State& state) {
    Rig& r = rig();
    const int n = int(state.range(0));
    const bool full = state.range(2) != 0;
    r.panel.resize(1920, int(state.range(1)));
    QCoreApplication::processEvents();
    PaintCounter counter;
    r.panel.table()->viewport()->installEventFilter(&counter);
    for (auto _ : state) {
        r.update(n);
        if (full) {
            r.panel.table()->viewport()->repaint();
            r.panel.queueTable()->viewport()->repaint();
        } else {
            QCoreApplication::processEvents();
        }
    }
    r.panel.table()->viewport()->removeEventFilter(&counter);
    state.counters["changed"] = n;
    state.counters["rows_visible"] = r.panel.table()->rowAt(r.panel.table()->viewport()->height() - 1) + 1;
    state.counters["table_paints"] = benchmark::Counter(counter.paints, benchmark::Counter::kAvgIterations);
    state.counters["table_px"] =
        benchmark::Counter(double(counter.pixels), benchmark::Counter::kAvgIterations);
    r.panel.resize(1920, 1080);
    QCoreApplication::processEvents();
}
// Panel heights: 380 px (the bottom dock of the default layout at 1920x1080), 1080 (the panel maximised).
BENCHMARK(BM_DispatchUpdateRepaint)
    ->Args({1000, 380, 1})
    ->Args({1000, 1080, 1})
    ->Args({100, 1080, 1})
    ->Args({1000, 380, 0})
    ->Args({1000, 1080, 0})
    ->Args({100, 1080, 0})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);

static void BM_DispatchModelOnly(benchmark::State& state) {
    Rig& r = rig();
    const int n = int(state.range(0));
    for (auto _ : state)
        r.update(n);
    state.counters["changed"] = n;
}
BENCHMARK(BM_DispatchModelOnly)->Arg(1000)->Arg(100)->Unit(benchmark::kMillisecond)->MinTime(2.0);

int main(int argc, char** argv) {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    delete g_rig; // before the QApplication
    return 0;
}
