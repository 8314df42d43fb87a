#pragma once
// Sees a mouse press on the STOP ALL button, or its keys (F12, Ctrl+Shift+Space), before the GUI thread does:
// a thread of its own with its own X connection receives the X server's raw button and key events (XInput 2)
// and checks, by asking the server, that the pointer is over the button's rectangle inside our window and
// that no other window covers it there, or that the keyboard focus is in our window. The GUI thread may be
// busy painting for tens of milliseconds; this path is not (docs/decisions/ stop-from-callers-thread.md).
// Plain C++ over Xlib; the widget side publishes where the button is.

#include "widgets/StopPressClaims.h"

#include <atomic>
#include <functional>
#include <mutex>
#include <set>
#include <string>
#include <thread>

namespace ocu {

class X11StopPressWatcher {
public:
    // `pressed` runs on the watcher's thread with what was pressed and its X server time (milliseconds).
    using Pressed = std::function<void(StopInput input, unsigned long serverTimeMs)>;
    explicit X11StopPressWatcher(Pressed pressed);
    ~X11StopPressWatcher(); // stops and joins: no call of `pressed` after it returns
    X11StopPressWatcher(const X11StopPressWatcher&) = delete;
    X11StopPressWatcher& operator=(const X11StopPressWatcher&) = delete;

    // Connects to $DISPLAY and starts the thread; false with the reason (no display, no XInput 2.0).
    bool start(std::string& error);

    // Where presses count: the button's rectangle in root coordinates, in the top-level X window `window`.
    // Not armed: every press is ignored (button hidden or disabled, window minimised).
    void setTarget(unsigned long window, int x, int y, int width, int height, bool armed);

    // Raw presses of button 1 decided (acted on or not), and those acted on.
    int pressesSeen() const { return m_seen.load(); }
    int pressesActed() const { return m_acted.load(); }
    // Stop key presses decided (acted on or not), and those acted on (focus in our window).
    int keysSeen() const { return m_keysSeen.load(); }
    int keysActed() const { return m_keysActed.load(); }

private:
    struct Target {
        unsigned long window = 0;
        int x = 0, y = 0, width = 0, height = 0;
        bool armed = false;
    };
    void run();
    bool overTarget(const Target& t);
    bool focusInTarget(const Target& t);
    void onRawKey(int keycode, bool down, unsigned long time);

    Pressed m_pressed;
    void* m_display = nullptr; // Display*, the watcher thread's only once started
    int m_xiOpcode = 0;
    int m_wake[2] = {-1, -1}; // a pipe that ends the thread's wait
    std::mutex m_targetMutex;
    Target m_target; // guarded by m_targetMutex
    std::atomic<bool> m_stop{false};
    std::atomic<int> m_seen{0}, m_acted{0}, m_keysSeen{0}, m_keysActed{0};
    int m_f12 = 0, m_space = 0;                  // keycodes
    bool m_f12Down = false, m_spaceDown = false; // a held key acts once
    // Modifier keys as the raw events left them (asking the server later could see them released already).
    std::set<int> m_ctrlKeys, m_shiftKeys, m_otherModKeys, m_heldMods;
    std::thread m_thread;
};

} // namespace ocu
