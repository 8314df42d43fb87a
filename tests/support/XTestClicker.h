#pragma once
// Real window-system input for tests and benchmarks: pointer moves and button presses injected through the X
// server's XTest extension on a connection of its own, so the application receives them as from a mouse
// (through the X server, its event queue and the toolkit's event dispatch).

#include <string>

namespace ocu::test {

class XTestClicker {
public:
    XTestClicker() = default;
    ~XTestClicker();
    XTestClicker(const XTestClicker&) = delete;
    XTestClicker& operator=(const XTestClicker&) = delete;

    // Connects to $DISPLAY; false with the reason when there is no display or no XTest.
    bool open(std::string& error);
    void moveTo(int x, int y); // root-window coordinates
    void press();              // button 1 down, flushed to the server before returning
    void release();            // button 1 up, flushed
    // A key down or up by its X keysym name ("F12", "space", "Control_L", "Shift_L"), flushed.
    void key(const char* keysymName, bool down);

private:
    void* m_display = nullptr; // Display*
};

} // namespace ocu::test
