#include "widgets/X11StopPressWatcher.h"

#include <X11/Xlib.h>
#include <X11/extensions/XInput2.h>
#include <X11/keysym.h>
#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

namespace ocu {

namespace {
Display* dpy(void* d) {
    return static_cast<Display*>(d);
}
} // namespace

X11StopPressWatcher::X11StopPressWatcher(Pressed pressed) : m_pressed(std::move(pressed)) {}

X11StopPressWatcher::~X11StopPressWatcher() {
    m_stop = true;
    if (m_wake[1] >= 0) {
        const char c = 0;
        [[maybe_unused]] const auto w = ::write(m_wake[1], &c, 1);
    }
    if (m_thread.joinable())
        m_thread.join();
    if (m_display)
        XCloseDisplay(dpy(m_display));
    for (int fd : m_wake)
        if (fd >= 0)
            ::close(fd);
}

bool X11StopPressWatcher::start(std::string& error) {
    Display* d = XOpenDisplay(nullptr);
    if (!d) {
        error = "no X display";
        return false;
    }
    int event = 0, err = 0;
    int major = 2, minor = 0;
    if (!XQueryExtension(d, "XInputExtension", &m_xiOpcode, &event, &err) ||
        XIQueryVersion(d, &major, &minor) != Success) {
        XCloseDisplay(d);
        error = "the X server has no XInput 2";
        return false;
    }
    // Raw events are selected on the root window and reach this connection whatever window has the pointer
    // or a grab (XI 2.1+); the position is asked for when one comes.
    unsigned char bits[XIMaskLen(XI_LASTEVENT)] = {};
    XISetMask(bits, XI_RawButtonPress);
    XISetMask(bits, XI_RawKeyPress);
    XISetMask(bits, XI_RawKeyRelease);
    m_f12 = XKeysymToKeycode(d, XK_F12);
    m_space = XKeysymToKeycode(d, XK_space);
    for (KeySym k : {XK_Control_L, XK_Control_R})
        m_ctrlKeys.insert(XKeysymToKeycode(d, k));
    for (KeySym k : {XK_Shift_L, XK_Shift_R})
        m_shiftKeys.insert(XKeysymToKeycode(d, k));
    for (KeySym k : {XK_Alt_L, XK_Alt_R, XK_Super_L, XK_Super_R, XK_Meta_L, XK_Meta_R})
        m_otherModKeys.insert(XKeysymToKeycode(d, k));
    XIEventMask mask{XIAllMasterDevices, sizeof(bits), bits};
    XISelectEvents(d, DefaultRootWindow(d), &mask, 1);
    XFlush(d);
    if (::pipe2(m_wake, O_CLOEXEC) != 0) {
        XCloseDisplay(d);
        error = "pipe failed";
        return false;
    }
    m_display = d;
    m_thread = std::thread([this] { run(); });
    return true;
}

void X11StopPressWatcher::setTarget(unsigned long window, int x, int y, int width, int height, bool armed) {
    std::lock_guard lock(m_targetMutex);
    m_target = {window, x, y, width, height, armed};
}

// The pointer inside the rectangle, and the window chain under it (root's child down to the deepest) passing
// through our top-level window: a menu, a dialog or another program's window over the button is not ours.
bool X11StopPressWatcher::overTarget(const Target& t) {
    Display* d = dpy(m_display);
    Window root = DefaultRootWindow(d), r = 0, child = 0;
    int rx = 0, ry = 0, wx = 0, wy = 0;
    unsigned int keys = 0;
    if (!XQueryPointer(d, root, &r, &child, &rx, &ry, &wx, &wy, &keys))
        return false;
    if (rx < t.x || ry < t.y || rx >= t.x + t.width || ry >= t.y + t.height)
        return false;
    bool ours = false;
    for (int depth = 0; child != 0 && depth < 16; ++depth) {
        ours = ours || child == t.window;
        Window next = 0;
        if (!XQueryPointer(d, child, &r, &next, &rx, &ry, &wx, &wy, &keys))
            break;
        if (!ours && next == 0)
            return false; // the deepest window is not inside ours
        child = next;
    }
    return ours;
}

// The window with the keyboard focus is ours or inside ours.
bool X11StopPressWatcher::focusInTarget(const Target& t) {
    Display* d = dpy(m_display);
    Window focus = 0;
    int revert = 0;
    XGetInputFocus(d, &focus, &revert);
    const Window root = DefaultRootWindow(d);
    for (int depth = 0; focus != 0 && focus != PointerRoot && focus != root && depth < 16; ++depth) {
        if (focus == t.window)
            return true;
        Window r = 0, parent = 0, *children = nullptr;
        unsigned int n = 0;
        if (!XQueryTree(d, focus, &r, &parent, &children, &n))
            return false;
        if (children)
            XFree(children);
        focus = parent;
    }
    return false;
}

// F12 alone, or Space with Ctrl and Shift: the STOP ALL action's shortcuts (app/MainWindow.cpp).
void X11StopPressWatcher::onRawKey(int keycode, bool down, unsigned long time) {
    if (m_ctrlKeys.count(keycode) || m_shiftKeys.count(keycode) || m_otherModKeys.count(keycode)) {
        if (down)
            m_heldMods.insert(keycode);
        else
            m_heldMods.erase(keycode);
        return;
    }
    bool* held = keycode == m_f12 ? &m_f12Down : keycode == m_space ? &m_spaceDown : nullptr;
    if (!held)
        return;
    if (!down || *held) {
        *held = down;
        return;
    }
    *held = true;
    auto any = [this](const std::set<int>& codes) {
        for (int c : m_heldMods)
            if (codes.count(c))
                return true;
        return false;
    };
    const bool ctrl = any(m_ctrlKeys), shift = any(m_shiftKeys), other = any(m_otherModKeys);
    const bool f12 = keycode == m_f12 && !ctrl && !shift && !other;
    const bool space = keycode == m_space && ctrl && shift && !other;
    Target t;
    {
        std::lock_guard lock(m_targetMutex);
        t = m_target;
    }
    if ((f12 || space) && t.armed && t.window != 0 && focusInTarget(t)) {
        ++m_keysActed;
        m_pressed(f12 ? StopInput::F12 : StopInput::CtrlShiftSpace, time);
    }
    ++m_keysSeen;
}

void X11StopPressWatcher::run() {
    Display* d = dpy(m_display);
    pollfd fds[2] = {{ConnectionNumber(d), POLLIN, 0}, {m_wake[0], POLLIN, 0}};
    while (!m_stop) {
        if (XPending(d) == 0) {
            if (::poll(fds, 2, -1) < 0 || (fds[1].revents & POLLIN))
                continue; // woken to stop (or interrupted): the loop condition decides
        }
        while (!m_stop && XPending(d) > 0) {
            XEvent ev;
            XNextEvent(d, &ev);
            XGenericEventCookie* cookie = &ev.xcookie;
            if (cookie->type != GenericEvent || cookie->extension != m_xiOpcode || !XGetEventData(d, cookie))
                continue;
            if (cookie->evtype == XI_RawButtonPress) {
                const auto* raw = static_cast<const XIRawEvent*>(cookie->data);
                const int button = raw->detail;
                const unsigned long time = raw->time;
                XFreeEventData(d, cookie);
                if (button != 1)
                    continue;
                Target t;
                {
                    std::lock_guard lock(m_targetMutex);
                    t = m_target;
                }
                if (t.armed && t.window != 0 && overTarget(t)) {
                    ++m_acted;
                    m_pressed(StopInput::MouseButton, time);
                }
                ++m_seen; // after the decision: a test waiting for it sees the outcome
            } else if (cookie->evtype == XI_RawKeyPress || cookie->evtype == XI_RawKeyRelease) {
                const auto* raw = static_cast<const XIRawEvent*>(cookie->data);
                const int keycode = raw->detail;
                const unsigned long time = raw->time;
                const bool down = cookie->evtype == XI_RawKeyPress;
                XFreeEventData(d, cookie);
                onRawKey(keycode, down, time);
            } else {
                XFreeEventData(d, cookie);
            }
        }
    }
}

} // namespace ocu
