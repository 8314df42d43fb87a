#pragma once
// Protocol-neutral dispatch data for the dispatch panel: one DispatchTruck per haul truck as
// its fleet-management side last reported it, the areas a truck can be sent to, and the route a truck has
// left to drive. A protocol adapter (models/bridges/IsoDispatchSource for ISO 23725) fills it; widgets read
// only this (they include no protocol stack header). Everything here comes from the machines' reports; what
// this console asked is kept apart (requestedTask/requestedDestination, lastResponse).
#include "models/commands/OperatorCommand.h"

#include <QJsonObject>
#include <QMetaType>
#include <QObject>
#include <QString>
#include <QStringList>
#include <QVector>

#include <optional>

namespace ocu {

struct DispatchTruck {
    QString id; // machine id ("iso23725:<guid>"), as in FleetModel
    QString link;
    QString name;
    bool stateKnown = false;
    QString custodian; // "FMS", "AHS" or empty (not reported)
    bool needsAssignment = false;
    QString autonomyMode;
    QString assignmentId;     // as the truck reports it
    QString assignmentStatus; // Pending | Active | Completed | Cancelled; empty: none reported
    QString task;
    std::optional<qint64> destinationId;
    QString destinationName;
    // This console's last request and the truck's answer to it (empty: none yet).
    QString requestedAssignmentId;
    QString requestedTask;
    std::optional<qint64> requestedDestination;
    QString lastResponse; // Accepted | Rejected
    QString lastResponseDetail;
    QString productionState;
    std::optional<qint64> wayId;
    qint64 productionSinceMs = 0; // ms since the epoch of the production state report; 0 = unknown
    std::optional<double> payloadTonnes;
    std::optional<bool> loaded; // carries a load, as the truck reported (unknown: not reported)

    // The destination the truck is heading for: the reported assignment's while Pending/Active, else none.
    std::optional<qint64> activeDestination() const {
        if (assignmentStatus == QLatin1String("Pending") || assignmentStatus == QLatin1String("Active"))
            return destinationId;
        return std::nullopt;
    }
};

// A destination the dispatcher can pick: an area of the site's road network.
struct DispatchArea {
    QString link;
    qint64 wayId = 0;
    QString name;
    QString defaultTask; // Load, Offload, Park, Fuel, ...
    // The SiteMapData feature id of the area ("<link>/<way id>"), for the map click.
    QString featureId() const { return link + QLatin1Char('/') + QString::number(wayId); }
};

// The route a truck has left: way ids from its current way to its destination (both included).
struct DispatchRoute {
    QString link;
    QVector<qint64> ways;
    double lengthM = 0; // the ways entered after the current one (the current way's rest is not known)
    QString error;      // why there is none (ways empty)
    bool fromAssignment = false; // the ways of the assignment request; false: the console's shortest path
};

class DispatchSource : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;
    ~DispatchSource() override = default;

    virtual QVector<DispatchTruck> trucks() const = 0; // in id order
    virtual std::optional<DispatchTruck> truck(const QString& id) const = 0;
    virtual QVector<DispatchArea> areas() const = 0;
    // Why an assignment to this truck would be refused now, or empty (the bridge checks again when sent).
    virtual QString assignRefusal(const QString& id) const = 0;
    // The route the truck has left to its active destination (empty with a reason when none).
    virtual DispatchRoute route(const QString& id) const = 0;
    // The route the truck would drive to `area` from its reported way (the preview before assigning).
    virtual DispatchRoute routeTo(const QString& id, const DispatchArea& area) const = 0;
    // The assign command (CommandGate::command) for one task to `area`; the request's assignment id
    // (generated here) in `assignmentId`, to follow the truck's answer (DispatchTruck::lastResponse).
    virtual Assign assignCommand(const QString& id, const QString& task, const DispatchArea& area,
                                 QString* assignmentId = nullptr) const = 0;

signals:
    void trucksChanged(const QStringList& ids); // changed or removed
    void areasChanged();
};

} // namespace ocu

Q_DECLARE_METATYPE(ocu::DispatchTruck)
