// Hand-off messages: EnhancedAccessControl and HandoffController 1.1 (jaus-autonomy.md §8, HandoffClass.xml).
#include "protocols/jaus/MessagesHandoff.h"

#include "protocols/jaus/MessageSupport.h"

namespace ocu::jaus {

using namespace codec;

const char* handoffMessageName(std::uint16_t id) {
    switch (id) {
    case msg::RequestHandoff:
        return "RequestHandoff";
    case msg::QueryHandoffTimeout:
        return "QueryHandoffTimeout";
    case msg::QueryEnhancedTimeout:
        return "QueryEnhancedTimeout";
    case msg::RemoveHandoffRequest:
        return "RemoveHandoffRequest";
    case msg::ConfirmHandoffRequest:
        return "ConfirmHandoffRequest";
    case msg::ReportHandoffTimeout:
        return "ReportHandoffTimeout";
    case msg::ReportEnhancedTimeout:
        return "ReportEnhancedTimeout";
    case msg::RequestReleaseControl:
        return "RequestReleaseControl";
    case msg::ConfirmReleaseControl:
        return "ConfirmReleaseControl";
    default:
        return nullptr;
    }
}

const char* nameFor(HandoffCode c) {
    switch (c) {
    case HandoffCode::Granted:
        return "granted";
    case HandoffCode::NotAvailable:
        return "not available";
    case HandoffCode::Timeout:
        return "timeout";
    case HandoffCode::Denied:
        return "denied";
    case HandoffCode::Queued:
        return "queued";
    case HandoffCode::Deferred:
        return "deferred";
    case HandoffCode::InsufficientAuthority:
        return "insufficient authority";
    case HandoffCode::Wait:
        return "wait";
    }
    return "unknown";
}

Bytes encode(const RequestHandoff& m) {
    Bytes out;
    ByteWriter w = start(out, msg::RequestHandoff);
    w.u8(m.authority);
    putString8(w, m.explanation);
    return out;
}

Bytes encode(const ConfirmHandoffRequest& m) {
    Bytes out;
    ByteWriter w = start(out, msg::ConfirmHandoffRequest);
    w.u8(m.id);
    w.u8(std::uint8_t(m.code));
    return out;
}

Bytes encode(const RequestReleaseControl& m) {
    Bytes out;
    ByteWriter w = start(out, msg::RequestReleaseControl);
    const std::size_t n = std::min<std::size_t>(m.requests.size(), 255);
    w.u8(std::uint8_t(n));
    for (std::size_t i = 0; i < n; ++i) {
        const ReleaseRequest& r = m.requests[i];
        w.u8(r.id);
        w.u16(r.requester.subsystem);
        w.u8(r.requester.node);
        w.u8(r.requester.component);
        w.u8(r.authority);
        putString8(w, r.explanation);
    }
    return out;
}

Bytes encode(const ConfirmReleaseControl& m) {
    Bytes out;
    ByteWriter w = start(out, msg::ConfirmReleaseControl);
    const std::size_t n = std::min<std::size_t>(m.answers.size(), 255);
    w.u8(std::uint8_t(n));
    for (std::size_t i = 0; i < n; ++i) {
        w.u8(m.answers[i].id);
        w.u8(std::uint8_t(m.answers[i].code));
    }
    return out;
}

Result<RequestHandoff> decodeRequestHandoff(ByteSpan p) {
    auto r = open(p, msg::RequestHandoff);
    if (!r)
        return makeError(r.error());
    RequestHandoff m;
    m.authority = r->u8();
    m.explanation = getString8(*r);
    return finish(*r, std::move(m), msg::RequestHandoff);
}

Result<ConfirmHandoffRequest> decodeConfirmHandoffRequest(ByteSpan p) {
    auto r = open(p, msg::ConfirmHandoffRequest);
    if (!r)
        return makeError(r.error());
    ConfirmHandoffRequest m;
    m.id = r->u8();
    const std::uint8_t code = r->u8();
    if (r->ok() && code > std::uint8_t(HandoffCode::Wait))
        return makeError("value: ConfirmHandoffRequest response code " + std::to_string(code));
    m.code = HandoffCode(code);
    return finish(*r, m, msg::ConfirmHandoffRequest);
}

Result<RequestReleaseControl> decodeRequestReleaseControl(ByteSpan p) {
    auto r = open(p, msg::RequestReleaseControl);
    if (!r)
        return makeError(r.error());
    RequestReleaseControl m;
    const std::uint8_t n = r->u8();
    for (std::uint8_t i = 0; i < n && r->ok(); ++i) {
        ReleaseRequest q;
        q.id = r->u8();
        q.requester.subsystem = r->u16();
        q.requester.node = r->u8();
        q.requester.component = r->u8();
        q.authority = r->u8();
        q.explanation = getString8(*r);
        m.requests.push_back(std::move(q));
    }
    return finish(*r, std::move(m), msg::RequestReleaseControl);
}

Result<ConfirmReleaseControl> decodeConfirmReleaseControl(ByteSpan p) {
    auto r = open(p, msg::ConfirmReleaseControl);
    if (!r)
        return makeError(r.error());
    ConfirmReleaseControl m;
    const std::uint8_t n = r->u8();
    for (std::uint8_t i = 0; i < n && r->ok(); ++i) {
        ReleaseAnswer a;
        a.id = r->u8();
        const std::uint8_t code = r->u8();
        if (r->ok() && code > std::uint8_t(ReleaseCode::Wait))
            return makeError("value: ConfirmReleaseControl response code " + std::to_string(code));
        a.code = ReleaseCode(code);
        m.answers.push_back(a);
    }
    return finish(*r, std::move(m), msg::ConfirmReleaseControl);
}

} // namespace ocu::jaus
