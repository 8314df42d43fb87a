// The simulated UGV's driving: PrimitiveDriver and VelocityStateDriver on the Core Mobility Component
// (AS6009, AEP-4818 §7), the drive timeout and its recovery (§7.1.1), and the kinematic model that moves it.
#include "sim/jaus/UgvCore.h"

#include <algorithm>
#include <cmath>

#include "protocols/common/Log.h"
#include "sim/jaus/UgvSupport.h"

namespace ocu::sim {

using namespace ocu::jaus;
using ugv::kLog;
using ugv::secondsD;

namespace {
double approach(double cur, double target, double maxStep) {
    if (target > cur)
        return std::min(target, cur + maxStep);
    return std::max(target, cur - maxStep);
}
} // namespace

void UgvCore::registerDriving() {
    const JausId mob = mobility();
    m_table.onCommand(msg::SetWrenchEffort, mob,
                      [this](const JausId&, const JausId& src, ByteSpan p) { setWrenchEffort(src, p); });
    m_table.onCommand(msg::SetVelocityCommand, mob,
                      [this](const JausId&, const JausId& src, ByteSpan p) { setVelocityCommand(src, p); });
    m_table.onQuery(msg::QueryWrenchEffort, mob, [this](const JausId&, ByteSpan) {
        return encodeWrench(msg::ReportWrenchEffort, m_wrench); // echoes the command (AEP-4818 §7.7.2)
    });
    m_table.onQuery(msg::QueryVelocityCommand, mob, [this](const JausId&, ByteSpan q) {
        VelocityCommand v = m_velCmd;
        if (q.size() >= 4 && q[3] == 1) { // maximum limits in force
            v = VelocityCommand{};
            v.commandType = 1;
            v.vx = m_cfg.maxForwardSpeed;
            v.yawRate = m_cfg.maxYawRate;
        }
        return encodeVelocityCommand(msg::ReportVelocityCommand, v);
    });
}

void UgvCore::setWrenchEffort(const JausId& src, ByteSpan p) {
    const TimePoint now = m_clock.now();
    if (!isController(src)) {
        m_counters.add("rx.refused.not_controller");
        return;
    }
    auto w = decodeWrench(p, msg::SetWrenchEffort);
    if (!w)
        return rejectMalformed(w.error());
    m_wrench = *w;
    m_velocityMode = false;
    // One scaled-integer step around zero is zero (0 % encodes as 0x8000 = +0.0015 %).
    auto dead = [](double pct) { return std::abs(pct) < 0.01 ? 0.0 : pct; };
    const double lin = dead(w->propLinX.value_or(0)) / 100.0;
    m_cmdV = lin >= 0 ? lin * m_cfg.maxForwardSpeed : lin * m_cfg.maxReverseSpeed;
    m_cmdW = dead(w->propRotZ.value_or(0)) / 100.0 * m_cfg.maxYawRate;
    m_brake = dead(w->resLinX.value_or(0)) / 100.0;
    driveMessage(now);
}

void UgvCore::setVelocityCommand(const JausId& src, ByteSpan p) {
    const TimePoint now = m_clock.now();
    if (!isController(src)) {
        m_counters.add("rx.refused.not_controller");
        return;
    }
    auto v = decodeVelocityCommand(p, msg::SetVelocityCommand);
    if (!v)
        return rejectMalformed(v.error());
    if (v->commandType != 0)
        return; // limits (type 1-3) are fixed to the platform specification in the simulator
    m_velCmd = *v;
    m_velocityMode = true;
    m_cmdV = std::clamp(v->vx.value_or(0), -m_cfg.maxReverseSpeed, m_cfg.maxForwardSpeed);
    m_cmdW = std::clamp(v->yawRate.value_or(0), -m_cfg.maxYawRate, m_cfg.maxYawRate);
    m_brake = 0;
    driveMessage(now);
}

void UgvCore::forceDriveTimeout() {
    m_s.driveTimedOut = true;
    m_recoveryStart = TimePoint{};
}

void UgvCore::driveMessage(TimePoint now) {
    // Drive timeout recovery: commands must arrive continuously for driveRecoveryS (AEP-4818 §7.1.1).
    if (m_s.driveTimedOut) {
        const Duration maxGap = secondsD(1.0 / std::max(m_cfg.minDriveRateHz, 0.1));
        if (m_recoveryStart == TimePoint{} || now - m_lastDrive > maxGap)
            m_recoveryStart = now;
        if (now - m_recoveryStart >= secondsD(m_cfg.driveRecoveryS)) {
            m_s.driveTimedOut = false;
            logInfo(kLog, m_cfg.callSign + ": drive timeout recovered");
        }
    }
    m_lastDrive = now;
    m_haveDrive = true;
}

void UgvCore::physics(TimePoint now) {
    if (m_lastPhysics == TimePoint{}) {
        m_lastPhysics = now;
        return;
    }
    const double dt = std::min(ugv::seconds(now - m_lastPhysics), 0.5);
    m_lastPhysics = now;
    if (dt <= 0)
        return;
    followRoute(now);
    if (m_cfg.driveTimeoutS > 0 && m_haveDrive && !m_s.driveTimedOut &&
        now - m_lastDrive > secondsD(m_cfg.driveTimeoutS)) {
        m_s.driveTimedOut = true;
        m_recoveryStart = TimePoint{};
        m_counters.add("drive.timeouts"); // stays counted after recovery (tests tell a stop from a timeout)
        logWarning(kLog, m_cfg.callSign + ": drive timeout");
    }
    const bool mayMove = m_s.management == ManagementState::Ready && m_s.controller.subsystem != 0 &&
                         !m_s.driveTimedOut && m_haveDrive;
    double tv = mayMove ? m_cmdV * (1.0 - m_brake) : 0.0;
    double tw = mayMove ? m_cmdW : 0.0;
    if (m_cfg.kinematics == Kinematics::Ackermann) {
        // No turning on the spot: |yaw rate| ≤ |v| / minimum turn radius.
        const double maxW = std::abs(m_s.v) / std::max(m_cfg.minTurnRadius, 0.1);
        tw = std::clamp(tw, -maxW, maxW);
    }
    if (m_s.management == ManagementState::Emergency || m_s.management == ManagementState::Failure) {
        m_s.v = m_s.w = 0;
    } else {
        m_s.v = approach(m_s.v, tv, m_cfg.maxAccel * dt);
        m_s.w = approach(m_s.w, tw, m_cfg.maxYawAccel * dt);
    }
    // + yaw rate = turn right = clockwise from above (AEP-4818 §7.7); x north, y east.
    m_s.yaw = ugv::wrapAngle(m_s.yaw + m_s.w * dt);
    m_s.x += m_s.v * std::cos(m_s.yaw) * dt;
    m_s.y += m_s.v * std::sin(m_s.yaw) * dt;
    m_s.odometer += std::abs(m_s.v) * dt;
    recordPath();
}

} // namespace ocu::sim
