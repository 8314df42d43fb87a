#pragma once
// A UGV's mission as JSON: the fields the headless monitor shows per vehicle, and the flight recorder's
// change records from which a replay rebuilds the mission, its states and the path the vehicle drove.
#include "models/jaus/JausMission.h"

#include <QByteArray>
#include <QJsonObject>

#include <optional>

namespace ocu {

// The name of the recorder's records of a mission (FleetBridge::publishDetail's kind).
inline QString missionRecordKind() {
    return QStringLiteral("mission");
}

std::optional<MissionState> missionStateFromText(const QString& text);

// What a headless line says of a mission: "state", "waypoints" (n), "active_waypoint" (k, 1-based, when one
// is active), "last_seen_waypoint" (when lost), "distance_to_go_m", "eta_s", "global", "ours", "reason",
// "path_source" and "path_points" (when a driven path is known).
QJsonObject missionJson(const JausMission& mission);

// Whether `a` and `b` differ at most in what changes with every pose (distance to go, ETA, driven path):
// the recorder and the headless lines keep such changes to their interval, the others go out at once.
bool onlyProgressDiffers(JausMission a, const JausMission& b);

// One record of the change from `before` (what the previous records gave) to `now`: the state fields, the
// waypoints when they changed, the driven path as the points dropped from its front and added at its end (a
// growing trail, a sliding window of the PathReporter's path), or whole when it does not continue the one
// before. Compact JSON; lat/lon as written by Qt (shortest exact form), so a replay gets them back exactly.
QByteArray encodeMissionRecord(const JausMission& before, const JausMission& now);
// Applies one record onto the mission before it; false (and `mission` unchanged) when it is malformed.
bool applyMissionRecord(JausMission& mission, const QByteArray& record);

} // namespace ocu
