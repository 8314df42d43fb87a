#pragma once
// Waypoint missions (AEP-4818 §8.2; the OCU procedure of shared/research/jaus-autonomy.md §12):
//  * the list driver is found by service name in any namespace (mobility:{Global,Local}WaypointListDriver,
//    ListManager core 1.1 or mobility 1.0 or not listed at all), the single waypoint drivers and the
//    PathReporter (iop or behaviors) the same way;
//  * control first: a driver on the component the console controls for the vehicle uses that control
//    (requested if needed); a driver on a component of its own gets its own RequestControl, and the console
//    then lets go of the drive component while the mission runs, because such a list driver takes control
//    of the vehicle's primitive driver itself (JAUS++'s does, §3.4);
//  * upload: DeleteElement(65535), then SetElement with every element (UIDs 1..N, Prev i-1, Next i+1, the
//    tail's Next 0), split into messages below 1.4 kB where each appended part links to the held tail;
//    ConfirmElementRequest matched by RequestID (0 accepted while one request is outstanding, the JTS
//    example's answer); RejectElementRequest ends the upload with its code;
//  * read-back: QueryElementCount, QueryElementList (as a set), QueryElement for every UID (a
//    ReportElementCount answer, FKIE's, ends the element check); "uploaded" only when the vehicle's list
//    equals ours;
//  * start: Resume until the driver reports Ready, then ExecuteList with the real start UID (never 0) and
//    the waypoint's speed; progress from ReportActiveElement (an on-change event where offered, polled at
//    1 Hz else, 2 Hz while starting), distance to go and ETA from the pose;
//  * pause = Standby; resume = Resume + ExecuteList(active UID); abort = DeleteElement(65535) + Standby
//    (§3.4: the portable set of every public stack); a new waypoint speed = ExecuteList(active UID, speed);
//  * an emergency during a mission shows StoppedByEmergency and nothing restarts it; link down or control
//    lost shows Lost with the last waypoint seen;
//  * the driven path from the PathReporter's historical path where offered, else from the pose trail.
// Results go to SubsystemSnapshot::mission; each phase change is a MissionChanged event.
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "protocols/jaus/Messages.h"
#include "protocols/jaus/MessagesMission.h"
#include "protocols/jaus/MissionTypes.h"
#include "protocols/jaus/clients/ClientService.h"
#include "protocols/jaus/clients/MissionFrame.h"

namespace ocu::jaus {

class AccessControlClient;
class EventsClient;

class MissionClient : public ClientService {
public:
    MissionClient(ClientContext& context, EventsClient& events, AccessControlClient& access)
        : ClientService(context), m_events(events), m_access(access) {}

    void registerMessages(MessageTable& table) override;
    void onServicesKnown(RemoteSubsystem& remote) override;
    void tick(RemoteSubsystem& remote, TimePoint now) override;
    void forget(std::uint16_t subsystem) override { m_state.erase(subsystem); }

    // Commands; each returns false with the reason (ClientContext::refuse) when nothing went out.
    // global: the GlobalWaypointListDriver (true), the local one (false), or global where offered (empty).
    bool upload(std::uint16_t subsystem, const std::vector<MissionPoint>& points, std::optional<bool> global);
    bool start(std::uint16_t subsystem, int fromIndex);
    bool pause(std::uint16_t subsystem);
    bool resume(std::uint16_t subsystem);
    bool abort(std::uint16_t subsystem);
    // One waypoint: the single waypoint driver where offered, else a one-element list started at once.
    bool goTo(std::uint16_t subsystem, const MissionPoint& point);

    // ConfirmControl / RejectControl from a list driver component this client controls itself.
    bool handleControlMessage(RemoteSubsystem& remote, const JausId& source, std::uint16_t id,
                              ByteSpan payload);
    // ReportStatus from such a component (the vehicle's own Management state is the ManagementClient's).
    bool handleStatus(RemoteSubsystem& remote, const JausId& source, ByteSpan payload);

    // The internal steps, exposed for tests.
    enum class Step {
        Idle,      // nothing under way (see the published phase)
        Control,   // waiting for control of the driver
        Clearing,  // DeleteElement(65535) sent, waiting for its answer or 3 s
        Sending,   // SetElement parts, each confirmed before the next
        Verifying, // the read-back
        Readying,  // Resume sent, waiting for Ready
        Starting,  // ExecuteList sent, waiting for an active element
        Running,
        Pausing, // Standby sent
        Paused,
        Aborting, // DeleteElement(65535) + Standby sent
    };
    std::optional<Step> step(std::uint16_t subsystem) const;

private:
    enum class OwnControl { None, Requested, Controlled };
    enum class Verify { Count, List, Elements };
    enum class Goal { Upload, Start, Resume, GoTo };
    struct Drivers {
        bool located = false;
        JausId localList, globalList, localSingle, globalSingle, pathReporter;
    };
    struct State {
        Drivers drivers;
        MissionStatus status;
        Step step = Step::Idle;
        Goal goal = Goal::Upload;
        TimePoint since{}, lastSent{};
        int tries = 0;
        // control of a driver on a component of its own
        OwnControl control = OwnControl::None;
        TimePoint lastControlRequest{}, lastControlConfirm{};
        std::optional<ManagementState> driverStatus; // that component's ReportStatus
        // upload
        std::optional<MissionFrame> frame; // local missions
        std::vector<ListElement> elements;
        std::size_t sentUpTo = 0, partEnd = 0;
        std::uint8_t requestId = 0;
        bool verified = false;
        // read-back
        Verify verify = Verify::Count;
        std::set<std::uint16_t> pendingElements;
        std::size_t nextElement = 0;
        // execution
        int startIndex = 0;
        std::uint16_t active = 0;
        double speed = 0;
        bool startAfterUpload = false;
        TimePoint lastActiveQuery{};
        // path reporter
        bool pathCapsKnown = false;
        std::optional<std::uint8_t> pathType;
        TimePoint lastPathQuery{};
    };

    static std::string waypointWord(int index, std::size_t n); // "waypoint 2 of 5"
    State* stateFor(std::uint16_t subsystem, const char* what);
    void locate(RemoteSubsystem& remote, State& state);
    bool ownComponent(const RemoteSubsystem& remote, const State& state) const;
    bool haveControl(const RemoteSubsystem& remote, const State& state) const;
    bool askControl(RemoteSubsystem& remote, State& state);
    std::optional<ManagementState> driverStatus(const RemoteSubsystem& remote, const State& state) const;
    void setPhase(RemoteSubsystem& remote, State& state, MissionPhase phase, std::string reason = {});
    void fail(RemoteSubsystem& remote, State& state, std::string reason);
    void go(State& state, Step step);
    bool sendToDriver(State& state, const Bytes& payload);

    // Steps (MissionClient.cpp)
    void tickControl(RemoteSubsystem& remote, State& state, TimePoint now);
    void afterControl(RemoteSubsystem& remote, State& state);
    bool afterGoal(RemoteSubsystem& remote, State& state);
    void sendNextPart(RemoteSubsystem& remote, State& state);
    void beginReadying(RemoteSubsystem& remote, State& state);
    void sendExecute(RemoteSubsystem& remote, State& state, std::uint16_t uid);
    void tickSteps(RemoteSubsystem& remote, State& state, TimePoint now);
    void watchSafety(RemoteSubsystem& remote, State& state);
    double speedFor(const RemoteSubsystem& remote, const State& state, int index) const;
    // Polls of the active element (no event from the driver): at the status poll rate, 1 Hz at least.
    double activePollHz() const;
    bool goToSingle(RemoteSubsystem& remote, State& state, const MissionPoint& point);

    // Reports (MissionClientReports.cpp)
    void onConfirm(RemoteSubsystem& remote, const JausId& source, ByteSpan payload);
    void onReject(RemoteSubsystem& remote, const JausId& source, ByteSpan payload);
    void onCount(RemoteSubsystem& remote, const JausId& source, ByteSpan payload);
    void onList(RemoteSubsystem& remote, const JausId& source, ByteSpan payload);
    void onElement(RemoteSubsystem& remote, const JausId& source, ByteSpan payload);
    void onActive(RemoteSubsystem& remote, const JausId& source, ByteSpan payload);
    void onPathCapabilities(RemoteSubsystem& remote, const JausId& source, ByteSpan payload);
    void onPath(RemoteSubsystem& remote, const JausId& source, ByteSpan payload);
    void queryElements(State& state);
    void verified(RemoteSubsystem& remote, State& state);
    bool sameElement(const State& state, const ListElement& ours, const ListElement& theirs) const;
    void progress(RemoteSubsystem& remote, State& state);
    void trail(RemoteSubsystem& remote, State& state);

    EventsClient& m_events;
    AccessControlClient& m_access;
    std::map<std::uint16_t, State> m_state;
    std::uint8_t m_nextRequestId = 1;
};

} // namespace ocu::jaus
