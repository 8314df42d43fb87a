#pragma once
// Liveness (AS5710A Liveness, AEP-4818 §4.8 and §9 item 9): every message from a subsystem refreshes its
// link; the link is degraded after 2.5 heartbeat periods (at most half of link_lost_s) and down after
// link_lost_s of silence (events LinkLost / LinkRestored). A periodic ReportHeartbeatPulse event from the
// platform manager keeps a quiet vehicle talking. As a subsystem the console answers QueryHeartbeatPulse.
// (A received ReportHeartbeatPulse refreshes the link like any message; the DiscoveryClient handles its
// content: a heartbeat from a subsystem not yet identified.)
#include <cstdint>
#include <map>

#include "protocols/jaus/clients/ClientService.h"

namespace ocu::jaus {

class EventsClient;

class LivenessClient : public ClientService {
public:
    LivenessClient(ClientContext& context, EventsClient& events) : ClientService(context), m_events(events) {}

    void registerMessages(MessageTable& table) override;
    void onServicesKnown(RemoteSubsystem& remote) override;
    // Up / degraded / down from the time since the last message; runs before discovery each tick.
    void tick(RemoteSubsystem& remote, TimePoint now) override;
    void forget(std::uint16_t subsystem) override {
        m_lastHeard.erase(subsystem);
        m_lastProbe.erase(subsystem);
    }

    // Any message from the subsystem (firstContact: its record was just created). Returns true when the link
    // was down and is back: JausCore then tells every client (onLinkRestored).
    bool heard(RemoteSubsystem& remote, bool firstContact);

private:
    EventsClient& m_events;
    std::map<std::uint16_t, TimePoint> m_lastHeard;
    std::map<std::uint16_t, TimePoint> m_lastProbe; // link-down probes
};

} // namespace ocu::jaus
