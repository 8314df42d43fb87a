#pragma once
// What the coverage report's outputs share (tables, CSV, GeoTIFF, map, PDF): their translation context, the
// areas in the worksite frame, and the names of lifts and numbers as the files print them.
#include "models/coverage/CoverageReport.h"

#include <QCoreApplication>

namespace ocu::coverage {

// The report's texts in the translation context "ocu::CoverageReport"; a class, so that lupdate sees the
// context and no free tr() shadows QObject::tr.
struct ReportText {
    Q_DECLARE_TR_FUNCTIONS(ocu::CoverageReport)
};

// The area's ring in the worksite frame (vertices that do not convert are left out).
osyris::LocalRing areaRing(const CoverageFrames& frames, const CompactionArea& area);
// The job's area of that name, or nullptr.
const CompactionArea* findArea(const CoverageJob& job, const QString& name);
// "every lift", "top view (…)" or "lift n (z … m)".
QString liftName(const osyris::PassCountSnapshot& snap, int lift);
// Fixed-point with d decimals.
QString num(double v, int d);

} // namespace ocu::coverage
