#pragma once
// The dispatch view of an ISO 23725 haul truck on the Qt side, as value types a dispatch
// panel and the headless monitor read: who dispatches it (DispatchingCustodian), whether it asked for work,
// the assignment the AHS reports (HaulTruckAssignmentV1) and the responses to this console's last request,
// the production state and payload as last reported. Everything here comes from the AHS's reports, never from
// what the console asked (the requested tasks are kept apart, labelled as such).
#include "models/commands/OperatorCommand.h"
#include "protocols/iso23725/IsoListener.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QMetaType>
#include <QString>
#include <QVector>

#include <optional>

namespace ocu {

// One task of an assignment request (models/commands/OperatorCommand.h).
using IsoTask = AssignTask;

struct IsoAssignmentResponse {
    QString assignmentId;
    QString response; // Accepted | Rejected
    QString detail;
};

// A destination the dispatcher can pick: an area of the AHS's MapConnectivityV1.
struct IsoDestination {
    QString link;
    qint64 wayId = 0;
    QString name;
    QString defaultTask; // Load, Offload, Park, Fuel, ...
};

struct IsoDispatchState {
    QString id; // "iso23725:<guid>"
    QString link;
    QString name;            // HID
    bool stateKnown = false; // false while the link is down / before the snapshot (§2.1)
    QString custodian;       // "FMS", "AHS" or empty (not reported)
    bool needsAssignment = false;
    QString autonomyMode;
    // HaulTruckAssignmentV1 as reported by the AHS (status empty: none reported).
    QString assignmentId;
    QString assignmentStatus; // Pending | Active | Completed | Cancelled
    QString task;
    std::optional<qint64> destinationId;
    QString destinationName;                  // from MapConnectivityV1 when known
    QVector<IsoTask> requested;               // this console's last request (not the truck's state)
    QVector<IsoAssignmentResponse> responses; // the AHS's answers to it (unsolicited Rejected included)
    // HaulTruckProductionStateV2 and HaulTruckPayloadV1 as reported.
    QString productionState;
    std::optional<qint64> wayId;
    qint64 productionSinceMs = 0;        // header time of the production state report
    std::optional<double> payloadTonnes; // null payload stays unknown, never 0
    qint64 payloadUnixMs = 0;
    // Whether the truck carries a load, as it reported: HaulTruckProductionStateSensorV1.Loaded when it sends
    // that, else a payload above 0 reported after its last dump; unknown when neither.
    std::optional<bool> loaded;

    // The newest response naming `assignmentId`, or null.
    const IsoAssignmentResponse* response(const QString& assignmentId) const;
};

IsoDispatchState toDispatchState(const iso23725::IsoMachineSnapshot& m);

// {"id":..,"name":..,"custodian":..,"needs_assignment":..,"assignment":{..}|null,"production_state":..,...}
QJsonObject dispatchToJson(const IsoDispatchState& s);

std::vector<iso23725::AssignmentItem> toAssignmentItems(const QVector<IsoTask>& tasks);

} // namespace ocu

Q_DECLARE_METATYPE(ocu::IsoDispatchState)
