#pragma once
// Who is at a shared console, and its lock (docs/roles.md). The operator starts as the OS user running the
// console; "Switch operator" lets the next person sign in with their own password (checked by the
// Authenticate function: PAM in the console, a fake in tests) while the stacks keep running. Control of
// machines held by the console is kept across the switch when the next person's role may take control,
// and otherwise released (as the previous operator, audited) after the caller's confirmation. The lock
// (on demand, or after the idle time) leaves only stops to the command gate; the same person's password
// unlocks it. Sign-in, sign-out, lock and unlock (and their refusals) are audited with the person's name.
#include "models/commands/CommandPermissions.h"

#include <QObject>
#include <QPointer>
#include <QStringList>
#include <QTimer>

#include <functional>

namespace ocu {

class AlarmModel;
class CommandGate;
class FleetModel;

class OperatorSession : public QObject {
    Q_OBJECT
public:
    // Empty when the password is right, else why not.
    using Authenticate = std::function<QString(const QString& user, const QString& password)>;
    // The identity (role, console) the site gives a user.
    using IdentityOf = std::function<OperatorIdentity(const QString& user)>;
    // Asked with the machines whose control would be released; false cancels the switch.
    using ConfirmRelease = std::function<bool(const QStringList& machines)>;

    OperatorSession(CommandGate* gate, FleetModel* fleet, AlarmModel* alarms, Authenticate authenticate,
                    IdentityOf identityOf, QObject* parent = nullptr);

    OperatorIdentity current() const;
    // Sets the operator without a password (the OS user at start).
    void setOperator(const OperatorIdentity& identity);

    enum class Switch { Switched, WrongPassword, Cancelled };
    // `why` gets the refusal text.
    Switch switchTo(const QString& user, const QString& password, const ConfirmRelease& confirm,
                    QString* why = nullptr);
    // The machines this console controls that `next` may not keep.
    QStringList controlToRelease(const OperatorIdentity& next) const;

    void lock();
    // The current operator's password; `why` gets the refusal text.
    bool unlock(const QString& password, QString* why = nullptr);
    bool isLocked() const;
    // Locks after this long without activity (0: never); activity() restarts the count.
    void setIdleLockMs(int ms);
    int idleLockMs() const { return m_idleMs; }
    void activity();

signals:
    void operatorChanged(const ocu::OperatorIdentity& identity);
    void lockedChanged(bool locked);

private:
    void lockBecause(const QString& why);

    QPointer<CommandGate> m_gate;
    QPointer<FleetModel> m_fleet;
    QPointer<AlarmModel> m_alarms;
    Authenticate m_authenticate;
    IdentityOf m_identityOf;
    QTimer m_idle;
    int m_idleMs = 0;
};

} // namespace ocu
