#pragma once
// A gamepad or USB button mapped to STOP ALL, read on a thread of its own: a press is acted on without
// waiting for the GUI thread, which may be busy painting (docs/decisions/stop-from-callers-thread.md).
// Plain C++ over SDL2; SDL's joystick calls take its joystick lock, so the teleop panel's polling on the GUI
// thread may run beside it.

#include <atomic>
#include <cstdint>
#include <functional>
#include <mutex>
#include <set>
#include <string>
#include <thread>

namespace ocu {

class JoystickStopButton {
public:
    struct Options {
        std::string device; // part of the device name (SDL's), any device when empty
        int button = 0;     // SDL button index
        int pollMs = 2;     // a press is seen within this, plus the time to send
    };
    struct Callbacks {
        // Once per press, on the watcher's thread; also for a button already held when its device appears
        // (a latched mushroom button means stop).
        std::function<void(const std::string& device)> pressed;
        // The watched device appeared (true) or went away (false), on the watcher's thread.
        std::function<void(bool connected, const std::string& device)> connection;
    };

    JoystickStopButton(Options options, Callbacks callbacks);
    ~JoystickStopButton(); // stops and joins the thread: no callback runs after it returns
    JoystickStopButton(const JoystickStopButton&) = delete;
    JoystickStopButton& operator=(const JoystickStopButton&) = delete;

    // False when SDL's joystick subsystem could not start; error() says why.
    bool available() const { return m_available; }
    std::string error() const { return m_error; }
    // The device being watched, empty while none matches.
    std::string device() const;
    // Completed reads of the devices (tests wait for a number of them instead of for a time).
    std::uint64_t polls() const { return m_polls.load(); }

private:
    void run();
    void openMatching();
    void closeDevice();

    Options m_options;
    Callbacks m_callbacks;
    bool m_available = false;
    std::string m_error;
    std::atomic<bool> m_stop{false};
    std::atomic<std::uint64_t> m_polls{0};
    mutable std::mutex m_deviceMutex;
    std::string m_device;       // guarded by m_deviceMutex
    void* m_joystick = nullptr; // SDL_Joystick*, the watcher thread's only
    bool m_down = false;
    std::set<int> m_rejected; // devices without the button (SDL instance ids)
    std::thread m_thread;
};

} // namespace ocu
