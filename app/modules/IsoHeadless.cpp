#include "app/modules/IsoHeadless.h"

#include "app/HeadlessCommands.h"
#include "app/ShiftReportCommand.h"
#include "models/AutoDispatcher.h"
#include "models/FleetModel.h"
#include "models/ProductionModel.h"
#include "models/bridges/IsoBridge.h"

#include <QJsonArray>
#include <QPointer>
#include <QUuid>

namespace ocu {

namespace {

// assign and reset_assignment: a truck to address; assign's shorthand (one task at the top level) becomes
// "tasks", and every task gets its AssignmentId here so the result line names them.
HeadlessCommands::GateRequest dispatchRequest(const QString& name, const QJsonObject& cmd) {
    if (cmd.value(QStringLiteral("id")).toString().isEmpty()) {
        HeadlessCommands::GateRequest r;
        r.refusal = QStringLiteral("missing \"id\"");
        return r;
    }
    QJsonObject args = cmd;
    if (name == QLatin1String("assign") &&
        !(cmd.contains(QStringLiteral("tasks")) && !cmd.value(QStringLiteral("tasks")).isArray())) {
        // (tasks that are not an array are read as they are: the reader says why)
        QJsonArray tasks = cmd.value(QStringLiteral("tasks")).toArray();
        if (!cmd.contains(QStringLiteral("tasks"))) {
            QJsonObject one;
            for (const char* k : {"task", "destination", "equipment", "spot", "route", "assignment_id"})
                if (cmd.contains(QLatin1String(k)))
                    one[QLatin1String(k)] = cmd.value(QLatin1String(k));
            tasks << one;
        }
        for (int i = 0; i < tasks.size(); ++i)
            if (tasks[i].isObject() && !tasks[i].toObject().contains(QStringLiteral("assignment_id"))) {
                QJsonObject t = tasks[i].toObject();
                t[QStringLiteral("assignment_id")] = QUuid::createUuid().toString(QUuid::WithoutBraces);
                tasks[i] = t;
            }
        args[QStringLiteral("tasks")] = tasks;
    }
    HeadlessCommands::GateRequest r = HeadlessCommands::read(name, args);
    if (args.value(QStringLiteral("tasks")).isArray())
        r.echo[QStringLiteral("tasks")] = args.value(QStringLiteral("tasks"));
    return r;
}

QJsonObject productionFields(const IsoBridge* bridge, const QJsonObject& cmd) {
    const QString id = cmd.value(QStringLiteral("id")).toString();
    QJsonArray trucks;
    if (bridge)
        for (const auto& t : bridge->productionJson())
            if (id.isEmpty() || t.toObject().value(QStringLiteral("id")).toString() == id)
                trucks << t;
    return {{QStringLiteral("ok"), bridge != nullptr},
            {QStringLiteral("trucks"), trucks},
            {QStringLiteral("message"), bridge ? QStringLiteral("%1 trucks").arg(trucks.size())
                                               : QStringLiteral("no ISO 23725 bridge in this console")}};
}

QJsonObject autoDispatchFields(AutoDispatcher* d, const IsoBridge* bridge, const QJsonObject& cmd) {
    const QJsonValue on = cmd.value(QStringLiteral("on"));
    if (!on.isUndefined() && !on.isBool())
        return {{QStringLiteral("ok"), false},
                {QStringLiteral("message"), QStringLiteral("\"on\" must be true or false")}};
    QJsonArray list;
    if (d && bridge) {
        if (on.isBool())
            d->setOn(on.toBool(), HeadlessCommands::origin());
        list.append(QJsonObject{{QStringLiteral("bridge"), toText(bridge->protocol())},
                                {QStringLiteral("on"), d->isOn()},
                                {QStringLiteral("sent"), d->assignmentsSent()},
                                {QStringLiteral("last"), d->lastAction()}});
    }
    const bool isOn = d && bridge && d->isOn();
    return {
        {QStringLiteral("ok"), !list.isEmpty()},
        {QStringLiteral("on"), isOn},
        {QStringLiteral("dispatchers"), list},
        {QStringLiteral("message"),
         list.isEmpty()
             ? QStringLiteral("no dispatch source in this console (ISO 23725 haul trucks)")
             : QStringLiteral("auto dispatch %1").arg(isOn ? QStringLiteral("ON") : QStringLiteral("OFF"))}};
}

} // namespace

void registerIsoHeadless(HeadlessCommands& table, const IsoHeadlessParts& parts) {
    for (const QString& name : {QStringLiteral("assign"), QStringLiteral("reset_assignment")})
        table.addGateCommand(name, [name](const QJsonObject& cmd) { return dispatchRequest(name, cmd); });
    QPointer<IsoBridge> bridge(parts.bridge);
    table.addLocal(QStringLiteral("production"),
                   [bridge](const QJsonObject& cmd) { return productionFields(bridge.data(), cmd); });
    QPointer<AutoDispatcher> dispatcher(parts.dispatcher);
    table.addLocal(
        QStringLiteral("auto_dispatch"),
        [bridge, dispatcher](const QJsonObject& cmd) {
            return autoDispatchFields(dispatcher.data(), bridge.data(), cmd);
        },
        [](const QJsonObject& cmd) { return cmd.contains(QStringLiteral("on")); }); // without "on": a query
    QPointer<ProductionModel> production(parts.production);
    QPointer<FleetModel> fleet(parts.fleet);
    table.addLocal(
        QStringLiteral("shift_report"),
        [bridge, production, fleet](const QJsonObject& cmd) {
            ShiftReportRequest r{cmd.value(QStringLiteral("pdf")).toString(),
                                 cmd.value(QStringLiteral("csv")).toString(), std::nullopt,
                                 cmd.value(QStringLiteral("site")).toString()};
            if (cmd.contains(QStringLiteral("plan_tonnes")))
                r.planTonnes = cmd.value(QStringLiteral("plan_tonnes")).toDouble();
            return writeShiftReport(production.data(), bridge.data(), fleet.data(), r);
        },
        HeadlessCommands::always);
}

} // namespace ocu
