#include "protocols/jaus/clients/EventsClient.h"

namespace ocu::jaus {

void EventsClient::registerMessages(MessageTable& table) {
    m_table = &table;
    table.onVehicleMessage(msg::ConfirmEventRequest, [this](RemoteSubsystem& r, const JausId& src,
                                                            ByteSpan p) { onConfirm(r, src, p); });
    table.onVehicleMessage(msg::RejectEventRequest, [this](RemoteSubsystem& r, const JausId& src,
                                                           ByteSpan p) { onReject(r, src, p); });
    table.onVehicleMessage(msg::Event,
                           [this](RemoteSubsystem& r, const JausId& src, ByteSpan p) { onEvent(r, src, p); });
    table.onRequest(msg::CreateEvent, [this](const JausId& src, ByteSpan p) {
        if (auto ce = decodeCreateEvent(p)) {
            RejectEventRequest rej;
            rej.requestId = ce->requestId;
            rej.responseCode = 5; // message not supported: the OCU serves no events
            m_ctx.send(src, encode(rej));
        }
        // Not only a question to the console: from a vehicle it still counts as a sign of life.
        return false;
    });
}

void EventsClient::subscribe(RemoteSubsystem& r, const JausId& target, Bytes query, double rateHz,
                             EventType type) {
    const std::uint16_t queryId = peekMessageId(query);
    auto& subs = m_subs[r.id()];
    // The same subscription again (services learnt in parts call this once per part): kept as it is, so
    // an event already created is not created twice.
    if (auto it = subs.find(queryId); it != subs.end() && it->second.target == target &&
                                      it->second.query == query && it->second.type == type &&
                                      it->second.rateHz == rateHz)
        return;
    Subscription s;
    s.type = type;
    s.target = target;
    s.rateHz = rateHz;
    s.query = std::move(query);
    subs[queryId] = std::move(s);
}

std::optional<EventsClient::SubscriptionState> EventsClient::state(std::uint16_t ss,
                                                                   std::uint16_t queryId) const {
    auto it = m_subs.find(ss);
    if (it == m_subs.end())
        return std::nullopt;
    auto s = it->second.find(queryId);
    if (s == it->second.end())
        return std::nullopt;
    return s->second.state;
}

void EventsClient::onLinkRestored(RemoteSubsystem& r) {
    auto it = m_subs.find(r.id());
    if (it == m_subs.end())
        return;
    for (auto& [k, s] : it->second)
        s.state = SubscriptionState::None;
}

void EventsClient::tick(RemoteSubsystem& r, TimePoint now) {
    if (!r.reachable())
        return;
    auto it = m_subs.find(r.id());
    if (it == m_subs.end())
        return;
    for (auto& [k, s] : it->second) {
        switch (s.state) {
        case SubscriptionState::None: {
            s.requestId = m_nextRequestId++;
            if (m_nextRequestId == 0)
                m_nextRequestId = 1;
            s.state = SubscriptionState::Pending;
            s.sent = now;
            m_ctx.send(s.target,
                       encode(CreateEvent{s.requestId, s.type, s.type == EventType::Periodic ? s.rateHz : 0.0,
                                          s.query}));
            break;
        }
        case SubscriptionState::Pending:
            if (now - s.sent > secondsD(m_ctx.config().eventConfirmTimeoutS)) {
                s.state = SubscriptionState::Polling;
                m_ctx.counters().add("events.fallback.timeout");
            }
            break;
        case SubscriptionState::Polling:
            if (now - s.lastPoll >= periodOf(s.rateHz)) {
                s.lastPoll = now;
                m_ctx.send(s.target, s.query);
            }
            break;
        case SubscriptionState::Active:
            break;
        }
    }
}

void EventsClient::onConfirm(RemoteSubsystem& r, const JausId& src, ByteSpan p) {
    auto m = decodeConfirmEventRequest(p);
    if (!m)
        return m_ctx.rejected(src, m.error());
    auto it = m_subs.find(r.id());
    if (it == m_subs.end())
        return;
    for (auto& [k, s] : it->second) {
        if (s.state == SubscriptionState::Pending && s.requestId == m->requestId) {
            s.eventId = m->eventId;
            // Accepted at a much lower rate than asked (ConfirmEventRequest's confirmed rate): poll instead.
            if (s.type == EventType::Periodic && m->rateHz + 1e-6 < s.rateHz * 0.5) {
                m_ctx.send(s.target, encode(CancelEvent{s.requestId, s.eventId}));
                s.state = SubscriptionState::Polling;
                m_ctx.counters().add("events.fallback.rate");
            } else {
                s.state = SubscriptionState::Active;
            }
        }
    }
}

void EventsClient::onReject(RemoteSubsystem& r, const JausId& src, ByteSpan p) {
    auto m = decodeRejectEventRequest(p);
    if (!m)
        return m_ctx.rejected(src, m.error());
    auto it = m_subs.find(r.id());
    if (it == m_subs.end())
        return;
    for (auto& [k, s] : it->second)
        if (s.state == SubscriptionState::Pending && s.requestId == m->requestId) {
            s.state = SubscriptionState::Polling;
            m_ctx.counters().add("events.fallback.rejected");
        }
}

void EventsClient::onEvent(RemoteSubsystem& r, const JausId& src, ByteSpan p) {
    auto m = decodeEvent(p);
    if (!m)
        return m_ctx.rejected(src, m.error());
    const std::uint16_t inner = peekMessageId(m->reportMessage);
    if (inner == msg::Event)
        return m_ctx.rejected(src, "nested: Event wraps an Event");
    if (!m_table || !m_table->dispatch(r, src, inner, m->reportMessage))
        m_ctx.counters().add("rx.unhandled");
}

} // namespace ocu::jaus
