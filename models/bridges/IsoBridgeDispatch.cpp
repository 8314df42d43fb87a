#include "models/bridges/IsoBridgeDispatch.h"

#include <QCoreApplication>

#include <cmath>

namespace ocu {

using namespace iso23725;

namespace {
QString q(const std::string& s) {
    return QString::fromStdString(s);
}
QString tr(const char* text) {
    return QCoreApplication::translate("IsoDispatch", text);
}
} // namespace

const IsoAssignmentResponse* IsoDispatchState::response(const QString& assignmentId) const {
    for (auto it = responses.crbegin(); it != responses.crend(); ++it)
        if (it->assignmentId == assignmentId)
            return &*it;
    return nullptr;
}

IsoDispatchState toDispatchState(const IsoMachineSnapshot& m) {
    IsoDispatchState s;
    s.id = QStringLiteral("iso23725:") + q(m.equipmentId);
    s.link = q(m.link);
    s.name = m.hid.empty() ? q(m.equipmentId).left(8) : q(m.hid);
    s.stateKnown = m.stateKnown;
    s.custodian = q(m.dispatchingCustodian);
    s.needsAssignment = m.needsAssignment;
    s.autonomyMode = q(m.autonomyMode);
    if (m.assignment) {
        s.assignmentId = m.assignment->assignmentId ? q(*m.assignment->assignmentId) : QString();
        s.assignmentStatus = q(m.assignment->status);
        s.task = m.assignment->task ? q(*m.assignment->task) : QString();
        if (m.assignment->destinationId)
            s.destinationId = *m.assignment->destinationId;
    }
    for (const auto& a : m.requestedAssignments) {
        IsoTask t;
        t.assignmentId = q(a.assignmentId);
        t.task = q(a.task);
        t.destinationId = a.destinationId;
        t.destinationEquipmentId = a.destinationEquipmentId ? q(*a.destinationEquipmentId) : QString();
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
        s.responses << IsoAssignmentResponse{q(r.assignmentId), q(r.response),
                                             r.detail ? q(*r.detail) : QString()};
    if (m.production) {
        s.productionState = q(m.production->productionState);
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

QJsonArray tasksToJson(const QVector<IsoTask>& tasks) {
    QJsonArray out;
    for (const auto& t : tasks) {
        QJsonObject o;
        if (!t.assignmentId.isEmpty())
            o[QStringLiteral("assignment_id")] = t.assignmentId;
        o[QStringLiteral("task")] = t.task;
        o[QStringLiteral("destination")] = double(t.destinationId);
        if (!t.destinationEquipmentId.isEmpty())
            o[QStringLiteral("equipment")] = t.destinationEquipmentId;
        if (t.destinationSpotId)
            o[QStringLiteral("spot")] = double(*t.destinationSpotId);
        if (t.route) {
            QJsonArray r;
            for (qint64 w : *t.route)
                r << double(w);
            o[QStringLiteral("route")] = r;
        }
        out << o;
    }
    return out;
}

namespace {
// A JSON number that is an integer way/spot id within ±2^53.
std::optional<qint64> wholeNumber(const QJsonValue& v) {
    if (!v.isDouble())
        return std::nullopt;
    const double d = v.toDouble();
    if (!std::isfinite(d) || std::floor(d) != d || std::fabs(d) > 9007199254740992.0)
        return std::nullopt;
    return static_cast<qint64>(d);
}
} // namespace

std::optional<QVector<IsoTask>> tasksFromJson(const QJsonObject& args, QString* error) {
    auto fail = [&](const QString& why) -> std::optional<QVector<IsoTask>> {
        if (error)
            *error = why;
        return std::nullopt;
    };
    QJsonArray list;
    if (args.contains(QStringLiteral("tasks"))) {
        if (!args.value(QStringLiteral("tasks")).isArray())
            return fail(tr("\"tasks\" must be an array of tasks"));
        list = args.value(QStringLiteral("tasks")).toArray();
    } else {
        list << args; // single-task shorthand
    }
    if (list.isEmpty())
        return fail(tr("no task given"));
    if (list.size() > 64)
        return fail(tr("at most 64 tasks per request"));
    QVector<IsoTask> out;
    for (int i = 0; i < list.size(); ++i) {
        const QString where = list.size() > 1 || args.contains(QStringLiteral("tasks"))
                                  ? tr("task %1: ").arg(i + 1)
                                  : QString();
        if (!list[i].isObject())
            return fail(where + tr("must be an object"));
        const QJsonObject o = list[i].toObject();
        IsoTask t;
        t.task = o.value(QStringLiteral("task")).toString();
        if (t.task.isEmpty())
            return fail(where + tr("\"task\" missing (Load, Offload, Fuel, Park or Wait)"));
        const auto dest = wholeNumber(o.value(QStringLiteral("destination")));
        if (!dest)
            return fail(where + tr("\"destination\" must be a way id (integer)"));
        t.destinationId = *dest;
        t.assignmentId = o.value(QStringLiteral("assignment_id")).toString();
        t.destinationEquipmentId = o.value(QStringLiteral("equipment")).toString();
        if (o.contains(QStringLiteral("spot"))) {
            const auto spot = wholeNumber(o.value(QStringLiteral("spot")));
            if (!spot)
                return fail(where + tr("\"spot\" must be an integer"));
            t.destinationSpotId = *spot;
        }
        if (o.contains(QStringLiteral("route"))) {
            if (!o.value(QStringLiteral("route")).isArray())
                return fail(where + tr("\"route\" must be an array of way ids"));
            QVector<qint64> r;
            for (const auto& w : o.value(QStringLiteral("route")).toArray()) {
                const auto id = wholeNumber(w);
                if (!id)
                    return fail(where + tr("\"route\" must be an array of way ids"));
                r << *id;
            }
            t.route = r;
        }
        out << t;
    }
    return out;
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
