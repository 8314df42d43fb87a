#pragma once
// A simulated haul truck's motion: the route it drives (a polyline over the pit map's ways, in the site's ENU
// frame, knowing which way each stretch follows) and its longitudinal motion along it (accelerate to a cruise
// speed, brake, slow down so as to stop at the route's end). Pure arithmetic on simulated seconds: no clock,
// no sockets, no map; the haul fleet builds routes from the map and decides the cruise speed.
#include "protocols/common/GeoFrame.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace ocu::sim {

// A drive over consecutive ways. Between legs the polyline runs straight from one leg's last point to the
// next leg's first (junctions where the ways' end nodes are a few metres apart).
class Route {
public:
    // Appends one leg: the way followed and its points in travel order (at least one).
    void addLeg(std::int64_t wayId, const std::vector<EnuPoint>& points);

    bool empty() const { return m_points.size() < 2; }
    double length() const { return m_length; } // horizontal (east/north) length, m
    const std::vector<EnuPoint>& points() const { return m_points; }
    const std::vector<std::int64_t>& legWays() const { return m_legWays; }

    struct Pose {
        EnuPoint position;
        std::optional<double> headingDeg; // of the stretch driven; none on a stretch too short to tell
        std::int64_t wayId = 0;           // the way of the leg that stretch belongs to
    };
    // The pose `s` metres from the start (clamped to the ends); none for an empty route.
    std::optional<Pose> poseAt(double s) const;

private:
    std::vector<EnuPoint> m_points;
    std::vector<std::size_t> m_legStart; // index into m_points where each leg starts
    std::vector<std::int64_t> m_legWays;
    double m_length = 0;
};

// Longitudinal limits of a loaded or empty haul truck (m/s²; the creep speed and arrival tolerance keep a
// truck from stalling just short of its destination).
struct DriveLimits {
    double accel = 1.0;            // speeding up
    double approachDecel = 1.0;    // planned stop at the route's end
    double creepSpeed = 0.5;       // m/s, floor of the approach speed
    double arrivalTolerance = 0.5; // m before the end counts as arrived
};

// A truck on its route: distance driven, speed, and the pose they give.
class TruckMotion {
public:
    explicit TruckMotion(DriveLimits limits = {}) : m_limits(limits) {}

    // Starts a route from its beginning (the speed is kept: a truck that just arrived is at rest).
    void setRoute(Route route);
    // Places the truck `s` metres along its route (at rest or not) and updates the pose.
    void placeAt(double s);
    // One step of dt seconds towards `cruise` m/s (0 = brake to a stop), braking at `decel` m/s² and never
    // faster than lets it stop at the route's end.
    void drive(double dt, double cruise, double decel);
    // At the route's end (within the arrival tolerance).
    bool arrived() const { return m_s >= m_route.length() - m_limits.arrivalTolerance; }
    void halt() { m_speed = 0; }

    const Route& route() const { return m_route; }
    double distance() const { return m_s; } // along the route, m
    double remaining() const { return m_route.length() - m_s; }
    double speed() const { return m_speed; } // m/s
    const EnuPoint& position() const { return m_position; }
    double headingDeg() const { return m_headingDeg; } // compass, [0, 360)
    std::int64_t wayId() const { return m_wayId; }     // 0 before the first route

private:
    void updatePose();

    DriveLimits m_limits;
    Route m_route;
    double m_s = 0;
    double m_speed = 0;
    EnuPoint m_position;
    double m_headingDeg = 0;
    std::int64_t m_wayId = 0;
};

} // namespace ocu::sim
