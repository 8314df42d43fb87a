#include "models/bridges/JausBridge.h"

#include "protocols/common/Clock.h"
#include "protocols/jaus/JausStack.h"

#include <QPointer>

#include <cmath>

namespace ocu {

using namespace jaus;

namespace {
DriveCommand toDriveCommand(const JausDrive& demand) {
    DriveCommand command;
    command.mode =
        demand.mode == JausDrive::Mode::Wrench ? DriveCommand::Mode::Wrench : DriveCommand::Mode::Velocity;
    command.linear = demand.linear;
    command.angular = demand.angular;
    command.brake = demand.brake;
    return command;
}
} // namespace

std::optional<TargetOutcome> JausBridge::refuseDriving(quint16 subsystem) const {
    const QString target = machineId(subsystem);
    if (auto r = refuseIfMonitor(target, tr("drive")))
        return r;
    if (!m_stack->running())
        return refusal(target, OutcomeReason::NotRunning,
                       tr("drive refused: the JAUS stack is not running; nothing sent"));
    auto s = this->subsystem(subsystem);
    if (s && s->link == JausLink::Down)
        return refuseIfUnreachable(subsystem, tr("drive"));
    if (!s || !s->controlledByUs)
        return refusal(target, OutcomeReason::NotControlled,
                       tr("drive refused: this console does not control %1").arg(target));
    // Components accept no command in the emergency platform state (AEP-4818 §6.2.6).
    if (s->platformServices.emergencyState())
        return refusal(
            target, OutcomeReason::Refused,
            tr("drive refused: %1 reports the emergency platform state; nothing sent").arg(target));
    return std::nullopt;
}

CommandResult JausBridge::drive(quint16 subsystem, const JausDrive& demand) {
    if (auto r = refuseDriving(subsystem))
        return CommandResult::failure(reasonText(*r));
    if (!m_sessions.contains(subsystem))
        return CommandResult::failure(tr("drive refused: no drive session open for %1 (a session starts "
                                         "through the command gate)")
                                          .arg(machineId(subsystem)));
    m_stack->setDriveCommand(subsystem, toDriveCommand(demand), {}); // the stream: failures are events
    return CommandResult::success(tr("drive demand handed to the drive stream"));
}

CommandResult JausBridge::stopDriving(quint16 subsystem) {
    m_sessions.remove(subsystem);
    if (QTimer* t = m_driveTimers.take(subsystem)) {
        t->stop();
        t->deleteLater();
    }
    if (!m_stack->running())
        return CommandResult::failure(tr("the JAUS stack is not running; no zero drive commands sent"));
    m_stack->stopDriving(subsystem, {}); // zeros, several times
    return CommandResult::success(tr("zero drive commands handed to the stack"));
}

CommandResult JausBridge::panTilt(quint16 subsystem, quint16 sensorId, double panRate, double tiltRate) {
    // Same rules as driving: role, running stack, link, control of the vehicle.
    if (auto r = refuseIfMonitor(machineId(subsystem), tr("pan-tilt")))
        return CommandResult::failure(reasonText(*r));
    if (!m_stack->running())
        return CommandResult::failure(tr("pan-tilt refused: the JAUS stack is not running; nothing sent"));
    auto s = this->subsystem(subsystem);
    if (s && s->link == JausLink::Down)
        return CommandResult::failure(reasonText(*refuseIfUnreachable(subsystem, tr("pan-tilt"))));
    if (!s || !s->controlledByUs)
        return CommandResult::failure(
            tr("pan-tilt refused: this console does not control %1").arg(machineId(subsystem)));
    if (!std::isfinite(panRate) || !std::isfinite(tiltRate))
        return CommandResult::failure(tr("pan-tilt refused: the rates must be finite numbers"));
    // Refusals on the io thread (no camera on a pan-tilt, control of the unit not confirmed yet) arrive as
    // CommandRefused events; the stream is not audited per message, like the drive stream.
    m_stack->panTilt(subsystem, sensorId, panRate, tiltRate, [](std::vector<TargetOutcome>) {});
    return CommandResult::success(tr("pan-tilt demand handed to the stack"));
}

void JausBridge::startSession(quint16 subsystem, OutcomeCallback done) {
    m_sessions.insert(subsystem);
    // A session the stack refused (or whose first message did not leave) is no session: the stream would
    // only be refused at the drive rate.
    QPointer<JausBridge> self(this);
    m_stack->startDriving(subsystem, [self, subsystem, done = std::move(done)](std::vector<TargetOutcome> o) {
        if (!allSent(o))
            QMetaObject::invokeMethod(
                self.data(),
                [self, subsystem] {
                    if (self)
                        self->m_sessions.remove(subsystem);
                },
                Qt::QueuedConnection);
        done(std::move(o));
    });
}

void JausBridge::startTimedDrive(quint16 subsystem, const JausDrive& c, double durationS,
                                 OutcomeCallback done) {
    if (!m_sessions.contains(subsystem))
        startSession(subsystem, [](std::vector<TargetOutcome>) {}); // the demand's outcome tells
    m_stack->setDriveCommand(subsystem, toDriveCommand(c), std::move(done));
    // The demand is refreshed at the drive rate for the duration (the stack zeroes a stale demand),
    // then the session stops with zeros.
    QTimer*& t = m_driveTimers[subsystem];
    if (!t) {
        t = new QTimer(this);
        t->setTimerType(Qt::PreciseTimer);
    }
    t->disconnect();
    const std::uint16_t s = subsystem;
    // On the steady clock: a wall-clock step (NTP, a time zone change) must not lengthen a timed drive.
    const TimePoint until = SteadyClock::instance().now() +
                            std::chrono::duration_cast<Duration>(std::chrono::duration<double>(durationS));
    connect(t, &QTimer::timeout, this, [this, s, c, until] {
        if (SteadyClock::instance().now() >= until || !drive(s, c).ok)
            stopDriving(s);
    });
    t->start(static_cast<int>(1000.0 / std::max(1.0, m_config.driveRateHz)));
}

void JausBridge::endSession(quint16 subsystem, const QString& why, OutcomeCallback done) {
    if (QTimer* t = m_driveTimers.take(subsystem)) {
        t->stop();
        t->deleteLater();
    }
    m_sessions.remove(subsystem);
    if (refuseIfNotRunning(machineId(subsystem), done))
        return;
    m_stack->stopDriving(subsystem, [why, done = std::move(done)](std::vector<TargetOutcome> o) {
        if (!why.isEmpty())
            for (TargetOutcome& t : o)
                if (t.sent)
                    t.note = "session ended: " + why.toStdString();
        done(std::move(o));
    });
}

} // namespace ocu
