#include "protocols/common/PosePlausibility.h"

#include <cmath>

namespace ocu {

const char* nameFor(PoseFault fault) {
    switch (fault) {
    case PoseFault::None:
        return "none";
    case PoseFault::NonFinite:
        return "non_finite";
    case PoseFault::OutsideExtent:
        return "outside_extent";
    case PoseFault::Speed:
        return "speed";
    case PoseFault::Jump:
        return "jump";
    }
    return "unknown";
}

std::string describe(PoseFault fault, const PoseLimits& l) {
    auto num = [](double v) { return std::to_string(static_cast<long long>(std::llround(v))); };
    switch (fault) {
    case PoseFault::None:
        return "plausible";
    case PoseFault::NonFinite:
        return "a coordinate or the speed is not a finite number";
    case PoseFault::OutsideExtent:
        return "beyond " + num(l.extentM) + " m from the site origin";
    case PoseFault::Speed:
        return "speed above " + num(l.maxSpeedMps) + " m/s";
    case PoseFault::Jump:
        return "a jump faster than " + num(l.maxSpeedMps) + " m/s from the last good position";
    }
    return "unknown";
}

PoseGate::Peer& PoseGate::peer(const std::string& id) {
    auto it = m_peers.find(id);
    if (it != m_peers.end()) {
        m_lru.splice(m_lru.begin(), m_lru, it->second.lru);
        return it->second;
    }
    if (m_peers.size() >= kMaxPeers) {
        m_peers.erase(m_lru.back());
        m_lru.pop_back();
    }
    m_lru.push_front(id);
    Peer& p = m_peers[id];
    p.lru = m_lru.begin();
    return p;
}

bool PoseGate::jumps(const Pose& from, double e, double n, TimePoint now) const {
    const double dt = std::max(0.0, std::chrono::duration<double>(now - from.at).count());
    return std::hypot(e - from.e, n - from.n) > m_limits.maxSpeedMps * dt + m_limits.jumpSlackM;
}

PoseGate::Verdict PoseGate::check(const std::string& id, double e, double n, double u,
                                  std::optional<double> speedMps, TimePoint now) {
    Peer& p = peer(id);
    Verdict v;
    if (!std::isfinite(e) || !std::isfinite(n) || !std::isfinite(u) ||
        (speedMps && !std::isfinite(*speedMps)))
        v.fault = PoseFault::NonFinite;
    else if (std::hypot(e, n) > m_limits.extentM || std::abs(u) > m_limits.extentM)
        v.fault = PoseFault::OutsideExtent;
    else if (speedMps && std::abs(*speedMps) > m_limits.maxSpeedMps)
        v.fault = PoseFault::Speed;
    else if (p.lastGood && jumps(*p.lastGood, e, n, now)) {
        // Several poses in a row that agree with each other but not with the last good one: the machine is
        // there now (or the last good one was the wrong one). Re-anchor instead of pinning it forever.
        const bool agrees = p.lastJump && !jumps(*p.lastJump, e, n, now);
        p.agreeingJumps = agrees ? p.agreeingJumps + 1 : 1;
        p.lastJump = Pose{e, n, now};
        if (p.agreeingJumps < kReanchorAfter)
            v.fault = PoseFault::Jump;
    }
    if (v.ok()) {
        p.lastGood = Pose{e, n, now};
        p.lastJump.reset();
        p.agreeingJumps = 0;
        v.peerCount = p.count;
        return v;
    }
    v.peerCount = ++p.count;
    auto [it, first] = p.warnedAt.try_emplace(v.fault, now);
    if (first || now - it->second >= kWarningGap) {
        it->second = now;
        v.warn = true;
    }
    return v;
}

void PoseGate::forget(const std::string& id) {
    auto it = m_peers.find(id);
    if (it == m_peers.end())
        return;
    m_lru.erase(it->second.lru);
    m_peers.erase(it);
}

std::uint64_t PoseGate::peerCount(const std::string& id) const {
    auto it = m_peers.find(id);
    return it == m_peers.end() ? 0 : it->second.count;
}

} // namespace ocu
