#include "widgets/teleop/SdlJoysticks.h"

#include <SDL.h>

namespace ocu {

bool startSdlJoysticks(std::string& error) {
    // Devices are read whether or not a window of ours has the focus: a STOP button must work while the
    // operator types in another program.
    SDL_SetHint(SDL_HINT_JOYSTICK_ALLOW_BACKGROUND_EVENTS, "1");
    // The joystick subsystem starts SDL's event subsystem, which would install SIGINT/SIGTERM handlers that
    // only queue an SDL_QUIT nobody reads: the console would ignore kill and Ctrl+C. The application owns the
    // signals (app/ConsoleApp.cpp, installQuitSignalHandlers).
    SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
    SDL_SetMainReady();
    if (SDL_InitSubSystem(SDL_INIT_JOYSTICK) != 0) {
        error = SDL_GetError();
        return false;
    }
    return true;
}

void stopSdlJoysticks() {
    SDL_QuitSubSystem(SDL_INIT_JOYSTICK);
}

} // namespace ocu
