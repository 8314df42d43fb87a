#include "models/OperatorSession.h"

#include "models/AlarmModel.h"
#include "models/CommandGate.h"
#include "models/FleetModel.h"

namespace ocu {

OperatorSession::OperatorSession(CommandGate* gate, FleetModel* fleet, AlarmModel* alarms,
                                 Authenticate authenticate, IdentityOf identityOf, QObject* parent)
    : QObject(parent), m_gate(gate), m_fleet(fleet), m_alarms(alarms),
      m_authenticate(std::move(authenticate)), m_identityOf(std::move(identityOf)) {
    m_idle.setSingleShot(true);
    connect(&m_idle, &QTimer::timeout, this,
            [this] { lockBecause(tr("idle for %1 s").arg(m_idleMs / 1000)); });
}

OperatorIdentity OperatorSession::current() const {
    return m_gate ? m_gate->operatorIdentity() : OperatorIdentity{};
}

void OperatorSession::setOperator(const OperatorIdentity& identity) {
    if (m_gate)
        m_gate->setOperator(identity);
    if (m_alarms)
        m_alarms->setOperatorName(identity.byText());
    emit operatorChanged(identity);
}

QStringList OperatorSession::controlToRelease(const OperatorIdentity& next) const {
    QStringList out;
    if (!m_fleet || !m_gate || m_gate->permissions().permits(QStringLiteral("request_control"), next.role))
        return out;
    for (const MachineState& m : m_fleet->machinesSnapshot())
        if (m.control == ControlState::ControlledByMe)
            out << m.id;
    return out;
}

OperatorSession::Switch OperatorSession::switchTo(const QString& user, const QString& password,
                                                  const ConfirmRelease& confirm, QString* why) {
    const QString refused = m_authenticate ? m_authenticate(user, password) : tr("no authentication");
    const OperatorIdentity next = m_identityOf(user);
    if (!refused.isEmpty()) {
        if (m_gate)
            m_gate->auditSession(QStringLiteral("sign_in"), next, false,
                                 tr("sign-in refused: %1").arg(refused));
        if (why)
            *why = refused;
        return Switch::WrongPassword;
    }
    const QStringList release = controlToRelease(next);
    if (!release.isEmpty() && (!confirm || !confirm(release))) {
        if (why)
            *why = tr("switch cancelled: control kept by %1").arg(current().user);
        return Switch::Cancelled;
    }
    // A person signed in: the console is theirs, unlocked (also so that the release below may go out).
    const bool wasLocked = isLocked();
    if (wasLocked)
        m_gate->setLocked(false);
    // Released by the operator who held it (audited as theirs), before the next one is in.
    for (const QString& id : release)
        m_gate->command(ReleaseControl{id}, QStringLiteral("switch"));
    const OperatorIdentity previous = current();
    m_gate->auditSession(QStringLiteral("sign_out"), previous, true,
                         tr("operator switched to %1").arg(next.user));
    setOperator(next);
    m_gate->auditSession(QStringLiteral("sign_in"), next, true,
                         tr("signed in as %1 after %2").arg(next.roleText(), previous.user));
    if (wasLocked)
        emit lockedChanged(false);
    activity();
    return Switch::Switched;
}

void OperatorSession::lock() {
    lockBecause(tr("on demand"));
}

void OperatorSession::lockBecause(const QString& why) {
    if (!m_gate || m_gate->isLocked())
        return;
    m_gate->setLocked(true);
    m_gate->auditSession(QStringLiteral("lock"), current(), true, tr("console locked: %1").arg(why));
    m_idle.stop();
    emit lockedChanged(true);
}

bool OperatorSession::unlock(const QString& password, QString* why) {
    if (!isLocked())
        return true;
    const QString refused =
        m_authenticate ? m_authenticate(current().user, password) : tr("no authentication");
    if (!refused.isEmpty()) {
        m_gate->auditSession(QStringLiteral("unlock"), current(), false,
                             tr("unlock refused: %1").arg(refused));
        if (why)
            *why = refused;
        return false;
    }
    m_gate->setLocked(false);
    m_gate->auditSession(QStringLiteral("unlock"), current(), true, tr("console unlocked"));
    emit lockedChanged(false);
    activity();
    return true;
}

bool OperatorSession::isLocked() const {
    return m_gate && m_gate->isLocked();
}

void OperatorSession::setIdleLockMs(int ms) {
    m_idleMs = ms;
    activity();
}

void OperatorSession::activity() {
    if (m_idleMs > 0 && !isLocked())
        m_idle.start(m_idleMs);
    else
        m_idle.stop();
}

} // namespace ocu
