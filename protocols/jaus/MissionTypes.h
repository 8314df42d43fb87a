#pragma once
// A waypoint mission as the JAUS stack knows it (AEP-4818 §8.2; procedure in
// shared/research/jaus-autonomy.md §12): what the console uploaded and what the vehicle reports about it.
// Every phase past Uploading comes from the vehicle's own reports (read-back, ReportActiveElement,
// ReportStatus, the pose), never from what was asked. The console's models mirror it in JausMission.
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "protocols/jaus/JudpCodec.h"

namespace ocu::jaus {

// One waypoint in WGS84; speed and tolerance as the operator set them (0 = the vehicle's default).
struct MissionPoint {
    double lat = 0, lon = 0; // degrees
    double speed = 0;        // m/s
    double tolerance = 0;    // metres
    bool operator==(const MissionPoint&) const = default;
};

enum class MissionPhase {
    None,               // no mission on this vehicle from this console
    Uploading,          // SetElement records on the wire, read-back not yet equal
    Uploaded,           // the vehicle's list equals ours (verified by read-back)
    Running,            // ExecuteList went out and the vehicle reports an active element
    Paused,             // our pause: the list driver reports Standby
    Completed,          // the active element went back to 0 after the last waypoint
    Aborted,            // aborted by the operator (or the vehicle ended the list early: reason says)
    StoppedByEmergency, // an emergency arrived while the mission ran; never restarts by itself
    Lost,               // control lost or link down: the vehicle's progress is unknown
    Rejected            // an element, the read-back or ExecuteList was refused (reason says why)
};
const char* nameFor(MissionPhase p);

struct MissionStatus {
    MissionPhase phase = MissionPhase::None;
    std::vector<MissionPoint> waypoints; // as uploaded (verified once phase >= Uploaded)
    bool global = false;                 // uploaded to a GlobalWaypointListDriver (else local)
    bool single = false;                 // a single waypoint through a (Local/Global)WaypointDriver
    JausId driver;                       // the component hosting the driver, zero until chosen
    int activeIndex = -1;                // 0-based waypoint the vehicle reports active; -1 = none
    int lastSeenIndex = -1;              // the last active waypoint seen (kept when Lost)
    std::optional<double> distanceToGoM, etaS;
    bool ours = true;   // false once another console controls the list driver
    std::string reason; // why Rejected / Lost / Aborted, in the vehicle's or the stack's words
    std::vector<std::pair<double, double>> drivenPath; // (lat, lon), PathReporter's or the pose trail
    std::string pathSource;                            // "path reporter" or "pose trail"
    bool operator==(const MissionStatus&) const = default;
};

} // namespace ocu::jaus
