#pragma once
// The foreign vehicle's Local Waypoint List Driver, as public stacks build it (jaus-autonomy.md §2.4, §3.4,
// JAUS++'s tutorial vehicle): mobility:LocalWaypointListDriver 1.0 over mobility:ListManager 1.0, no
// GlobalWaypointListDriver, no PathReporter, no events (ReportActiveElement only when queried), ReportElement
// without its format byte, ReportElementList in ascending UID order, QueryElement(0) unanswered, a failed
// SetElement rejected with code 7, ExecuteList only from the controller in Ready, the speed clamped to
// 1 m/s. Written from the research note with its own decoding (nothing from protocols/ or sim/).
// On a component of its own it keeps its own control and management state and, while it executes, takes
// control of the vehicle's drive component itself (refusing to start while a console holds it).
#include "tests/protocols/jaus/foreign/ForeignBytes.h"

#include <cstdint>
#include <map>
#include <vector>

namespace foreign {

class WaypointListDriver {
public:
    struct Options {
        std::uint8_t rejectSetElementCode = 0; // non-zero: every SetElement is refused with this code
        bool ignoreExecuteList = false;        // ExecuteList never starts anything
        double maxSpeed = 1.0;                 // m/s (FKIE's clamp)
    };
    // controller / status: the component's own control and Management state (or the vehicle's, when the
    // driver shares its component); driveController: the vehicle's drive component's controller.
    WaypointListDriver(Options options, std::uint32_t self, std::uint32_t& controller, std::uint8_t& status,
                       std::uint32_t& driveController)
        : m_opt(options), m_self(self), m_controller(controller), m_status(status),
          m_driveController(driveController) {}

    // A message to the driver's component: true when it is the driver's (answers appended to `replies`).
    bool handle(std::uint16_t mid, std::uint32_t src, const std::uint8_t* body, std::size_t len,
                std::vector<Buf>& replies);
    // On the drive component itself: its control is the vehicle's (the one-component layout).
    bool sharesDriveComponent() const { return &m_controller == &m_driveController; }
    // Moves (x, y) (metres, x north, y east) towards the active element; vehicleEmergency stops it.
    void step(double dt, bool vehicleEmergency, double& x, double& y);
    // The vehicle went into emergency: its own Ready is left and the speed reset at once.
    void emergency() {
        if (m_status == 1)
            m_status = 2;
        m_speed = 0;
    }
    std::uint16_t active() const { return m_active; }
    bool executing() const { return m_active != 0 && m_speed > 0; }

private:
    struct Element {
        std::uint16_t prev = 0, next = 0;
        double x = 0, y = 0, tolerance = 0.25; // JAUS++'s default capture radius
        Buf raw;                               // the element's data as received
    };
    void stop();

    Options m_opt;
    std::uint32_t m_self;
    std::uint32_t& m_controller;
    std::uint8_t& m_status;
    std::uint32_t& m_driveController;
    std::map<std::uint16_t, Element> m_list;
    std::uint16_t m_active = 0;
    double m_speed = 0;
};

} // namespace foreign
