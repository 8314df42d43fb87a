#pragma once
// The shift report from the command line and the headless monitor: writes the production
// model's report (the one a protocol module offers, ProtocolModule::production()) as PDF and/or CSV and says
// truthfully what was written.
#include <QJsonObject>
#include <QString>

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
// ok only when a file was asked for and every file asked for was written. model nullptr: none in this
// console; the PDF's map is mapSource's site map with the fleet's machines.
QJsonObject writeShiftReport(ProductionModel* model, const FleetBridge* mapSource, FleetModel* fleet,
                             const ShiftReportRequest& r);

} // namespace ocu
