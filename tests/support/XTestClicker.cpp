#include "tests/support/XTestClicker.h"

#include <X11/Xlib.h>
#include <X11/extensions/XTest.h>

namespace ocu::test {

namespace {
Display* dpy(void* d) {
    return static_cast<Display*>(d);
}
} // namespace

XTestClicker::~XTestClicker() {
    if (m_display)
        XCloseDisplay(dpy(m_display));
}

bool XTestClicker::open(std::string& error) {
    Display* d = XOpenDisplay(nullptr);
    if (!d) {
        error = "cannot open the X display (run under xvfb-run with QT_QPA_PLATFORM=xcb)";
        return false;
    }
    int event = 0, err = 0, major = 0, minor = 0;
    if (!XTestQueryExtension(d, &event, &err, &major, &minor)) {
        XCloseDisplay(d);
        error = "the X server has no XTest extension";
        return false;
    }
    m_display = d;
    return true;
}

void XTestClicker::moveTo(int x, int y) {
    XTestFakeMotionEvent(dpy(m_display), -1, x, y, CurrentTime);
    XSync(dpy(m_display), False); // the pointer is there before the next press
}

void XTestClicker::press() {
    XTestFakeButtonEvent(dpy(m_display), 1, True, CurrentTime);
    XFlush(dpy(m_display));
}

void XTestClicker::key(const char* keysymName, bool down) {
    Display* d = dpy(m_display);
    XTestFakeKeyEvent(d, XKeysymToKeycode(d, XStringToKeysym(keysymName)), down ? True : False, CurrentTime);
    XSync(d, False);
}

void XTestClicker::release() {
    XTestFakeButtonEvent(dpy(m_display), 1, False, CurrentTime);
    XSync(dpy(m_display), False);
}

} // namespace ocu::test
