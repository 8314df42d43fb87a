// The simulated UGV's sensor component (GlobalPoseSensor, LocalPoseSensor, VelocityStateSensor, AS6009)
// and the Core Mobility Component's PlatformSpecifications: reports built from the kinematic state.
#include "sim/jaus/UgvCore.h"

#include <cmath>

#include "sim/jaus/UgvSupport.h"

namespace ocu::sim {

using namespace ocu::jaus;
using ugv::wrapAngle;

void UgvCore::registerPoseSensors() {
    const JausId sen = sensors();
    m_table.onQuery(msg::QueryGlobalPose, sen,
                    [this](const JausId&, ByteSpan q) { return reportGlobalPose(q); });
    m_table.onQuery(msg::QueryLocalPose, sen,
                    [this](const JausId&, ByteSpan q) { return reportLocalPose(q); });
    m_table.onQuery(msg::QueryVelocityState, sen,
                    [this](const JausId&, ByteSpan q) { return reportVelocityState(q); });
    m_table.onQuery(msg::QueryPlatformSpecifications, mobility(),
                    [this](const JausId&, ByteSpan) { return reportPlatformSpecifications(); });
}

GlobalPose UgvCore::globalPose() const {
    // Local x north, y east -> ENU (e = y, n = x).
    GeoPoint g = m_geo.toGeodetic(EnuPoint{m_s.y, m_s.x, 0});
    GlobalPose p;
    p.lat = g.lat;
    p.lon = g.lon;
    p.alt = g.alt;
    p.positionRms = 0.05;
    p.roll = 0.0;
    p.pitch = 0.0;
    p.yaw = wrapAngle(m_s.yaw);
    p.attitudeRms = 0.01;
    return p;
}

Bytes UgvCore::reportGlobalPose(ByteSpan q) const {
    auto pv = decodeQueryPv16(q, msg::QueryGlobalPose);
    GlobalPose p = globalPose();
    const std::uint16_t mask = pv ? *pv : 0xFFFF;
    if (!(mask & 1))
        p.lat.reset();
    if (!(mask & 2))
        p.lon.reset();
    if (!(mask & 4))
        p.alt.reset();
    if (!(mask & 8))
        p.positionRms.reset();
    if (!(mask & 16))
        p.roll.reset();
    if (!(mask & 32))
        p.pitch.reset();
    if (!(mask & 64))
        p.yaw.reset();
    if (!(mask & 128))
        p.attitudeRms.reset();
    return encode(p);
}

Bytes UgvCore::reportLocalPose(ByteSpan q) const {
    auto pv = decodeQueryPv16(q, msg::QueryLocalPose);
    const std::uint16_t mask = pv ? *pv : 0xFFFF;
    LocalPose p;
    if (mask & 1)
        p.x = m_s.x;
    if (mask & 2)
        p.y = m_s.y;
    if (mask & 4)
        p.z = 0.0;
    if (mask & 64)
        p.yaw = wrapAngle(m_s.yaw);
    return encode(p);
}

Bytes UgvCore::reportVelocityState(ByteSpan q) const {
    auto pv = decodeQueryPv16(q, msg::QueryVelocityState);
    const std::uint16_t mask = pv ? *pv : 0xFFFF;
    VelocityState v;
    if (mask & 1)
        v.vx = m_s.v;
    if (mask & 2)
        v.vy = 0.0;
    if (mask & 64)
        v.yawRate = m_s.w;
    return encode(v);
}

Bytes UgvCore::reportPlatformSpecifications() const {
    PlatformSpecifications s;
    s.steeringType = m_cfg.kinematics == Kinematics::SkidSteer ? 0 : 1;
    if (s.steeringType == 0) {
        s.trackSeparation = m_cfg.trackWidth;
        s.driveWheelRadius = m_cfg.wheelRadius;
    } else {
        s.minTurnRadius = m_cfg.minTurnRadius;
        s.wheelSeparation = m_cfg.trackWidth;
        s.ackDriveWheelRadius = m_cfg.wheelRadius;
        s.steeringAngleRange = std::atan(m_cfg.wheelBase / m_cfg.minTurnRadius);
    }
    s.maxForwardSpeed = m_cfg.maxForwardSpeed;
    s.maxReverseSpeed = m_cfg.maxReverseSpeed;
    s.maxRotationalSpeed = m_cfg.maxYawRate;
    s.maxForwardAccel = m_cfg.maxAccel;
    s.maxReverseAccel = m_cfg.maxAccel;
    s.maxForwardDecel = m_cfg.maxAccel;
    s.maxReverseDecel = m_cfg.maxAccel;
    s.name = "OCU-SIM " + std::string(m_cfg.kinematics == Kinematics::SkidSteer ? "SkidSteer" : "Ackermann");
    s.front = m_cfg.length / 2;
    s.back = m_cfg.length / 2;
    s.left = m_cfg.width / 2;
    s.right = m_cfg.width / 2;
    s.bottom = 0.0;
    s.top = m_cfg.height;
    return encode(s);
}

} // namespace ocu::sim
