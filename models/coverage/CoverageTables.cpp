#include "models/coverage/CoverageReportCommon.h"

#include <algorithm>
#include <cstdint>

namespace ocu {

using coverage::areaRing;
using coverage::findArea;
using coverage::ReportText;
using osyris::CoverageStats;
using osyris::LocalPoint;
using osyris::LocalRing;
using osyris::PassCountSnapshot;

CoverageTables computeCoverageTables(const CoverageJob& job, const CoverageFrames& frames, int lift,
                                     const QString& area) {
    CoverageTables t;
    t.epsg = frames.epsg();
    t.crsName = frames.crsName();
    if (!job.snapshot) {
        t.problems << ReportText::tr("no pass counts yet");
        return t;
    }
    const PassCountSnapshot& snap = *job.snapshot;
    const int l = lift == kAllLifts ? -1 : lift;
    // The whole lift: every cell with a count (and, in the top view, incomplete cells without one).
    CoverageStats w;
    w.cellSize = snap.cellSize();
    w.targetMin = snap.targetMin();
    w.targetMax = snap.targetMax();
    std::uint64_t sum = 0;
    int mn = INT32_MAX;
    snap.forEachCell(l, [&](std::int32_t, std::int32_t, int c, bool inc) {
        ++w.cells;
        if (inc)
            ++w.incomplete;
        if (c == 0)
            return;
        ++w.covered;
        sum += std::uint64_t(c);
        mn = std::min(mn, c);
        w.maxPasses = std::max(w.maxPasses, c);
        (c < w.targetMin ? w.under : c <= w.targetMax ? w.atTarget : w.over)++;
    });
    w.uncovered = w.cells - w.covered;
    if (w.covered) {
        w.minPasses = mn;
        w.meanPasses = double(sum) / double(w.covered);
    }
    t.whole = w;

    for (const CompactionArea& a : job.areas) {
        if (!area.isEmpty() && a.name != area)
            continue;
        const LocalRing ring = areaRing(frames, a);
        if (ring.size() < 3) {
            t.problems << ReportText::tr("area \"%1\" has fewer than 3 usable vertices").arg(a.name);
            continue;
        }
        t.areas.push_back({a.name, a.source, osyris::coverageInRings(snap, {ring}, l)});
    }
    if (!area.isEmpty() && t.areas.isEmpty() && !findArea(job, area))
        t.problems << ReportText::tr("no area named \"%1\"").arg(area);

    if (job.design && !job.design->alignments.empty()) {
        if (!frames.hasDesignCrs()) {
            t.problems << ReportText::tr("the design names no EPSG code: station ranges cannot be placed");
        } else {
            const landxml::Alignment& al = job.design->alignments.front();
            t.alignment = QString::fromStdString(al.name);
            osyris::StationPointFn fn = [&](double s, double off) -> std::optional<LocalPoint> {
                const auto p = al.pointAt(s, off);
                LocalPoint out;
                if (!p || !frames.designToLocal(*p, out))
                    return std::nullopt;
                return out;
            };
            double from = al.staStart, to = al.staEnd();
            const double step = job.stationStep > 0 ? job.stationStep : 20;
            const auto bins =
                osyris::coverageByStation(snap, fn, from, to, step, job.bandLeft, job.bandRight, l, 2.0);
            t.stations = QVector<osyris::StationBin>(bins.begin(), bins.end());
        }
    }
    return t;
}

} // namespace ocu
