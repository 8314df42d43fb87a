#pragma once
// Management (AS5710A Management, AEP-4818 §4.2 and §4.5): the vehicle's management state (on-change event
// on QueryStatus, polled at status_poll_hz too), Resume / Standby / Shutdown / Reset (need our control), and
// the emergency stop: SetEmergency at safety priority, repeated every 200 ms (up to 5 times) until
// ReportStatus shows EMERGENCY, allowed for every role; ClearEmergency with the same code, not for the
// monitor.
#include <cstdint>
#include <functional>
#include <map>
#include <optional>

#include "protocols/jaus/Messages.h"
#include "protocols/jaus/clients/ClientService.h"

namespace ocu::jaus {

class DriveClient;
class EventsClient;

class ManagementClient : public ClientService {
public:
    // An emergency ends the drive session.
    ManagementClient(ClientContext& context, EventsClient& events, DriveClient& drive)
        : ClientService(context), m_events(events), m_drive(drive) {}

    void registerMessages(MessageTable& table) override;
    void onServicesKnown(RemoteSubsystem& remote) override;
    void tick(RemoteSubsystem& remote, TimePoint now) override;
    void forget(std::uint16_t subsystem) override { m_state.erase(subsystem); }

    // Commands; each returns false and emits CommandRefused when not allowed.
    // id: msg::Resume, Standby, Shutdown or Reset; what names it in the refusal.
    bool command(std::uint16_t subsystem, std::uint16_t id, const char* what);
    // alreadySent: the SetEmergency left on the caller's thread (JausStack's STOP ALL fast path); the state
    // machine learns it (retries, drive session, status query) exactly as if it had sent it itself.
    bool setEmergency(std::uint16_t subsystem, EmergencyCode code = EmergencyCode::Safety,
                      bool alreadySent = false);
    // STOP ALL to a subsystem configured as a static endpoint and never heard: SetEmergency
    // to all of its components (ss.255.255) at the configured address. True when the socket took it.
    bool setEmergencyUnheard(std::uint16_t subsystem, EmergencyCode code = EmergencyCode::Safety);
    // Where setEmergency would send SetEmergency now (nullopt: it would refuse). No side effects.
    std::optional<JausId> emergencyTarget(std::uint16_t subsystem) const;
    bool clearEmergency(std::uint16_t subsystem);
    // ReportStatus from a component another client follows (a list driver on a component of its own): the
    // filter returns true when it handled the message, which then is not the vehicle's Management state.
    using OtherStatus = std::function<bool(RemoteSubsystem&, const JausId&, ByteSpan)>;
    void setOtherStatus(OtherStatus filter) { m_other = std::move(filter); }

private:
    struct State {
        int emergencyRetries = 0;
        TimePoint lastEmergencySent{};
        EmergencyCode emergencyCode = EmergencyCode::Safety;
        TimePoint lastStatusPoll{};
    };
    void onStatus(RemoteSubsystem& remote, const JausId& source, ByteSpan payload);
    bool sendEmergency(const JausId& target, EmergencyCode code);

    EventsClient& m_events;
    DriveClient& m_drive;
    OtherStatus m_other;
    std::map<std::uint16_t, State> m_state;
};

} // namespace ocu::jaus
