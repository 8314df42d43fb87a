#include "protocols/osyris/CoverageStats.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ocu::osyris {

bool rasterizeRings(const std::vector<LocalRing>& rings, double cellSize,
                    const std::function<void(std::int32_t, std::int32_t, std::int32_t)>& f,
                    std::uint64_t maxCells) {
    if (!(cellSize > 0))
        return true;
    // Every edge crosses the centre lines of a range of rows; collect (row, x) of the crossings, sort,
    // and fill between pairs (even-odd). Work is proportional to the perimeter in cells, not the area.
    struct Cross {
        std::int64_t row;
        double x;
    };
    std::vector<Cross> xs;
    constexpr double kLimit = 1e9; // cells; beyond it a vertex is nonsense
    for (const LocalRing& ring : rings) {
        const std::size_t n = ring.size();
        if (n < 3)
            continue;
        for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
            const LocalPoint a = ring[j], b = ring[i];
            if (!std::isfinite(a.x) || !std::isfinite(a.y) || !std::isfinite(b.x) || !std::isfinite(b.y))
                return false;
            const double ya = a.y / cellSize - 0.5, yb = b.y / cellSize - 0.5; // row-centre units
            if (std::fabs(ya) > kLimit || std::fabs(yb) > kLimit)
                return false;
            if (ya == yb)
                continue;
            const double lo = std::min(ya, yb), hi = std::max(ya, yb);
            // Rows r with lo <= r < hi (half-open: a vertex on a centre line counts once).
            const std::int64_t r0 = static_cast<std::int64_t>(std::ceil(lo));
            const std::int64_t r1 = static_cast<std::int64_t>(std::ceil(hi)) - 1;
            if (r1 - r0 > 10'000'000)
                return false;
            for (std::int64_t r = r0; r <= r1; ++r) {
                const double t = (double(r) - ya) / (yb - ya);
                xs.push_back({r, (a.x + t * (b.x - a.x)) / cellSize - 0.5});
            }
        }
    }
    std::sort(xs.begin(), xs.end(),
              [](const Cross& p, const Cross& q) { return p.row != q.row ? p.row < q.row : p.x < q.x; });
    std::uint64_t total = 0;
    for (std::size_t i = 0; i + 1 < xs.size();) {
        if (xs[i + 1].row != xs[i].row) {
            ++i; // odd crossing count on a row (degenerate ring): skip the stray one
            continue;
        }
        // Cells c with x0 <= c < x1 (cell centre c in cell-centre units).
        const double x0 = xs[i].x, x1 = xs[i + 1].x;
        if (std::fabs(x0) > kLimit || std::fabs(x1) > kLimit)
            return false;
        const std::int64_t c0 = static_cast<std::int64_t>(std::ceil(x0));
        const std::int64_t c1 = static_cast<std::int64_t>(std::ceil(x1)) - 1;
        if (c1 >= c0) {
            total += std::uint64_t(c1 - c0 + 1);
            if (total > maxCells)
                return false;
            f(static_cast<std::int32_t>(xs[i].row), static_cast<std::int32_t>(c0),
              static_cast<std::int32_t>(c1));
        }
        i += 2;
    }
    return true;
}

CoverageStats coverageInRings(const PassCountSnapshot& snap, const std::vector<LocalRing>& rings, int lift) {
    CoverageStats s;
    s.cellSize = snap.cellSize();
    s.targetMin = snap.targetMin();
    s.targetMax = snap.targetMax();
    std::vector<PassCount> row;
    std::uint64_t sum = 0;
    int mn = std::numeric_limits<int>::max(), mx = 0;
    const bool flags = snap.anyIncomplete();
    rasterizeRings(rings, s.cellSize, [&](std::int32_t cy, std::int32_t cx0, std::int32_t cx1) {
        const int n = cx1 - cx0 + 1;
        row.resize(std::size_t(n));
        snap.countsInRect(cx0, cy, n, 1, row.data(), lift);
        s.cells += std::uint64_t(n);
        for (int i = 0; i < n; ++i) {
            const int c = row[std::size_t(i)];
            if (flags && snap.incompleteAtCell(cx0 + i, cy))
                ++s.incomplete;
            if (c == 0)
                continue;
            ++s.covered;
            sum += std::uint64_t(c);
            mn = std::min(mn, c);
            mx = std::max(mx, c);
            if (c < s.targetMin)
                ++s.under;
            else if (c <= s.targetMax)
                ++s.atTarget;
            else
                ++s.over;
        }
    });
    s.uncovered = s.cells - s.covered;
    if (s.covered) {
        s.minPasses = mn;
        s.maxPasses = mx;
        s.meanPasses = double(sum) / double(s.covered);
    }
    return s;
}

LocalRing stationBandRing(const StationPointFn& pointAt, double from, double to, double offsetLeft,
                          double offsetRight, double sample) {
    LocalRing ring;
    if (!(to > from) || !(sample > 0))
        return ring;
    const int n = std::max(1, static_cast<int>(std::ceil((to - from) / sample)));
    // Right edge forward, left edge back (offsets + right).
    for (int k = 0; k <= n; ++k) {
        auto p = pointAt(from + (to - from) * k / n, offsetRight);
        if (!p)
            return {};
        ring.push_back(*p);
    }
    for (int k = n; k >= 0; --k) {
        auto p = pointAt(from + (to - from) * k / n, -offsetLeft);
        if (!p)
            return {};
        ring.push_back(*p);
    }
    return ring;
}

std::vector<StationBin> coverageByStation(const PassCountSnapshot& snap, const StationPointFn& pointAt,
                                          double from, double to, double step, double offsetLeft,
                                          double offsetRight, int lift, double sample) {
    std::vector<StationBin> out;
    if (!(step > 0) || !(to > from) || !std::isfinite(from) || !std::isfinite(to) || (to - from) / step > 1e6)
        return out;
    // A last piece under 1 % of a step (rounding of the design's geometry) joins the range before it.
    const auto n = static_cast<std::int64_t>(std::ceil((to - from) / step - 0.01));
    for (std::int64_t k = 0; k < n; ++k) {
        StationBin b;
        b.from = from + double(k) * step;
        b.to = k + 1 == n ? to : std::min(to, b.from + step);
        const LocalRing ring = stationBandRing(pointAt, b.from, b.to, offsetLeft, offsetRight, sample);
        if (!ring.empty())
            b.stats = coverageInRings(snap, {ring}, lift);
        else {
            b.stats.cellSize = snap.cellSize();
            b.stats.targetMin = snap.targetMin();
            b.stats.targetMax = snap.targetMax();
        }
        out.push_back(b);
    }
    return out;
}

} // namespace ocu::osyris
