#include "widgets/X11StopPressWatcher.h"

#include <X11/Xlib.h>
#include <X11/extensions/XInput2.h>
#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

namespace ocu {

namespace {
Display* dpy(void* d) {
    return static_cast<Display*>(d);
}
} // namespace

X11StopPressWatcher::X11StopPressWatcher(std::function<void(unsigned long)> pressed)
    : m_pressed(std::move(pressed)) {}

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
                    m_pressed(time);
                }
                ++m_seen; // after the decision: a test waiting for it sees the outcome
            } else {
                XFreeEventData(d, cookie);
            }
        }
    }
}

} // namespace ocu
