#include "protocols/jaus/clients/DriveClient.h"

#include <algorithm>

#include "protocols/jaus/Messages.h"

namespace ocu::jaus {

bool DriveClient::startDriving(std::uint16_t ss) {
    if (!m_ctx.config().mayControl())
        return m_ctx.refuse(ss, "the monitor role may not drive", OutcomeReason::NotPermitted);
    RemoteSubsystem* r = m_ctx.find(ss);
    if (!r || !r->snap.controlledByUs)
        return m_ctx.refuse(ss, "driving needs control of subsystem " + std::to_string(ss),
                            OutcomeReason::NotControlled);
    if (r->snap.emergency)
        return m_ctx.refuse(ss, r->snap.callSign + " is in EMERGENCY");
    // Drivers obey only in READY (AEP-4818 §4.2.2, §9 item 18).
    if (r->snap.management != ManagementState::Ready) {
        m_ctx.send(r->mobility(), encodeEmpty(msg::Resume));
        m_ctx.send(r->mobility(), encodeEmpty(msg::QueryStatus));
    }
    State& s = m_state[ss];
    s.session = Session::Driving;
    s.stopRepeatsLeft = 0;
    s.drive = DriveCommand{};
    s.drive.mode = startMode(*r);
    r->snap.driving = true;
    s.lastSent = TimePoint{};
    s.lastUpdate = m_ctx.now();
    s.failureReported = false;
    m_ctx.changed(*r);
    // The session's first message, a zero demand, goes out at once: the session is open on the wire when the
    // socket took it (the periodic stream follows at the drive rate).
    if (!r->mobility().subsystem)
        return m_ctx.refuseNoTarget(ss, "a driver (PrimitiveDriver / VelocityStateDriver)");
    if (!send(*r, s, true))
        return m_ctx.refuse(ss,
                            "drive session for " + r->snap.callSign +
                                ": the first drive command was not sent: " + s.lastError,
                            OutcomeReason::SendFailed);
    return true;
}

bool DriveClient::setDriveCommand(std::uint16_t ss, DriveCommand c) {
    RemoteSubsystem* r = m_ctx.find(ss);
    auto it = m_state.find(ss);
    if (!r || it == m_state.end() || it->second.session == Session::Closed)
        return m_ctx.refuse(ss, "no drive session open for subsystem " + std::to_string(ss));
    State& s = it->second;
    if (const char* missing = missingDriver(*r, c.mode))
        return m_ctx.refuse(ss, r->snap.callSign + " offers no " + missing + ": " +
                                    (c.mode == DriveCommand::Mode::Velocity ? "velocity" : "effort") +
                                    " demands are not sent to it");
    // Clamp to the platform specifications (AEP-4818 §7.2, §9 item 24).
    if (c.mode == DriveCommand::Mode::Wrench) {
        c.linear = std::clamp(c.linear, -100.0, 100.0);
        c.angular = std::clamp(c.angular, -100.0, 100.0);
        c.brake = std::clamp(c.brake, 0.0, 100.0);
    } else if (r->snap.platform) {
        auto& p = *r->snap.platform;
        if (p.maxForwardSpeed)
            c.linear = std::min(c.linear, *p.maxForwardSpeed);
        if (p.maxReverseSpeed)
            c.linear = std::max(c.linear, -*p.maxReverseSpeed);
        if (p.maxRotationalSpeed)
            c.angular = std::clamp(c.angular, -*p.maxRotationalSpeed, *p.maxRotationalSpeed);
    }
    const bool changed = c.mode != s.drive.mode || c.linear != s.drive.linear ||
                         c.angular != s.drive.angular || c.brake != s.drive.brake ||
                         s.session == Session::Stale;
    s.drive = c;
    s.lastUpdate = m_ctx.now();
    s.session = Session::Driving;
    // A new demand goes out at once (teleop latency); the periodic stream repeats it.
    if (changed && r->mobility().subsystem)
        send(*r, s, false);
    if (!r->mobility().subsystem)
        return m_ctx.refuseNoTarget(ss, "a driver (PrimitiveDriver / VelocityStateDriver)");
    if (!s.lastSendOk)
        return m_ctx.refuse(ss, "drive command for " + r->snap.callSign + " was not sent: " + s.lastError,
                            OutcomeReason::SendFailed);
    return true;
}

DriveCommand::Mode DriveClient::startMode(const RemoteSubsystem& r) const {
    // The configured preference where the driver takes it, else what the driver takes: a vehicle is sent
    // only demands its services name (a PrimitiveDriver alone never gets SetVelocityCommand).
    const ComponentTable& t = r.components;
    const bool velocity = m_ctx.config().velocityDrive;
    if (velocity && !t.driverTakesVelocity && t.driverTakesEffort)
        return DriveCommand::Mode::Wrench;
    if (!velocity && !t.driverTakesEffort && t.driverTakesVelocity)
        return DriveCommand::Mode::Velocity;
    return velocity ? DriveCommand::Mode::Velocity : DriveCommand::Mode::Wrench;
}

const char* DriveClient::missingDriver(const RemoteSubsystem& r, DriveCommand::Mode mode) {
    const ComponentTable& t = r.components;
    if (!t.driverTakesVelocity && !t.driverTakesEffort)
        return nullptr; // nothing known about the driver: the stream's own checks decide
    if (mode == DriveCommand::Mode::Velocity && !t.driverTakesVelocity)
        return "VelocityStateDriver";
    if (mode == DriveCommand::Mode::Wrench && !t.driverTakesEffort)
        return "PrimitiveDriver";
    return nullptr;
}

bool DriveClient::stopDriving(std::uint16_t ss) {
    RemoteSubsystem* r = m_ctx.find(ss);
    if (!r)
        return m_ctx.refuse(ss, "subsystem " + std::to_string(ss) + " is unknown",
                            OutcomeReason::UnknownTarget);
    State& s = m_state[ss];
    if (!stop(*r, s))
        return m_ctx.refuse(
            ss,
            r->snap.controlledByUs
                ? "the zero drive command for " + r->snap.callSign + " was not sent: " + s.lastError
                : "this console does not control " + r->snap.callSign +
                      ": no zero drive commands sent (the vehicle's own drive "
                      "timeout stops it)",
            r->snap.controlledByUs ? OutcomeReason::SendFailed : OutcomeReason::NotControlled);
    return true;
}

bool DriveClient::stop(RemoteSubsystem& r, State& s) {
    s.session = Session::Closed;
    // Several zero commands, never a single message (AEP-4818 §9 item 21).
    s.stopRepeatsLeft = r.snap.controlledByUs ? m_ctx.config().stopRepeats : 0;
    s.drive.linear = s.drive.angular = 0;
    bool sent = false;
    if (s.stopRepeatsLeft > 0) {
        sent = send(r, s, true);
        --s.stopRepeatsLeft;
    }
    r.snap.driving = s.stopRepeatsLeft > 0;
    m_ctx.changed(r);
    return sent;
}

void DriveClient::endSession(RemoteSubsystem& r, bool dropZeroTail) {
    State& s = m_state[r.id()];
    s.session = Session::Closed;
    if (dropZeroTail)
        s.stopRepeatsLeft = 0;
    r.snap.driving = false;
}

void DriveClient::beforeRelease(RemoteSubsystem& r) {
    State& s = m_state[r.id()];
    if (s.session != Session::Closed)
        stop(r, s);
    // Zero drive commands go out before the release in the same tick order.
    for (int i = 0; i < 2 && r.snap.controlledByUs; ++i)
        send(r, s, true);
    s.stopRepeatsLeft = 0;
    r.snap.driving = false;
}

bool DriveClient::anyActive() const {
    for (auto& [ss, s] : m_state)
        if (s.session != Session::Closed || s.stopRepeatsLeft > 0)
            return true;
    return false;
}

bool DriveClient::send(RemoteSubsystem& r, State& s, bool zero) {
    s.lastSent = m_ctx.now();
    const DriveCommand c = s.drive;
    bool ok;
    if (c.mode == DriveCommand::Mode::Velocity) {
        VelocityCommand v;
        v.vx = zero ? 0.0 : c.linear;
        v.yawRate = zero ? 0.0 : c.angular;
        ok = m_ctx.send(r.mobility(), encodeVelocityCommand(msg::SetVelocityCommand, v));
    } else {
        WrenchEffort w;
        w.propLinX = zero ? 0.0 : c.linear;
        w.propRotZ = zero ? 0.0 : c.angular;
        w.resLinX = zero ? 0.0 : c.brake;
        ok = m_ctx.send(r.mobility(), encodeWrench(msg::SetWrenchEffort, w));
    }
    s.lastSendOk = ok;
    s.lastError = ok ? std::string() : m_ctx.lastSendError();
    if (!ok) {
        m_ctx.counters().add("tx.drive.failed");
        // The stream runs at the drive rate: one event per failing streak, not one per message.
        if (!s.failureReported) {
            s.failureReported = true;
            m_ctx.notify(Severity::Error, EventKind::DriveNotSent, r.id(),
                         "drive command for " + r.snap.callSign + " NOT sent: " + s.lastError);
        }
        return false;
    }
    m_ctx.counters().add("tx.drive");
    if (s.failureReported) {
        s.failureReported = false;
        m_ctx.notify(Severity::Info, EventKind::DriveNotSent, r.id(),
                     "drive commands for " + r.snap.callSign + " are going out again");
    }
    return true;
}

void DriveClient::tick(RemoteSubsystem& r, TimePoint now) {
    auto it = m_state.find(r.id());
    if (it == m_state.end())
        return;
    State& s = it->second;
    const JausConfig& cfg = m_ctx.config();
    // Drive command watchdog: the stream carries the console's demand only while the console refreshes it.
    if (s.session == Session::Driving && cfg.driveCommandTimeoutS > 0 &&
        now - s.lastUpdate > secondsD(cfg.driveCommandTimeoutS) &&
        (s.drive.linear != 0 || s.drive.angular != 0)) {
        s.session = Session::Stale;
        s.drive.linear = s.drive.angular = 0;
        m_ctx.notify(Severity::Warning, EventKind::CommandRefused, r.id(),
                     "drive demand for " + r.snap.callSign + " not refreshed within " +
                         std::to_string(cfg.driveCommandTimeoutS) + " s: streaming zero");
    }
    if ((s.session != Session::Closed || s.stopRepeatsLeft > 0) &&
        now - s.lastSent >= periodOf(cfg.driveRateHz)) {
        if (s.session != Session::Closed) {
            send(r, s, false);
        } else {
            send(r, s, true);
            if (--s.stopRepeatsLeft == 0) {
                r.snap.driving = false;
                m_ctx.changed(r);
            }
        }
    }
}

} // namespace ocu::jaus
