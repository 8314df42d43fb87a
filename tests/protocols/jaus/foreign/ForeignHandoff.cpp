#include "tests/protocols/jaus/foreign/ForeignHandoff.h"

#include <algorithm>

namespace foreign {

namespace {

// jaus-autonomy.md §8 (FK-CORE iop/MessageSet/HandoffClass.xml).
enum : std::uint16_t {
    RejectControl = 0x0010,
    RequestHandoff = 0xFF31,
    QueryHandoffTimeout = 0xFF32,
    QueryEnhancedTimeout = 0xFF33,
    RemoveHandoffRequest = 0xFF34,
    ConfirmHandoffRequest = 0xFF35,
    ReportHandoffTimeout = 0xFF36,
    ReportEnhancedTimeout = 0xFF37,
    RequestReleaseControl = 0xFF38,
    ConfirmReleaseControl = 0xFF39,
};
enum : std::uint8_t { Granted = 0, NotAvailable = 1, Timeout = 2, Denied = 3, Queued = 4, Insufficient = 6 };
enum : std::uint8_t { ReleaseGranted = 0, ReleaseDenied = 1, ReleaseWait = 2 };
constexpr std::uint8_t kImmediate = 255; // the ID of an answer that queued nothing
constexpr std::uint8_t kControlReleased = 0;

Buf message(std::uint16_t id) {
    Buf b;
    put16(b, id);
    return b;
}

} // namespace

void EnhancedAccessControl::post(std::uint32_t to, Buf payload) {
    if (m_opt.answerDelayMs <= 0)
        return m_send(to, payload);
    m_late.push_back({Clock::now() + std::chrono::milliseconds(m_opt.answerDelayMs), to, std::move(payload)});
}

void EnhancedAccessControl::answer(std::uint32_t to, std::uint8_t id, std::uint8_t code) {
    Buf b = message(ConfirmHandoffRequest);
    put8(b, id);
    put8(b, code);
    post(to, std::move(b));
}

void EnhancedAccessControl::forwardQueue() {
    if (!m_controller)
        return;
    Buf b = message(RequestReleaseControl);
    put8(b, std::uint8_t(m_queue.size()));
    for (const Entry& e : m_queue) {
        put8(b, e.id);
        put16(b, std::uint16_t(e.requester >> 16));
        put8(b, std::uint8_t(e.requester >> 8));
        put8(b, std::uint8_t(e.requester));
        put8(b, e.authority);
        putStr8(b, e.explanation);
    }
    post(m_controller, std::move(b));
}

bool EnhancedAccessControl::handle(std::uint16_t mid, std::uint32_t src, const std::uint8_t* body,
                                   std::size_t len) {
    switch (mid) {
    case RequestHandoff:
        onRequest(src, body, len);
        return true;
    case RemoveHandoffRequest:
        onRemove(src, body, len);
        return true;
    case ConfirmReleaseControl:
        onConfirmRelease(src, body, len);
        return true;
    case QueryHandoffTimeout:
    case QueryEnhancedTimeout: {
        const bool decision = mid == QueryHandoffTimeout;
        Buf b = message(decision ? ReportHandoffTimeout : ReportEnhancedTimeout);
        put8(b, decision ? m_opt.decisionTimeoutS : m_opt.requestTimeoutS);
        post(src, std::move(b));
        return true;
    }
    default:
        return false;
    }
}

void EnhancedAccessControl::onRequest(std::uint32_t src, const std::uint8_t* body, std::size_t len) {
    if (len < 2 || len < std::size_t(2 + body[1]))
        return; // Authority u8; Explanation str8
    const std::uint8_t authority = body[0];
    const std::string explanation(reinterpret_cast<const char*>(body + 2), body[1]);
    if (m_controller == 0)
        return answer(src, kImmediate, Denied); // nobody to hand over from: RequestControl instead
    if (src == m_controller) {
        m_authority = authority;
        return answer(src, kImmediate, Granted);
    }
    if (authority < m_opt.defaultAuthority)
        return answer(src, kImmediate, Insufficient);
    if (m_opt.denyAll)
        return answer(src, kImmediate, Denied);
    const auto now = Clock::now();
    auto it =
        std::find_if(m_queue.begin(), m_queue.end(), [&](const Entry& e) { return e.requester == src; });
    if (it == m_queue.end()) {
        Entry e;
        e.id = m_nextId;
        m_nextId = std::uint8_t(m_nextId % 254 + 1); // 1..254: 255 is "no queue entry"
        e.requester = src;
        e.asked = now;
        m_queue.push_back(e);
        it = m_queue.end() - 1;
    }
    it->authority = authority;
    it->explanation = explanation;
    it->asserted = now;
    answer(src, it->id, Queued);
    forwardQueue();
}

void EnhancedAccessControl::onRemove(std::uint32_t src, const std::uint8_t* body, std::size_t len) {
    if (len < 1)
        return;
    auto it = std::find_if(m_queue.begin(), m_queue.end(),
                           [&](const Entry& e) { return e.id == body[0] && e.requester == src; });
    if (it == m_queue.end())
        return;
    answer(src, it->id, Denied);
    m_queue.erase(it);
    forwardQueue();
}

void EnhancedAccessControl::onConfirmRelease(std::uint32_t src, const std::uint8_t* body, std::size_t len) {
    if (src != m_controller || len < 1 || len < std::size_t(1 + 2 * body[0]))
        return; // only the holder decides
    bool grantedOne = false, changed = false;
    for (int i = 0; i < body[0]; ++i) {
        const std::uint8_t id = body[1 + 2 * i], code = body[2 + 2 * i];
        auto it = std::find_if(m_queue.begin(), m_queue.end(), [&](const Entry& e) { return e.id == id; });
        if (it == m_queue.end())
            continue;
        if (code == ReleaseWait) {
            it->asked = Clock::now(); // the holder takes more time
            answer(it->requester, it->id, m_opt.waitAnswer);
            continue;
        }
        const std::uint32_t requester = it->requester;
        m_queue.erase(it);
        changed = true;
        if (code != ReleaseGranted || grantedOne) { // at most one GRANTED (EnhancedAccessControl_V1)
            answer(requester, id, Denied);
            continue;
        }
        grantedOne = true;
        ++m_granted;
        Buf reject = message(RejectControl);
        put8(reject, kControlReleased);
        post(m_controller, std::move(reject));
        m_controller = 0;
        m_authority = 0;
        answer(requester, id, Granted); // the requester takes it with RequestControl
    }
    if (changed && !grantedOne)
        forwardQueue();
}

void EnhancedAccessControl::tick(Clock::time_point now) {
    bool changed = false;
    for (auto it = m_queue.begin(); it != m_queue.end();) {
        const bool dropped =
            m_opt.requestTimeoutS > 0 && now - it->asserted > std::chrono::seconds(m_opt.requestTimeoutS);
        const bool undecided =
            m_opt.decisionTimeoutS > 0 && now - it->asked > std::chrono::seconds(m_opt.decisionTimeoutS);
        if (!dropped && !undecided && m_controller != 0) {
            ++it;
            continue;
        }
        // Not re-asserted: dropped; not decided: TIMEOUT; the holder gone: nobody to decide.
        answer(it->requester, it->id, dropped ? Denied : undecided ? Timeout : NotAvailable);
        it = m_queue.erase(it);
        changed = true;
    }
    if (changed)
        forwardQueue();
    for (auto it = m_late.begin(); it != m_late.end();) {
        if (it->due > now) {
            ++it;
            continue;
        }
        m_send(it->to, it->payload);
        it = m_late.erase(it);
    }
}

} // namespace foreign
