#pragma once
// The one table of which operator role may issue which command, and who is at the console. The CommandGate
// holds it and checks every command against it before anything is sent; the shared rows (the stop path) are
// the gate's, every protocol module adds the rows of its own commands (ProtocolModule::addPermissions).
// STOP ALL, every per-machine stop and the commands a module declares stops (addStop: a link's all-stop, the
// end of a drive session) are allowed to every role, signed in or locked: no row can narrow them.
// A command without a row is refused (a new command must be given its roles), naming no role.
#include "models/commands/OperatorCommand.h"
#include "protocols/common/OperatorRoles.h"

#include <QCoreApplication>
#include <QHash>
#include <QSet>
#include <QString>
#include <QStringList>
#include <QVector>

#include <initializer_list>

namespace ocu {

// Who issues commands at this console: the operator (an OS user), their role and the console's name.
struct OperatorIdentity {
    QString user;
    OperatorRole role = OperatorRole::Monitor;
    QString console;
    QString roleText() const {
        return QString::fromLatin1(roleName(role).data(), qsizetype(roleName(role).size()));
    }
    // "alice (supervisor) @ ocu-1": acknowledgements and shelvings say who did them with this.
    QString byText() const;
    bool operator==(const OperatorIdentity&) const = default;
};

// The role's name for people ("UGV operator").
QString roleDisplayName(OperatorRole role);

class CommandPermissions {
    Q_DECLARE_TR_FUNCTIONS(ocu::CommandPermissions)
public:
    CommandPermissions(); // the shared rows: stop_all and stop for everyone, clear_stop

    // A row: `command` (commandName) may be issued by these roles. A later row of the same command replaces
    // it, except for the stop rows.
    void allow(const QString& command, std::initializer_list<OperatorRole> roles);
    void allow(const QString& command, const QVector<OperatorRole>& roles);

    // A command that stops machines: allowed to everyone, locked or not; rows cannot narrow it.
    void addStop(const QString& command);
    bool isStop(const QString& command) const { return m_stops.contains(command); }
    bool permits(const QString& command, OperatorRole role) const;
    QVector<OperatorRole> rolesFor(const QString& command) const { return m_rows.value(command); }
    bool hasRow(const QString& command) const { return m_rows.contains(command); }
    QStringList commands() const;
    // Why `role` may not issue `command`: "needs the supervisor or admin role" (empty when it may).
    QString refusalText(const QString& command, OperatorRole role) const;
    // The same for people, without the command's name: "Needs the supervisor or admin role (you are
    // Monitor)" (a disabled button's tooltip).
    QString roleNeededText(const QString& command, OperatorRole role) const;

private:
    QString roleList(const QString& command) const; // "UGV operator, supervisor or admin"
    QHash<QString, QVector<OperatorRole>> m_rows;
    QSet<QString> m_stops;
};

} // namespace ocu
