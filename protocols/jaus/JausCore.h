#pragma once
// The OCU's JAUS client services as one state machine without sockets (AEP-4818 §9): one client per JAUS
// service (clients/: discovery, liveness, events, access control, management, driving, pose, platform
// specifications, health, video, missions, platform mode/state with lights and odometry), composed here
// behind a dispatch table keyed by message ID. Messages enter via handle(), time via tick(); messages leave
// through JausOutput. JausStack drives it from its io thread; tests drive it with a FakeClock.
#include <cstdint>
#include <optional>
#include <vector>

#include "protocols/common/Clock.h"
#include "protocols/common/CommandOutcome.h"
#include "protocols/common/Counters.h"
#include "protocols/jaus/JausConfig.h"
#include "protocols/jaus/JausOutput.h"
#include "protocols/jaus/JausTypes.h"
#include "protocols/jaus/Messages.h"
#include "protocols/jaus/clients/AccessControlClient.h"
#include "protocols/jaus/clients/ClientContext.h"
#include "protocols/jaus/clients/DiscoveryClient.h"
#include "protocols/jaus/clients/DriveClient.h"
#include "protocols/jaus/clients/EventsClient.h"
#include "protocols/jaus/clients/HandoffClient.h"
#include "protocols/jaus/clients/HealthMonitorClient.h"
#include "protocols/jaus/clients/LivenessClient.h"
#include "protocols/jaus/clients/ManagementClient.h"
#include "protocols/jaus/clients/MessageTable.h"
#include "protocols/jaus/clients/MissionClient.h"
#include "protocols/jaus/clients/PlatformClient.h"
#include "protocols/jaus/clients/PlatformSpecificationsClient.h"
#include "protocols/jaus/clients/PoseClient.h"
#include "protocols/jaus/clients/VideoClient.h"

namespace ocu::jaus {

class JausCore {
public:
    JausCore(JausConfig config, JausListener& listener, JausOutput& output, const Clock& clock,
             Counters& counters);
    JausCore(const JausCore&) = delete;
    JausCore& operator=(const JausCore&) = delete;

    // One received (reassembled) message.
    void handle(const JausId& source, const JausId& destination, ByteSpan payload);
    // Timers: call often (the stack uses 10 ms).
    void tick();

    // Commands (io thread). Each returns false and emits CommandRefused when not allowed.
    bool requestControl(std::uint16_t subsystem) { return m_access.requestControl(subsystem); }
    bool releaseControl(std::uint16_t subsystem) { return m_access.releaseControl(subsystem); }
    void releaseAll() { m_access.releaseAll(); }
    bool setEmergency(std::uint16_t subsystem, EmergencyCode code = EmergencyCode::Safety) {
        return m_management.setEmergency(subsystem, code);
    }
    bool clearEmergency(std::uint16_t subsystem) { return m_management.clearEmergency(subsystem); }
    bool resume(std::uint16_t subsystem) { return m_management.command(subsystem, msg::Resume, "resume"); }
    bool standby(std::uint16_t subsystem) { return m_management.command(subsystem, msg::Standby, "standby"); }
    bool shutdown(std::uint16_t subsystem) {
        return m_management.command(subsystem, msg::Shutdown, "shutdown");
    }
    bool reset(std::uint16_t subsystem) { return m_management.command(subsystem, msg::Reset, "reset"); }
    // Drive and mission commands are refused while the vehicle reports the emergency platform state.
    bool startDriving(std::uint16_t subsystem) {
        return !m_platformServices.refuseInEmergency(subsystem, "driving") && m_drive.startDriving(subsystem);
    }
    bool setDriveCommand(std::uint16_t subsystem, DriveCommand command) {
        return !m_platformServices.refuseInEmergency(subsystem, "driving", true) &&
               m_drive.setDriveCommand(subsystem, command);
    }
    bool stopDriving(std::uint16_t subsystem) { return m_drive.stopDriving(subsystem); }
    // Pan-tilt rates (rad/s) for a camera of the subsystem; zero stops (VideoClient).
    bool panTilt(std::uint16_t subsystem, std::uint16_t sensorId, double panRate, double tiltRate) {
        return m_video.panTilt(subsystem, sensorId, panRate, tiltRate);
    }
    // Waypoint missions (MissionClient): each returns false with the reason when nothing went out.
    bool missionUpload(std::uint16_t subsystem, const std::vector<MissionPoint>& points,
                       std::optional<bool> global) {
        return !m_platformServices.refuseInEmergency(subsystem, "a mission upload") &&
               m_mission.upload(subsystem, points, global);
    }
    bool missionStart(std::uint16_t subsystem, int fromIndex) {
        return !m_platformServices.refuseInEmergency(subsystem, "a mission start") &&
               m_mission.start(subsystem, fromIndex);
    }
    bool missionPause(std::uint16_t subsystem) { return m_mission.pause(subsystem); }
    bool missionResume(std::uint16_t subsystem) {
        return !m_platformServices.refuseInEmergency(subsystem, "a mission resume") &&
               m_mission.resume(subsystem);
    }
    bool missionAbort(std::uint16_t subsystem) { return m_mission.abort(subsystem); }
    bool goTo(std::uint16_t subsystem, const MissionPoint& point) {
        return !m_platformServices.refuseInEmergency(subsystem, "a go-to") &&
               m_mission.goTo(subsystem, point);
    }
    // Platform mode and state, lights, odometry (PlatformClient): false with the reason when nothing went
    // out.
    bool setPlatformMode(std::uint16_t subsystem, std::uint8_t mode) {
        return m_platformServices.setMode(subsystem, mode);
    }
    bool setPlatformState(std::uint16_t subsystem, std::uint8_t state) {
        return m_platformServices.setState(subsystem, state);
    }
    bool setLights(std::uint16_t subsystem, std::uint32_t mask, std::uint32_t on) {
        return m_platformServices.setLights(subsystem, mask, on);
    }
    bool resetTripOdometer(std::uint16_t subsystem) { return m_platformServices.resetTrip(subsystem); }
    bool queryOdometry(std::uint16_t subsystem) { return m_platformServices.queryOdometry(subsystem); }
    // Hand-off between consoles (HandoffClient): ask the holder, withdraw, answer a forwarded request.
    bool handoffRequest(std::uint16_t subsystem, const std::string& reason) {
        return m_handoff.request(subsystem, reason);
    }
    bool handoffCancel(std::uint16_t subsystem) { return m_handoff.cancel(subsystem); }
    bool handoffAnswer(std::uint16_t subsystem, std::uint8_t id, bool accept) {
        return m_handoff.answer(subsystem, id, accept ? ReleaseCode::Granted : ReleaseCode::Denied);
    }
    bool handoffWait(std::uint16_t subsystem, std::uint8_t id) {
        return m_handoff.answer(subsystem, id, ReleaseCode::Wait);
    }
    // STOP ALL: SetEmergency to every discovered subsystem, whether this console controls it
    // or not; one outcome per subsystem.
    // alreadySent: subsystems whose SetEmergency already left on the caller's thread (JausStack's fast path):
    // they count as sent and the state machine learns it; the others are sent now.
    std::vector<TargetOutcome> setEmergencyAll(EmergencyCode code = EmergencyCode::Safety,
                                               const std::vector<std::uint16_t>& alreadySent = {});
    // One subsystem whose SetEmergency already left on the caller's thread: the state machine learns it.
    TargetOutcome emergencySent(std::uint16_t subsystem, EmergencyCode code) {
        return emergencyOutcome(subsystem, m_management.setEmergency(subsystem, code, true));
    }
    // The outcome of a SetEmergency just run: outcome(), noted when it went to every component because the
    // vehicle's services are not known.
    TargetOutcome emergencyOutcome(std::uint16_t subsystem, bool sent) const;
    // Where SetEmergency for this subsystem would go now (nullopt: it would be refused). No side effects.
    std::optional<JausId> emergencyTarget(std::uint16_t subsystem) const {
        return m_management.emergencyTarget(subsystem);
    }
    // The outcome of a command just run for one subsystem: sent, or not sent with the refusal's reason.
    TargetOutcome outcome(std::uint16_t subsystem, bool sent) const;
    static std::string targetId(std::uint16_t subsystem) { return "jaus:" + std::to_string(subsystem); }

    // Starts discovery now (also done on the first tick).
    void discoverNow() { m_discovery.discoverNow(); }

    const JausConfig& config() const { return m_ctx.config(); }
    std::optional<SubsystemSnapshot> snapshot(std::uint16_t subsystem) const;
    std::vector<std::uint16_t> subsystems() const;
    // True while any drive stream (including the zero tail after a stop) is pending.
    bool anyDriveActive() const { return m_drive.anyActive(); }

private:
    void servicesKnown(RemoteSubsystem& remote);
    void forget(std::uint16_t subsystem);

    ClientContext m_ctx;
    MessageTable m_table;
    EventsClient m_events;
    DriveClient m_drive;
    LivenessClient m_liveness;
    DiscoveryClient m_discovery;
    AccessControlClient m_access;
    ManagementClient m_management;
    PoseClient m_pose;
    PlatformSpecificationsClient m_platform;
    HealthMonitorClient m_health;
    VideoClient m_video;
    MissionClient m_mission;
    PlatformClient m_platformServices;
    HandoffClient m_handoff;
    std::vector<ClientService*> m_all;
    // The timers that run once a subsystem's services are known, in this order (liveness and discovery
    // run before them, for every subsystem).
    std::vector<ClientService*> m_afterDiscovery;
};

} // namespace ocu::jaus
