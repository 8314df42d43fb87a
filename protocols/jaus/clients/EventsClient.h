#pragma once
// Events (AS5710A): asks each vehicle for its reports as events (CreateEvent, periodic or on change) and
// falls back to polling the query at the requested rate when the request is rejected, not confirmed within
// event_confirm_timeout_s, or confirmed below half the requested rate (counters events.fallback.*). Unwraps
// Event messages and hands the report inside to the client that handles it. Events are re-created when a
// link comes back. As a subsystem the console serves no events: a CreateEvent sent to it is rejected.
#include <cstdint>
#include <map>
#include <optional>

#include "protocols/jaus/Messages.h"
#include "protocols/jaus/clients/ClientService.h"

namespace ocu::jaus {

class EventsClient : public ClientService {
public:
    enum class SubscriptionState { None, Pending, Active, Polling };

    explicit EventsClient(ClientContext& context) : ClientService(context) {}

    void registerMessages(MessageTable& table) override;
    void onLinkRestored(RemoteSubsystem& remote) override;
    void tick(RemoteSubsystem& remote, TimePoint now) override;
    void forget(std::uint16_t subsystem) override { m_subs.erase(subsystem); }

    // Asks target for the report of query (a whole query message, ID first): periodically at rateHz, or on
    // every change with polling at rateHz as the fallback. One subscription per query message ID.
    void subscribe(RemoteSubsystem& remote, const JausId& target, Bytes query, double rateHz,
                   EventType type = EventType::Periodic);
    std::optional<SubscriptionState> state(std::uint16_t subsystem, std::uint16_t queryId) const;

private:
    struct Subscription {
        JausId target;
        Bytes query;
        double rateHz = 1; // periodic rate, or the polling rate of an on-change event's fallback
        EventType type = EventType::Periodic;
        SubscriptionState state = SubscriptionState::None;
        std::uint8_t requestId = 0;
        std::uint8_t eventId = 0;
        TimePoint sent{};
        TimePoint lastPoll{};
    };
    using Subscriptions = std::map<std::uint16_t, Subscription>; // by query message ID

    void onConfirm(RemoteSubsystem& remote, const JausId& source, ByteSpan payload);
    void onReject(RemoteSubsystem& remote, const JausId& source, ByteSpan payload);
    void onEvent(RemoteSubsystem& remote, const JausId& source, ByteSpan payload);

    const MessageTable* m_table = nullptr; // where the report inside an Event goes
    std::map<std::uint16_t, Subscriptions> m_subs;
    std::uint8_t m_nextRequestId = 1; // one sequence for every vehicle, never 0
};

} // namespace ocu::jaus
