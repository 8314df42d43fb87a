// The coverage report as a whole: checks the request, computes the tables once and writes each file asked
// for (CoverageCsv, CoverageGeoTiff, CoveragePdf).
#include "models/coverage/CoverageReportCommon.h"

#include <QJsonArray>

namespace ocu {

using coverage::findArea;
using coverage::ReportText;

QJsonObject writeCoverageReport(const CoverageJob& job, const CoverageReportRequest& r) {
    QJsonObject o;
    QJsonObject written{
        {QStringLiteral("pdf"), false}, {QStringLiteral("csv"), false}, {QStringLiteral("geotiff"), false}};
    QJsonArray errors;
    auto finish = [&](const QString& msg) {
        o[QStringLiteral("written")] = written;
        o[QStringLiteral("errors")] = errors;
        const bool asked = !r.pdf.isEmpty() || !r.csv.isEmpty() || !r.geotiff.isEmpty();
        o[QStringLiteral("ok")] = asked && errors.isEmpty();
        o[QStringLiteral("message")] =
            msg.isEmpty()
                ? (errors.isEmpty() ? ReportText::tr("coverage report written") : errors.first().toString())
                : msg;
        return o;
    };
    if (r.pdf.isEmpty() && r.csv.isEmpty() && r.geotiff.isEmpty())
        errors << ReportText::tr("give \"pdf\", \"csv\" and/or \"geotiff\" (file names)");
    if (!job.snapshot) {
        errors << ReportText::tr("no pass counts yet (no OSYRIS station, or nothing counted)");
        return finish({});
    }
    CoverageFrames frames;
    if (const QString e = frames.init(job); !e.isEmpty()) {
        errors << e;
        return finish({});
    }
    if (!r.area.isEmpty() && !findArea(job, r.area)) {
        errors << ReportText::tr("no area named \"%1\"").arg(r.area);
        return finish({});
    }
    const int lift = r.lift;
    if (lift != -1 && lift != kAllLifts && (lift < 0 || lift >= job.snapshot->liftCount())) {
        errors << ReportText::tr("no lift %1 (the data has %2)").arg(lift + 1).arg(job.snapshot->liftCount());
        return finish({});
    }
    const CoverageTables t = computeCoverageTables(job, frames, lift, r.area);
    o[QStringLiteral("epsg")] = t.epsg;
    o[QStringLiteral("crs")] = t.crsName;
    o[QStringLiteral("cells")] = double(t.whole.covered);
    o[QStringLiteral("incomplete_cells")] = double(t.whole.incomplete);
    o[QStringLiteral("lifts")] = job.snapshot->liftCount();
    QJsonArray areas;
    for (const AreaStats& a : t.areas)
        areas << QJsonObject{{QStringLiteral("name"), a.name},
                             {QStringLiteral("cells"), double(a.stats.cells)},
                             {QStringLiteral("coverage_pct"), a.stats.coveragePercent()},
                             {QStringLiteral("at_target_pct"), a.stats.percentOf(a.stats.atTarget)},
                             {QStringLiteral("incomplete"), double(a.stats.incomplete)}};
    o[QStringLiteral("areas")] = areas;
    o[QStringLiteral("station_ranges")] = int(t.stations.size());
    if (job.dataFrom.isValid()) { // the counted data's time range (UTC, ISO 8601)
        o[QStringLiteral("data_from")] = job.dataFrom.toUTC().toString(Qt::ISODate);
        o[QStringLiteral("data_to")] = job.dataTo.toUTC().toString(Qt::ISODate);
    }
    if (!r.csv.isEmpty()) {
        qint64 rows = 0;
        const QString e = writeCoverageCsv(job, frames, lift == -1 ? kAllLifts : lift, r.area, r.csv, &rows);
        if (e.isEmpty()) {
            written[QStringLiteral("csv")] = true;
            o[QStringLiteral("csv_rows")] = double(rows);
        } else {
            errors << e;
        }
    }
    if (!r.geotiff.isEmpty()) {
        double dev = 0;
        const QString e = writeCoverageGeoTiff(job, frames, lift, r.geotiff, &dev);
        if (e.isEmpty()) {
            written[QStringLiteral("geotiff")] = true;
            o[QStringLiteral("geotiff_affine_deviation_m")] = dev;
        } else {
            errors << e;
        }
    }
    if (!r.pdf.isEmpty()) {
        const QString e = writeCoveragePdf(job, frames, t, lift, r.area, r.pdf, r.mapSize);
        if (e.isEmpty())
            written[QStringLiteral("pdf")] = true;
        else
            errors << e;
    }
    return finish({});
}

} // namespace ocu
