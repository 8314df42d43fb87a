#pragma once
// Pose and velocity (AS6009 GlobalPoseSensor, LocalPoseSensor, VelocityStateSensor): periodic events at
// pose_rate_hz from the sensors discovery found (all presence-vector bits asked for), the latest report of
// each kept in the snapshot.
#include "protocols/jaus/clients/ClientService.h"

namespace ocu::jaus {

class EventsClient;

class PoseClient : public ClientService {
public:
    PoseClient(ClientContext& context, EventsClient& events) : ClientService(context), m_events(events) {}

    void registerMessages(MessageTable& table) override;
    void onServicesKnown(RemoteSubsystem& remote) override;

private:
    EventsClient& m_events;
};

} // namespace ocu::jaus
