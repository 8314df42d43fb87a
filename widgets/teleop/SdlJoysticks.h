#pragma once
// SDL2's joystick subsystem, started the same way by every user in this process (reference-counted by SDL).

#include <string>

namespace ocu {

// Starts the subsystem; false with the reason in `error` when SDL cannot. Each true return needs one
// stopSdlJoysticks().
bool startSdlJoysticks(std::string& error);
void stopSdlJoysticks();

} // namespace ocu
