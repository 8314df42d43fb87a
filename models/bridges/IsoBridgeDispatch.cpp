#include "models/bridges/IsoBridgeDispatch.h"
#include "models/QtStrings.h"

#include <QCoreApplication>

#include <cmath>

namespace ocu {

using namespace iso23725;

const IsoAssignmentResponse* IsoDispatchState::response(const QString& assignmentId) const {
    for (auto it = responses.crbegin(); it != responses.crend(); ++it)
        if (it->assignmentId == assignmentId)
            return &*it;
    return nullptr;
}

IsoDispatchState toDispatchState(const IsoMachineSnapshot& m) {
    IsoDispatchState s;
    s.id = QStringLiteral("iso23725:") + toQString(m.equipmentId);
    s.link = toQString(m.link);
    s.name = m.hid.empty() ? toQString(m.equipmentId).left(8) : toQString(m.hid);
    s.stateKnown = m.stateKnown;
    s.custodian = toQString(m.dispatchingCustodian);
    s.needsAssignment = m.needsAssignment;
    s.autonomyMode = toQString(m.autonomyMode);
    if (m.assignment) {
        s.assignmentId = m.assignment->assignmentId ? toQString(*m.assignment->assignmentId) : QString();
        s.assignmentStatus = toQString(m.assignment->status);
        s.task = m.assignment->task ? toQString(*m.assignment->task) : QString();
        if (m.assignment->destinationId)
            s.destinationId = *m.assignment->destinationId;
    }
    for (const auto& a : m.requestedAssignments) {
        IsoTask t;
        t.assignmentId = toQString(a.assignmentId);
        t.task = toQString(a.task);
        t.destinationId = a.destinationId;
        t.destinationEquipmentId =
            a.destinationEquipmentId ? toQString(*a.destinationEquipmentId) : QString();
        t.destinationSpotId = a.destinationSpotId;
        if (a.route) {
            QVector<qint64> r;
            for (auto& w : *a.route)
                r << w.wayId;
            t.route = r;
        }
        s.requested << t;
    }
    for (const auto& r : m.assignmentResponses)
        s.responses << IsoAssignmentResponse{toQString(r.assignmentId), toQString(r.response),
                                             r.detail ? toQString(*r.detail) : QString()};
    if (m.production) {
        s.productionState = toQString(m.production->productionState);
        if (m.production->wayId)
            s.wayId = *m.production->wayId;
        s.productionSinceMs = m.productionUnixMs;
    }
    if (m.payload && m.payload->payloadWeight) {
        s.payloadTonnes = double(*m.payload->payloadWeight);
        s.payloadUnixMs = m.payloadUnixMs;
    }
    if (m.sensor && m.sensor->loaded)
        s.loaded = *m.sensor->loaded;
    else if (m.payload && m.payload->payloadWeight)
        s.loaded = *m.payload->payloadWeight > 0 && (!m.lastDump || m.payloadUnixMs > m.dumpUnixMs);
    else if (m.lastDump)
        s.loaded = false;
    return s;
}

QJsonObject dispatchToJson(const IsoDispatchState& s) {
    auto orNull = [](const QString& v) { return v.isEmpty() ? QJsonValue(QJsonValue::Null) : QJsonValue(v); };
    QJsonObject o;
    o[QStringLiteral("id")] = s.id;
    o[QStringLiteral("link")] = s.link;
    o[QStringLiteral("name")] = s.name;
    o[QStringLiteral("state_known")] = s.stateKnown;
    o[QStringLiteral("custodian")] = orNull(s.custodian);
    o[QStringLiteral("needs_assignment")] = s.needsAssignment;
    o[QStringLiteral("autonomy_mode")] = orNull(s.autonomyMode);
    if (s.assignmentStatus.isEmpty()) {
        o[QStringLiteral("assignment")] = QJsonValue::Null;
    } else {
        QJsonObject a;
        a[QStringLiteral("assignment_id")] = orNull(s.assignmentId);
        a[QStringLiteral("status")] = s.assignmentStatus;
        a[QStringLiteral("task")] = orNull(s.task);
        a[QStringLiteral("destination")] =
            s.destinationId ? QJsonValue(double(*s.destinationId)) : QJsonValue();
        a[QStringLiteral("destination_name")] = orNull(s.destinationName);
        o[QStringLiteral("assignment")] = a;
    }
    QJsonArray responses;
    for (const auto& r : s.responses) {
        QJsonObject x;
        x[QStringLiteral("assignment_id")] = r.assignmentId;
        x[QStringLiteral("response")] = r.response;
        if (!r.detail.isEmpty())
            x[QStringLiteral("detail")] = r.detail;
        responses << x;
    }
    o[QStringLiteral("requested")] = tasksToJson(s.requested);
    o[QStringLiteral("responses")] = responses;
    o[QStringLiteral("production_state")] = orNull(s.productionState);
    o[QStringLiteral("way")] = s.wayId ? QJsonValue(double(*s.wayId)) : QJsonValue();
    o[QStringLiteral("payload_t")] = s.payloadTonnes ? QJsonValue(*s.payloadTonnes) : QJsonValue();
    return o;
}

std::vector<AssignmentItem> toAssignmentItems(const QVector<IsoTask>& tasks) {
    std::vector<AssignmentItem> out;
    for (const auto& t : tasks) {
        AssignmentItem a;
        a.assignmentId = t.assignmentId.toStdString();
        a.task = t.task.toStdString();
        a.destinationId = t.destinationId;
        if (!t.destinationEquipmentId.isEmpty())
            a.destinationEquipmentId = t.destinationEquipmentId.toStdString();
        a.destinationSpotId = t.destinationSpotId;
        if (t.route) {
            a.route.emplace();
            for (qint64 w : *t.route)
                a.route->push_back(WayRef{w});
        }
        out.push_back(std::move(a));
    }
    return out;
}

} // namespace ocu
