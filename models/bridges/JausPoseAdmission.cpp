#include "models/bridges/JausBridge.h"

#include "protocols/jaus/JausStack.h"

#include <cmath>
#include <cstring>

namespace ocu {

using namespace jaus;

QString JausBridge::admitPose(SubsystemSnapshot& s) {
    PoseIo& io = m_poseIo[s.subsystem];
    double pose[4] = {0, 0, 0, 0};
    bool hasPose = false;
    bool onGlobe = true;
    if (s.globalPose && s.globalPose->lat && s.globalPose->lon) {
        const double lat = *s.globalPose->lat, lon = *s.globalPose->lon;
        onGlobe = !(std::abs(lat) > 90) && !(std::abs(lon) > 180);
        const EnuPoint p = m_frame.toLocal({lat, lon, s.globalPose->alt.value_or(m_frame.origin().alt)});
        pose[0] = onGlobe ? p.e : 1e300; // beyond the globe: as far outside the site as it gets
        pose[1] = p.n;
        pose[2] = p.u;
        hasPose = true;
    } else if (s.localPose && s.localPose->x && s.localPose->y) {
        pose[0] = *s.localPose->y; // x north, y east
        pose[1] = *s.localPose->x;
        pose[2] = s.localPose->z.value_or(0);
        hasPose = true;
    }
    std::optional<double> speed;
    if (s.velocity && s.velocity->vx)
        speed = std::hypot(*s.velocity->vx, s.velocity->vy.value_or(0));
    pose[3] = speed.value_or(0);
    if (!hasPose)
        return {};
    // A snapshot changes for many reasons (status, control, heartbeats): the same pose is judged once.
    if (!io.hasChecked || std::memcmp(io.checked, pose, sizeof pose) != 0) {
        std::memcpy(io.checked, pose, sizeof pose);
        io.hasChecked = true;
        const PoseGate::Verdict v = m_poseGate.check(std::to_string(s.subsystem), pose[0], pose[1], pose[2],
                                                     speed, SteadyClock::instance().now());
        if (v.ok()) {
            io.implausible.clear();
            io.globalPose = s.globalPose;
            io.localPose = s.localPose;
            io.velocity = s.velocity;
        } else {
            const char* cause = nameFor(v.fault);
            m_stack->counters().add(std::string("rx.implausible.") + cause);
            const QString why = QString::fromStdString(describe(v.fault, m_poseGate.limits()));
            io.implausible = tr("implausible pose ignored (%1 so far): %2").arg(v.peerCount).arg(why);
            if (v.warn)
                publishEvent(
                    makeEvent(EventSeverity::Warning, ocu::EventKind::Diagnostic, machineId(s.subsystem),
                              tr("JAUS subsystem %1: pose ignored, %2 (east %3 m, north %4 m, speed %5 "
                                 "m/s); last good pose kept (counted in rx.implausible.%6; one warning "
                                 "per vehicle and cause every 30 s)")
                                  .arg(s.subsystem)
                                  .arg(why)
                                  .arg(pose[0], 0, 'g', 6)
                                  .arg(pose[1], 0, 'g', 6)
                                  .arg(pose[3], 0, 'g', 6)
                                  .arg(QLatin1String(cause)),
                              QStringLiteral("jaus")));
        }
    }
    if (!io.implausible.isEmpty()) {
        s.globalPose = io.globalPose;
        s.localPose = io.localPose;
        s.velocity = io.velocity;
    }
    return io.implausible;
}

} // namespace ocu
