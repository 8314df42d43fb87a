#pragma once
// Video and pan-tilt of a vehicle (AEP-4818 §9.1.2-9.1.8, §9.3.3; procedure in
// shared/research/jaus-services-extra.md §2.3):
//  * Digital Resource Discovery: QueryDigitalResourceEndpoint to the component offering
//    urn:jaus:jss:iop:DigitalResourceDiscovery every second until a report arrives (FKIE servers stay silent
//    for their first 5 s), then every 10 s; RTSP entries become VideoEndpoints (ResourceID = SensorID).
//  * Visual Sensor: QueryVisualSensorCapabilities (SensorID 0 = all, PV 0xFFFF) to each endpoint's host
//    component for the camera names, QuerySensorGeometricProperties for the pan-tilt a camera sits on
//    (V1.JAUS-57). A host without a Visual Sensor service is not asked: its endpoints stay unnamed.
//  * Configured endpoints (JausConfig::configuredVideo) are published beside the announced ones.
//  * Pan-tilt: while this console controls the vehicle it also holds control of each pan-tilt component
//    (the pan-tilt drivers inherit Management, so they have their own access control), resumes it, and
//    streams SetPanTiltJointVelocity at 10 Hz while a non-zero demand is refreshed (zero when it goes stale,
//    within the actuator drive timeout, §9.3.1.2); ReportPanTiltJointPositions is polled (5 Hz while moving,
//    1 Hz otherwise).
// Results go to SubsystemSnapshot::videoEndpoints and ::panTilts.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "protocols/jaus/Messages.h"
#include "protocols/jaus/MessagesVideo.h"
#include "protocols/jaus/clients/ClientService.h"

namespace ocu::jaus {

class VideoClient : public ClientService {
public:
    explicit VideoClient(ClientContext& context) : ClientService(context) {}

    void registerMessages(MessageTable& table) override;
    void onServicesKnown(RemoteSubsystem& remote) override;
    void onLinkRestored(RemoteSubsystem& remote) override;
    void tick(RemoteSubsystem& remote, TimePoint now) override;
    void forget(std::uint16_t subsystem) override { m_state.erase(subsystem); }
    // Every tick for every subsystem heard (services known or not): configured endpoints are published even
    // for a vehicle that reports nothing.
    void heard(RemoteSubsystem& remote);

    // Pan-tilt rates for the camera `sensorId` (rad/s, + pan = right, + tilt = up; zero = stop). Needs
    // control of the vehicle (as for driving) and a confirmed control of the camera's pan-tilt component.
    // True when the demand went on the wire (or, unchanged, is being streamed); false with the reason.
    bool panTilt(std::uint16_t subsystem, std::uint16_t sensorId, double panRate, double tiltRate);

    // ConfirmControl / RejectControl from a pan-tilt component this client controls: handled here (true),
    // not by the vehicle's access control. JausCore routes them through AccessControlClient's hook.
    bool handleControlMessage(RemoteSubsystem& remote, const JausId& source, std::uint16_t id,
                              ByteSpan payload);

private:
    // Our control of a pan-tilt component (AS5710A AccessControl, client side).
    enum class PanTiltControl {
        None,      // not requested (or given up, refused, lost)
        Requested, // RequestControl sent, no ConfirmControl(accepted) yet
        Controlled // accepted: re-requested within its timeout, velocities streamed
    };
    struct PanTilt {
        JausId component;
        PanTiltControl control = PanTiltControl::None;
        TimePoint lastRequest{}, lastPoll{}, lastSent{}, lastDemand{}, refusedUntil{};
        double pan = 0, tilt = 0; // current demand (rad/s)
        int zerosLeft = 0;
        PanTiltState report;
    };
    struct State {
        bool located = false;
        JausId drd; // component offering DigitalResourceDiscovery, zero when none
        std::vector<JausId> visualSensors;
        bool drdAnswered = false;   // a report with endpoints arrived, or the first one 30 s ago
        TimePoint firstDrdReport{}; // the first report (possibly empty: cameras register later)
        TimePoint lastDrdQuery{}, lastLocate{};
        std::vector<DigitalResourceEndpoint> endpoints;
        std::map<std::uint32_t, TimePoint> lastNameQuery; // host component -> last capabilities query
        std::map<std::pair<std::uint32_t, std::uint16_t>, std::string> names;
        std::map<std::pair<std::uint32_t, std::uint16_t>, JausId> mounts; // camera -> pan-tilt component
        std::map<std::uint32_t, bool> geometryAnswered, capsAnswered;
        std::vector<PanTilt> panTilts;
        bool published = false;
        std::string lastRefusal;
        TimePoint lastRefusalAt{};
    };

    void locate(RemoteSubsystem& remote, State& state);
    JausId hostOf(const State& state, const DigitalResourceEndpoint& endpoint) const;
    void publish(RemoteSubsystem& remote, State& state);
    void tickPanTilt(RemoteSubsystem& remote, PanTilt& unit, TimePoint now);
    PanTilt* unitFor(State& state, const JausId& component);
    // A pan-tilt refusal: an event the first time, then quietly while the same reason repeats within 2 s
    // (the command comes at the rate of a held key).
    bool refusePanTilt(std::uint16_t subsystem, const std::string& why);

    std::map<std::uint16_t, State> m_state;
};

} // namespace ocu::jaus
