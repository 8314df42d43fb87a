#pragma once
// Plausibility gate for machine poses of ISO 23725 and JAUS (OSYRIS has its own in
// protocols/osyris/Plausibility.h): a pose that cannot be a machine on this site is not drawn. Without it NaN
// coordinates were shown as "no position" with health "ok" and x = 10^30 m as a position on another
// continent. The caller keeps the last good pose, marks the machine implausible, counts the cause
// (rx.implausible.<cause>) and raises the warning this gate allows: one per peer and cause every 30 s.
//
// Poses are checked in the site's local East/North/Up frame (metres from the site origin). State is bounded:
// at most kMaxPeers peers are tracked (the least recently seen is forgotten first).
#include "protocols/common/Clock.h"

#include <cstdint>
#include <list>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>

namespace ocu {

struct PoseLimits {
    double extentM = 50000;  // horizontal distance from the site origin (and |up|)
    double maxSpeedMps = 30; // reported speed, and the speed implied between two poses (108 km/h)
    double jumpSlackM = 50;  // position noise allowed on top of maxSpeedMps x elapsed time between two poses
    bool operator==(const PoseLimits&) const = default;
};

enum class PoseFault { None, NonFinite, OutsideExtent, Speed, Jump };

// Stable names for counters and events: "non_finite", "outside_extent", "speed", "jump".
const char* nameFor(PoseFault fault);
// For people: what the limit is ("beyond 50000 m from the site origin", ...).
std::string describe(PoseFault fault, const PoseLimits& limits);

class PoseGate {
public:
    static constexpr std::size_t kMaxPeers = 4096;
    static constexpr std::chrono::seconds kWarningGap{30};
    // A pose that jumps from the last good one is accepted once this many poses in a row agree with each
    // other (the machine was moved, or its first pose was the wrong one): a jump cannot pin a machine
    // forever.
    static constexpr int kReanchorAfter = 3;

    explicit PoseGate(PoseLimits limits = {}) : m_limits(limits) {}
    const PoseLimits& limits() const { return m_limits; }

    struct Verdict {
        PoseFault fault = PoseFault::None;
        bool warn = false;           // raise the operator warning now (first for this peer and cause in 30 s)
        std::uint64_t peerCount = 0; // implausible poses of this peer so far
        bool ok() const { return fault == PoseFault::None; }
    };
    // e/n/u: metres from the site origin; speed: m/s as reported (if any). A good pose becomes the peer's
    // last good one.
    Verdict check(const std::string& peer, double e, double n, double u, std::optional<double> speedMps,
                  TimePoint now);
    void forget(const std::string& peer);
    std::uint64_t peerCount(const std::string& peer) const;
    std::size_t peers() const { return m_peers.size(); }

private:
    struct Pose {
        double e = 0, n = 0;
        TimePoint at;
    };
    struct Peer {
        std::optional<Pose> lastGood;
        std::optional<Pose> lastJump; // the last pose rejected as a jump
        int agreeingJumps = 0;
        std::uint64_t count = 0;
        std::map<PoseFault, TimePoint> warnedAt;
        std::list<std::string>::iterator lru;
    };
    bool jumps(const Pose& from, double e, double n, TimePoint now) const;
    Peer& peer(const std::string& id);

    PoseLimits m_limits;
    std::unordered_map<std::string, Peer> m_peers;
    std::list<std::string> m_lru; // most recently seen first
};

} // namespace ocu
