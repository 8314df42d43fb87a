// Lifts, filters and gaps of the pass-count engine on synthetic tracks with known answers:
// counts per elevation band and the top-most lift per cell, the vibration/direction/speed/time/machine
// filters, the snapshot's reader API (the seam the reports build on), and the given-up gap: counted after it,
// never swept across it, its cells marked incomplete, a late arrival recounted.
#include "protocols/osyris/PassCountGrid.h"
#include "protocols/osyris/RibbonStore.h"

#include <QtTest>

#include <cmath>

using namespace ocu;
using namespace ocu::osyris;

namespace {
constexpr std::uint32_t kGood = kPosValid | kPosAccuracyHigh | kPosVibrating;
constexpr std::int64_t kT0 = 1'790'000'000'000; // Unix ms

// A run along x at height z, one position per `step` m, 1 s apart starting at t0.
std::vector<CmPos> run(double x0, double x1, double y, double z, std::uint32_t firstSlot = 0,
                       std::uint32_t flags = kGood, double speed = 2.0, std::int64_t t0 = kT0) {
    std::vector<CmPos> out;
    const double step = 0.5;
    int n = static_cast<int>(std::lround(std::abs(x1 - x0) / step));
    double dir = x1 > x0 ? 1 : -1;
    for (int i = 0; i <= n; ++i) {
        CmPos p;
        p.x = static_cast<float>(x0 + dir * i * step);
        p.y = static_cast<float>(y);
        p.z = static_cast<float>(z);
        p.dx = 2.1f;
        p.speed = speed;
        p.time = unixMillisToFileTime(t0 + i * 1000);
        p.flags = flags | (dir > 0 ? kPosForward : kPosBackward);
        p.slot = firstSlot + static_cast<std::uint32_t>(i);
        out.push_back(p);
    }
    return out;
}

void feed(PassCountGrid& g, std::uint8_t m, const std::vector<CmPos>& ps) {
    for (auto& p : ps)
        g.addPosition(m, p);
}

void store(RibbonStore& s, std::uint8_t m, const std::vector<CmPos>& ps) {
    for (auto& p : ps)
        s.put(m, {p, {}});
}

PassCountSettings lifts10cm() {
    PassCountSettings s;
    s.liftThickness = 0.10;
    s.liftBase = 0;
    return s;
}
} // namespace

class TestOsyrisLifts : public QObject {
    Q_OBJECT
private slots:
    void countsPerLiftAndTopMost() {
        PassCountGrid g(lifts10cm());
        feed(g, 1, run(0, 20, 0, 0.05));      // lift 0, pass 1
        feed(g, 1, run(20, 0, 0, 0.06));      // lift 0, pass 2
        feed(g, 2, run(0, 10, 0, 0.15, 100)); // lift 1 over the first half only
        auto snap = g.snapshot();
        QCOMPARE(snap->liftCount(), 2);
        QCOMPARE(snap->liftBottom(0), 0.0);
        QVERIFY(std::abs(snap->liftTop(0) - 0.1) < 1e-9);
        QVERIFY(std::abs(snap->liftBottom(1) - 0.1) < 1e-9);
        QVERIFY(std::abs(snap->liftTop(1) - 0.2) < 1e-9);
        const auto ci = [&](double v) { return g.cellIndex(v); };
        // x = 5: both lifts; the top view shows lift 1.
        QCOMPARE(snap->countAtCell(ci(5), ci(0), 0), 2);
        QCOMPARE(snap->countAtCell(ci(5), ci(0), 1), 1);
        QCOMPARE(snap->countAtCell(ci(5), ci(0), -1), 1);
        QCOMPARE(snap->countAtCell(ci(5), ci(0)), 1);
        // x = 15: only lift 0 there, so the top-most lift with data is 0.
        QCOMPARE(snap->countAtCell(ci(15), ci(0), 1), 0);
        QCOMPARE(snap->countAtCell(ci(15), ci(0)), 2);
        QCOMPARE(g.countAtCell(ci(15), ci(0), 0), 2);
        // forEachCell agrees with countAtCell and with the per-lift summaries.
        for (int lift = -1; lift < 2; ++lift) {
            std::uint64_t cells = 0;
            bool agree = true;
            snap->forEachCell(lift, [&](std::int32_t cx, std::int32_t cy, int count, bool incomplete) {
                ++cells;
                agree = agree && count == snap->countAtCell(cx, cy, lift) && count > 0 && !incomplete;
            });
            QVERIFY(agree);
            QCOMPARE(cells, snap->summary(lift).coveredCells);
        }
        QVERIFY(snap->summary(1).coveredCells < snap->summary(0).coveredCells);
        const GridRect b = snap->bounds();
        QVERIFY(b.xMin <= 0 && b.xMax >= 20 && b.yMin <= -1.05 && b.yMax >= 1.05);
        QCOMPARE(snap->settings().liftThickness, 0.10);
    }

    void liftsOffIsOneLiftWithTheZRange() {
        PassCountGrid g;
        feed(g, 1, run(0, 10, 0, 101.2));
        feed(g, 1, run(10, 0, 0, 101.6));
        auto snap = g.snapshot();
        QCOMPARE(snap->liftCount(), 1);
        QVERIFY(std::abs(snap->liftBottom(0) - 101.2) < 1e-4);
        QVERIFY(std::abs(snap->liftTop(0) - 101.6) < 1e-4);
        QCOMPARE(snap->countAtCell(g.cellIndex(5), 0, 0), 2);
    }

    void aLiftChangeStartsANewPass() {
        // The same stretch driven once but rising through a lift boundary counts one pass in each lift.
        PassCountGrid g(lifts10cm());
        auto r = run(0, 10, 0, 0.09);
        for (auto& p : r)
            if (p.x >= 5)
                p.z = 0.11f;
        feed(g, 1, r);
        QCOMPARE(g.countAtCell(g.cellIndex(2), 0, 0), 1);
        QCOMPARE(g.countAtCell(g.cellIndex(2), 0, 1), 0);
        QCOMPARE(g.countAtCell(g.cellIndex(8), 0, 1), 1);
        QCOMPARE(g.countAtCell(g.cellIndex(8), 0, 0), 0);
    }

    void filters_data() {
        QTest::addColumn<int>("which");
        QTest::addColumn<int>("expected"); // passes counted at x = 5 of the four runs below
        // Runs: (a) forward vibrating 2 m/s t0, (b) backward vibrating 4 m/s t0+1h, (c) forward static 2 m/s,
        // (d) machine 2 forward vibrating 2 m/s.
        QTest::newRow("default (vibrating)") << 0 << 3;
        QTest::newRow("vibration off only") << 1 << 1;
        QTest::newRow("vibration any") << 2 << 4;
        QTest::newRow("forward") << 3 << 2;
        QTest::newRow("backward") << 4 << 1;
        QTest::newRow("speed 3..5") << 5 << 1;
        QTest::newRow("speed max 3") << 6 << 2;
        QTest::newRow("time first half hour") << 7 << 2;
        QTest::newRow("time from +1h") << 8 << 1;
        QTest::newRow("machine 2") << 9 << 1;
    }
    void filters() {
        QFETCH(int, which);
        QFETCH(int, expected);
        PassCountSettings s;
        switch (which) {
        case 1:
            s.vibration = VibrationFilter::Off;
            break;
        case 2:
            s.vibration = VibrationFilter::Any;
            break;
        case 3:
            s.direction = DirectionFilter::Forward;
            break;
        case 4:
            s.direction = DirectionFilter::Backward;
            break;
        case 5:
            s.speedMin = 3.0, s.speedMax = 5.0;
            break;
        case 6:
            s.speedMax = 3.0;
            break;
        case 7:
            s.timeFrom = kT0, s.timeTo = kT0 + 1800'000;
            break;
        case 8:
            s.timeFrom = kT0 + 3600'000;
            break;
        case 9:
            s.machines = {2};
            break;
        default:
            break;
        }
        PassCountGrid g(s);
        feed(g, 1, run(0, 10, 0, 0, 0, kGood, 2.0));
        feed(g, 1, run(10, 0, 0, 0, 100, kGood, 4.0, kT0 + 3600'000));
        feed(g, 1, run(0, 10, 0, 0, 200, kPosValid | kPosAccuracyHigh, 2.0));
        feed(g, 2, run(0, 10, 0, 0, 0, kGood, 2.0));
        QCOMPARE(g.countAt(5, 0), expected);
        QCOMPARE(g.snapshot()->settings(), g.settings());
    }

    // The report's data time range is that of the counted positions (not of the filtered ones).
    void dataTimeRangeOfCountedPositions() {
        PassCountGrid g{PassCountSettings{}};
        QCOMPARE(g.snapshot()->dataFromMs(), std::int64_t(0));
        feed(g, 1, run(0, 10, 0, 0, 0, kGood, 2.0, kT0)); // vibrating: counted, kT0 ... kT0 + 20 s
        feed(g, 1, run(10, 0, 0, 0, 100, kPosValid | kPosAccuracyHigh, 2.0, kT0 + 7200'000)); // static: not
        auto snap = g.snapshot();
        QVERIFY2(snap->dataFromMs() >= kT0 && snap->dataFromMs() <= kT0 + 1000,
                 qPrintable(QString::number(snap->dataFromMs() - kT0)));
        QCOMPARE(snap->dataToMs(), kT0 + 20'000);
        // A filter change clears the grid: the range is that of the recount.
        PassCountSettings any;
        any.vibration = VibrationFilter::Any;
        g.setSettings(any);
        QCOMPARE(g.snapshot()->dataFromMs(), std::int64_t(0));
        feed(g, 1, run(10, 0, 0, 0, 100, kPosValid | kPosAccuracyHigh, 2.0, kT0 + 7200'000));
        QCOMPARE(g.snapshot()->dataToMs(), kT0 + 7200'000 + 20'000);
    }

    void givenUpGapIsCountedAfterNeverAcross() {
        auto st = RibbonStore::inMemory();
        auto r = run(0, 20, 0, 0); // slots 0..40, x = slot / 2
        std::vector<CmPos> held;
        for (auto& p : r)
            if (p.slot < 10 || p.slot > 19) // x in [5, 9.5] lost
                held.push_back(p);
        store(*st, 1, held);
        PassCountGrid g;
        g.advanceAll(*st);
        QCOMPARE(g.nextSlot(1), 10u); // waits at the gap
        QCOMPARE(g.countAt(15, 0), 0);
        g.giveUp(1, 10, 19);
        g.advanceAll(*st);
        QCOMPARE(g.nextSlot(1), 41u);
        QCOMPARE(g.countAt(2, 0), 1);
        QCOMPARE(g.countAt(15, 0), 1);
        // Between the last position before (x 4.5) and the first after (x 10): not swept, marked incomplete.
        QCOMPARE(g.countAt(7, 0), 0);
        QVERIFY(g.incompleteAtCell(g.cellIndex(7), 0));
        QVERIFY(!g.incompleteAtCell(g.cellIndex(2), 0));
        QVERIFY(!g.incompleteAtCell(g.cellIndex(15), 0));
        QVERIFY(!g.incompleteAtCell(g.cellIndex(7), g.cellIndex(5))); // beside the drum's corridor
        auto snap = g.snapshot();
        QVERIFY(snap->anyIncomplete());
        QVERIFY(snap->incompleteAtCell(g.cellIndex(7), 0));
        QCOMPARE(snap->givenUp().at(1), (std::vector<SlotRange>{{10, 19}}));
        bool visited = false;
        snap->forEachCell(-1, [&](std::int32_t cx, std::int32_t cy, int count, bool incomplete) {
            if (cx == g.cellIndex(7) && cy == 0)
                visited = incomplete && count == 0;
        });
        QVERIFY(visited);

        // The lost slots arrive after all: a recount counts them, and nothing is incomplete any more.
        std::vector<CmPos> late(r.begin() + 10, r.begin() + 20);
        store(*st, 1, late);
        QVERIFY(g.givenUpArrived(1, *st));
        g.recount(*st);
        QCOMPARE(g.countAt(7, 0), 1);
        QVERIFY(!g.incompleteAtCell(g.cellIndex(7), 0));
        QVERIFY(g.givenUp().at(1).empty());
        QVERIFY(g.snapshot()->givenUp().empty());
    }

    void lateJoinLeadingGapMarksTheFirstFootprint() {
        auto st = RibbonStore::inMemory();
        auto r = run(0, 20, 0, 0);
        store(*st, 1, std::vector<CmPos>(r.begin() + 20, r.end())); // slots 0..19 never obtained
        PassCountGrid g;
        g.advanceAll(*st);
        QCOMPARE(g.countAt(15, 0), 0);
        g.giveUp(1, 0, 19);
        g.advanceAll(*st);
        QCOMPARE(g.countAt(15, 0), 1);
        QVERIFY(g.incompleteAtCell(g.cellIndex(10), 0)); // where the machine was first seen
        QVERIFY(!g.incompleteAtCell(g.cellIndex(5), 0)); // nothing is known about before
    }

    void partlyGivenUpStopsAtTheRest() {
        // Only part of the gap is given up: counting must still wait for the rest.
        auto st = RibbonStore::inMemory();
        auto r = run(0, 20, 0, 0);
        std::vector<CmPos> held;
        for (auto& p : r)
            if (p.slot < 10 || p.slot > 19)
                held.push_back(p);
        store(*st, 1, held);
        PassCountGrid g;
        g.giveUp(1, 10, 15);
        g.advanceAll(*st);
        QCOMPARE(g.nextSlot(1), 10u);
        QCOMPARE(g.countAt(15, 0), 0);
    }
};

QTEST_GUILESS_MAIN(TestOsyrisLifts)
#include "test_osyris_lifts.moc"
