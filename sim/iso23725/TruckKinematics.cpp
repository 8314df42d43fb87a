#include "sim/iso23725/TruckKinematics.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ocu::sim {

namespace {

double horizontal(const EnuPoint& a, const EnuPoint& b) {
    return std::hypot(b.e - a.e, b.n - a.n);
}
} // namespace

void Route::addLeg(std::int64_t wayId, const std::vector<EnuPoint>& points) {
    m_legStart.push_back(m_points.size());
    m_legWays.push_back(wayId);
    for (const auto& p : points) {
        if (!m_points.empty())
            m_length += horizontal(m_points.back(), p);
        m_points.push_back(p);
    }
}

std::optional<Route::Pose> Route::poseAt(double s) const {
    if (empty())
        return std::nullopt;
    double rem = s;
    for (std::size_t i = 0; i + 1 < m_points.size(); ++i) {
        const auto& a = m_points[i];
        const auto& b = m_points[i + 1];
        const double len = horizontal(a, b);
        if (rem <= len || i + 2 == m_points.size()) {
            Pose p;
            const double f = len > 0 ? std::clamp(rem / len, 0.0, 1.0) : 0.0;
            p.position = {a.e + f * (b.e - a.e), a.n + f * (b.n - a.n), a.u + f * (b.u - a.u)};
            if (len > 0.01)
                p.headingDeg =
                    std::fmod(std::atan2(b.e - a.e, b.n - a.n) * 180 / std::numbers::pi + 360.0, 360.0);
            std::size_t leg = 0;
            for (std::size_t k = 0; k < m_legStart.size(); ++k)
                if (m_legStart[k] <= i)
                    leg = k;
            p.wayId = m_legWays[leg];
            return p;
        }
        rem -= len;
    }
    return std::nullopt; // not reached: the last stretch takes any remainder
}

void TruckMotion::setRoute(Route route) {
    m_route = std::move(route);
    m_s = 0;
}

void TruckMotion::placeAt(double s) {
    m_s = s;
    updatePose();
}

void TruckMotion::drive(double dt, double cruise, double decel) {
    // Never faster than allows a stop at the end at the approach deceleration (plus a creep speed).
    const double target = std::min(
        cruise, std::sqrt(2 * m_limits.approachDecel * std::max(0.0, remaining())) + m_limits.creepSpeed);
    m_speed = target > m_speed ? std::min(target, m_speed + m_limits.accel * dt)
                               : std::max(target, m_speed - decel * dt);
    m_s += m_speed * dt;
    updatePose();
}

void TruckMotion::updatePose() {
    const auto p = m_route.poseAt(m_s);
    if (!p)
        return;
    m_position = p->position;
    if (p->headingDeg)
        m_headingDeg = *p->headingDeg; // a degenerate stretch keeps the last heading
    m_wayId = p->wayId;
}

} // namespace ocu::sim
