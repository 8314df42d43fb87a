// Platform messages: platform specifications (AS6009) and the IOP health summary (AEP-4818).
#include "protocols/jaus/Messages.h"

#include <numbers>

#include "protocols/jaus/MessageSupport.h"

namespace ocu::jaus {

using namespace codec;

namespace {

constexpr double kPi = std::numbers::pi;

} // namespace

Bytes encode(const PlatformSpecifications& m) {
    Bytes out;
    auto w = start(out, msg::ReportPlatformSpecifications);
    w.u8(m.steeringType);
    if (m.steeringType == 0) {
        PvWriter pv;
        pv.mark(m.trackSeparation);
        pv.mark(m.driveWheelRadius);
        w.u8(std::uint8_t(pv.pv));
        putU16s(w, m.trackSeparation, 0, 30);
        putU16s(w, m.driveWheelRadius, 0, 10);
    } else {
        PvWriter pv;
        pv.mark(m.steeringAngleRange);
        pv.mark(m.minTurnRadius);
        pv.mark(m.wheelSeparation);
        pv.mark(m.ackDriveWheelRadius);
        w.u8(std::uint8_t(pv.pv));
        putU16s(w, m.steeringAngleRange, -kPi / 2, kPi / 2);
        putU16s(w, m.minTurnRadius, 0, 25);
        putU16s(w, m.wheelSeparation, 0, 30);
        putU16s(w, m.ackDriveWheelRadius, 0, 10);
    }
    PvWriter iv;
    iv.mark(m.maxForwardSpeed);
    iv.mark(m.maxReverseSpeed);
    iv.mark(m.maxRotationalSpeed);
    iv.mark(m.maxForwardAccel);
    iv.mark(m.maxReverseAccel);
    iv.mark(m.maxForwardDecel);
    iv.mark(m.maxReverseDecel);
    w.u8(std::uint8_t(iv.pv));
    putU16s(w, m.maxForwardSpeed, 0, 90);
    putU16s(w, m.maxReverseSpeed, 0, 90);
    putU16s(w, m.maxRotationalSpeed, 0, 6.28);
    putU8s(w, m.maxForwardAccel, 0, 40);
    putU8s(w, m.maxReverseAccel, 0, 40);
    putU8s(w, m.maxForwardDecel, 0, 40);
    putU8s(w, m.maxReverseDecel, 0, 40);
    PvWriter sv;
    for (auto* f : {&m.front, &m.back, &m.right, &m.left, &m.bottom, &m.top})
        sv.mark(*f);
    w.u16(std::uint16_t(sv.pv));
    putString8(w, m.name);
    for (auto* f : {&m.front, &m.back, &m.right, &m.left, &m.bottom, &m.top})
        putU16s(w, *f, 0, 30);
    return out;
}
Result<PlatformSpecifications> decodePlatformSpecifications(ByteSpan p) {
    auto r = open(p, msg::ReportPlatformSpecifications);
    if (!r)
        return makeError(r.error());
    PlatformSpecifications m;
    m.steeringType = r->u8();
    if (m.steeringType == 0) {
        const std::uint32_t pv = r->u8();
        getU16s(*r, pv, 0, m.trackSeparation, 0, 30);
        getU16s(*r, pv, 1, m.driveWheelRadius, 0, 10);
    } else if (m.steeringType == 1) {
        const std::uint32_t pv = r->u8();
        getU16s(*r, pv, 0, m.steeringAngleRange, -kPi / 2, kPi / 2);
        getU16s(*r, pv, 1, m.minTurnRadius, 0, 25);
        getU16s(*r, pv, 2, m.wheelSeparation, 0, 30);
        getU16s(*r, pv, 3, m.ackDriveWheelRadius, 0, 10);
    } else {
        return makeError("value: ReportPlatformSpecifications variant " + std::to_string(m.steeringType));
    }
    const std::uint32_t iv = r->u8();
    getU16s(*r, iv, 0, m.maxForwardSpeed, 0, 90);
    getU16s(*r, iv, 1, m.maxReverseSpeed, 0, 90);
    getU16s(*r, iv, 2, m.maxRotationalSpeed, 0, 6.28);
    getU8s(*r, iv, 3, m.maxForwardAccel, 0, 40);
    getU8s(*r, iv, 4, m.maxReverseAccel, 0, 40);
    getU8s(*r, iv, 5, m.maxForwardDecel, 0, 40);
    getU8s(*r, iv, 6, m.maxReverseDecel, 0, 40);
    const std::uint32_t sv = r->u16();
    m.name = getString8(*r);
    std::optional<double>* dims[] = {&m.front, &m.back, &m.right, &m.left, &m.bottom, &m.top};
    for (int i = 0; i < 6; ++i)
        getU16s(*r, sv, i, *dims[i], 0, 30);
    // Remaining spec fields (centre of gravity, weight, angles) are not used by the console: skipped.
    return finish(*r, m, msg::ReportPlatformSpecifications);
}

Bytes encode(const HealthSummary& m) {
    Bytes out;
    auto w = start(out, msg::ReportHealthSummary);
    w.u8(m.severity);
    w.u8(std::uint8_t(std::min<std::size_t>(m.nodes.size(), 255)));
    for (std::size_t i = 0; i < m.nodes.size() && i < 255; ++i) {
        w.u8(m.nodes[i].first);
        w.u8(m.nodes[i].second);
    }
    return out;
}
Result<HealthSummary> decodeHealthSummary(ByteSpan p) {
    auto r = open(p, msg::ReportHealthSummary);
    if (!r)
        return makeError(r.error());
    HealthSummary m;
    m.severity = r->u8();
    auto n = r->u8();
    for (int i = 0; i < n && r->ok(); ++i) {
        auto node = r->u8();
        auto sev = r->u8();
        m.nodes.emplace_back(node, sev);
    }
    return finish(*r, m, msg::ReportHealthSummary);
}

} // namespace ocu::jaus
