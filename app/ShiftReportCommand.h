#pragma once
// The shift report from the command line and the headless monitor: writes the production
// model's report (the ISO 23725 bridge's) as PDF and/or CSV and says truthfully what was written.
#include <QJsonObject>
#include <QString>
#include <QVector>

#include <optional>

namespace ocu {

class FleetBridge;
class FleetModel;

struct ShiftReportRequest {
    QString pdf; // empty: no PDF
    QString csv; // empty: no CSV
    std::optional<double> planTonnes;
    QString siteName;
};

// {"ok":..,"message":..,"written":{"pdf":true,"csv":true},"errors":[..],"loads":..,"tonnes":..,"cycles":..}:
// ok only when a file was asked for and every file asked for was written.
QJsonObject writeShiftReport(const QVector<FleetBridge*>& bridges, FleetModel* fleet,
                             const ShiftReportRequest& r);

} // namespace ocu
