#pragma once
// Where a vehicle's local frame lies on the earth, from one pair of its own reports (ReportGlobalPose and
// ReportLocalPose of the same moment): local waypoints for a LocalWaypointListDriver are the map's points
// placed through it (jaus-autonomy.md §12 step 1, AEP-4818 §8.2), and local paths come back through it.
// The frames may be turned against each other (JAUS++ puts X along the start heading): the turn is the
// difference of the two reported yaws (both clockwise from their X axis; global X = north).
#include <optional>
#include <utility>

#include "protocols/common/GeoFrame.h"
#include "protocols/jaus/Messages.h"

namespace ocu::jaus {

class MissionFrame {
public:
    // Empty when either pose lacks its position.
    static std::optional<MissionFrame> from(const GlobalPose& global, const LocalPose& local);

    std::pair<double, double> toLocal(double lat, double lon) const; // (x, y) metres
    std::pair<double, double> toGlobal(double x, double y) const;    // (lat, lon) degrees
    double turn() const { return m_turn; }

private:
    MissionFrame(GeoPoint origin, double x0, double y0, double turn)
        : m_geo(origin), m_x0(x0), m_y0(y0), m_turn(turn) {}
    GeoFrame m_geo;
    double m_x0 = 0, m_y0 = 0, m_turn = 0; // the vehicle's local position at the origin; local yaw - global
};

// Horizontal distance in metres between two WGS84 points (spherical, short distances).
double groundDistance(double lat1, double lon1, double lat2, double lon2);

} // namespace ocu::jaus
