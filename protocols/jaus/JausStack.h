#pragma once
// The OCU side of JAUS: JausCore (client services) + JudpTransport on its own io thread.
// Command methods are thread-safe (they post to the io thread); listener callbacks run on the io thread.
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "protocols/common/Clock.h"
#include "protocols/common/CommandOutcome.h"
#include "protocols/common/Counters.h"
#include "protocols/jaus/JausConfig.h"
#include "protocols/jaus/JausTypes.h"

namespace ocu {
class MessageTap;
}

namespace ocu::jaus {

class JausStack {
public:
    JausStack(JausConfig config, JausListener& listener, ocu::Clock& clock = SteadyClock::instance());
    ~JausStack(); // stop()
    JausStack(const JausStack&) = delete;
    JausStack& operator=(const JausStack&) = delete;

    // The flight recorder: every message the transport delivers (and, when the tap wants them, every raw
    // datagram and JTCP read) goes to `tap` on the io thread. Set before start(); the tap outlives the
    // stack's run.
    void setMessageTap(MessageTap* tap);
    // Opens the sockets and starts the io thread; throws std::runtime_error when a socket cannot be opened.
    void start();
    // Releases all control (zero drive commands first), then stops the io thread. Safe to call twice.
    void stop();
    bool running() const;

    void releaseAll();
    void discoverNow();

    // The commands, each with its outcome: `done` runs once on the io thread with one TargetOutcome per
    // subsystem addressed (sent, or the reason it was refused). If the stack is not running, `done` never
    // runs: the caller's deadline decides. An empty `done` keeps no result (the drive stream, whose
    // failures are events of their own); there is no second way to send the same command.
    void requestControl(std::uint16_t subsystem, OutcomeCallback done);
    void releaseControl(std::uint16_t subsystem, OutcomeCallback done);
    void setEmergency(std::uint16_t subsystem, EmergencyCode code, OutcomeCallback done);
    void clearEmergency(std::uint16_t subsystem, OutcomeCallback done);
    void resume(std::uint16_t subsystem, OutcomeCallback done);
    void standby(std::uint16_t subsystem, OutcomeCallback done);
    void shutdown(std::uint16_t subsystem, OutcomeCallback done);
    void reset(std::uint16_t subsystem, OutcomeCallback done);
    // STOP ALL: SetEmergency to every discovered subsystem (controlled by this console or not).
    // setEmergency and setEmergencyAll send from the calling thread at once where the io thread planned the
    // datagram (UDP, known address: JudpTransport::plan, refreshed every 10 ms), the rest on the io thread;
    // `done` still runs on the io thread, once the core has learnt what was sent.
    void setEmergencyAll(EmergencyCode code, OutcomeCallback done);
    // The drive session with its outcome: sent when the socket took the session's first (zero) demand, the
    // demand itself (or, unchanged, the stream's latest message), the first of the zero commands.
    void startDriving(std::uint16_t subsystem, OutcomeCallback done);
    void setDriveCommand(std::uint16_t subsystem, DriveCommand command, OutcomeCallback done);
    void stopDriving(std::uint16_t subsystem, OutcomeCallback done);
    // Pan-tilt rates (rad/s, + pan right, + tilt up; zero stops) for the camera `sensorId`; needs
    // control of the vehicle. `done` says whether SetPanTiltJointVelocity went out (or why not).
    void panTilt(std::uint16_t subsystem, std::uint16_t sensorId, double panRate, double tiltRate,
                 OutcomeCallback done);

    // Waypoint missions (MissionClient): `done` says whether the first message of the step went out (or why
    // not); the mission's progress is SubsystemSnapshot::mission, from the vehicle's reports.
    // global: the GlobalWaypointListDriver (true), the local one (false), global where offered (empty).
    void missionUpload(std::uint16_t subsystem, std::vector<MissionPoint> points, std::optional<bool> global,
                       OutcomeCallback done);
    void missionStart(std::uint16_t subsystem, int fromIndex, OutcomeCallback done);
    void missionPause(std::uint16_t subsystem, OutcomeCallback done);
    void missionResume(std::uint16_t subsystem, OutcomeCallback done);
    void missionAbort(std::uint16_t subsystem, OutcomeCallback done);
    void goTo(std::uint16_t subsystem, MissionPoint point, OutcomeCallback done);
    // Platform services (PlatformClient): `done` says whether the Set went out, or waits for control just
    // requested (or why not); what the vehicle then reports is SubsystemSnapshot::platformServices.
    void setPlatformMode(std::uint16_t subsystem, std::uint8_t mode, OutcomeCallback done);
    void setPlatformState(std::uint16_t subsystem, std::uint8_t state, OutcomeCallback done);
    // The lights in `mask` switched to their bits in `on` (light:: bits of MessagesPlatformServices.h).
    void setLights(std::uint16_t subsystem, std::uint32_t mask, std::uint32_t on, OutcomeCallback done);
    void resetTripOdometer(std::uint16_t subsystem, OutcomeCallback done);
    void queryOdometry(std::uint16_t subsystem, OutcomeCallback done);

    // Hand-off between consoles (HandoffClient, AEP-4818 §6.3): `done` says whether RequestHandoff (or, for
    // a vehicle without Enhanced Access Control, RequestControl), RemoveHandoffRequest or
    // ConfirmReleaseControl went out; what followed is SubsystemSnapshot::handoff and HandoffChanged events.
    void handoffRequest(std::uint16_t subsystem, std::string reason, OutcomeCallback done);
    void handoffCancel(std::uint16_t subsystem, OutcomeCallback done);
    void handoffAnswer(std::uint16_t subsystem, std::uint8_t requestId, bool accept, OutcomeCallback done);
    // WAIT to a forwarded request: it stays queued and its decision time starts again.
    void handoffWait(std::uint16_t subsystem, std::uint8_t requestId, OutcomeCallback done);

    // Subsystems whose SetEmergency is planned for the caller's-thread fast path now (tests, diagnostics).
    std::size_t plannedStopCount() const;

    // Fault injection on what the OCU sends (e.g. loss = 1: the OCU falls silent). Tests and ocu-sim drills.
    void setTransmitFaults(double loss, int delayMs = 0);

    Counters& counters();
    // Watchdog: how long the io thread has not turned (0 while it turns or is not running).
    std::chrono::milliseconds ioStalledFor() const;
    // Runs f on the io thread without waiting (diagnostics; tests block the thread with it on purpose).
    void postToIo(std::function<void()> f);
    const JausConfig& config() const;
    // The UDP port actually bound (useful with port 0). 0 before start().
    std::uint16_t localPort() const;
    // Why the stack runs without its group socket since the last start() (the group's port held by another
    // process without SO_REUSEADDR, the group not joinable), or nullopt when it has one. Said once at start:
    // a log warning and a Warning TransportError event. Any thread.
    std::optional<GroupSocketProblem> groupSocketProblem() const;
    // Blocking reads through the io thread (tests, start-up); not for the GUI's hot paths.
    std::optional<SubsystemSnapshot> snapshot(std::uint16_t subsystem) const;
    std::vector<std::uint16_t> subsystems() const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace ocu::jaus
