#pragma once
// Pass statistics of compaction areas and station ranges: pure functions over a
// PassCountSnapshot, for the pass-count panel, the coverage report and tests.
//
// A cell belongs to a polygon when its centre lies inside (even-odd rule over all rings, so a second ring
// inside the first is a hole). Over the cells of a polygon, for one lift (-1 = the top view: the top-most
// lift with data at each cell):
//   cells      every cell of the polygon          covered   cells with >= 1 pass
//   uncovered  cells with no pass                 under     1 .. targetMin-1 passes
//   atTarget   targetMin .. targetMax passes      over      more than targetMax passes
//   incomplete cells a given-up ribbon gap may have passed over (their counts may be too low)
//   min/max/mean passes over the covered cells; coverage % = covered / cells.
#include "protocols/osyris/PassCountSnapshot.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace ocu::osyris {

struct LocalPoint {
    double x = 0; // m east of the worksite origin
    double y = 0; // m north
};
using LocalRing = std::vector<LocalPoint>; // closed implicitly (last vertex joins the first)

struct CoverageStats {
    std::uint64_t cells = 0, covered = 0, uncovered = 0, under = 0, atTarget = 0, over = 0, incomplete = 0;
    int minPasses = 0, maxPasses = 0;
    double meanPasses = 0;
    double cellSize = 0;
    int targetMin = 0, targetMax = 0;

    double areaM2() const { return double(cells) * cellSize * cellSize; }
    double percentOf(std::uint64_t n) const { return cells ? 100.0 * double(n) / double(cells) : 0.0; }
    double coveragePercent() const { return percentOf(covered); }
};

// The cells whose centres lie inside the rings: f(cy, cx0, cx1) once per row span (inclusive), rows in
// ascending order. Spans of at most maxCells cells in all (a polygon larger than that is cut off and the
// function returns false).
bool rasterizeRings(const std::vector<LocalRing>& rings, double cellSize,
                    const std::function<void(std::int32_t cy, std::int32_t cx0, std::int32_t cx1)>& f,
                    std::uint64_t maxCells = 400'000'000);

CoverageStats coverageInRings(const PassCountSnapshot& snap, const std::vector<LocalRing>& rings,
                              int lift = -1);

// The position of (station, offset) in the local frame (offset + right of the direction of stationing);
// nullopt outside the alignment. The report composes the design's stationing and the CRS conversion.
using StationPointFn = std::function<std::optional<LocalPoint>(double station, double offset)>;

struct StationBin {
    double from = 0, to = 0;
    CoverageStats stats;
};

// Bins [from, from+step), ... up to `to`, each the band offsetLeft m left to offsetRight m right of the
// centre line (its edges sampled every `sample` m, so arcs are followed). step <= 0 or from >= to: none.
std::vector<StationBin> coverageByStation(const PassCountSnapshot& snap, const StationPointFn& pointAt,
                                          double from, double to, double step, double offsetLeft,
                                          double offsetRight, int lift = -1, double sample = 1.0);

// The ring of one station band (as coverageByStation builds it); empty when the alignment gives no point.
LocalRing stationBandRing(const StationPointFn& pointAt, double from, double to, double offsetLeft,
                          double offsetRight, double sample = 1.0);

} // namespace ocu::osyris
