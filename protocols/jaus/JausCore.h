#pragma once
// The OCU's JAUS client services as one state machine without sockets: discovery, liveness, access control,
// management, events, driving, pose/velocity/platform/health (AEP-4818 §9). Messages enter via handle(),
// time via tick(); messages leave through JausOutput. JausStack drives it from its io thread; tests drive
// it with a FakeClock.
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>

#include "protocols/common/Clock.h"
#include "protocols/common/Counters.h"
#include "protocols/jaus/JausConfig.h"
#include "protocols/jaus/JausOutput.h"
#include "protocols/jaus/JausTypes.h"
#include "protocols/jaus/Messages.h"

namespace ocu::jaus {

class JausCore {
public:
    JausCore(JausConfig config, JausListener& listener, JausOutput& output, const Clock& clock,
             Counters& counters);

    // One received (reassembled) message.
    void handle(const JausId& source, const JausId& destination, ByteSpan payload);
    // Timers: call often (the stack uses 10 ms).
    void tick();

    // Commands (io thread). Each returns false and emits CommandRefused when not allowed.
    bool requestControl(std::uint16_t subsystem);
    bool releaseControl(std::uint16_t subsystem);
    void releaseAll();
    bool setEmergency(std::uint16_t subsystem, EmergencyCode code = EmergencyCode::Safety);
    bool clearEmergency(std::uint16_t subsystem);
    bool resume(std::uint16_t subsystem) { return management(subsystem, msg::Resume, "resume"); }
    bool standby(std::uint16_t subsystem) { return management(subsystem, msg::Standby, "standby"); }
    bool shutdown(std::uint16_t subsystem) { return management(subsystem, msg::Shutdown, "shutdown"); }
    bool reset(std::uint16_t subsystem) { return management(subsystem, msg::Reset, "reset"); }
    bool startDriving(std::uint16_t subsystem);
    bool setDriveCommand(std::uint16_t subsystem, DriveCommand command);
    bool stopDriving(std::uint16_t subsystem);
    // Starts discovery now (also done on the first tick).
    void discoverNow();

    const JausConfig& config() const { return m_cfg; }
    std::optional<SubsystemSnapshot> snapshot(std::uint16_t subsystem) const;
    std::vector<std::uint16_t> subsystems() const;
    // True while any drive stream (including the zero tail after a stop) is pending.
    bool anyDriveActive() const;

private:
    enum class SubState { None, Pending, Active, Polling };
    struct Subscription {
        std::uint16_t queryId = 0;
        JausId target;
        Bytes query;
        double rateHz = 1; // periodic rate, or the polling rate of an on-change event's fallback
        EventType type = EventType::Periodic;
        SubState state = SubState::None;
        std::uint8_t requestId = 0;
        std::uint8_t eventId = 0;
        TimePoint sent{};
        TimePoint lastPoll{};
    };
    struct Remote {
        SubsystemSnapshot snap;
        JausId platformManager;
        JausId globalPoseSensor, localPoseSensor, velocitySensor, healthMonitor, platformSpecs;
        bool servicesKnown = false;
        bool discoveredEvent = false;
        TimePoint lastHeard{};
        TimePoint lastIdentQuery{}, lastServicesQuery{}, lastSpecsQuery{}, lastStatusPoll{}, lastHealthPoll{};
        TimePoint lastRecheck{};
        std::map<std::uint16_t, Subscription> subs; // by query message ID
        // access control
        bool wantControl = false;
        bool releasing = false;
        bool classifyLoss = false;
        TimePoint classifyDeadline{};
        TimePoint lastRequest{}, lastConfirm{};
        bool timeoutQueried = false;
        // emergency
        int emergencyRetries = 0;
        TimePoint lastEmergencySent{};
        EmergencyCode emergencyCode = EmergencyCode::Safety;
        // driving
        bool driveActive = false;
        int stopRepeatsLeft = 0;
        DriveCommand drive;
        TimePoint lastDriveSent{};
        TimePoint lastDriveUpdate{}; // last setDriveCommand (drive command watchdog)
        bool driveStale = false;
    };

    void send(const JausId& dst, const Bytes& payload, SendOptions o = {});
    void notify(Severity s, EventKind k, std::uint16_t ss, std::string text);
    void changed(Remote& r);
    Remote& remote(std::uint16_t ss);
    Remote* find(std::uint16_t ss);
    bool refuse(std::uint16_t ss, const std::string& why);
    bool management(std::uint16_t ss, std::uint16_t id, const char* what);

    void answerOwn(const JausId& src, std::uint16_t id, ByteSpan payload);
    void handleReport(Remote& r, const JausId& src, std::uint16_t id, ByteSpan payload);
    void onServices(Remote& r, const JausId& src, const std::vector<NodeServices>& nodes);
    void onControlLost(Remote& r, const std::string& why);
    void classify(Remote& r, const ReportControl& rc);
    void subscribe(Remote& r, const JausId& target, std::uint16_t queryId, Bytes query, double rateHz,
                   EventType type = EventType::Periodic);
    void tickRemote(Remote& r, TimePoint now);
    void sendDrive(Remote& r, bool zero);
    Duration reRequestPeriod(const Remote& r) const;

    JausConfig m_cfg;
    JausListener& m_listener;
    JausOutput& m_out;
    const Clock& m_clock;
    Counters& m_counters;
    JausId m_self;
    std::map<std::uint16_t, Remote> m_remotes;
    std::set<std::uint16_t> m_otherOcus; // subsystems that identified as OCU
    TimePoint m_lastDiscovery{};
    bool m_started = false;
    std::uint8_t m_nextRequestId = 1;
};

} // namespace ocu::jaus
