// Events service messages (AS5710A): create, update, cancel, confirm, reject, the Event wrapper,
// query/report.
#include "protocols/jaus/Messages.h"

#include "protocols/jaus/MessageSupport.h"

namespace ocu::jaus {

using namespace codec;

// ---- events ----
Bytes encode(const CreateEvent& m) {
    Bytes out;
    auto w = start(out, msg::CreateEvent);
    w.u8(m.requestId);
    w.u8(std::uint8_t(m.type));
    w.u16(scaleToInt<std::uint16_t>(m.rateHz, 0, kEventRateMax));
    putBlob32(w, m.queryMessage);
    return out;
}
Result<CreateEvent> decodeCreateEvent(ByteSpan p) {
    auto r = open(p, msg::CreateEvent);
    if (!r)
        return makeError(r.error());
    CreateEvent m;
    m.requestId = r->u8();
    m.type = EventType(r->u8() & 1);
    m.rateHz = intToScale<std::uint16_t>(r->u16(), 0, kEventRateMax);
    m.queryMessage = getBlob32(*r);
    return finish(*r, m, msg::CreateEvent);
}
Bytes encode(const UpdateEvent& m) {
    Bytes out;
    auto w = start(out, msg::UpdateEvent);
    w.u8(m.requestId);
    w.u8(std::uint8_t(m.type));
    w.u16(scaleToInt<std::uint16_t>(m.rateHz, 0, kEventRateMax));
    w.u8(m.eventId);
    putBlob32(w, m.queryMessage);
    return out;
}
Result<UpdateEvent> decodeUpdateEvent(ByteSpan p) {
    auto r = open(p, msg::UpdateEvent);
    if (!r)
        return makeError(r.error());
    UpdateEvent m;
    m.requestId = r->u8();
    m.type = EventType(r->u8() & 1);
    m.rateHz = intToScale<std::uint16_t>(r->u16(), 0, kEventRateMax);
    m.eventId = r->u8();
    m.queryMessage = getBlob32(*r);
    return finish(*r, m, msg::UpdateEvent);
}
Bytes encode(const CancelEvent& m) {
    Bytes out;
    auto w = start(out, msg::CancelEvent);
    w.u8(m.requestId);
    w.u8(m.eventId);
    return out;
}
Result<CancelEvent> decodeCancelEvent(ByteSpan p) {
    auto r = open(p, msg::CancelEvent);
    if (!r)
        return makeError(r.error());
    CancelEvent m;
    m.requestId = r->u8();
    m.eventId = r->u8();
    return finish(*r, m, msg::CancelEvent);
}
Bytes encode(const ConfirmEventRequest& m) {
    Bytes out;
    auto w = start(out, msg::ConfirmEventRequest);
    w.u8(m.requestId);
    w.u8(m.eventId);
    w.u16(scaleToInt<std::uint16_t>(m.rateHz, 0, kEventRateMax));
    return out;
}
Result<ConfirmEventRequest> decodeConfirmEventRequest(ByteSpan p) {
    auto r = open(p, msg::ConfirmEventRequest);
    if (!r)
        return makeError(r.error());
    ConfirmEventRequest m;
    m.requestId = r->u8();
    m.eventId = r->u8();
    m.rateHz = intToScale<std::uint16_t>(r->u16(), 0, kEventRateMax);
    return finish(*r, m, msg::ConfirmEventRequest);
}
Bytes encode(const RejectEventRequest& m) {
    Bytes out;
    auto w = start(out, msg::RejectEventRequest);
    w.u8(std::uint8_t((m.responseCode ? 1 : 0) | (m.errorMessage ? 2 : 0)));
    w.u8(m.requestId);
    if (m.responseCode)
        w.u8(*m.responseCode);
    if (m.errorMessage)
        w.fixedString(*m.errorMessage, 80);
    return out;
}
Result<RejectEventRequest> decodeRejectEventRequest(ByteSpan p) {
    auto r = open(p, msg::RejectEventRequest);
    if (!r)
        return makeError(r.error());
    RejectEventRequest m;
    auto pv = r->u8();
    m.requestId = r->u8();
    if (pv & 1)
        m.responseCode = r->u8();
    if (pv & 2)
        m.errorMessage = r->fixedString(80);
    return finish(*r, m, msg::RejectEventRequest);
}
Bytes encode(const EventMsg& m) {
    Bytes out;
    auto w = start(out, msg::Event);
    w.u8(m.eventId);
    w.u8(m.sequence);
    putBlob32(w, m.reportMessage);
    return out;
}
Result<EventMsg> decodeEvent(ByteSpan p) {
    auto r = open(p, msg::Event);
    if (!r)
        return makeError(r.error());
    EventMsg m;
    m.eventId = r->u8();
    m.sequence = r->u8();
    m.reportMessage = getBlob32(*r);
    if (r->ok() && m.reportMessage.size() < 2)
        return makeError("value: Event wraps no report message");
    return finish(*r, m, msg::Event);
}
Bytes encode(const QueryEvents& m) {
    Bytes out;
    auto w = start(out, msg::QueryEvents);
    w.u8(m.variant);
    if (m.variant == 0)
        w.u16(m.value);
    else
        w.u8(std::uint8_t(m.value));
    return out;
}
Result<QueryEvents> decodeQueryEvents(ByteSpan p) {
    auto r = open(p, msg::QueryEvents);
    if (!r)
        return makeError(r.error());
    QueryEvents m;
    m.variant = r->u8();
    if (m.variant > 3)
        return makeError("value: QueryEvents variant " + std::to_string(m.variant));
    m.value = m.variant == 0 ? r->u16() : r->u8();
    return finish(*r, m, msg::QueryEvents);
}
Bytes encode(const ReportEvents& m) {
    Bytes out;
    auto w = start(out, msg::ReportEvents);
    w.u8(std::uint8_t(std::min<std::size_t>(m.events.size(), 255)));
    for (std::size_t i = 0; i < m.events.size() && i < 255; ++i) {
        w.u8(std::uint8_t(m.events[i].type));
        w.u8(m.events[i].eventId);
        putBlob32(w, m.events[i].queryMessage);
    }
    return out;
}
Result<ReportEvents> decodeReportEvents(ByteSpan p) {
    auto r = open(p, msg::ReportEvents);
    if (!r)
        return makeError(r.error());
    ReportEvents m;
    auto n = r->u8();
    for (int i = 0; i < n && r->ok(); ++i) {
        ReportEvents::Entry e;
        e.type = EventType(r->u8() & 1);
        e.eventId = r->u8();
        e.queryMessage = getBlob32(*r);
        m.events.push_back(std::move(e));
    }
    return finish(*r, m, msg::ReportEvents);
}

} // namespace ocu::jaus
