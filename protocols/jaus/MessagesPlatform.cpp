// Platform messages: platform specifications (AS6009) and the IOP health summary (AEP-4818).
#include "protocols/jaus/Messages.h"

#include <array>
#include <numbers>

#include "protocols/jaus/MessageSupport.h"

namespace ocu::jaus {

using namespace codec;

namespace {

using Specs = PlatformSpecifications;
// Field tables (JSIDL ReportPlatformSpecifications, jaus-wire.md §5): each record has its own presence
// vector.
constexpr std::array<ScaledField<Specs>, 2> kSkidSteerFields{{
    {&Specs::trackSeparation, 2, 0, 30},
    {&Specs::driveWheelRadius, 2, 0, 10},
}};
constexpr std::array<ScaledField<Specs>, 4> kAckermannFields{{
    {&Specs::steeringAngleRange, 2, -std::numbers::pi / 2, std::numbers::pi / 2},
    {&Specs::minTurnRadius, 2, 0, 25},
    {&Specs::wheelSeparation, 2, 0, 30},
    {&Specs::ackDriveWheelRadius, 2, 0, 10},
}};
constexpr std::array<ScaledField<Specs>, 7> kLimitFields{{
    {&Specs::maxForwardSpeed, 2, 0, 90},
    {&Specs::maxReverseSpeed, 2, 0, 90},
    {&Specs::maxRotationalSpeed, 2, 0, 6.28},
    {&Specs::maxForwardAccel, 1, 0, 40},
    {&Specs::maxReverseAccel, 1, 0, 40},
    {&Specs::maxForwardDecel, 1, 0, 40},
    {&Specs::maxReverseDecel, 1, 0, 40},
}};
// After the name (str8), which sits between this record's presence vector and its fields.
constexpr std::array<ScaledField<Specs>, 6> kDimensionFields{{
    {&Specs::front, 2, 0, 30},
    {&Specs::back, 2, 0, 30},
    {&Specs::right, 2, 0, 30},
    {&Specs::left, 2, 0, 30},
    {&Specs::bottom, 2, 0, 30},
    {&Specs::top, 2, 0, 30},
}};

template <const auto& Fields> void putRecordU8(ByteWriter& w, const Specs& m) {
    w.u8(std::uint8_t(presenceOf<Fields>(m)));
    putFields<Fields>(w, m);
}
template <const auto& Fields> void getRecordU8(ByteReader& r, Specs& m) {
    const std::uint32_t pv = r.u8();
    getFields<Fields>(r, pv, 0, m);
}

} // namespace

Bytes encode(const PlatformSpecifications& m) {
    Bytes out;
    auto w = start(out, msg::ReportPlatformSpecifications);
    w.u8(m.steeringType);
    if (m.steeringType == 0)
        putRecordU8<kSkidSteerFields>(w, m);
    else
        putRecordU8<kAckermannFields>(w, m);
    putRecordU8<kLimitFields>(w, m);
    w.u16(std::uint16_t(presenceOf<kDimensionFields>(m)));
    putString8(w, m.name);
    putFields<kDimensionFields>(w, m);
    return out;
}
Result<PlatformSpecifications> decodePlatformSpecifications(ByteSpan p) {
    auto r = open(p, msg::ReportPlatformSpecifications);
    if (!r)
        return makeError(r.error());
    PlatformSpecifications m;
    m.steeringType = r->u8();
    if (m.steeringType == 0)
        getRecordU8<kSkidSteerFields>(*r, m);
    else if (m.steeringType == 1)
        getRecordU8<kAckermannFields>(*r, m);
    else
        return makeError("value: ReportPlatformSpecifications variant " + std::to_string(m.steeringType));
    getRecordU8<kLimitFields>(*r, m);
    const std::uint32_t sv = r->u16();
    m.name = getString8(*r);
    getFields<kDimensionFields>(*r, sv, 0, m);
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
