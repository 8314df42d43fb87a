// The simulated UGV's Enhanced Access Control 1.1 on the Core Mobility Component (AEP-4818 §6.3; the public
// EnhancedAccessControl_V1.xml rules, shared/research/jaus-autonomy.md §8): a console that asks for a vehicle
// another one holds is queued, the whole queue goes to the controller as RequestReleaseControl, and the
// controller's ConfirmReleaseControl decides. A request not re-asserted within the Handoff Request Timeout,
// or not decided within the Handoff Decision Timeout, is answered TIMEOUT. On GRANTED the old controller gets
// RejectControl(CONTROL_RELEASED) and the requester becomes the controller at once, so its RequestControl
// that follows is confirmed (FKIE's EAC instead leaves control free until that RequestControl: the console
// works with both).
#include "sim/jaus/UgvCore.h"

#include <algorithm>
#include <cmath>

#include "protocols/common/Log.h"
#include "sim/jaus/UgvSupport.h"

namespace ocu::sim {

using namespace ocu::jaus;
using ugv::kLog;
using ugv::secondsD;

void UgvCore::registerHandoff() {
    const JausId mob = mobility();
    m_table.onCommand(msg::RequestHandoff, mob, [this](const JausId&, const JausId& src, ByteSpan p) {
        auto m = decodeRequestHandoff(p);
        if (!m)
            return rejectMalformed(m.error());
        requestHandoff(src, *m);
    });
    m_table.onCommand(msg::RemoveHandoffRequest, mob, [this](const JausId&, const JausId& src, ByteSpan p) {
        auto id = decodeU8(p, msg::RemoveHandoffRequest);
        if (!id)
            return rejectMalformed(id.error());
        auto& q = m_handoff.requests;
        auto it = std::find_if(q.begin(), q.end(),
                               [&](const UgvHandoffRequest& r) { return r.id == *id && r.requester == src; });
        if (it == q.end())
            return;
        q.erase(it);
        answerHandoff(src, *id, HandoffCode::Denied); // the EAC's answer to a removal (JSIDL)
        forwardHandoffQueue();
    });
    m_table.onCommand(msg::ConfirmReleaseControl, mob,
                      [this](const JausId&, const JausId& src, ByteSpan p) { confirmRelease(src, p); });
    m_table.onQuery(msg::QueryHandoffTimeout, mob, [this](const JausId&, ByteSpan) {
        return encodeU8(msg::ReportHandoffTimeout, std::uint8_t(std::lround(m_cfg.handoffDecisionTimeoutS)));
    });
    m_table.onQuery(msg::QueryEnhancedTimeout, mob, [this](const JausId&, ByteSpan) {
        return encodeU8(msg::ReportEnhancedTimeout, std::uint8_t(std::lround(m_cfg.handoffRequestTimeoutS)));
    });
}

void UgvCore::answerHandoff(const JausId& to, std::uint8_t id, HandoffCode code) {
    send(mobility(), to, encode(ConfirmHandoffRequest{id, code}));
}

void UgvCore::requestHandoff(const JausId& src, const RequestHandoff& request) {
    const TimePoint now = m_clock.now();
    if (m_s.management == ManagementState::Emergency && !isController(src))
        return answerHandoff(src, kNoHandoffId, HandoffCode::NotAvailable);
    if (m_s.controller.subsystem == 0)
        return answerHandoff(src, kNoHandoffId, HandoffCode::Denied); // nobody to ask: RequestControl instead
    if (request.authority < m_cfg.defaultAuthority)
        return answerHandoff(src, kNoHandoffId, HandoffCode::InsufficientAuthority);
    if (isController(src)) {
        m_s.controllerAuthority = request.authority;
        return answerHandoff(src, kNoHandoffId, HandoffCode::Granted);
    }
    auto& q = m_handoff.requests;
    auto it =
        std::find_if(q.begin(), q.end(), [&](const UgvHandoffRequest& r) { return r.requester == src; });
    if (it != q.end()) {
        // A re-assertion (AEP-4818 §6.3.2.2): the request stays queued.
        it->lastAsserted = now;
        const bool changed = it->authority != request.authority || it->explanation != request.explanation;
        it->authority = request.authority;
        it->explanation = request.explanation;
        answerHandoff(src, it->id, HandoffCode::Queued);
        if (changed)
            forwardHandoffQueue();
        return;
    }
    std::uint8_t id = m_handoff.nextId;
    while (id == 0 || id == kNoHandoffId ||
           std::any_of(q.begin(), q.end(), [&](const UgvHandoffRequest& r) { return r.id == id; }))
        ++id;
    m_handoff.nextId = std::uint8_t(id + 1);
    q.push_back(UgvHandoffRequest{id, src, request.authority, request.explanation, now, now});
    logInfo(kLog, m_cfg.callSign + ": hand-off request " + std::to_string(id) + " from " + src.toString());
    answerHandoff(src, id, HandoffCode::Queued);
    forwardHandoffQueue();
}

void UgvCore::forwardHandoffQueue() {
    if (m_s.controller.subsystem == 0 || m_s.controller == internalClient())
        return;
    RequestReleaseControl m;
    for (const UgvHandoffRequest& r : m_handoff.requests)
        m.requests.push_back(ReleaseRequest{r.id, r.requester, r.authority, r.explanation});
    m_handoff.forwardedTo = m_s.controller;
    send(mobility(), m_s.controller, encode(m));
}

void UgvCore::confirmRelease(const JausId& src, ByteSpan p) {
    auto m = decodeConfirmReleaseControl(p);
    if (!m)
        return rejectMalformed(m.error());
    if (!isController(src))
        return; // only the controller decides
    auto& q = m_handoff.requests;
    bool changed = false;
    for (const ReleaseAnswer& a : m->answers) {
        auto it = std::find_if(q.begin(), q.end(), [&](const UgvHandoffRequest& r) { return r.id == a.id; });
        if (it == q.end())
            continue;
        if (a.code == ReleaseCode::Wait) {
            it->forwarded = m_clock.now();                               // the controller asks for more time
            answerHandoff(it->requester, it->id, HandoffCode::Deferred); // the requester can show it
            continue;
        }
        const UgvHandoffRequest r = *it;
        q.erase(it);
        changed = true;
        if (a.code == ReleaseCode::Denied || !isController(src)) {
            answerHandoff(r.requester, r.id, HandoffCode::Denied);
            continue;
        }
        // GRANTED: the old controller is told, the requester holds control now (at most one GRANTED).
        logInfo(kLog, m_cfg.callSign + ": control handed over from " + src.toString() + " to " +
                          r.requester.toString());
        send(mobility(), src, encodeU8(msg::RejectControl, std::uint8_t(RejectControlCode::Released)));
        m_s.controller = r.requester;
        m_s.controllerAuthority = r.authority;
        m_lastRequest = m_clock.now();
        m_haveDrive = false;
        m_cmdV = m_cmdW = 0;
        answerHandoff(r.requester, r.id, HandoffCode::Granted);
    }
    if (changed)
        forwardHandoffQueue();
}

void UgvCore::tickHandoff(TimePoint now) {
    auto& q = m_handoff.requests;
    if (q.empty())
        return;
    bool changed = false;
    for (auto it = q.begin(); it != q.end();) {
        const bool reassertLate = m_cfg.handoffRequestTimeoutS > 0 &&
                                  now - it->lastAsserted > secondsD(m_cfg.handoffRequestTimeoutS);
        const bool undecided = m_cfg.handoffDecisionTimeoutS > 0 &&
                               now - it->forwarded > secondsD(m_cfg.handoffDecisionTimeoutS);
        if (reassertLate || undecided) {
            logInfo(kLog, m_cfg.callSign + ": hand-off request " + std::to_string(it->id) + " timed out (" +
                              (reassertLate ? "not re-asserted" : "controller did not decide") + ")");
            answerHandoff(it->requester, it->id, HandoffCode::Timeout);
            it = q.erase(it);
            changed = true;
        } else {
            ++it;
        }
    }
    if (!q.empty() && !(m_s.controller == m_handoff.forwardedTo)) {
        if (m_s.controller.subsystem == 0) {
            // The controller let go: the first in the queue may take control with its RequestControl.
            const UgvHandoffRequest r = q.front();
            q.erase(q.begin());
            answerHandoff(r.requester, r.id, HandoffCode::Granted);
            m_handoff.forwardedTo = JausId{};
            return;
        }
        // A new controller decides afresh.
        for (UgvHandoffRequest& r : q)
            r.forwarded = now;
        changed = true;
    }
    if (changed)
        forwardHandoffQueue();
}

} // namespace ocu::sim
