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
    connect(&m_idle, &QTimer::timeout, this, &OperatorSession::lock);
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
    if (!refused.isEmpty()) {
        if (why)
            *why = refused;
        return Switch::WrongPassword;
    }
    const OperatorIdentity next = m_identityOf(user);
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
    setOperator(next);
    if (wasLocked)
        emit lockedChanged(false);
    activity();
    return Switch::Switched;
}

void OperatorSession::lock() {
    if (!m_gate || m_gate->isLocked())
        return;
    m_gate->setLocked(true);
    m_idle.stop();
    emit lockedChanged(true);
}

bool OperatorSession::unlock(const QString& password, QString* why) {
    if (!isLocked())
        return true;
    const QString refused =
        m_authenticate ? m_authenticate(current().user, password) : tr("no authentication");
    if (!refused.isEmpty()) {
        if (why)
            *why = refused;
        return false;
    }
    m_gate->setLocked(false);
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
