#pragma once
// The IOP platform services an operator works besides driving (AEP-4818 §6.2.5, §6.2.6, §9.2.2, §5.7, §8.8;
// wire facts in shared/research/jaus-autonomy.md §6, §7, §9):
//  * each service is found by its name in any namespace (iop:PlatformMode, iop:PlatformState,
//    ugv:IlluminationService, ugv:OdometryService) and its version kept; a CommsLostPolicyManager is only
//    detected and shown, because no public layout of its messages exists (§6.1);
//  * mode, state and lights as on-change events where the vehicle offers them, polled at status_poll_hz
//    otherwise; the odometer (PLATFORM and TRIP_A) polled at 1 Hz; the supported modes and lights asked for
//    until answered;
//  * every Set needs control of the component offering the service (each inherits AccessControl): on the
//    component the console controls for the vehicle the vehicle's control is used (requested as the mission
//    client does); a component of its own gets its own RequestControl, kept while commands follow and
//    released 3 s after the last one. A command waits at most 5 s for control; then the operator is told;
//  * no confirmation exists for mode, lights and odometry: the Set is followed by its query, and the
//    snapshot shows what the vehicle reports, never what was asked;
//  * the lights an operator may switch are light::kOperatorSwitchable; VisibleLightSource is never changed
//    (AEP-4818 §9.2.2 forbids it for the whole vehicle).
// Results go to SubsystemSnapshot::platformServices.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "protocols/jaus/MessagesPlatformServices.h"
#include "protocols/jaus/clients/ClientService.h"

namespace ocu::jaus {

class AccessControlClient;
class EventsClient;

class PlatformClient : public ClientService {
public:
    PlatformClient(ClientContext& context, EventsClient& events, AccessControlClient& access)
        : ClientService(context), m_events(events), m_access(access) {}

    void registerMessages(MessageTable& table) override;
    void onServicesKnown(RemoteSubsystem& remote) override;
    void tick(RemoteSubsystem& remote, TimePoint now) override;
    void forget(std::uint16_t subsystem) override { m_state.erase(subsystem); }

    // Commands; each returns false with the reason (ClientContext::refuse) when nothing went out. True when
    // the Set went out, or when it waits for control that was just requested.
    bool setMode(std::uint16_t subsystem, std::uint8_t mode);
    bool setState(std::uint16_t subsystem, std::uint8_t state);
    // The lights in `mask` are switched to their bits in `on`; the others keep what the vehicle reports.
    bool setLights(std::uint16_t subsystem, std::uint32_t mask, std::uint32_t on);
    bool resetTrip(std::uint16_t subsystem);     // ResetOdometry(TRIP_A)
    bool queryOdometry(std::uint16_t subsystem); // both odometers now (needs no control)

    // The vehicle reports the Emergency platform state: drive and mission commands are refused until it
    // leaves it (AEP-4818 §6.2.6). refuseInEmergency refuses `what` with the reason when it does.
    bool emergencyState(std::uint16_t subsystem) const;
    bool refuseInEmergency(std::uint16_t subsystem, const char* what, bool quietly = false);

    // ConfirmControl / RejectControl from a component this client controls itself.
    bool handleControlMessage(RemoteSubsystem& remote, const JausId& source, std::uint16_t id,
                              ByteSpan payload);

private:
    enum class Service { Mode, State, Illumination, Odometry };
    enum class OwnControl { None, Requested, Controlled };
    struct Control {
        OwnControl phase = OwnControl::None;
        TimePoint lastRequest{}, lastConfirm{}, lastUse{};
    };
    struct Pending {
        JausId target;
        Bytes payload, readBack;
        std::string what;
        TimePoint queued{};
    };
    struct State {
        JausId mode, state, illumination, odometry; // zero where not offered
        std::map<std::uint32_t, Control> own;       // by component (JausId::value)
        std::vector<Pending> pending;
        TimePoint lastOdometryPoll{}, lastCapabilityQuery{};
    };

    JausId& componentOf(State& state, Service service);
    bool command(std::uint16_t subsystem, Service service, Bytes payload, Bytes readBack, std::string what);
    bool ready(const RemoteSubsystem& remote, State& state, const JausId& target);
    void sendNow(RemoteSubsystem& remote, State& state, const Pending& pending);
    void tickControl(RemoteSubsystem& remote, State& state, TimePoint now);
    void tickPending(RemoteSubsystem& remote, State& state, TimePoint now);
    void tickQueries(RemoteSubsystem& remote, State& state, TimePoint now);
    void onConfirmState(RemoteSubsystem& remote, const JausId& source, ByteSpan payload);
    void onOdometry(RemoteSubsystem& remote, const JausId& source, ByteSpan payload);

    EventsClient& m_events;
    AccessControlClient& m_access;
    std::map<std::uint16_t, State> m_state;
};

} // namespace ocu::jaus
