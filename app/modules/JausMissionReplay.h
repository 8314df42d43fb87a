#pragma once
// The UGVs' missions in a replay, as the flight recorder kept them (their states at the replay time, the
// route and the path driven), read-only: the mission panel with its 2D and 3D drawing in the replay window,
// and the "mission" fields of the headless replay's lines.
#include "app/ProtocolModule.h"

namespace ocu {

class MissionReplayBridge;

// The recording's missions following the controller's time (not yet set: connect to it first, then
// setTime(controller->position())); nullptr when the recording holds none.
MissionReplayBridge* makeMissionReplayBridge(recording::ReplayController* controller, QObject* parent);

// Puts the replayed mission panel under `panelKey` when the recording holds missions (else the panel keeps
// saying that commands are disabled).
void populateMissionReplay(const ModuleReplay& replay, const QString& panelKey);

// The missions in the headless replay's machine lines and "list", as live.
void registerMissionReplayHeadless(const ModuleHeadlessReplay& replay);

} // namespace ocu
