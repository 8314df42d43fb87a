#include "protocols/jaus/clients/AccessControlClient.h"

#include "protocols/common/Log.h"
#include "protocols/jaus/clients/DriveClient.h"

namespace ocu::jaus {

namespace {
// Our own ID in the snapshot's controller field only while we hold control: otherwise the console would
// show itself as "another" controller. Unknown until the vehicle reports who it is.
void dropSelfAsController(RemoteSubsystem& r, const JausId& self) {
    if (!r.snap.controlledByUs && r.snap.controller == self) {
        r.snap.controller = JausId{};
        r.snap.controllerAuthority = 0;
    }
}
// How long a RejectControl to an outstanding request waits for a ConfirmControl(accepted) to the same
// request before it counts (stacks that answer a pre-empting request with both).
constexpr auto kRejectGrace = std::chrono::milliseconds(1500);
} // namespace

void AccessControlClient::registerMessages(MessageTable& table) {
    table.onVehicleMessage(msg::ConfirmControl, [this](RemoteSubsystem& r, const JausId& src, ByteSpan p) {
        if (m_other && m_other(r, src, msg::ConfirmControl, p))
            return;
        onConfirm(r, src, p);
    });
    table.onVehicleMessage(msg::RejectControl, [this](RemoteSubsystem& r, const JausId& src, ByteSpan p) {
        if (m_other && m_other(r, src, msg::RejectControl, p))
            return;
        onReject(r, src, p);
    });
    table.onVehicleMessage(msg::ReportControl, [this](RemoteSubsystem& r, const JausId& src, ByteSpan p) {
        onReport(r, src, p);
    });
    table.onVehicleMessage(msg::ReportTimeout, [this](RemoteSubsystem& r, const JausId& src, ByteSpan p) {
        auto m = decodeU8(p, msg::ReportTimeout);
        if (!m)
            return m_ctx.rejected(src, m.error());
        r.snap.accessTimeoutS = *m;
        m_ctx.changed(r);
    });
    // Known and deliberately unused: the console shows the controller's authority from ReportControl.
    table.onVehicleMessage(msg::ReportAuthority, [](RemoteSubsystem&, const JausId&, ByteSpan) {});
}

bool AccessControlClient::wantsControl(std::uint16_t ss) const {
    auto it = m_state.find(ss);
    return it != m_state.end() && it->second.wants();
}

double AccessControlClient::timeoutS(const RemoteSubsystem& r) const {
    return r.snap.accessTimeoutS > 0 ? r.snap.accessTimeoutS : m_ctx.config().accessTimeoutS;
}

// ---- commands
// ----------------------------------------------------------------------------------------------

bool AccessControlClient::requestControl(std::uint16_t ss) {
    const JausConfig& cfg = m_ctx.config();
    if (!cfg.mayControl())
        return m_ctx.refuse(ss, "the monitor role (authority 0) never requests control",
                            OutcomeReason::NotPermitted);
    RemoteSubsystem* r = m_ctx.find(ss);
    if (!r || !r->controlTarget().subsystem)
        return m_ctx.refuseNoTarget(ss, "AccessControl");
    if (!m_ctx.send(r->controlTarget(), encodeU8(msg::RequestControl, cfg.authority)))
        return m_ctx.sendFailed(ss, "RequestControl");
    State& s = m_state[ss];
    s.phase = Phase::Requesting;
    s.lossCheckUntil.reset();
    s.lastRequest = m_ctx.now();
    if (!s.timeoutQueried) {
        s.timeoutQueried = true;
        m_ctx.send(r->controlTarget(), encodeEmpty(msg::QueryTimeout));
    }
    return true;
}

bool AccessControlClient::releaseControl(std::uint16_t ss) {
    RemoteSubsystem* r = m_ctx.find(ss);
    if (!r || !r->controlTarget().subsystem)
        return m_ctx.refuseNoTarget(ss, "AccessControl");
    m_drive.beforeRelease(*r);
    State& s = m_state[ss];
    s.phase = r->snap.controlledByUs ? Phase::Releasing : Phase::Idle;
    if (s.phase != Phase::Releasing && r->snap.access == AccessState::ControlAccepted)
        r->snap.access = AccessState::ControlReleased;
    s.releaseDeadline = m_ctx.now() + secondsD(timeoutS(*r));
    s.lastReleaseSent = m_ctx.now();
    if (!m_ctx.send(r->controlTarget(), encodeEmpty(msg::ReleaseControl)))
        return m_ctx.sendFailed(ss, "ReleaseControl");
    return true;
}

void AccessControlClient::handOver(std::uint16_t ss) {
    RemoteSubsystem* r = m_ctx.find(ss);
    if (!r)
        return;
    m_drive.beforeRelease(*r);
    State& s = m_state[ss];
    s.phase = r->snap.controlledByUs ? Phase::Releasing : Phase::Idle;
    s.releaseDeadline = m_ctx.now() + secondsD(timeoutS(*r));
    s.lastReleaseSent = m_ctx.now();
}

void AccessControlClient::releaseAll() {
    for (auto& [ss, r] : m_ctx.remotes())
        if (wantsControl(ss) || r.snap.controlledByUs)
            releaseControl(ss);
}

// ---- received
// ----------------------------------------------------------------------------------------------

void AccessControlClient::onConfirm(RemoteSubsystem& r, const JausId& src, ByteSpan p) {
    auto m = decodeU8(p, msg::ConfirmControl);
    if (!m)
        return m_ctx.rejected(src, m.error());
    State& s = m_state[r.id()];
    const std::uint8_t authority = m_ctx.config().authority;
    s.lastConfirm = m_ctx.now();
    if (*m == std::uint8_t(ConfirmControlCode::Accepted)) {
        if (s.phase == Phase::RefusalPending)
            s.phase = Phase::Requesting; // Reject-then-Confirm to the same request: accepted
        if (!s.wants()) {
            // A late accept after we gave up: hand it back.
            m_ctx.send(src, encodeEmpty(msg::ReleaseControl));
            return;
        }
        r.snap.controller = m_ctx.self();
        r.snap.controllerAuthority = authority;
        if (!r.snap.controlledByUs) {
            r.snap.controlledByUs = true;
            r.snap.access = AccessState::ControlAccepted;
            m_ctx.notify(Severity::Info, EventKind::ControlAccepted, r.id(),
                         "control of " + r.snap.callSign + " accepted (authority " +
                             std::to_string(authority) + ")");
            m_ctx.changed(r);
        }
        return;
    }
    if (!s.wants() &&
        (s.phase == Phase::Releasing || m_ctx.now() - s.lastReleaseSent < std::chrono::seconds(2))) {
        // A refusal of a re-request sent before we let go (released or handed over): the release's own answer
        // (RejectControl) decides, not this one.
        return;
    }
    const bool had = r.snap.controlledByUs;
    s.giveUp();
    r.snap.controlledByUs = false;
    dropSelfAsController(r, m_ctx.self());
    m_drive.endSession(r, false);
    r.snap.access = *m == std::uint8_t(ConfirmControlCode::NotAvailable) ? AccessState::NotAvailable
                                                                         : AccessState::InsufficientAuthority;
    const std::string why = *m == 1 ? "not available" : "insufficient authority";
    if (had) {
        r.snap.access = AccessState::Preempted;
        m_ctx.notify(Severity::Warning, EventKind::ControlPreempted, r.id(),
                     "control of " + r.snap.callSign + " lost: re-request refused (" + why + ")");
    } else {
        m_ctx.notify(Severity::Warning, EventKind::ControlRejected, r.id(),
                     "control of " + r.snap.callSign + " refused: " + why);
    }
    m_ctx.send(src, encodeEmpty(msg::QueryControl));
    m_ctx.changed(r);
}

void AccessControlClient::onReject(RemoteSubsystem& r, const JausId& src, ByteSpan p) {
    auto m = decodeU8(p, msg::RejectControl);
    if (!m)
        return m_ctx.rejected(src, m.error());
    State& s = m_state[r.id()];
    if (s.phase == Phase::Releasing) {
        s.phase = Phase::Idle;
        r.snap.controlledByUs = false;
        dropSelfAsController(r, m_ctx.self());
        r.snap.access = AccessState::ControlReleased;
        m_ctx.notify(Severity::Info, EventKind::ControlReleased, r.id(),
                     "control of " + r.snap.callSign + " released");
        m_ctx.changed(r);
        return;
    }
    if (!r.snap.controlledByUs && s.wants()) {
        // Not final yet: a ConfirmControl(accepted) to the same request may follow (see kRejectGrace).
        if (s.phase != Phase::RefusalPending) {
            s.phase = Phase::RefusalPending;
            s.rejectDeadline = m_ctx.now() + kRejectGrace;
            s.rejectCode = *m;
        }
        return;
    }
    if (r.snap.controlledByUs)
        onControlLost(r, s, *m == 0 ? "released by the platform" : "control not available");
}

void AccessControlClient::onReport(RemoteSubsystem& r, const JausId& src, ByteSpan p) {
    auto m = decodeReportControl(p);
    if (!m)
        return m_ctx.rejected(src, m.error());
    State& s = m_state[r.id()];
    r.snap.controller = m->controller;
    r.snap.controllerAuthority = m->authority;
    const bool ours = m->controller == m_ctx.self();
    if (ours && !r.snap.controlledByUs) {
        if (s.wants()) {
            // The vehicle lists us as its controller: accepted, whatever answers were lost on the way.
            s.phase = Phase::Requesting;
            s.lastConfirm = m_ctx.now();
            r.snap.controlledByUs = true;
            r.snap.access = AccessState::ControlAccepted;
            m_ctx.notify(Severity::Info, EventKind::ControlAccepted, r.id(),
                         "control of " + r.snap.callSign + " accepted (reported by the vehicle)");
        } else if (s.phase == Phase::Releasing || m_ctx.now() - s.lastReleaseSent < std::chrono::seconds(2)) {
            // Our release is on its way, or this report left the vehicle before it arrived.
            dropSelfAsController(r, m_ctx.self());
        } else {
            // We hold control we do not want (a late accept, a lost release): say so and hand it back.
            r.snap.controlledByUs = true;
            r.snap.access = AccessState::ControlAccepted;
            s.phase = Phase::Releasing;
            s.releaseDeadline = m_ctx.now() + secondsD(timeoutS(r));
            m_ctx.send(src, encodeEmpty(msg::ReleaseControl));
        }
        m_ctx.changed(r);
        return;
    }
    if (s.phase == Phase::Releasing && r.snap.controlledByUs && !ours && m->controller.subsystem != 0) {
        // Released (or handed over) and someone else holds it already: the RejectControl may still come.
        s.phase = Phase::Idle;
        r.snap.controlledByUs = false;
        r.snap.access = AccessState::ControlReleased;
        m_ctx.notify(Severity::Info, EventKind::ControlReleased, r.id(),
                     "control of " + r.snap.callSign + " released to " + m->controller.toString());
    } else if (s.lossCheckUntil) {
        classify(r, s, *m);
    } else if (r.snap.controlledByUs && !ours && m->controller.subsystem != 0 &&
               m_ctx.now() - s.lastConfirm > std::chrono::milliseconds(500)) {
        // Someone else holds control although we think we do (a missed RejectControl).
        classify(r, s, *m);
    } else if (!r.snap.controlledByUs && !s.wants() &&
               (r.snap.access == AccessState::Monitoring || r.snap.access == AccessState::NotControlled)) {
        r.snap.access = m->controller.subsystem == 0 ? AccessState::NotControlled : AccessState::Monitoring;
    }
    m_ctx.changed(r);
}

void AccessControlClient::onControlLost(RemoteSubsystem& r, State& s, const std::string& why) {
    s.giveUp();
    r.snap.controlledByUs = false;
    dropSelfAsController(r, m_ctx.self());
    m_drive.endSession(r, true);
    // Find out who holds control now to tell pre-emption from a timeout (AEP-4818 §9 item 14).
    s.lossCheckUntil = m_ctx.now() + std::chrono::seconds(1);
    r.snap.access = AccessState::ControlReleased;
    if (r.controlTarget().subsystem)
        m_ctx.send(r.controlTarget(), encodeEmpty(msg::QueryControl));
    logInfo("ocu.jaus", "control of " + r.snap.callSign + " ended: " + why);
    m_ctx.changed(r);
}

void AccessControlClient::classify(RemoteSubsystem& r, State& s, const ReportControl& rc) {
    s.lossCheckUntil.reset();
    r.snap.controlledByUs = false;
    s.giveUp();
    dropSelfAsController(r, m_ctx.self());
    m_drive.endSession(r, false);
    if (rc.controller.subsystem != 0 && !(rc.controller == m_ctx.self()) &&
        rc.authority > m_ctx.config().authority) {
        r.snap.access = AccessState::Preempted;
        m_ctx.notify(Severity::Warning, EventKind::ControlPreempted, r.id(),
                     "control of " + r.snap.callSign + " pre-empted by " + rc.controller.toString() +
                         " (authority " + std::to_string(rc.authority) + ")");
    } else {
        r.snap.access = AccessState::Timeout;
        m_ctx.notify(Severity::Warning, EventKind::ControlLost, r.id(),
                     "control of " + r.snap.callSign + " lost");
    }
    m_ctx.changed(r);
}

// ---- timers
// ------------------------------------------------------------------------------------------------

void AccessControlClient::tick(RemoteSubsystem& r, TimePoint now) {
    const JausId mob = r.controlTarget();
    State& s = m_state[r.id()];
    // Who controls the vehicle, at the status rate (AEP-4818 §9 item 13).
    if (mob.subsystem && r.reachable() && now - s.lastControlPoll >= periodOf(m_ctx.config().statusPollHz)) {
        s.lastControlPoll = now;
        m_ctx.send(mob, encodeEmpty(msg::QueryControl));
    }
    // Keep re-requesting inside the timeout; notice silence.
    if (s.wants() && mob.subsystem) {
        const double timeout = timeoutS(r);
        // Re-request well inside the timeout (AEP-4818 §4.3.4): 40 % of it, i.e. at most half.
        const Duration period = r.snap.controlledByUs ? secondsD(timeout * 0.4) : std::chrono::seconds(1);
        if (now - s.lastRequest >= period) {
            s.lastRequest = now;
            m_ctx.send(mob, encodeU8(msg::RequestControl, m_ctx.config().authority));
        }
        if (r.snap.controlledByUs && now - s.lastConfirm > secondsD(timeout)) {
            s.giveUp();
            r.snap.controlledByUs = false;
            dropSelfAsController(r, m_ctx.self());
            m_drive.endSession(r, false);
            r.snap.access = AccessState::Timeout;
            m_ctx.notify(Severity::Warning, EventKind::ControlLost, r.id(),
                         "control of " + r.snap.callSign +
                             " lost: no confirmation within the access-control timeout");
            m_ctx.changed(r);
        }
    }
    if (s.lossCheckUntil && now > *s.lossCheckUntil)
        classify(r, s, ReportControl{});
    if (s.phase == Phase::RefusalPending && now > s.rejectDeadline) {
        s.phase = Phase::Idle;
        r.snap.access = s.rejectCode == std::uint8_t(RejectControlCode::Released)
                            ? AccessState::ControlReleased
                            : AccessState::NotAvailable;
        m_ctx.notify(Severity::Warning, EventKind::ControlRejected, r.id(),
                     "control of " + r.snap.callSign + " refused: RejectControl (" +
                         (s.rejectCode == 0 ? "control released" : "not available") + ")");
        m_ctx.changed(r);
    }
    // A release the vehicle never answered (no RejectControl, no QueryControl): it has dropped us by its own
    // access timeout, since we stopped re-requesting (AS5710A AccessControl timeout).
    if (s.phase == Phase::Releasing && now > s.releaseDeadline) {
        s.phase = Phase::Idle;
        r.snap.controlledByUs = false;
        dropSelfAsController(r, m_ctx.self());
        r.snap.access = AccessState::ControlReleased;
        m_ctx.notify(Severity::Info, EventKind::ControlReleased, r.id(),
                     "control of " + r.snap.callSign + " released (access timeout passed)");
        m_ctx.changed(r);
    }
}

} // namespace ocu::jaus
