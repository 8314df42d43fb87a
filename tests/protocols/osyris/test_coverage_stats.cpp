// Pass statistics per area and per station range on hand-made grids (1 m cells), with every
// expected figure counted by hand in the comments.
#include "protocols/osyris/CoverageStats.h"

#include <QtTest>

using namespace ocu::osyris;

namespace {

// Counts [row][col] of cells (0..3, 0..2) in tile (0, 0):
//   row 2:  3 3 3 0
//   row 1:  5 6 0 0
//   row 0:  1 2 3 4
constexpr int kCounts[3][4] = {{1, 2, 3, 4}, {5, 6, 0, 0}, {3, 3, 3, 0}};

PassCountSnapshot handMade() {
    auto t = std::make_shared<PassCountTile>();
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c)
            t->counts[std::size_t(r * kTileSize + c)] = PassCount(kCounts[r][c]);
    // Tile (-1, -1): cells (-2, -1) = 7 and (-1, -1) = 0.
    auto neg = std::make_shared<PassCountTile>();
    neg->counts[std::size_t(31 * kTileSize + 30)] = 7;
    std::vector<PassCountSnapshot::Entry> tiles{{-1, -1, neg}, {0, 0, t}};
    return PassCountSnapshot(std::move(tiles), 1.0, 3, 5, 1, 1);
}

LocalRing rect(double x0, double y0, double x1, double y1) {
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

} // namespace

class TestCoverageStats : public QObject {
    Q_OBJECT
private slots:
    void rectangleArea() {
        const auto snap = handMade();
        const CoverageStats s = coverageInRings(snap, {rect(0, 0, 4, 3)});
        QCOMPARE(s.cells, 12u);  // centres 0.5..3.5 x 0.5..2.5
        QCOMPARE(s.covered, 9u); // three zeros
        QCOMPARE(s.uncovered, 3u);
        QCOMPARE(s.under, 2u);    // 1, 2
        QCOMPARE(s.atTarget, 6u); // 3 4 5 3 3 3
        QCOMPARE(s.over, 1u);     // 6
        QCOMPARE(s.minPasses, 1);
        QCOMPARE(s.maxPasses, 6);
        QCOMPARE(s.meanPasses, 30.0 / 9.0);
        QCOMPARE(s.areaM2(), 12.0);
        QCOMPARE(s.coveragePercent(), 75.0);
        QCOMPARE(s.incomplete, 0u);
    }
    void holeAndPartialCells() {
        const auto snap = handMade();
        // The inner ring removes cell (1, 1) (6 passes): even-odd.
        CoverageStats s = coverageInRings(snap, {rect(0, 0, 4, 3), rect(1, 1, 2, 2)});
        QCOMPARE(s.cells, 11u);
        QCOMPARE(s.covered, 8u);
        QCOMPARE(s.over, 0u);
        QCOMPARE(s.maxPasses, 5);
        QCOMPARE(s.meanPasses, 3.0);
        // A triangle (0,0)-(4,0)-(0,4): centres with x + y < 4: row 0 x 0.5..2.5 (3), row 1 (2), row 2 (1),
        // row 3 none (0.5 + 3.5 = 4 is on the edge; the cell at x=0.5 has its centre on it and is out by the
        // half-open rule: the right edge's crossing at x=0.5 ends the span before that centre).
        s = coverageInRings(snap, {{{0, 0}, {4, 0}, {0, 4}}});
        QCOMPARE(s.cells, 6u); // counts 1 2 3 / 5 6 / 3
        QCOMPARE(s.covered, 6u);
        QCOMPARE(s.meanPasses, 20.0 / 6.0);
        // Negative cells: (-2, -1) = 7 passes (over), (-1, -1) = 0.
        s = coverageInRings(snap, {rect(-2, -1, 0, 0)});
        QCOMPARE(s.cells, 2u);
        QCOMPARE(s.covered, 1u);
        QCOMPARE(s.over, 1u);
        QCOMPARE(s.maxPasses, 7);
        // Empty or degenerate rings: no cells.
        QCOMPARE(coverageInRings(snap, {}).cells, 0u);
        QCOMPARE(coverageInRings(snap, {{{0, 0}, {4, 0}}}).cells, 0u);
        // Hostile vertices: refused, nothing counted, no hang.
        QCOMPARE(coverageInRings(snap, {rect(0, 0, 1e15, 1)}).cells, 0u);
        QCOMPARE(coverageInRings(snap, {{{0, 0}, {std::nan(""), 1}, {1, 1}}}).cells, 0u);
    }
    void liftsAndIncomplete() {
        // Top view: cell (0,0) 4 passes in lift 1, cell (1,0) 2 passes in lift 0 only, cell (2,0) no count
        // but incomplete, cell (0,0) incomplete too. Lift 0: (0,0) 3 passes, (1,0) 2.
        auto top = std::make_shared<PassCountTopTile>();
        top->counts[0] = 4;
        top->lift[0] = 1;
        top->counts[1] = 2;
        top->lift[1] = 0;
        top->flags[0] = kCellIncomplete;
        top->flags[2] = kCellIncomplete;
        auto l0 = std::make_shared<PassCountTile>();
        l0->counts[0] = 3;
        l0->counts[1] = 2;
        auto l1 = std::make_shared<PassCountTile>();
        l1->counts[0] = 4;
        PassCountSettings st;
        st.cellSize = 1.0;
        st.targetMin = 3;
        st.targetMax = 3;
        st.liftThickness = 0.05;
        std::vector<PassCountSnapshot::Lift> lifts{{0, 0.0, 0.05, {{0, 0, l0}}},
                                                   {1, 0.05, 0.10, {{0, 0, l1}}}};
        PassCountSnapshot snap({{0, 0, top}}, std::move(lifts), st, 1, 1, {{2, {SlotRange{10, 20}}}});
        QVERIFY(snap.anyIncomplete());
        const LocalRing r = rect(0, 0, 3, 1); // cells (0,0) (1,0) (2,0)
        CoverageStats s = coverageInRings(snap, {r}, -1);
        QCOMPARE(s.cells, 3u);
        QCOMPARE(s.covered, 2u);
        QCOMPARE(s.over, 1u);  // 4 > 3
        QCOMPARE(s.under, 1u); // 2
        QCOMPARE(s.incomplete, 2u);
        s = coverageInRings(snap, {r}, 0);
        QCOMPARE(s.covered, 2u);
        QCOMPARE(s.atTarget, 1u); // 3
        QCOMPARE(s.meanPasses, 2.5);
        s = coverageInRings(snap, {r}, 1);
        QCOMPARE(s.covered, 1u);
        QCOMPARE(s.maxPasses, 4);
        QCOMPARE(s.incomplete, 2u); // the flag is per cell, whatever the lift
    }
    void stationBins() {
        const auto snap = handMade();
        // A straight alignment along +x from (0, 0): station s, offset o (+ right = south) -> (s, -o).
        StationPointFn along = [](double s, double o) -> std::optional<LocalPoint> {
            if (s < 0 || s > 100)
                return std::nullopt;
            return LocalPoint{s, -o};
        };
        // 3 m left (north), 0 m right: the rectangle 0..4 x 0..3, in bins of 2 m.
        auto bins = coverageByStation(snap, along, 0, 4, 2, 3, 0);
        QCOMPARE(bins.size(), std::size_t(2));
        QCOMPARE(bins[0].from, 0.0);
        QCOMPARE(bins[0].to, 2.0);
        QCOMPARE(bins[0].stats.cells, 6u);   // columns 0, 1
        QCOMPARE(bins[0].stats.covered, 6u); // 1 2 / 5 6 / 3 3
        QCOMPARE(bins[0].stats.over, 1u);
        QCOMPARE(bins[1].stats.cells, 6u);   // columns 2, 3
        QCOMPARE(bins[1].stats.covered, 3u); // 3 4 / 0 0 / 3 0
        QCOMPARE(bins[1].stats.atTarget, 3u);
        // A last short bin, and nothing beyond the alignment's end.
        bins = coverageByStation(snap, along, 0, 3, 2, 3, 0);
        QCOMPARE(bins.size(), std::size_t(2));
        QCOMPARE(bins[1].to, 3.0);
        QCOMPARE(bins[1].stats.cells, 3u);
        bins = coverageByStation(snap, along, 99, 103, 2, 3, 0);
        QCOMPARE(bins[1].stats.cells, 0u);
        QVERIFY(coverageByStation(snap, along, 0, 4, 0, 3, 0).empty());
    }
};

QTEST_GUILESS_MAIN(TestCoverageStats)
#include "test_coverage_stats.moc"
