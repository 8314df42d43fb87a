#include "sim/osyris/SimulatedRoller.h"

#include <cmath>
#include <numbers>

namespace ocu::sim::osyris {

using namespace ocu::osyris;

namespace {
// Deterministic hash noise in [0, 1) (no shared RNG state: poses are pure functions of time).
double noise(std::uint32_t seed, std::uint64_t n) {
    std::uint64_t x = (std::uint64_t(seed) << 32) ^ (n * 0x9E3779B97F4A7C15ull);
    x ^= x >> 31;
    x *= 0xBF58476D1CE4E5B9ull;
    x ^= x >> 27;
    x *= 0x94D049BB133111EBull;
    x ^= x >> 31;
    return double(x >> 11) / double(1ull << 53);
}
} // namespace

CmPos SimulatedMachine::poseAt(double t, std::int64_t unixMs) const {
    const auto& s = m_spec;
    CmPos p;
    p.time = unixMs ? unixMillisToFileTime(unixMs) : 0;
    p.dx = static_cast<float>(s.width);
    p.dy = s.kind == MachineKind::Roller ? 1.2f : 0.f;
    p.z = 100.f;
    const float east = static_cast<float>(-std::numbers::pi / 2); // yaw: north = 0, west = +pi/2
    std::uint32_t flags = kPosValid;
    double x = 0, y = 0;
    switch (s.kind) {
    case MachineKind::Paver:
        x = paverX(t);
        y = s.laneOffset;
        p.yaw = east;
        p.speed = s.paverSpeed;
        flags |= kPosForward;
        break;
    case MachineKind::Roller: {
        double L = s.passLength;
        double d = s.speed * t + s.phase;
        double cyc = std::fmod(d, 2 * L);
        long pass = static_cast<long>(std::floor(d / L));
        double winStart = paverX(t) - s.gapBehindPaver - L;
        bool fwd = cyc < L;
        x = winStart + (fwd ? cyc : 2 * L - cyc);
        y = s.laneOffset;
        p.yaw = east; // a tandem roller reverses without turning
        p.speed = s.speed;
        flags |= fwd ? kPosForward : kPosBackward;
        if (!(s.vibrationOffEvery > 0 && pass % s.vibrationOffEvery == s.vibrationOffEvery - 1))
            flags |= kPosVibrating;
        break;
    }
    case MachineKind::Relay: {
        double dx = s.x1 - s.x0, dy = s.y1 - s.y0;
        double len = std::hypot(dx, dy);
        double f = 0;
        if (len > 0 && s.speed > 0) {
            double c = std::fmod(s.speed * t, 2 * len);
            f = (c < len ? c : 2 * len - c) / len;
            flags |= c < len ? kPosForward : kPosBackward;
        } else {
            flags |= kPosStop;
        }
        x = s.x0 + f * dx;
        y = s.y0 + f * dy;
        p.yaw = static_cast<float>(std::atan2(-dx, dy));
        p.speed = s.speed;
        break;
    }
    }
    std::uint64_t n = static_cast<std::uint64_t>(t * 10);
    flags |= noise(s.seed, n) < s.mediumAccuracyRate ? kPosAccuracyMed : kPosAccuracyHigh;
    if (s.shadowFromX < s.shadowToX && x >= s.shadowFromX && x <= s.shadowToX)
        flags = (flags & ~(kPosValid | kPosAccuracyMed | kPosAccuracyHigh)) | kPosGpsShadow | kPosAccuracyLow;
    if (s.job && s.kind != MachineKind::Relay) {
        int lift = 0;
        double station = 0, heading = 0;
        s.job->liftOf(x, lift, station);
        s.job->at(station, y, x, y, heading);
        p.z = static_cast<float>(s.job->zOf(lift));
        p.yaw = static_cast<float>(heading - std::numbers::pi / 2); // north = 0, west = +pi/2
    }
    p.x = static_cast<float>(x);
    p.y = static_cast<float>(y);
    p.flags = flags;
    return p;
}

std::optional<std::string> SimulatedMachine::crewMessage(double t0, double t1) const {
    if (m_spec.job && m_spec.kind != MachineKind::Relay && t1 > 0) {
        // A lift finished: the driver says so ("Roller 1: lift 2 done").
        const auto along = [&](double t) {
            const CmPos straight = SimulatedMachine([&] {
                                       MachineSpec plain = m_spec;
                                       plain.job.reset();
                                       return plain;
                                   }())
                                       .poseAt(t);
            return double(straight.x);
        };
        int k0 = 0, k1 = 0;
        double st = 0;
        m_spec.job->liftOf(along(std::max(t0, 0.0)), k0, st);
        m_spec.job->liftOf(along(t1), k1, st);
        if (k1 > k0)
            return (m_spec.name + ": lift " + std::to_string(k0 + 1) + " done").substr(0, 79);
    }
    const double every = m_spec.crewMessageEveryS;
    if (m_spec.kind == MachineKind::Relay || !(every > 0) || t1 <= 0 ||
        std::floor(t1 / every) <= std::floor(std::max(t0, 0.0) / every))
        return std::nullopt;
    const auto x = static_cast<long>(std::lround(
        m_spec.kind == MachineKind::Paver ? paverX(t1)
                                          : paverX(t1) - m_spec.gapBehindPaver - m_spec.passLength));
    std::string text = m_spec.kind == MachineKind::Paver
                           ? m_spec.name + ": paved up to x=" + std::to_string(x) + " m"
                           : m_spec.name + ": rolled up to x=" + std::to_string(x) + " m";
    return text.substr(0, 79);
}

std::string SimulatedMachine::crewReply(const std::string& received) const {
    return (m_spec.name + ": OK, " + received).substr(0, 79);
}

} // namespace ocu::sim::osyris
