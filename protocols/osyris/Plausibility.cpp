#include "protocols/osyris/Plausibility.h"

#include <cmath>

namespace ocu::osyris {

const char* nameFor(PositionFault fault) {
    switch (fault) {
    case PositionFault::None:
        return "none";
    case PositionFault::NonFinite:
        return "non_finite";
    case PositionFault::OutsideExtent:
        return "outside_extent";
    case PositionFault::DrumWidth:
        return "drum_width";
    case PositionFault::Speed:
        return "speed";
    }
    return "unknown";
}

PositionFault checkPosition(const CmPos& p, const PlausibilityLimits& l) {
    for (double v : {double(p.x), double(p.y), double(p.z), double(p.yaw), double(p.dx), p.speed})
        if (!std::isfinite(v))
            return PositionFault::NonFinite;
    if (std::abs(p.x) > l.extentM || std::abs(p.y) > l.extentM || std::abs(p.z) > l.extentM)
        return PositionFault::OutsideExtent;
    if (p.dx > kNoExtentBelowM && (p.dx < l.minWidthM || p.dx > l.maxWidthM))
        return PositionFault::DrumWidth;
    if (p.dx < 0)
        return PositionFault::DrumWidth;
    if (std::abs(p.speed) > l.maxSpeedMps)
        return PositionFault::Speed;
    return PositionFault::None;
}

} // namespace ocu::osyris
