#pragma once
// A UGV mission as the operator plans it and as the vehicle reports it (AEP-4818 §8.2: the waypoint list
// drivers behind the ListManager). The plan editor builds MissionWaypoints; the JAUS bridge uploads them and
// fills JausMission from the vehicle's own reports (ReportElementList/ReportElement read-back,
// ReportActiveElement, the pose, Management and emergency state), never from what was asked.
#include <QPair>
#include <QString>
#include <QVector>

#include <optional>

namespace ocu {

// One waypoint in WGS84; speed and tolerance as the operator set them (0 = the vehicle's default).
struct MissionWaypoint {
    double lat = 0, lon = 0; // degrees
    double speed = 0;        // m/s
    double tolerance = 0;    // metres
    bool operator==(const MissionWaypoint&) const = default;
};

enum class MissionState {
    None,               // no mission on this vehicle from this console
    Uploading,          // SetElement records on the wire, read-back not yet equal
    Uploaded,           // the vehicle's list equals ours (verified by read-back)
    Running,            // ExecuteList accepted and the active element reported
    Paused,             // stopped by our pause; resumable
    Completed,          // the last element was reached
    Aborted,            // aborted by the operator
    StoppedByEmergency, // an emergency stop arrived while running; never restarts by itself
    Lost,               // control lost or link down: the vehicle's progress is unknown
    Rejected            // an element or ExecuteList was refused (reason says why)
};

struct JausMission {
    MissionState state = MissionState::None;
    QVector<MissionWaypoint> waypoints; // as uploaded (and verified when state >= Uploaded)
    bool global = false;                // uploaded to a GlobalWaypointListDriver (else local)
    int activeIndex = -1;               // 0-based waypoint the vehicle reports active; -1 = none
    int lastSeenIndex = -1;             // the last active waypoint seen before Lost
    std::optional<double> distanceToGoM;
    std::optional<double> etaS;
    bool ours = true; // false once another console holds the list driver
    QString reason;   // why Rejected/Lost/Aborted, in the vehicle's or the stack's words
    QVector<QPair<double, double>> drivenPath; // (lat, lon), PathReporter's or the pose trail
    QString pathSource;                        // "path reporter" or "pose trail"
    bool operator==(const JausMission&) const = default;
};

// The word headless JSON and the audit use for a state.
inline QString toText(MissionState s) {
    switch (s) {
    case MissionState::None:
        return QStringLiteral("none");
    case MissionState::Uploading:
        return QStringLiteral("uploading");
    case MissionState::Uploaded:
        return QStringLiteral("uploaded");
    case MissionState::Running:
        return QStringLiteral("running");
    case MissionState::Paused:
        return QStringLiteral("paused");
    case MissionState::Completed:
        return QStringLiteral("completed");
    case MissionState::Aborted:
        return QStringLiteral("aborted");
    case MissionState::StoppedByEmergency:
        return QStringLiteral("stopped by emergency");
    case MissionState::Lost:
        return QStringLiteral("lost");
    case MissionState::Rejected:
        return QStringLiteral("rejected");
    }
    return QStringLiteral("none");
}

} // namespace ocu
