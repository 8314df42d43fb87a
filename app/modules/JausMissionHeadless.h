#pragma once
// Each UGV's mission in the headless monitor's lines, live and in a replay alike: its fields ("mission":
// state, waypoint k of n, distance, ETA, path) in every machine line and in "list", and the machine's line
// printed again when only its mission changed (at once for a change of state, waypoint, ownership or
// reason; within the monitor's rate limit for progress).
#include <QPointer>

namespace ocu {

class HeadlessCommands;
class JausVehicleBridge;

// `bridge`: the live JAUS bridge or a replay's mission bridge (nullptr: nothing added).
void addMissionLines(JausVehicleBridge* bridge, HeadlessCommands& table);

} // namespace ocu
