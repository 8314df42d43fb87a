// The simulated UGV's Events service on every component (AS5710A Events): subscriptions to any query the
// component answers, periodic at the confirmed rate or on every change of the report.
#include "sim/jaus/UgvCore.h"

#include <algorithm>

#include "sim/jaus/UgvSupport.h"

namespace ocu::sim {

using namespace ocu::jaus;
using ugv::secondsD;

void UgvCore::registerEvents() {
    m_table.onCommand(msg::CreateEvent, std::nullopt, [this](const JausId& c, const JausId& src, ByteSpan p) {
        auto ce = decodeCreateEvent(p);
        if (!ce)
            return rejectMalformed(ce.error());
        createEvent(c, src, *ce);
    });
    m_table.onCommand(msg::UpdateEvent, std::nullopt,
                      [this](const JausId& c, const JausId& src, ByteSpan p) { updateEvent(c, src, p); });
    m_table.onCommand(msg::CancelEvent, std::nullopt,
                      [this](const JausId& c, const JausId& src, ByteSpan p) { cancelEvent(c, src, p); });
    m_table.onQuery(msg::QueryEvents, std::nullopt, [this](const JausId& c, ByteSpan) {
        ReportEvents re;
        for (auto& [k, e] : m_events)
            if (e.component == c)
                re.events.push_back({e.type, e.eventId, e.query});
        return encode(re);
    });
}

void UgvCore::createEvent(const JausId& comp, const JausId& src, const CreateEvent& ce) {
    RejectEventRequest rej;
    rej.requestId = ce.requestId;
    if (m_cfg.faults.rejectEvents) {
        rej.responseCode = ce.type == EventType::Periodic ? 1 : 2;
        send(comp, src, encode(rej));
        return;
    }
    const std::uint16_t qid = peekMessageId(ce.queryMessage);
    if (!serves(comp, qid) || !report(comp, ce.queryMessage)) {
        rej.responseCode = 5;
        send(comp, src, encode(rej));
        return;
    }
    if (ce.type == EventType::Periodic && ce.rateHz <= 0) {
        rej.responseCode = 4;
        send(comp, src, encode(rej));
        return;
    }
    EventSub e;
    e.eventId = m_nextEventId++;
    if (m_nextEventId == 0)
        m_nextEventId = 1;
    e.requestId = ce.requestId;
    e.requester = src;
    e.component = comp;
    e.type = ce.type;
    e.rateHz = ce.type == EventType::Periodic ? std::min(ce.rateHz, 100.0) * m_cfg.faults.eventRateScale : 0;
    e.query = ce.queryMessage;
    m_events[e.eventId] = e;
    send(comp, src, encode(ConfirmEventRequest{ce.requestId, e.eventId, e.rateHz}));
}

void UgvCore::updateEvent(const JausId& c, const JausId& src, ByteSpan p) {
    auto ue = decodeUpdateEvent(p);
    if (!ue)
        return rejectMalformed(ue.error());
    auto it = m_events.find(ue->eventId);
    if (it == m_events.end() || !(it->second.requester == src)) {
        RejectEventRequest rej;
        rej.requestId = ue->requestId;
        rej.responseCode = 6;
        send(c, src, encode(rej));
        return;
    }
    it->second.type = ue->type;
    it->second.rateHz = std::min(ue->rateHz, 100.0) * m_cfg.faults.eventRateScale;
    it->second.query = ue->queryMessage;
    it->second.requestId = ue->requestId;
    send(c, src, encode(ConfirmEventRequest{ue->requestId, ue->eventId, it->second.rateHz}));
}

void UgvCore::cancelEvent(const JausId& c, const JausId& src, ByteSpan p) {
    auto ce = decodeCancelEvent(p);
    if (!ce)
        return rejectMalformed(ce.error());
    auto it = m_events.find(ce->eventId);
    if (it == m_events.end()) {
        RejectEventRequest rej;
        rej.requestId = ce->requestId;
        rej.responseCode = 6;
        send(c, src, encode(rej));
        return;
    }
    m_events.erase(it);
    send(c, src, encode(ConfirmEventRequest{ce->requestId, ce->eventId, 0}));
}

void UgvCore::tickEvents(TimePoint now) {
    // Periodic at the confirmed rate, on-change when the report differs (checked every tick).
    for (auto& [id, e] : m_events) {
        if (e.type == EventType::Periodic) {
            if (e.rateHz <= 0 || now - e.lastSent < secondsD(1.0 / e.rateHz))
                continue;
        }
        auto r = report(e.component, e.query);
        if (!r)
            continue;
        if (e.type == EventType::EveryChange && *r == e.lastReport)
            continue;
        e.lastSent = now;
        e.lastReport = *r;
        send(e.component, e.requester, encode(EventMsg{e.eventId, e.sequence++, *r}));
    }
}

} // namespace ocu::sim
