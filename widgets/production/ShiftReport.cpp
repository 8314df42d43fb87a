#include "widgets/production/ShiftReport.h"

#include "models/PdfPageWriter.h"
#include "models/ProductionModel.h"
#include "models/SiteMapData.h"
#include "widgets/SiteMapView.h"
#include "widgets/production/ProductionCharts.h"

#include <QDateTime>
#include <QFile>
#include <QFileInfo>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>
#include <QSaveFile>
#include <QTextStream>

#include <algorithm>

namespace ocu {

namespace {

QString num(double v, int decimals) {
    return QString::number(v, 'f', decimals);
}

QString csvField(const QString& s) {
    if (!s.contains(QLatin1Char(',')) && !s.contains(QLatin1Char('"')) && !s.contains(QLatin1Char('\n')))
        return s;
    QString q = s;
    q.replace(QLatin1String("\""), QLatin1String("\"\""));
    return QLatin1Char('"') + q + QLatin1Char('"');
}

QStringList row(const QString& section, const ProductionTally& t) {
    QStringList r{section,
                  t.key,
                  t.name,
                  QString::number(t.loads),
                  num(t.tonnes, 1),
                  QString::number(t.loadsWithoutTonnes),
                  QString::number(t.cycle.cycles),
                  num(t.cycle.averageTotal(), 1)};
    for (int p = 0; p < CycleBreakdown::PartCount; ++p)
        r << num(t.cycle.average(CycleBreakdown::Part(p)), 1);
    return r;
}

QString when(qint64 ms) {
    return QDateTime::fromMSecsSinceEpoch(ms).toString(QStringLiteral("yyyy-MM-dd HH:mm"));
}

QString minutes(double seconds) {
    return QStringLiteral("%1:%2")
        .arg(qint64(seconds) / 60)
        .arg(qint64(seconds) % 60, 2, 10, QLatin1Char('0'));
}

QVector<QStringList> tableRows(const QVector<ProductionTally>& tallies, const ProductionTally* total) {
    QVector<QStringList> rows;
    auto add = [&](const ProductionTally& t) {
        QStringList r{t.name, QString::number(t.loads), num(t.tonnes, 0),
                      t.loads ? num(t.tonnes / std::max(1, t.loads - t.loadsWithoutTonnes), 0)
                              : QStringLiteral("–"),
                      QString::number(t.cycle.cycles)};
        for (auto part : {CycleBreakdown::Queue, CycleBreakdown::Spot, CycleBreakdown::Load,
                          CycleBreakdown::Haul, CycleBreakdown::Dump, CycleBreakdown::Return})
            r << (t.cycle.cycles ? minutes(t.cycle.average(part)) : QStringLiteral("–"));
        r << (t.cycle.cycles ? minutes(t.cycle.averageTotal()) : QStringLiteral("–"));
        rows << r;
    };
    for (const auto& t : tallies)
        add(t);
    if (total)
        add(*total);
    return rows;
}

} // namespace

QVector<QStringList> shiftCsvRows(const ProductionModel& m) {
    QVector<QStringList> rows;
    QStringList header{QStringLiteral("section"), QStringLiteral("key"),
                       QStringLiteral("name"),    QStringLiteral("loads"),
                       QStringLiteral("tonnes"),  QStringLiteral("loads_without_tonnes"),
                       QStringLiteral("cycles"),  QStringLiteral("avg_cycle_s")};
    for (int p = 0; p < CycleBreakdown::PartCount; ++p)
        header << CycleBreakdown::partName(CycleBreakdown::Part(p)) + QStringLiteral("_s");
    rows << header;
    rows << row(QStringLiteral("shift"), m.shift());
    for (const auto& t : m.trucks())
        rows << row(QStringLiteral("truck"), t);
    for (const auto& t : m.shovels())
        rows << row(QStringLiteral("shovel"), t);
    for (const auto& t : m.dumps())
        rows << row(QStringLiteral("dump"), t);
    return rows;
}

QString writeShiftCsv(const ProductionModel& m, const QString& file) {
    QSaveFile f(file);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Text))
        return QObject::tr("cannot write %1: %2").arg(file, f.errorString());
    QTextStream out(&f);
    out << "# OCU shift report\n";
    out << "# shift_start," << QDateTime::fromMSecsSinceEpoch(m.shiftStart()).toUTC().toString(Qt::ISODate)
        << "\n";
    out << "# shift_end," << QDateTime::fromMSecsSinceEpoch(m.shiftEnd()).toUTC().toString(Qt::ISODate)
        << "\n";
    out << "# plan_tonnes," << num(m.planTonnes(), 1) << "\n";
    for (const QStringList& r : shiftCsvRows(m)) {
        QStringList cells;
        for (const QString& c : r)
            cells << csvField(c);
        out << cells.join(QLatin1Char(',')) << "\n";
    }
    out.flush();
    if (!f.commit())
        return QObject::tr("cannot write %1: %2").arg(file, f.errorString());
    return {};
}

QString writeShiftPdf(const ProductionModel& m, const QImage& map, const QString& siteName,
                      const QString& file) {
    {
        QFile probe(file);
        if (!probe.open(QIODevice::WriteOnly))
            return QObject::tr("cannot write %1: %2").arg(file, probe.errorString());
    }
    QPdfWriter pdf(file);
    pdf.setPageSize(QPageSize(QPageSize::A4));
    pdf.setResolution(150);
    pdf.setPageMargins(QMarginsF(12, 12, 12, 12), QPageLayout::Millimeter);
    pdf.setTitle(QObject::tr("Shift report"));
    pdf.setCreator(QStringLiteral("OCU"));
    QPainter p;
    if (!p.begin(&pdf))
        return QObject::tr("cannot write %1").arg(file);
    p.setRenderHint(QPainter::Antialiasing);
    p.setRenderHint(QPainter::SmoothPixmapTransform);
    PdfPageWriter w(pdf, p, 9);
    const int W = w.width();

    const QString site = siteName.isEmpty() ? m.siteName() : siteName;
    w.heading(site.isEmpty() ? QObject::tr("Shift report") : QObject::tr("Shift report — %1").arg(site), 16);
    w.text(QObject::tr("Shift %1 to %2 · written %3")
               .arg(when(m.shiftStart()), when(m.shiftEnd()),
                    QDateTime::currentDateTime().toString(QStringLiteral("yyyy-MM-dd HH:mm"))));
    const auto& s = m.shift();
    const qint64 now = std::clamp(m.nowMs(), m.shiftStart(), m.shiftEnd());
    QString planText =
        m.planTonnes() > 0
            ? QObject::tr("plan %1 t for the shift, %2 t due by now (%3 %)")
                  .arg(num(m.planTonnes(), 0), num(m.plannedTonnesAt(now), 0),
                       num(m.plannedTonnesAt(now) > 0 ? 100 * s.tonnes / m.plannedTonnesAt(now) : 0, 0))
            : QObject::tr("no plan set");
    w.text(QObject::tr("%1 loads, %2 t dumped, %3 cycles, average cycle %4 · %5")
               .arg(s.loads)
               .arg(num(s.tonnes, 0))
               .arg(s.cycle.cycles)
               .arg(s.cycle.cycles ? minutes(s.cycle.averageTotal()) : QStringLiteral("–"))
               .arg(planText));
    if (s.loadsWithoutTonnes)
        w.text(QObject::tr("%1 loads were dumped without a reported weight (not in the tonnes)")
                   .arg(s.loadsWithoutTonnes));
    w.y() += 10;

    // Map snapshot, then the two charts side by side.
    const int mapH = W * 9 / 20;
    if (!map.isNull()) {
        const QImage scaled = map.scaled(W, mapH, Qt::KeepAspectRatio, Qt::SmoothTransformation);
        // (callers render the snapshot at about 3/4 of this size, so its labels stay legible on paper)
        const int x = (W - scaled.width()) / 2;
        p.drawImage(QPoint(x, w.y()), scaled);
        p.setPen(QColor(0x80, 0x80, 0x80));
        p.drawRect(QRect(x, w.y(), scaled.width(), scaled.height()));
        p.setPen(Qt::black);
        w.y() += scaled.height() + 12;
    } else {
        w.text(QObject::tr("(no site map available for the snapshot)"));
    }
    const int chartH = W * 2 / 5;
    w.need(chartH);
    const QImage tonnes = renderProductionChart(ProductionChart::TonnesVsPlan, m, QSize(W / 2 - 6, chartH));
    const QImage cycle = renderProductionChart(ProductionChart::CycleBreakdown, m, QSize(W / 2 - 6, chartH));
    p.drawImage(QPoint(0, w.y()), tonnes);
    p.drawImage(QPoint(W / 2 + 6, w.y()), cycle);
    w.y() += chartH + 12;

    const QStringList header{QObject::tr("Name"),   QObject::tr("Loads"),  QObject::tr("Tonnes"),
                             QObject::tr("t/load"), QObject::tr("Cycles"), QObject::tr("Queue"),
                             QObject::tr("Spot"),   QObject::tr("Load"),   QObject::tr("Haul"),
                             QObject::tr("Dump"),   QObject::tr("Return"), QObject::tr("Cycle")};
    const QVector<double> widths{0.145, 0.085, 0.085, 0.075, 0.075, 0.076,
                                 0.076, 0.076, 0.076, 0.076, 0.076, 0.079};
    ProductionTally total = s;
    total.name = QObject::tr("Shift");
    w.heading(QObject::tr("Trucks (cycle parts: average min:s per cycle)"), 12);
    w.table(header, tableRows(m.trucks(), &total), widths, {4, true, true}); // the shift's total in bold
    w.heading(QObject::tr("Shovels (load areas)"), 12);
    w.table(header, tableRows(m.shovels(), nullptr), widths, {4, true, false});
    w.heading(QObject::tr("Dumps and crusher"), 12);
    w.table(header, tableRows(m.dumps(), nullptr), widths, {4, true, false});
    if (!p.end())
        return QObject::tr("cannot write %1").arg(file);
    if (QFileInfo(file).size() == 0)
        return QObject::tr("cannot write %1").arg(file);
    return {};
}

QImage renderSiteSnapshot(FleetModel* fleet, const SiteMapData& map, const QSize& size) {
    if (map.features.isEmpty())
        return {};
    SiteMapView view;
    view.resize(size);
    view.setSiteMap(map);
    // Framed to the map (machines of other protocols may be far away), with a small margin.
    const QRectF b = map.bounds();
    if (b.width() > 0 && b.height() > 0)
        view.setView(b.center(), 0.94 * std::min(size.width() / b.width(), size.height() / b.height()));
    if (fleet)
        view.setFleet(fleet, nullptr);
    QImage img(size, QImage::Format_ARGB32_Premultiplied);
    img.fill(Qt::white);
    QPainter p(&img);
    view.paintScene(p, size);
    return img;
}

} // namespace ocu
