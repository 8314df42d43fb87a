#pragma once
// Plausibility gate for OSYRIS positions: a position that cannot be a roller or paver on this
// site is kept in its ribbon (so the slot stays complete for everyone's repair) but never reaches the
// pass-count grid or a model. Without it one CmPos with a drum width of 10^6 m made the grid sweep ~10^13
// cells on the io thread, and x = 10^30 m was drawn on another continent.
#include "protocols/osyris/OsyrisCodec.h"

namespace ocu::osyris {

struct PlausibilityLimits {
    double extentM = 50000;  // |x|, |y| and |z| from the worksite origin (local ENU)
    double minWidthM = 0.2;  // drum or screed width dx, when the position carries one (dx > 0.05 m)
    double maxWidthM = 6.0;  // the safe default; configurable for wide paver screeds
    double maxSpeedMps = 30; // 108 km/h: far beyond any roller or paver
    bool operator==(const PlausibilityLimits&) const = default;
};

enum class PositionFault { None, NonFinite, OutsideExtent, DrumWidth, Speed };

// Stable names for counters and events: "non_finite", "outside_extent", "drum_width", "speed".
const char* nameFor(PositionFault fault);

// The first rule the position breaks, or None.
PositionFault checkPosition(const CmPos& p, const PlausibilityLimits& limits);

// A position's extent dx counts as a drum width only above this (below it the position carries none).
constexpr double kNoExtentBelowM = 0.05;

} // namespace ocu::osyris
