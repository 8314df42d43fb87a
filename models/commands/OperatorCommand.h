#pragma once
// The operator's commands as typed values, one struct per command with its target and arguments. Panels
// build them directly; the headless monitor parses its JSON lines into them once, at its edge
// (parseOperatorCommand). The CommandGate takes them, checks and audits them (toJson for the audit line)
// and hands each to the bridge that owns its target; a bridge acts on the commands it knows
// (FleetBridge::command) and refuses the rest as not supported.
//
// Adding a command: a struct here (with operator==), its name in commandName, its JSON in toJson and
// parseOperatorCommand, its route in commandRoute, and the bridge's visitor case.
#include "models/MachineState.h"
#include "models/jaus/JausMission.h"
#include "models/jaus/JausPlatformServices.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QString>
#include <QVector>

#include <optional>
#include <variant>

namespace ocu {

// ---- every protocol (the gate calls FleetBridge::stopAll / stopMachine / clearStop) ----

struct StopAll {
    bool operator==(const StopAll&) const = default;
};
struct StopMachine {
    QString id;
    bool operator==(const StopMachine&) const = default;
};
// A stop release needs the operator's deliberate confirmation: the GUI's hold-to-confirm gives a token
// (CommandGate::requestClearToken), the headless line an explicit "confirm": true. The token is never
// written to JSON.
struct ClearStop {
    QString id;
    bool confirm = false;
    QString token;
    bool operator==(const ClearStop&) const = default;
};

// ---- JAUS: access control, management, driving ----

struct RequestControl {
    QString id;
    bool operator==(const RequestControl&) const = default;
};
// Also drops the wish for control, so the console does not take control back when the vehicle is heard again.
struct ReleaseControl {
    QString id;
    bool operator==(const ReleaseControl&) const = default;
};
// Releases every vehicle this console controls (routed to the JAUS bridge).
struct ReleaseAll {
    bool operator==(const ReleaseAll&) const = default;
};
// The Management service's commands (resume, standby, shutdown, reset).
enum class ManagementAction { Resume, Standby, Shutdown, Reset };
struct Management {
    QString id;
    ManagementAction action = ManagementAction::Resume;
    bool operator==(const Management&) const = default;
};
// A teleop session: one audited command per session, not per drive message.
struct DriveStart {
    QString id;
    QString reason;
    bool operator==(const DriveStart&) const = default;
};
struct DriveStop {
    QString id;
    QString reason; // why the session ended (the note of the sent targets)
    bool operator==(const DriveStop&) const = default;
};
// A timed drive (headless "drive"): velocity in m/s and rad/s, or effort in % (±100).
struct TimedDrive {
    enum class Mode { Velocity, Effort };
    QString id;
    Mode mode = Mode::Velocity;
    double linear = 0;
    double angular = 0;
    double durationS = 1.0;
    bool operator==(const TimedDrive&) const = default;
};

// ---- JAUS: waypoint missions (AEP-4818 §8.2) ----

// Uploads the route to the vehicle's waypoint list driver; global: the GlobalWaypointListDriver (true), the
// local one (false), global where the vehicle offers it (empty).
struct MissionUpload {
    QString id;
    QVector<MissionWaypoint> waypoints;
    std::optional<bool> global;
    bool operator==(const MissionUpload&) const = default;
};
// Executes the uploaded (verified) list from the 0-based waypoint fromIndex.
struct MissionStart {
    QString id;
    int fromIndex = 0;
    bool operator==(const MissionStart&) const = default;
};
struct MissionPause {
    QString id;
    bool operator==(const MissionPause&) const = default;
};
struct MissionResume {
    QString id;
    bool operator==(const MissionResume&) const = default;
};
struct MissionAbort {
    QString id;
    bool operator==(const MissionAbort&) const = default;
};
// One waypoint: the vehicle's single waypoint driver, else a one-waypoint list started at once.
struct GoTo {
    QString id;
    MissionWaypoint waypoint;
    bool operator==(const GoTo&) const = default;
};

// ---- JAUS: platform services (AEP-4818 §6.2.5, §6.2.6, §9.2.2, §5.7); JSON in PlatformCommandJson.cpp ----

// "platform_mode": 0 standard, 1 training, 2 maintenance, 175-255 program-specific.
struct SetPlatformMode {
    QString id;
    int mode = 0;
    bool operator==(const SetPlatformMode&) const = default;
};
// "platform_state": 0 initialize ... 5 render useless (JausPlatformState); the vehicle decides which it
// takes.
struct SetPlatformState {
    QString id;
    int state = 1;
    bool operator==(const SetPlatformState&) const = default;
};
// "lights": the lights in `mask` (JausLight bits) switched to their bits in `on`; the others unchanged.
struct SetLights {
    QString id;
    quint32 mask = 0, on = 0;
    bool operator==(const SetLights&) const = default;
};
// "odometry": read the odometers now; resetTrip also starts a new trip (ResetOdometry TRIP_A).
struct Odometry {
    QString id;
    bool resetTrip = false;
    bool operator==(const Odometry&) const = default;
};

// ---- JAUS: hand-off between consoles (AEP-4818 §6.3) ----

// Asks the console holding the vehicle to hand it over (Enhanced Access Control), with the reason its
// operator sees; a vehicle without it is asked by the ordinary pre-emption rules. cancel: withdraw ours.
struct HandoffRequest {
    QString id;
    QString reason;
    bool cancel = false;
    bool operator==(const HandoffRequest&) const = default;
};
// This console's answer to a request the vehicle forwarded (requestId: the vehicle's queue entry).
struct HandoffAnswer {
    QString id;
    int requestId = 0;
    bool accept = false;
    bool wait = false; // WAIT instead: the request stays queued, its decision time starts again
    bool operator==(const HandoffAnswer&) const = default;
};

// ---- ISO 23725: all-stop per AHS link, map, dispatch ----

// The link by name, else the link of the machine `id`, else the only link.
struct AllStopApply {
    QString link;
    QString id;
    bool operator==(const AllStopApply&) const = default;
};
struct AllStopRemove {
    QString link;
    QString id;
    bool operator==(const AllStopRemove&) const = default;
};
struct FetchMap {
    QString link;
    QString id;
    bool operator==(const FetchMap&) const = default;
};
// One task of an assignment request (ISO 23725 §5 #21): Load, Offload, Fuel, Park or Wait at a destination
// way, optionally at a piece of equipment (a shovel) or a spot, optionally along a route of way ids.
struct AssignTask {
    QString assignmentId; // empty: generated when sent
    QString task;
    qint64 destinationId = 0;
    QString destinationEquipmentId; // empty = none
    std::optional<qint64> destinationSpotId;
    std::optional<QVector<qint64>> route; // none: the console routes it (or the AHS)
    bool operator==(const AssignTask&) const = default;
};
struct Assign {
    QString id;
    QVector<AssignTask> tasks;
    bool operator==(const Assign&) const = default;
};
struct ResetAssignment {
    QString id;
    bool operator==(const ResetAssignment&) const = default;
};

// ---- OSYRIS: crew messages, station ping ----

// To one station (`id`, "osyris:<idx>") or, with no id, to every station.
struct SendText {
    QString id;
    QString text;
    bool operator==(const SendText&) const = default;
};
struct PingStation {
    int idx = -1;
    bool operator==(const PingStation&) const = default;
};

using OperatorCommand =
    std::variant<StopAll, StopMachine, ClearStop, RequestControl, ReleaseControl, ReleaseAll, Management,
                 DriveStart, DriveStop, TimedDrive, AllStopApply, AllStopRemove, FetchMap, Assign,
                 ResetAssignment, SendText, PingStation, MissionUpload, MissionStart, MissionPause,
                 MissionResume, MissionAbort, GoTo, SetPlatformMode, SetPlatformState, SetLights, Odometry,
                 HandoffRequest, HandoffAnswer>;

// The visitor idiom: std::visit(Overloaded{[](const StopAll&) {...}, [](const auto&) {...}}, command).
template <class... Ts> struct Overloaded : Ts... { using Ts::operator()...; };
template <class... Ts> Overloaded(Ts...) -> Overloaded<Ts...>;

// "stop_all", "stop", "clear_stop", "request_control", ... (the headless "cmd", the audit "action").
QString commandName(const OperatorCommand& command);

// Which bridge a command goes to: every bridge (STOP ALL), the owner of `machine`, else the bridge of
// `protocol`.
struct CommandRoute {
    bool everyBridge = false;
    QString machine;
    std::optional<Protocol> protocol;
};
CommandRoute commandRoute(const OperatorCommand& command);
// The machine the command names, or empty (the audit line's "target").
inline QString commandTarget(const OperatorCommand& command) {
    return commandRoute(command).machine;
}

// {"cmd": name, arguments...}: the audit line's "command", the headless result line, the recorder.
QJsonObject toJson(const OperatorCommand& command);

// A headless JSON command read into its typed value, or why it cannot be: an unknown name, a missing or
// malformed argument. `target` names the machine of a malformed command when it named one (the gate
// audits that refusal against it).
struct ParsedCommand {
    std::optional<OperatorCommand> command;
    QString error;
    QString target;
};
ParsedCommand parseOperatorCommand(const QString& name, const QJsonObject& args);
// True when `name` is an operator command parseOperatorCommand knows.
bool isOperatorCommand(const QString& name);

// The "tasks" argument of assign: [{"task":"Load","destination":4201,"equipment":"<guid>","spot":3,
// "route":[2001],"assignment_id":"<guid>"}]; the single-task shorthand puts those keys at the top.
QJsonArray tasksToJson(const QVector<AssignTask>& tasks);
// An error text (and no tasks) when the arguments do not describe at least one well-formed task.
std::optional<QVector<AssignTask>> tasksFromJson(const QJsonObject& args, QString* error);

// A waypoint as JSON: {"lat","lon","speed","tolerance"} (speed and tolerance 0 = the vehicle's default).
QJsonObject waypointToJson(const MissionWaypoint& waypoint);
// The same read back; [lat, lon] is accepted too. An error text when it is not a waypoint in WGS84.
std::optional<MissionWaypoint> waypointFromJson(const QJsonValue& value, QString* error);

} // namespace ocu
