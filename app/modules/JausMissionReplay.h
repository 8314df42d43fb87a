#pragma once
// The mission panel in a replay: the UGVs' missions as the flight recorder kept them (their states at the
// replay time, the route and the path driven on the map), read-only.
#include "app/ProtocolModule.h"

namespace ocu {

// Puts the replayed mission panel under `panelKey` when the recording holds missions (else the panel keeps
// saying that commands are disabled).
void populateMissionReplay(const ModuleReplay& replay, const QString& panelKey);

} // namespace ocu
