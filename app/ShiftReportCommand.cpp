#include "app/ShiftReportCommand.h"

#include "models/FleetBridge.h"
#include "models/ProductionModel.h"
#include "widgets/production/ShiftReport.h"

#include <QJsonArray>

namespace ocu {

QJsonObject writeShiftReport(ProductionModel* model, const FleetBridge* mapSource, FleetModel* fleet,
                             const ShiftReportRequest& r) {
    QJsonObject o;
    QJsonObject written{{QStringLiteral("pdf"), false}, {QStringLiteral("csv"), false}};
    QJsonArray errors;
    if (!model) {
        o[QStringLiteral("ok")] = false;
        o[QStringLiteral("message")] =
            QStringLiteral("no production model in this console (no link reports production)");
        o[QStringLiteral("written")] = written;
        return o;
    }
    if (r.pdf.isEmpty() && r.csv.isEmpty())
        errors << QStringLiteral("give \"pdf\" and/or \"csv\" (file names)");
    if (r.planTonnes)
        model->setPlanTonnes(*r.planTonnes);
    if (!r.pdf.isEmpty()) {
        const QImage map =
            renderSiteSnapshot(fleet, mapSource ? mapSource->siteMap() : SiteMapData{}, QSize(1100, 500));
        const QString e = writeShiftPdf(*model, map, r.siteName, r.pdf);
        if (e.isEmpty())
            written[QStringLiteral("pdf")] = true;
        else
            errors << e;
    }
    if (!r.csv.isEmpty()) {
        const QString e = writeShiftCsv(*model, r.csv);
        if (e.isEmpty())
            written[QStringLiteral("csv")] = true;
        else
            errors << e;
    }
    const bool ok = errors.isEmpty();
    o[QStringLiteral("ok")] = ok;
    o[QStringLiteral("written")] = written;
    if (!errors.isEmpty())
        o[QStringLiteral("errors")] = errors;
    o[QStringLiteral("loads")] = model->shift().loads;
    o[QStringLiteral("tonnes")] = model->shift().tonnes;
    o[QStringLiteral("cycles")] = model->shift().cycle.cycles;
    QStringList files;
    if (written[QStringLiteral("pdf")].toBool())
        files << r.pdf;
    if (written[QStringLiteral("csv")].toBool())
        files << r.csv;
    o[QStringLiteral("message")] =
        ok ? QStringLiteral("shift report written: %1 (%2 loads, %3 t)")
                 .arg(files.join(QStringLiteral(", ")))
                 .arg(model->shift().loads)
                 .arg(model->shift().tonnes, 0, 'f', 0)
           : QStringLiteral("shift report not (fully) written: %1")
                 .arg(errors.toVariantList().isEmpty() ? QString() : errors.first().toString());
    return o;
}

} // namespace ocu
