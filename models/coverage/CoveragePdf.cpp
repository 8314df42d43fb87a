// The coverage PDF: what was counted and how (site, CRS, design, machines, filters, lifts, the "incomplete"
// statement), the map snapshot, and the statistics per area and per station range (docs/coverage-report.md).
#include "models/coverage/CoverageReportCommon.h"

#include "models/PdfPageWriter.h"

#include <QFile>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>

namespace ocu {

using coverage::liftName;
using coverage::num;
using coverage::ReportText;
using osyris::CoverageStats;
using osyris::PassCountSnapshot;

namespace {

QStringList statsRow(const QString& name, const CoverageStats& s) {
    return {name,
            num(s.areaM2(), 0),
            num(s.coveragePercent(), 1),
            num(s.percentOf(s.under), 1),
            num(s.percentOf(s.atTarget), 1),
            num(s.percentOf(s.over), 1),
            s.covered ? QString::number(s.minPasses) : QStringLiteral("–"),
            s.covered ? num(s.meanPasses, 2) : QStringLiteral("–"),
            s.covered ? QString::number(s.maxPasses) : QStringLiteral("–"),
            QString::number(s.incomplete)};
}

QString filtersText(const osyris::PassCountSettings& st) {
    QStringList f;
    f << (st.vibration == osyris::VibrationFilter::On    ? ReportText::tr("vibration on only")
          : st.vibration == osyris::VibrationFilter::Off ? ReportText::tr("vibration off only")
                                                         : ReportText::tr("vibration on or off"));
    f << (st.direction == osyris::DirectionFilter::Forward    ? ReportText::tr("forward passes only")
          : st.direction == osyris::DirectionFilter::Backward ? ReportText::tr("backward passes only")
                                                              : ReportText::tr("both directions"));
    if (st.speedMin || st.speedMax)
        f << ReportText::tr("speed %1 … %2 m/s")
                 .arg(st.speedMin ? num(*st.speedMin, 2) : QStringLiteral("0"),
                      st.speedMax ? num(*st.speedMax, 2) : QStringLiteral("∞"));
    if (st.timeFrom || st.timeTo)
        f << ReportText::tr("time %1 … %2")
                 .arg(st.timeFrom ? QDateTime::fromMSecsSinceEpoch(*st.timeFrom).toString(Qt::ISODate)
                                  : QStringLiteral("–"),
                      st.timeTo ? QDateTime::fromMSecsSinceEpoch(*st.timeTo).toString(Qt::ISODate)
                                : QStringLiteral("–"));
    if (!st.machines.empty()) {
        QStringList m;
        for (auto i : st.machines)
            m << QString::number(i);
        f << ReportText::tr("machines %1 only").arg(m.join(QStringLiteral(", ")));
    }
    return f.join(QStringLiteral(" · "));
}

// What was counted and how: site, time written, lift, cell, targets, CRS, design, machines, data time range,
// filters, lifts, the incomplete statement and the problems met.
void writeSummary(PdfPageWriter& w, const CoverageJob& job, const CoverageTables& t, int lift) {
    const PassCountSnapshot& snap = *job.snapshot;
    w.heading(job.siteName.isEmpty() ? ReportText::tr("Compaction coverage report")
                                     : ReportText::tr("Compaction coverage report — %1").arg(job.siteName),
              15);
    w.text(ReportText::tr("Written %1 · %2 · cell %3 m · target %4–%5 passes")
               .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyy-MM-dd HH:mm")),
                    liftName(snap, lift), num(snap.cellSize(), 2))
               .arg(snap.targetMin())
               .arg(snap.targetMax()));
    w.text(ReportText::tr("CRS: EPSG:%1 (%2) · design: %3")
               .arg(t.epsg)
               .arg(t.crsName, job.design ? QStringLiteral("%1 (%2 alignments, %3 boundaries)")
                                                .arg(job.designPath)
                                                .arg(job.design->alignments.size())
                                                .arg(job.design->boundaries.size())
                                          : ReportText::tr("none")));
    w.text(ReportText::tr("Machines: %1 · data %2")
               .arg(job.machines.isEmpty() ? ReportText::tr("none known")
                                           : job.machines.join(QStringLiteral(", ")),
                    job.dataFrom.isValid()
                        ? ReportText::tr("%1 to %2")
                              .arg(job.dataFrom.toUTC().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss")),
                                   job.dataTo.toUTC().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss 'UTC'")))
                        : ReportText::tr("time range not known")));
    w.text(ReportText::tr("Filters: %1").arg(filtersText(snap.settings())));
    QStringList lifts;
    for (int i = 0; i < snap.liftCount(); ++i)
        lifts << ReportText::tr("%1: z %2 … %3 m")
                     .arg(i + 1)
                     .arg(snap.liftBottom(i), 0, 'f', 2)
                     .arg(snap.liftTop(i), 0, 'f', 2);
    w.text(ReportText::tr("Lifts (thickness %1): %2")
               .arg(snap.settings().liftThickness > 0
                        ? QStringLiteral("%1 m").arg(snap.settings().liftThickness)
                        : ReportText::tr("off"),
                    lifts.isEmpty() ? ReportText::tr("none") : lifts.join(QStringLiteral("; "))));
    // The incomplete statement: always said, one way or the other.
    if (snap.anyIncomplete() || t.whole.incomplete) {
        QStringList gaps;
        for (const auto& [idx, ranges] : snap.givenUp())
            gaps << ReportText::tr("machine %1: %2 slot ranges").arg(idx).arg(ranges.size());
        w.text(ReportText::tr("INCOMPLETE: %1 cells may be under-counted: ribbon data that never arrived was "
                              "given up (%2). "
                              "Their counts are lower bounds.")
                   .arg(t.whole.incomplete)
                   .arg(gaps.join(QStringLiteral(", "))));
    } else {
        w.text(ReportText::tr(
            "Complete: every ribbon slot of every machine was received; no cell is marked incomplete."));
    }
    for (const QString& prob : t.problems)
        w.text(ReportText::tr("Note: %1").arg(prob));
}

// The map snapshot, centred, scaled to the page width (at most 5:8 high), framed.
void drawMap(PdfPageWriter& w, QPainter& p, const QImage& map) {
    const int W = w.width();
    const QImage scaled = map.scaled(W, W * 5 / 8, Qt::KeepAspectRatio, Qt::SmoothTransformation);
    w.need(scaled.height());
    p.drawImage(QPoint((W - scaled.width()) / 2, w.y()), scaled);
    p.setPen(QColor(0x80, 0x80, 0x80));
    p.drawRect(QRect((W - scaled.width()) / 2, w.y(), scaled.width(), scaled.height()));
    p.setPen(Qt::black);
    w.y() += scaled.height() + 10;
}

// Statistics per area, then per station range along the design's first alignment.
void writeStatistics(PdfPageWriter& w, const CoverageJob& job, const CoverageTables& t) {
    const QStringList header{ReportText::tr("Area"),      ReportText::tr("m²"),   ReportText::tr("covered %"),
                             ReportText::tr("under %"),   ReportText::tr("at %"), ReportText::tr("over %"),
                             ReportText::tr("min"),       ReportText::tr("mean"), ReportText::tr("max"),
                             ReportText::tr("incomplete")};
    const QVector<double> widths{0.19, 0.08, 0.11, 0.09, 0.08, 0.09, 0.06, 0.08, 0.06, 0.13};
    w.heading(ReportText::tr("Statistics per area"), 11);
    QVector<QStringList> rows;
    rows << statsRow(ReportText::tr("All counted cells"), t.whole);
    for (const AreaStats& a : t.areas)
        rows << statsRow(a.name, a.stats);
    w.table(header, rows, widths, {3});
    w.text(ReportText::tr(
        "Cells belong to an area when their centre lies inside it. covered = at least one pass; "
        "under/at/over "
        "the target as % of the area's cells; min/mean/max over covered cells."));
    if (t.stations.isEmpty())
        return;
    w.y() += 6;
    w.heading(ReportText::tr("Statistics per station range — %1, %2 m left to %3 m right of the centre line")
                  .arg(t.alignment)
                  .arg(job.bandLeft)
                  .arg(job.bandRight),
              11);
    QVector<QStringList> srows;
    QStringList sh = header;
    sh[0] = ReportText::tr("Stations");
    for (const auto& b : t.stations)
        srows << statsRow(
            QStringLiteral("%1 – %2").arg(QString::fromStdString(landxml::formatStation(b.from, 0)),
                                          QString::fromStdString(landxml::formatStation(b.to, 0))),
            b.stats);
    w.table(sh, srows, widths, {3});
}

} // namespace

QString writeCoveragePdf(const CoverageJob& job, const CoverageFrames& frames, const CoverageTables& t,
                         int lift, const QString& area, const QString& path, QSize mapSize) {
    if (!job.snapshot)
        return ReportText::tr("no pass counts yet");
    {
        QFile probe(path);
        if (!probe.open(QIODevice::WriteOnly))
            return ReportText::tr("cannot write %1: %2").arg(path, probe.errorString());
    }
    QPdfWriter pdf(path);
    pdf.setPageSize(QPageSize(QPageSize::A4));
    pdf.setResolution(150);
    pdf.setPageMargins(QMarginsF(12, 12, 12, 12), QPageLayout::Millimeter);
    pdf.setTitle(ReportText::tr("Compaction coverage report"));
    pdf.setCreator(QStringLiteral("OCU"));
    QPainter p;
    if (!p.begin(&pdf))
        return ReportText::tr("cannot write %1").arg(path);
    p.setRenderHint(QPainter::Antialiasing);
    p.setRenderHint(QPainter::SmoothPixmapTransform);
    PdfPageWriter w(pdf, p, 8.5);
    writeSummary(w, job, t, lift);
    w.y() += 8;
    drawMap(w, p, renderCoverageMap(job, frames, lift, area, mapSize));
    writeStatistics(w, job, t);
    p.end();
    return {};
}

} // namespace ocu
