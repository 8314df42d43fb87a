#include "widgets/teleop/JoystickStopButton.h"

#include "widgets/teleop/SdlJoysticks.h"

#include <SDL.h>

#include <chrono>

namespace ocu {

JoystickStopButton::JoystickStopButton(Options options, Callbacks callbacks)
    : m_options(std::move(options)), m_callbacks(std::move(callbacks)) {
    m_available = startSdlJoysticks(m_error);
    if (m_available)
        m_thread = std::thread([this] { run(); });
}

JoystickStopButton::~JoystickStopButton() {
    m_stop = true;
    if (m_thread.joinable())
        m_thread.join();
    if (m_available)
        stopSdlJoysticks();
}

std::string JoystickStopButton::device() const {
    std::lock_guard lock(m_deviceMutex);
    return m_device;
}

void JoystickStopButton::openMatching() {
    for (int i = 0; i < SDL_NumJoysticks(); ++i) {
        const char* name = SDL_JoystickNameForIndex(i);
        const std::string n = name ? name : "";
        const SDL_JoystickID id = SDL_JoystickGetDeviceInstanceID(i);
        if (m_rejected.count(id) ||
            (!m_options.device.empty() && n.find(m_options.device) == std::string::npos))
            continue;
        SDL_Joystick* j = SDL_JoystickOpen(i);
        if (!j)
            continue;
        if (SDL_JoystickNumButtons(j) <= m_options.button) {
            SDL_JoystickClose(j);
            m_rejected.insert(id); // not opened again on every poll
            continue;
        }
        m_joystick = j;
        m_down = false;
        {
            std::lock_guard lock(m_deviceMutex);
            m_device = n;
        }
        if (m_callbacks.connection)
            m_callbacks.connection(true, n);
        return;
    }
}

void JoystickStopButton::closeDevice() {
    SDL_JoystickClose(static_cast<SDL_Joystick*>(m_joystick));
    m_joystick = nullptr;
    std::string gone;
    {
        std::lock_guard lock(m_deviceMutex);
        gone.swap(m_device);
    }
    if (m_callbacks.connection)
        m_callbacks.connection(false, gone);
}

void JoystickStopButton::run() {
    const auto period = std::chrono::milliseconds(std::max(1, m_options.pollMs));
    while (!m_stop) {
        SDL_JoystickUpdate(); // reads the devices and notices hot-plugging
        // State is read directly; the queued copies of these events would pile up where no teleop panel
        // drains SDL's queue. Device added/removed events stay for the panel.
        SDL_FlushEvents(SDL_JOYAXISMOTION, SDL_JOYBUTTONUP);
        SDL_FlushEvent(SDL_JOYBATTERYUPDATED);
        if (m_joystick && !SDL_JoystickGetAttached(static_cast<SDL_Joystick*>(m_joystick)))
            closeDevice();
        if (!m_joystick)
            openMatching();
        if (m_joystick) {
            const bool down =
                SDL_JoystickGetButton(static_cast<SDL_Joystick*>(m_joystick), m_options.button) != 0;
            if (down && !m_down && m_callbacks.pressed)
                m_callbacks.pressed(device());
            m_down = down;
        }
        ++m_polls;
        std::this_thread::sleep_for(period);
    }
    if (m_joystick)
        SDL_JoystickClose(static_cast<SDL_Joystick*>(m_joystick));
}

} // namespace ocu
