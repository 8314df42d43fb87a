#include "models/commands/CommandPermissions.h"

#include <algorithm>

namespace ocu {

QString OperatorIdentity::byText() const {
    return QStringLiteral("%1 (%2) @ %3").arg(user, roleText(), console);
}

QString roleDisplayName(OperatorRole role) {
    switch (role) {
    case OperatorRole::Monitor:
        return CommandPermissions::tr("monitor");
    case OperatorRole::Dispatcher:
        return CommandPermissions::tr("dispatcher");
    case OperatorRole::SiteManager:
        return CommandPermissions::tr("site manager");
    case OperatorRole::UgvOperator:
        return CommandPermissions::tr("UGV operator");
    case OperatorRole::Supervisor:
        return CommandPermissions::tr("supervisor");
    case OperatorRole::Admin:
        return CommandPermissions::tr("admin");
    }
    return {};
}

namespace {
QVector<OperatorRole> everyRole() {
    return {kAllOperatorRoles.begin(), kAllOperatorRoles.end()};
}
} // namespace

CommandPermissions::CommandPermissions() {
    // Stopping is never refused: any person at any console may stop a machine.
    addStop(QStringLiteral("stop_all"));
    addStop(QStringLiteral("stop"));
    // Releasing a stop puts machines back in motion: the roles that command machines.
    allow(QStringLiteral("clear_stop"),
          {OperatorRole::Dispatcher, OperatorRole::SiteManager, OperatorRole::UgvOperator,
           OperatorRole::Supervisor, OperatorRole::Admin});
}

void CommandPermissions::addStop(const QString& command) {
    m_stops.insert(command);
    m_rows.insert(command, everyRole());
}

void CommandPermissions::allow(const QString& command, std::initializer_list<OperatorRole> roles) {
    allow(command, QVector<OperatorRole>(roles));
}

void CommandPermissions::allow(const QString& command, const QVector<OperatorRole>& roles) {
    if (isStop(command))
        return;
    QVector<OperatorRole> sorted = roles;
    std::sort(sorted.begin(), sorted.end());
    sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
    m_rows.insert(command, sorted);
}

bool CommandPermissions::permits(const QString& command, OperatorRole role) const {
    return isStop(command) || m_rows.value(command).contains(role);
}

QStringList CommandPermissions::commands() const {
    QStringList out = m_rows.keys();
    out.sort();
    return out;
}

QString CommandPermissions::roleList(const QString& command) const {
    QStringList names;
    for (OperatorRole r : m_rows.value(command))
        names << roleDisplayName(r);
    const QString last = names.takeLast();
    return names.isEmpty() ? last : tr("%1 or %2").arg(names.join(QStringLiteral(", ")), last);
}

QString CommandPermissions::refusalText(const QString& command, OperatorRole role) const {
    if (permits(command, role))
        return {};
    if (m_rows.value(command).isEmpty())
        return tr("%1 is not permitted to any role at this console").arg(command);
    return tr("%1 needs the %2 role (you are %3)").arg(command, roleList(command), roleDisplayName(role));
}

QString CommandPermissions::roleNeededText(const QString& command, OperatorRole role) const {
    if (permits(command, role))
        return {};
    if (m_rows.value(command).isEmpty())
        return tr("Not permitted to any role at this console");
    return tr("Needs the %1 role (you are %2)").arg(roleList(command), roleDisplayName(role));
}

} // namespace ocu
