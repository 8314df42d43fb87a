#include "protocols/jaus/clients/HandoffClient.h"

#include <algorithm>

#include "protocols/common/Log.h"
#include "protocols/jaus/ServiceInheritance.h"
#include "protocols/jaus/clients/AccessControlClient.h"

namespace ocu::jaus {

namespace {
constexpr std::string_view kEac = "urn:jaus:jss:iop:EnhancedAccessControl";
// After GRANTED, how long our RequestControl may take before the hand-off counts as failed.
constexpr auto kGrantedControlWait = std::chrono::seconds(5);
// Beyond the decision timeout, how long a request waits for the vehicle's own TIMEOUT before giving up.
constexpr double kDecisionMarginS = 5;

bool active(HandoffPhase p) {
    return p == HandoffPhase::Requesting || p == HandoffPhase::Queued || p == HandoffPhase::Waiting;
}
std::string seconds(double s) {
    return std::to_string(int(s + 0.5)) + " s";
}
} // namespace

JausId HandoffClient::locate(const RemoteSubsystem& r) {
    JausId found;
    for (const NodeInfo& n : r.snap.services)
        for (const ComponentInfo& c : n.components) {
            if (!offers(c.services, kEac))
                continue;
            const JausId id{r.id(), n.node, c.component};
            if (id == r.controlTarget())
                return id;
            if (!found.subsystem)
                found = id;
        }
    return found;
}

void HandoffClient::registerMessages(MessageTable& table) {
    table.onVehicleMessage(msg::ConfirmHandoffRequest, [this](RemoteSubsystem& r, const JausId& src,
                                                              ByteSpan p) { onConfirm(r, src, p); });
    table.onVehicleMessage(msg::RequestReleaseControl, [this](RemoteSubsystem& r, const JausId& src,
                                                              ByteSpan p) { onReleaseRequest(r, src, p); });
    table.onVehicleMessage(msg::ReportHandoffTimeout,
                           [this](RemoteSubsystem& r, const JausId& src, ByteSpan p) {
                               auto m = decodeU8(p, msg::ReportHandoffTimeout);
                               if (!m)
                                   return m_ctx.rejected(src, m.error());
                               // 0 = the vehicle never times a decision out: the prompt then waits for the
                               // operator.
                               r.snap.handoff.decisionTimeoutS = *m;
                               for (HandoffPrompt& q : r.snap.handoff.prompts)
                                   q.decisionTimeoutS = *m;
                               m_ctx.changed(r);
                           });
    table.onVehicleMessage(msg::ReportEnhancedTimeout,
                           [this](RemoteSubsystem& r, const JausId& src, ByteSpan p) {
                               auto m = decodeU8(p, msg::ReportEnhancedTimeout);
                               if (!m)
                                   return m_ctx.rejected(src, m.error());
                               r.snap.handoff.requestTimeoutS = *m;
                               m_ctx.changed(r);
                           });
}

void HandoffClient::onServicesKnown(RemoteSubsystem& r) {
    const JausId eac = locate(r);
    HandoffStatus& h = r.snap.handoff;
    if (eac == h.component && h.offered == bool(eac.subsystem))
        return;
    h.component = eac;
    h.offered = eac.subsystem != 0;
    if (h.offered)
        queryTimeouts(r, m_state[r.id()]);
    m_ctx.changed(r);
}

void HandoffClient::queryTimeouts(RemoteSubsystem& r, State& s) {
    if (s.timeoutsQueried || !r.snap.handoff.offered)
        return;
    s.timeoutsQueried = true;
    m_ctx.send(r.snap.handoff.component, encodeEmpty(msg::QueryEnhancedTimeout));
    m_ctx.send(r.snap.handoff.component, encodeEmpty(msg::QueryHandoffTimeout));
}

void HandoffClient::setPhase(RemoteSubsystem& r, HandoffPhase phase, std::string reason, Severity severity) {
    HandoffStatus& h = r.snap.handoff;
    h.phase = phase;
    h.reason = std::move(reason);
    m_ctx.notify(severity, EventKind::HandoffChanged, r.id(), h.reason);
    m_ctx.changed(r);
}

// ---- requester
// ----------------------------------------------------------------------------------------------

bool HandoffClient::request(std::uint16_t ss, const std::string& reason) {
    const JausConfig& cfg = m_ctx.config();
    if (!cfg.mayControl())
        return m_ctx.refuse(ss, "the monitor role (authority 0) never asks for control",
                            OutcomeReason::NotPermitted);
    RemoteSubsystem* r = m_ctx.find(ss);
    if (!r || !r->components.known || !r->controlTarget().subsystem)
        return m_ctx.refuseNoTarget(ss, "AccessControl");
    if (r->snap.controlledByUs)
        return m_ctx.refuse(ss, "this console already controls " + r->snap.callSign, OutcomeReason::Refused);
    State& s = m_state[ss];
    s.explanation = cfg.callSign + ": " + (reason.empty() ? std::string("hand-off requested") : reason);
    if (!r->snap.handoff.offered)
        return preempt(*r,
                       r->snap.callSign +
                           " offers no Enhanced Access Control: the ordinary pre-emption rules apply "
                           "(RequestControl with authority " +
                           std::to_string(cfg.authority) +
                           (r->snap.controller.subsystem ? "; granted only above the holder's authority " +
                                                               std::to_string(r->snap.controllerAuthority)
                                                         : std::string("; no holder known")) +
                           ")");
    if (!m_ctx.send(r->snap.handoff.component, encode(RequestHandoff{cfg.authority, s.explanation})))
        return m_ctx.sendFailed(ss, "RequestHandoff");
    s.since = s.lastSent = m_ctx.now();
    s.holder = r->snap.controller;
    r->snap.handoff.queueId = kNoHandoffId;
    s.timeoutsQueried = false;
    queryTimeouts(*r, s);
    const std::string holder =
        r->snap.controller.subsystem ? r->snap.controller.toString() : std::string("its controller");
    setPhase(*r, HandoffPhase::Requesting,
             "hand-off of " + r->snap.callSign + " requested from " + holder + " (authority " +
                 std::to_string(cfg.authority) + ")",
             Severity::Info);
    return true;
}

bool HandoffClient::preempt(RemoteSubsystem& r, const std::string& why) {
    if (!m_access.requestControl(r.id()))
        return false;
    setPhase(r, HandoffPhase::Preempting, why, Severity::Warning);
    return true;
}

void HandoffClient::sendRequest(RemoteSubsystem& r, State& s) {
    s.lastSent = m_ctx.now();
    m_ctx.send(r.snap.handoff.component, encode(RequestHandoff{m_ctx.config().authority, s.explanation}));
}

bool HandoffClient::cancel(std::uint16_t ss) {
    RemoteSubsystem* r = m_ctx.find(ss);
    if (!r || !active(r->snap.handoff.phase))
        return m_ctx.refuse(
            ss, "no hand-off request of this console is waiting for subsystem " + std::to_string(ss),
            OutcomeReason::InvalidArgument);
    // Without our queue ID the vehicle drops the request once we stop re-asserting it.
    if (r->snap.handoff.queueId != kNoHandoffId &&
        !m_ctx.send(r->snap.handoff.component, encodeU8(msg::RemoveHandoffRequest, r->snap.handoff.queueId)))
        return m_ctx.sendFailed(ss, "RemoveHandoffRequest");
    setPhase(*r, HandoffPhase::Cancelled, "hand-off request for " + r->snap.callSign + " withdrawn",
             Severity::Info);
    return true;
}

void HandoffClient::onConfirm(RemoteSubsystem& r, const JausId& src, ByteSpan p) {
    auto m = decodeConfirmHandoffRequest(p);
    if (!m)
        return m_ctx.rejected(src, m.error());
    HandoffStatus& h = r.snap.handoff;
    if (!active(h.phase))
        return; // an answer to a request we no longer make (cancelled, already final)
    State& s = m_state[r.id()];
    const JausId holder = r.snap.controller.subsystem ? r.snap.controller : s.holder;
    const std::string who = holder.subsystem ? holder.toString() : "the holder";
    switch (m->code) {
    case HandoffCode::Deferred:
    case HandoffCode::Wait:
        h.queueId = m->id;
        if (h.phase != HandoffPhase::Waiting) {
            s.since = m_ctx.now(); // the vehicle gives the holder its decision time again
            setPhase(r, HandoffPhase::Waiting,
                     who + " asks to wait for " + r.snap.callSign +
                         ": the request is kept up (answer within " + seconds(h.decisionTimeoutS) + ")",
                     Severity::Info);
        }
        return;
    case HandoffCode::Queued:
        h.queueId = m->id;
        // QUEUED again (a re-assertion answered, or a WAIT passed on as QUEUED) changes nothing.
        if (h.phase == HandoffPhase::Requesting)
            setPhase(r, HandoffPhase::Queued,
                     "hand-off of " + r.snap.callSign + " waiting for " + who + " to answer (up to " +
                         seconds(h.decisionTimeoutS) + ")",
                     Severity::Info);
        return;
    case HandoffCode::Granted:
        s.grantedAt = m_ctx.now();
        m_access.requestControl(r.id());
        setPhase(r, HandoffPhase::Granted, "hand-off of " + r.snap.callSign + " granted by " + who,
                 Severity::Info);
        return;
    case HandoffCode::Denied:
    case HandoffCode::NotAvailable:
        if (m->id == kNoHandoffId && r.snap.controller.subsystem == 0) {
            // Nobody holds the vehicle: the EAC leaves it to RequestControl (EnhancedAccessControl_V1.xml).
            preempt(r, "nobody holds " + r.snap.callSign + ": control requested directly");
            return;
        }
        if (m->code == HandoffCode::Denied)
            setPhase(r, HandoffPhase::Denied, "hand-off of " + r.snap.callSign + " denied by " + who,
                     Severity::Warning);
        else
            setPhase(r, HandoffPhase::Refused,
                     "hand-off of " + r.snap.callSign + " refused: control is not available",
                     Severity::Warning);
        return;
    case HandoffCode::Timeout:
        setPhase(r, HandoffPhase::TimedOut,
                 "hand-off of " + r.snap.callSign + ": " + who + " did not answer within " +
                     seconds(h.decisionTimeoutS),
                 Severity::Warning);
        return;
    case HandoffCode::InsufficientAuthority:
        setPhase(r, HandoffPhase::Refused,
                 "hand-off of " + r.snap.callSign + " refused: authority " +
                     std::to_string(m_ctx.config().authority) + " is below the vehicle's default",
                 Severity::Warning);
        return;
    }
}

void HandoffClient::tickRequest(RemoteSubsystem& r, State& s, TimePoint now) {
    HandoffStatus& h = r.snap.handoff;
    if (active(h.phase)) {
        if (r.snap.controller.subsystem)
            s.holder = r.snap.controller;
        // Re-assert within the Handoff Request Timeout (AEP-4818 §6.3.2.2): every third of it, as FKIE does.
        const double period = std::max(0.2, (h.requestTimeoutS > 0 ? h.requestTimeoutS : 5.0) / 3);
        if (now - s.lastSent >= secondsD(period))
            sendRequest(r, s);
        if (h.decisionTimeoutS > 0 && now - s.since > secondsD(h.decisionTimeoutS + kDecisionMarginS))
            setPhase(r, HandoffPhase::TimedOut,
                     "hand-off of " + r.snap.callSign + ": no decision from the vehicle within " +
                         seconds(h.decisionTimeoutS),
                     Severity::Warning);
        return;
    }
    if (h.phase == HandoffPhase::Granted || h.phase == HandoffPhase::Preempting) {
        if (r.snap.controlledByUs) {
            setPhase(r, HandoffPhase::Completed,
                     h.phase == HandoffPhase::Granted ? "control of " + r.snap.callSign + " handed over"
                                                      : "control of " + r.snap.callSign + " taken",
                     Severity::Info);
        } else if (h.phase == HandoffPhase::Granted && now - s.grantedAt > kGrantedControlWait) {
            setPhase(r, HandoffPhase::Refused,
                     "hand-off of " + r.snap.callSign + " granted, but RequestControl was not confirmed",
                     Severity::Warning);
        } else if (h.phase == HandoffPhase::Preempting && !m_access.wantsControl(r.id())) {
            setPhase(r, HandoffPhase::Refused,
                     "control of " + r.snap.callSign + " refused: " + nameFor(r.snap.access) +
                         " (ordinary pre-emption: the holder's authority is not lower)",
                     Severity::Warning);
        }
    }
}

// ---- holder
// ---------------------------------------------------------------------------------------------------

void HandoffClient::onReleaseRequest(RemoteSubsystem& r, const JausId& src, ByteSpan p) {
    auto m = decodeRequestReleaseControl(p);
    if (!m)
        return m_ctx.rejected(src, m.error());
    State& s = m_state[r.id()];
    s.eacOfPrompts = src;
    HandoffStatus& h = r.snap.handoff;
    if (!h.offered) { // a vehicle that forwards requests offers the service, whatever its services said
        h.offered = true;
        h.component = src;
    }
    queryTimeouts(r, s);
    std::vector<HandoffPrompt> next;
    for (const ReleaseRequest& q : m->requests) {
        auto old = std::find_if(h.prompts.begin(), h.prompts.end(), [&](const HandoffPrompt& o) {
            return o.id == q.id && o.requester == q.requester;
        });
        if (old != h.prompts.end()) {
            next.push_back(*old);
            continue;
        }
        HandoffPrompt n{q.id,        q.requester,     q.authority,       q.explanation,
                        m_ctx.now(), unixMillisNow(), h.decisionTimeoutS};
        m_ctx.notify(Severity::Warning, EventKind::HandoffChanged, r.id(),
                     q.requester.toString() + " asks for control of " + r.snap.callSign + " (authority " +
                         std::to_string(q.authority) + ")" +
                         (q.explanation.empty() ? "" : ": " + q.explanation) + "; request " +
                         std::to_string(q.id) + ", answer within " + seconds(h.decisionTimeoutS));
        next.push_back(std::move(n));
    }
    for (const HandoffPrompt& o : h.prompts) {
        if (std::any_of(next.begin(), next.end(), [&](const HandoffPrompt& n) { return n.id == o.id; }))
            continue;
        // Gone from the vehicle's queue: at the end of the decision time its own timeout (the vehicle's clock
        // runs a transit ahead of ours), before it the requester withdrew it or stopped re-asserting it.
        const bool decisionOver =
            o.decisionTimeoutS > 0 && m_ctx.now() - o.received > secondsD(o.decisionTimeoutS - 1);
        m_ctx.notify(decisionOver ? Severity::Warning : Severity::Info, EventKind::HandoffChanged, r.id(),
                     "hand-off request of " + o.requester.toString() + " for " + r.snap.callSign +
                         (decisionOver ? " not answered within " + seconds(o.decisionTimeoutS) +
                                             ": the vehicle answers it TIMEOUT"
                                       : " withdrawn (or no longer re-asserted)"));
    }
    h.prompts = std::move(next);
    m_ctx.changed(r);
}

bool HandoffClient::answer(std::uint16_t ss, std::uint8_t id, ReleaseCode code) {
    RemoteSubsystem* r = m_ctx.find(ss);
    if (!r)
        return m_ctx.refuseNoTarget(ss, "EnhancedAccessControl");
    std::vector<HandoffPrompt>& prompts = r->snap.handoff.prompts;
    auto it =
        std::find_if(prompts.begin(), prompts.end(), [&](const HandoffPrompt& q) { return q.id == id; });
    if (it == prompts.end())
        return m_ctx.refuse(ss,
                            "no hand-off request " + std::to_string(id) + " is waiting for an answer on " +
                                r->snap.callSign,
                            OutcomeReason::InvalidArgument);
    const State& s = m_state[ss];
    const JausId to = s.eacOfPrompts.subsystem ? s.eacOfPrompts : r->snap.handoff.component;
    const ConfirmReleaseControl answer{{{id, code}}};
    if (!m_ctx.send(to, encode(answer)))
        return m_ctx.sendFailed(ss, "ConfirmReleaseControl");
    const std::string who = it->requester.toString();
    if (code == ReleaseCode::Wait) {
        it->waited = true;
        it->received = m_ctx.now(); // the vehicle restarts its decision time
        it->receivedUnixMs = unixMillisNow();
        m_ctx.notify(Severity::Info, EventKind::HandoffChanged, ss,
                     "hand-off of " + r->snap.callSign + " to " + who + ": asked to wait");
        m_ctx.changed(*r);
        return true;
    }
    const bool accept = code == ReleaseCode::Granted;
    if (accept) {
        // At most one GRANTED (EnhancedAccessControl_V1.xml); the others go to the new holder.
        m_access.handOver(ss);
        prompts.clear();
    } else {
        prompts.erase(it);
    }
    m_ctx.notify(Severity::Info, EventKind::HandoffChanged, ss,
                 "hand-off of " + r->snap.callSign + " to " + who + (accept ? " granted" : " denied"));
    m_ctx.changed(*r);
    return true;
}

void HandoffClient::tickPrompts(RemoteSubsystem& r, TimePoint now) {
    auto& prompts = r.snap.handoff.prompts;
    if (!prompts.empty() && !r.snap.controlledByUs) {
        // Control went elsewhere (pre-empted, lost): the requests are no longer ours to answer.
        prompts.clear();
        m_ctx.changed(r);
        return;
    }
    const auto expired = [&](const HandoffPrompt& q) {
        return q.decisionTimeoutS > 0 && now - q.received > secondsD(q.decisionTimeoutS);
    };
    if (std::none_of(prompts.begin(), prompts.end(), expired))
        return;
    for (const HandoffPrompt& q : prompts)
        if (expired(q))
            m_ctx.notify(Severity::Warning, EventKind::HandoffChanged, r.id(),
                         "hand-off request of " + q.requester.toString() + " for " + r.snap.callSign +
                             " not answered within " + seconds(q.decisionTimeoutS) +
                             ": the vehicle answers it TIMEOUT");
    prompts.erase(std::remove_if(prompts.begin(), prompts.end(), expired), prompts.end());
    m_ctx.changed(r);
}

void HandoffClient::tick(RemoteSubsystem& r, TimePoint now) {
    auto it = m_state.find(r.id());
    if (it != m_state.end())
        tickRequest(r, it->second, now);
    tickPrompts(r, now);
}

} // namespace ocu::jaus
