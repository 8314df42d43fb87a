#pragma once
// One machine state as a JSON object: the fields of the headless monitor's "machine" lines, shared by the
// headless monitor (which adds stale, status, age_ms) and the recording's export (which adds t), so a
// replay's JSON lines are the live ones.
#include "models/MachineState.h"

#include <QJsonObject>

namespace ocu {

QJsonObject machineStateJson(const MachineState& m);

} // namespace ocu
