#include "models/coverage/CoverageReportCommon.h"

namespace ocu::coverage {

osyris::LocalRing areaRing(const CoverageFrames& frames, const CompactionArea& area) {
    osyris::LocalRing r;
    for (const GeoPoint& g : area.ring)
        if (auto p = frames.geoToLocal(g))
            r.push_back(*p);
    return r;
}

const CompactionArea* findArea(const CoverageJob& job, const QString& name) {
    for (const auto& a : job.areas)
        if (a.name == name)
            return &a;
    return nullptr;
}

QString liftName(const osyris::PassCountSnapshot& snap, int lift) {
    if (lift == kAllLifts)
        return ReportText::tr("every lift");
    if (lift < 0 || lift >= snap.liftCount())
        return ReportText::tr("top view (top-most lift per cell)");
    return ReportText::tr("lift %1 (z %2 … %3 m)")
        .arg(lift + 1)
        .arg(snap.liftBottom(lift), 0, 'f', 2)
        .arg(snap.liftTop(lift), 0, 'f', 2);
}

QString num(double v, int d) {
    return QString::number(v, 'f', d);
}

} // namespace ocu::coverage
