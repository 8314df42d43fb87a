#include "protocols/jaus/clients/MissionFrame.h"

#include <cmath>
#include <numbers>

namespace ocu::jaus {

std::optional<MissionFrame> MissionFrame::from(const GlobalPose& g, const LocalPose& l) {
    if (!g.lat || !g.lon || !l.x || !l.y)
        return std::nullopt;
    const double turn = (g.yaw && l.yaw) ? *l.yaw - *g.yaw : 0.0;
    return MissionFrame(GeoPoint{*g.lat, *g.lon, 0}, *l.x, *l.y, turn);
}

std::pair<double, double> MissionFrame::toLocal(double lat, double lon) const {
    const EnuPoint p = m_geo.toLocal(GeoPoint{lat, lon, 0});
    const double c = std::cos(m_turn), s = std::sin(m_turn);
    return {m_x0 + p.n * c - p.e * s, m_y0 + p.n * s + p.e * c};
}

std::pair<double, double> MissionFrame::toGlobal(double x, double y) const {
    const double dx = x - m_x0, dy = y - m_y0;
    const double c = std::cos(m_turn), s = std::sin(m_turn);
    const GeoPoint g = m_geo.toGeodetic(EnuPoint{-dx * s + dy * c, dx * c + dy * s, 0});
    return {g.lat, g.lon};
}

double groundDistance(double lat1, double lon1, double lat2, double lon2) {
    constexpr double kEarthRadius = 6371008.8;
    constexpr double kRad = std::numbers::pi / 180.0;
    const double dn = (lat2 - lat1) * kRad * kEarthRadius;
    const double de = (lon2 - lon1) * kRad * kEarthRadius * std::cos(0.5 * (lat1 + lat2) * kRad);
    return std::hypot(dn, de);
}

} // namespace ocu::jaus
