#pragma once
// The shift report from the command line and the headless monitor: writes the production
// model's report (a protocol module's, ProtocolModule::production()) as PDF and/or CSV and says truthfully
// what was written.
#include <QJsonObject>
#include <QString>
#include <QVector>

#include <optional>

namespace ocu {

class FleetBridge;
class FleetModel;
class ProductionModel;

struct ShiftReportRequest {
    QString pdf; // empty: no PDF
    QString csv; // empty: no CSV
    std::optional<double> planTonnes;
    QString siteName;
};

// {"ok":..,"message":..,"written":{"pdf":true,"csv":true},"errors":[..],"loads":..,"tonnes":..,"cycles":..}:
// ok only when a file was asked for and every file asked for was written. `model` nullptr: none in this
// console; `mapSource` gives the site map of the PDF.
QJsonObject writeShiftReport(ProductionModel* model, const FleetBridge* mapSource, FleetModel* fleet,
                             const ShiftReportRequest& r);
// The same with the production model found among the bridges (the headless monitor's shift_report).
QJsonObject writeShiftReport(const QVector<FleetBridge*>& bridges, FleetModel* fleet,
                             const ShiftReportRequest& r);

} // namespace ocu
