#include "models/bridges/JausBridge.h"

#include "protocols/common/OutcomeCollector.h"
#include "protocols/jaus/JausStack.h"

#include <algorithm>
#include <cmath>

namespace ocu {

using namespace jaus;

// ---- GUI thread: commands ----

std::optional<TargetOutcome> JausBridge::refuseIfMonitor(const QString& target, const QString& what) const {
    if (!m_config.mayControl())
        return refusal(target, OutcomeReason::NotPermitted,
                       tr("%1 refused: this console's JAUS role is MONITOR").arg(what));
    return std::nullopt;
}

std::optional<TargetOutcome> JausBridge::refuseIfUnreachable(quint16 subsystem, const QString& what) const {
    auto it = m_latest.find(subsystem);
    if (it == m_latest.end())
        return refusal(machineId(subsystem), OutcomeReason::LinkDown,
                       tr("%1 refused: %2 has not been heard on the JAUS link; nothing sent")
                           .arg(what, machineId(subsystem)));
    if (it->link == JausLink::Down)
        return refusal(
            machineId(subsystem), OutcomeReason::LinkDown,
            tr("%1 refused: the link to %2 is down; nothing sent").arg(what, machineId(subsystem)));
    return std::nullopt;
}

bool JausBridge::refuseIfNotRunning(const QString& target, OutcomeCallback& done) const {
    if (m_stack->running())
        return false;
    done({refusal(target, OutcomeReason::NotRunning, tr("the JAUS stack is not running; nothing sent"))});
    return true;
}

void JausBridge::stopAll(OutcomeCallback done) {
    if (!m_config.mayStop()) { // the one stop rule (JausConfig): every role may stop today
        done({refusal(QStringLiteral("jaus"), OutcomeReason::NotPermitted,
                      tr("emergency stop refused by this console's JAUS role"))});
        return;
    }
    if (!m_stack->running()) {
        // Nothing can go out; the result names every vehicle the console knows (heard earlier, or configured
        // as a static endpoint), each with the reason (one target per machine).
        std::vector<TargetOutcome> out;
        for (quint16 ss : knownSubsystems())
            out.push_back(refusal(machineId(ss), OutcomeReason::NotRunning,
                                  tr("the JAUS stack is not running; nothing sent")));
        if (out.empty())
            out.push_back(
                refusal(QStringLiteral("jaus"), OutcomeReason::NotRunning,
                        tr("no JAUS vehicle known and the JAUS stack is not running; nothing sent")));
        done(std::move(out));
        return;
    }
    // SetEmergency to every discovered subsystem, controlled by this console or not: the Management service
    // accepts it from any client, and to every configured static endpoint. No vehicle known at all: say that
    // nothing went out on JAUS.
    m_stack->setEmergencyAll(EmergencyCode::Safety, [done = std::move(done)](std::vector<TargetOutcome> out) {
        if (out.empty())
            out.push_back(TargetOutcome::refused("jaus", OutcomeReason::UnknownTarget,
                                                 "no JAUS vehicle known (none discovered, no static endpoint "
                                                 "configured): no SetEmergency sent"));
        done(std::move(out));
    });
}

QList<quint16> JausBridge::knownSubsystems() const {
    QList<quint16> out = subsystems();
    for (const StaticEndpoint& se : m_config.transport.staticEndpoints)
        if (se.id.subsystem != 0 && se.id.subsystem != 0xFFFF && se.id.subsystem != m_config.subsystemId &&
            !out.contains(se.id.subsystem))
            out << se.id.subsystem;
    std::sort(out.begin(), out.end());
    return out;
}

void JausBridge::stopMachine(const QString& id, OutcomeCallback done) {
    auto sub = subsystemOf(id);
    if (!sub) {
        done({refusal(id, OutcomeReason::UnknownTarget, tr("not a JAUS machine"))});
        return;
    }
    if (!m_config.mayStop()) {
        done({refusal(id, OutcomeReason::NotPermitted,
                      tr("emergency stop refused by this console's JAUS role"))});
        return;
    }
    if (auto r = refuseIfUnreachable(*sub, tr("emergency stop"))) {
        done({refusal(id, r->cause, reasonText(*r))});
        return;
    }
    if (refuseIfNotRunning(id, done))
        return;
    m_stack->setEmergency(*sub, EmergencyCode::Safety, std::move(done));
}

void JausBridge::clearStop(const QString& id, OutcomeCallback done) {
    auto sub = subsystemOf(id);
    if (!sub) {
        done({refusal(id, OutcomeReason::UnknownTarget, tr("not a JAUS machine"))});
        return;
    }
    if (!m_config.mayClearStop()) { // only roles with command rights may clear (JausConfig)
        done({refusal(id, OutcomeReason::NotPermitted,
                      tr("clear emergency refused: this console's JAUS role has no command rights"))});
        return;
    }
    if (auto r = refuseIfUnreachable(*sub, tr("clear emergency"))) {
        done({refusal(id, r->cause, reasonText(*r))});
        return;
    }
    if (refuseIfNotRunning(id, done))
        return;
    m_stack->clearEmergency(*sub, std::move(done));
}

void JausBridge::releaseAll(OutcomeCallback done) {
    if (refuseIfNotRunning(QStringLiteral("jaus"), done))
        return;
    // One target per subsystem this console controls; releaseAll also drops pending wishes for control.
    QList<quint16> controlled;
    for (const auto& v : std::as_const(m_latest))
        if (v.controlledByUs)
            controlled << v.subsystem;
    if (controlled.isEmpty()) {
        m_stack->releaseAll();
        done({refusal(QStringLiteral("jaus"), OutcomeReason::NotControlled,
                      tr("this console controls no JAUS vehicle: nothing to release"))});
        return;
    }
    auto collector = OutcomeCollector::create(int(controlled.size()), std::move(done));
    for (quint16 ss : controlled)
        m_stack->releaseControl(ss, collector->part());
    m_stack->releaseAll();
}

std::optional<quint16> JausBridge::vehicleOf(const QString& id, const QString& what,
                                             OutcomeCallback& done) const {
    if (auto sub = subsystemOf(id))
        return sub;
    done({refusal(id.isEmpty() ? QStringLiteral("jaus") : id, OutcomeReason::UnknownTarget,
                  tr("%1: \"id\" must name a JAUS machine such as \"jaus:101\"").arg(what))});
    return std::nullopt;
}

void JausBridge::sendToVehicle(const QString& id, const QString& what, OutcomeCallback done,
                               const std::function<void(quint16, OutcomeCallback)>& send) {
    auto sub = vehicleOf(id, what, done);
    if (!sub)
        return;
    if (auto r = refuseIfMonitor(id, what))
        return done({*r});
    // Over the link: never queued for a vehicle not heard or whose link is down.
    if (auto r = refuseIfUnreachable(*sub, what))
        return done({refusal(id, r->cause, reasonText(*r))});
    if (refuseIfNotRunning(id, done))
        return;
    send(*sub, std::move(done));
}

void JausBridge::timedDrive(const TimedDrive& c, OutcomeCallback done) {
    const QString what = QStringLiteral("drive");
    auto sub = vehicleOf(c.id, what, done);
    if (!sub)
        return;
    auto refuse = [&](OutcomeReason cause, const QString& why) { done({refusal(c.id, cause, why)}); };
    if (auto r = refuseIfMonitor(c.id, what))
        return done({*r});
    if (refuseIfNotRunning(c.id, done))
        return;
    JausDrive demand;
    demand.mode = c.mode == TimedDrive::Mode::Effort ? JausDrive::Mode::Wrench : JausDrive::Mode::Velocity;
    demand.linear = c.linear;
    demand.angular = c.angular;
    if (!(c.durationS > 0 && c.durationS <= 60))
        return refuse(OutcomeReason::InvalidArgument,
                      tr("drive: \"duration\" must be between 0 and 60 seconds"));
    if (demand.mode == JausDrive::Mode::Wrench &&
        (std::abs(demand.linear) > 100 || std::abs(demand.angular) > 100))
        return refuse(OutcomeReason::InvalidArgument, tr("drive: effort must be within ±100 %"));
    if (auto r = refuseDriving(*sub))
        return refuse(r->cause, reasonText(*r));
    startTimedDrive(*sub, demand, c.durationS, std::move(done));
}

void JausBridge::command(const OperatorCommand& command, OutcomeCallback done) {
    const QString what = commandName(command);
    std::visit(
        Overloaded{
            [&](const ReleaseAll&) { releaseAll(std::move(done)); },
            // Releasing is never refused for a down link (nor for the monitor role): it also drops the wish
            // for control, so the console does not take control back when the vehicle is heard again.
            [&](const ReleaseControl& c) {
                auto sub = vehicleOf(c.id, what, done);
                if (sub && !refuseIfNotRunning(c.id, done))
                    m_stack->releaseControl(*sub, std::move(done));
            },
            [&](const RequestControl& c) {
                sendToVehicle(c.id, what, std::move(done), [this](quint16 ss, OutcomeCallback d) {
                    m_stack->requestControl(ss, std::move(d));
                });
            },
            // Management commands: the stack says per vehicle what went on the wire (or why not); the
            // vehicle's management state shows the effect.
            [&](const Management& c) {
                sendToVehicle(c.id, what, std::move(done),
                              [this, a = c.action](quint16 ss, OutcomeCallback d) {
                                  switch (a) {
                                  case ManagementAction::Resume:
                                      return m_stack->resume(ss, std::move(d));
                                  case ManagementAction::Standby:
                                      return m_stack->standby(ss, std::move(d));
                                  case ManagementAction::Shutdown:
                                      return m_stack->shutdown(ss, std::move(d));
                                  case ManagementAction::Reset:
                                      return m_stack->reset(ss, std::move(d));
                                  }
                              });
            },
            // A teleop session: one gate command (and audit line) per session, not per message.
            [&](const DriveStart& c) {
                auto sub = vehicleOf(c.id, what, done);
                if (!sub)
                    return;
                if (auto r = refuseIfMonitor(c.id, what))
                    return done({*r});
                if (auto r = refuseDriving(*sub))
                    return done({refusal(c.id, r->cause, reasonText(*r))});
                startSession(*sub, std::move(done));
            },
            // End of a drive session (release, focus loss, joystick loss, vehicle changed...).
            [&](const DriveStop& c) {
                auto sub = vehicleOf(c.id, what, done);
                if (!sub)
                    return;
                if (auto r = refuseIfMonitor(c.id, what))
                    return done({*r});
                endSession(*sub, c.reason, std::move(done));
            },
            [&](const TimedDrive& c) { timedDrive(c, std::move(done)); },
            // Waypoint missions: the stack says what went on the wire; the mission's state comes from the
            // vehicle's reports (JausVehicle::mission).
            [&](const MissionUpload& c) {
                std::vector<MissionPoint> points;
                for (const MissionWaypoint& w : c.waypoints)
                    points.push_back(MissionPoint{w.lat, w.lon, w.speed, w.tolerance});
                sendToVehicle(c.id, what, std::move(done),
                              [this, points, g = c.global](quint16 ss, OutcomeCallback d) {
                                  m_stack->missionUpload(ss, points, g, std::move(d));
                              });
            },
            [&](const MissionStart& c) {
                sendToVehicle(c.id, what, std::move(done),
                              [this, from = c.fromIndex](quint16 ss, OutcomeCallback d) {
                                  m_stack->missionStart(ss, from, std::move(d));
                              });
            },
            [&](const MissionPause& c) {
                sendToVehicle(c.id, what, std::move(done), [this](quint16 ss, OutcomeCallback d) {
                    m_stack->missionPause(ss, std::move(d));
                });
            },
            [&](const MissionResume& c) {
                sendToVehicle(c.id, what, std::move(done), [this](quint16 ss, OutcomeCallback d) {
                    m_stack->missionResume(ss, std::move(d));
                });
            },
            [&](const MissionAbort& c) {
                sendToVehicle(c.id, what, std::move(done), [this](quint16 ss, OutcomeCallback d) {
                    m_stack->missionAbort(ss, std::move(d));
                });
            },
            [&](const GoTo& c) {
                const MissionWaypoint& w = c.waypoint;
                sendToVehicle(c.id, what, std::move(done), [this, w](quint16 ss, OutcomeCallback d) {
                    m_stack->goTo(ss, MissionPoint{w.lat, w.lon, w.speed, w.tolerance}, std::move(d));
                });
            },
            // The platform services and the hand-off: their own visitor below.
            [&](const auto&) { platformOrHandoffCommand(command, what, std::move(done)); },
        },
        command);
}

// Platform mode and state, lights, odometry (AEP-4818 §6.2, §9.2.2) and the hand-off between consoles
// (§6.3); every other command is refused as not supported.
void JausBridge::platformOrHandoffCommand(const OperatorCommand& command, const QString& what,
                                          OutcomeCallback done) {
    std::visit(Overloaded{
                   [&](const SetPlatformMode& c) {
                       sendToVehicle(c.id, what, std::move(done),
                                     [this, m = c.mode](quint16 ss, OutcomeCallback d) {
                                         m_stack->setPlatformMode(ss, std::uint8_t(m), std::move(d));
                                     });
                   },
                   [&](const SetPlatformState& c) {
                       sendToVehicle(c.id, what, std::move(done),
                                     [this, st = c.state](quint16 ss, OutcomeCallback d) {
                                         m_stack->setPlatformState(ss, std::uint8_t(st), std::move(d));
                                     });
                   },
                   [&](const SetLights& c) {
                       sendToVehicle(c.id, what, std::move(done),
                                     [this, mask = c.mask, on = c.on](quint16 ss, OutcomeCallback d) {
                                         m_stack->setLights(ss, mask, on, std::move(d));
                                     });
                   },
                   [&](const Odometry& c) { odometry(c, std::move(done)); },
                   // Hand-off between consoles: the stack says what went on the wire; what followed is the
                   // vehicle's answer (JausVehicle::handoff and the events).
                   [&](const HandoffRequest& c) {
                       sendToVehicle(c.id, what, std::move(done),
                                     [this, reason = c.reason.toStdString(),
                                      cancel = c.cancel](quint16 ss, OutcomeCallback d) {
                                         if (cancel)
                                             m_stack->handoffCancel(ss, std::move(d));
                                         else
                                             m_stack->handoffRequest(ss, reason, std::move(d));
                                     });
                   },
                   [&](const HandoffAnswer& c) {
                       sendToVehicle(c.id, what, std::move(done),
                                     [this, id = std::uint8_t(c.requestId), accept = c.accept,
                                      wait = c.wait](quint16 ss, OutcomeCallback d) {
                                         if (wait)
                                             m_stack->handoffWait(ss, id, std::move(d));
                                         else
                                             m_stack->handoffAnswer(ss, id, accept, std::move(d));
                                     });
                   },
                   [&](const auto&) { FleetBridge::command(command, std::move(done)); },
               },
               command);
}

void JausBridge::odometry(const Odometry& c, OutcomeCallback done) {
    // A read says what the vehicle last reported (the fresh report follows in the vehicle's view).
    std::string note;
    if (auto sub = subsystemOf(c.id); sub && m_latest.contains(*sub)) {
        const JausPlatformServices& p = m_latest.value(*sub).platformServices;
        if (p.odometerM || p.tripM)
            note = tr("last reported: odometer %1 m, trip %2 m")
                       .arg(p.odometerM ? QString::number(*p.odometerM) : QStringLiteral("?"),
                            p.tripM ? QString::number(*p.tripM) : QStringLiteral("?"))
                       .toStdString();
    }
    auto withNote = [note, done = std::move(done)](std::vector<TargetOutcome> outcomes) {
        for (TargetOutcome& o : outcomes)
            if (o.sent && o.note.empty())
                o.note = note;
        done(std::move(outcomes));
    };
    sendToVehicle(c.id, commandName(c), std::move(withNote),
                  [this, reset = c.resetTrip](quint16 ss, OutcomeCallback d) {
                      if (reset)
                          m_stack->resetTripOdometer(ss, std::move(d));
                      else
                          m_stack->queryOdometry(ss, std::move(d));
                  });
}

} // namespace ocu
