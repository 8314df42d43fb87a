#include "widgets/jaus/MissionTakeover.h"

#include "models/CommandGate.h"
#include "models/jaus/JausVehicleBridge.h"

#include <QMessageBox>
#include <QPushButton>

namespace ocu {

MissionTakeover::MissionTakeover(JausVehicleBridge* bridge, CommandGate* gate, QWidget* dialogParent)
    : QObject(dialogParent), m_bridge(bridge), m_gate(gate), m_parent(dialogParent) {
    if (!m_gate)
        return;
    auto ours = [this](const QString& action, const QString& target) {
        return m_paused && action == QLatin1String("mission_pause") &&
               target == JausVehicleBridge::machineId(m_subsystem);
    };
    connect(m_gate, &CommandGate::commandConfirmed, this,
            [this, ours](const QString& action, const QString& target, const QString&, qint64) {
                if (ours(action, target))
                    finish(true, {});
            });
    connect(m_gate, &CommandGate::commandUnconfirmed, this,
            [this, ours](const QString& action, const QString& target, const QString& text) {
                if (ours(action, target))
                    finish(false, tr("the mission was not paused: %1").arg(text));
            });
}

bool MissionTakeover::runsMission(quint16 subsystem) const {
    const auto v = m_bridge ? m_bridge->subsystem(subsystem) : std::nullopt;
    return v && v->mission.state == MissionState::Running;
}

void MissionTakeover::pauseThen(quint16 subsystem, std::function<void()> proceed,
                                std::function<void(QString)> refused) {
    if (pending()) {
        refused(tr("a takeover of the mission is already being confirmed"));
        return;
    }
    m_subsystem = subsystem;
    m_proceed = std::move(proceed);
    m_refused = std::move(refused);
    m_paused = false;
    const auto v = m_bridge ? m_bridge->subsystem(subsystem) : std::nullopt;
    const QString name = v && !v->callSign.isEmpty() ? v->callSign : JausVehicleBridge::machineId(subsystem);
    const int n = v ? int(v->mission.waypoints.size()) : 0;
    const int k = v ? v->mission.activeIndex + 1 : 0;
    m_question = new QMessageBox(QMessageBox::Question, tr("Take over the mission?"),
                                 tr("%1 is running a mission (waypoint %2 of %3). Driving it by hand pauses "
                                    "the mission first; Resume in the mission panel continues it.")
                                     .arg(name)
                                     .arg(k)
                                     .arg(n),
                                 QMessageBox::NoButton, m_parent);
    m_question->setObjectName(QStringLiteral("missionTakeoverQuestion"));
    auto* yes = m_question->addButton(tr("&Pause and drive"), QMessageBox::AcceptRole);
    m_question->addButton(tr("&Keep the mission"), QMessageBox::RejectRole);
    m_question->setDefaultButton(qobject_cast<QPushButton*>(m_question->buttons().last()));
    m_question->setAttribute(Qt::WA_DeleteOnClose);
    connect(m_question, &QMessageBox::finished, this,
            [this, yes, box = m_question.data()] { answered(box->clickedButton() == yes); });
    // Not modal: STOP ALL and the panel's E-STOP stay at hand while the operator decides.
    m_question->setWindowModality(Qt::NonModal);
    m_question->show();
}

void MissionTakeover::answered(bool yes) {
    m_question = nullptr;
    if (!pending())
        return;
    if (!yes || !m_gate) {
        finish(false, yes ? tr("no command gate") : tr("the operator kept the mission"));
        return;
    }
    // Connected before the pause goes out: a vehicle that already reports it confirms at once.
    m_paused = true;
    const quint16 sub = m_subsystem;
    QPointer<MissionTakeover> self(this);
    m_gate->command(
        MissionPause{JausVehicleBridge::machineId(sub)}, QStringLiteral("teleop"),
        [self, sub](const CommandResult& r) {
            if (!self || self->m_subsystem != sub)
                return;
            if (!r.ok)
                self->finish(false, tr("the mission was not paused: %1")
                                        .arg(r.notSent().isEmpty() ? r.message
                                                                   : r.notSent().join(QStringLiteral("; "))));
            // A bridge that does not watch the pause in the vehicle's reports: the sending is
            // all there is to wait for.
            else if (self->m_bridge && !self->m_bridge->confirmsCommand(QStringLiteral("mission_pause")))
                self->finish(true, {});
        });
}

void MissionTakeover::finish(bool ok, const QString& why) {
    auto proceed = std::move(m_proceed);
    auto refused = std::move(m_refused);
    m_subsystem = 0;
    m_paused = false;
    m_proceed = {};
    m_refused = {};
    if (ok && proceed)
        proceed();
    else if (!ok && refused)
        refused(why);
}

void MissionTakeover::cancel() {
    m_subsystem = 0;
    m_paused = false;
    m_proceed = {};
    m_refused = {};
    if (m_question)
        m_question->close();
}

} // namespace ocu
