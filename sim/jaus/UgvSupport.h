#pragma once
// Time and angle helpers and the log category shared by the simulated UGV's service files (UgvCore*.cpp,
// Ugv<Service>.cpp); not for use outside sim/jaus.
#include <chrono>
#include <numbers>

#include "protocols/common/Clock.h"

namespace ocu::sim::ugv {

inline constexpr const char* kLog = "ocu.sim.jaus";

inline Duration secondsD(double s) {
    return std::chrono::duration_cast<Duration>(std::chrono::duration<double>(s));
}
inline double seconds(Duration d) {
    return std::chrono::duration<double>(d).count();
}
inline double wrapAngle(double a) {
    while (a > std::numbers::pi)
        a -= 2 * std::numbers::pi;
    while (a < -std::numbers::pi)
        a += 2 * std::numbers::pi;
    return a;
}

} // namespace ocu::sim::ugv
