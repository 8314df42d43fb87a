// Mobility messages (AS6009): wrench effort, velocity command, global/local pose, velocity state.
#include "protocols/jaus/Messages.h"

#include <array>
#include <numbers>

#include "protocols/jaus/MessageSupport.h"

namespace ocu::jaus {

using namespace codec;

namespace {

// Field tables (JSIDL layouts, jaus-wire.md §3 and §5): presence-vector bits in table order.
constexpr std::array<ScaledField<WrenchEffort>, 12> kWrenchFields{{
    {&WrenchEffort::propLinX, 2, -100, 100},
    {&WrenchEffort::propLinY, 2, -100, 100},
    {&WrenchEffort::propLinZ, 2, -100, 100},
    {&WrenchEffort::propRotX, 2, -100, 100},
    {&WrenchEffort::propRotY, 2, -100, 100},
    {&WrenchEffort::propRotZ, 2, -100, 100},
    {&WrenchEffort::resLinX, 1, 0, 100},
    {&WrenchEffort::resLinY, 1, 0, 100},
    {&WrenchEffort::resLinZ, 1, 0, 100},
    {&WrenchEffort::resRotX, 1, 0, 100},
    {&WrenchEffort::resRotY, 1, 0, 100},
    {&WrenchEffort::resRotZ, 1, 0, 100},
}};
constexpr std::array<ScaledField<VelocityCommand>, 6> kVelocityCommandFields{{
    {&VelocityCommand::vx, 4, -327.68, 327.67},
    {&VelocityCommand::vy, 4, -327.68, 327.67},
    {&VelocityCommand::vz, 4, -327.68, 327.67},
    {&VelocityCommand::rollRate, 2, -32.768, 32.767},
    {&VelocityCommand::pitchRate, 2, -32.768, 32.767},
    {&VelocityCommand::yawRate, 2, -32.768, 32.767},
}};
constexpr std::array<ScaledField<GlobalPose>, 8> kGlobalPoseFields{{
    {&GlobalPose::lat, 4, -90, 90},
    {&GlobalPose::lon, 4, -180, 180},
    {&GlobalPose::alt, 4, -10000, 35000},
    {&GlobalPose::positionRms, 4, 0, 100},
    {&GlobalPose::roll, 2, -std::numbers::pi, std::numbers::pi},
    {&GlobalPose::pitch, 2, -std::numbers::pi, std::numbers::pi},
    {&GlobalPose::yaw, 2, -std::numbers::pi, std::numbers::pi},
    {&GlobalPose::attitudeRms, 2, 0, std::numbers::pi},
}};
constexpr std::array<ScaledField<LocalPose>, 8> kLocalPoseFields{{
    {&LocalPose::x, 4, -100000, 100000},
    {&LocalPose::y, 4, -100000, 100000},
    {&LocalPose::z, 4, -100000, 100000},
    {&LocalPose::positionRms, 4, 0, 100},
    {&LocalPose::roll, 2, -std::numbers::pi, std::numbers::pi},
    {&LocalPose::pitch, 2, -std::numbers::pi, std::numbers::pi},
    {&LocalPose::yaw, 2, -std::numbers::pi, std::numbers::pi},
    {&LocalPose::attitudeRms, 2, 0, std::numbers::pi},
}};
constexpr std::array<ScaledField<VelocityState>, 8> kVelocityStateFields{{
    {&VelocityState::vx, 4, -327.68, 327.67},
    {&VelocityState::vy, 4, -327.68, 327.67},
    {&VelocityState::vz, 4, -327.68, 327.67},
    {&VelocityState::velocityRms, 4, 0, 100},
    {&VelocityState::rollRate, 2, -32.768, 32.767},
    {&VelocityState::pitchRate, 2, -32.768, 32.767},
    {&VelocityState::yawRate, 2, -32.768, 32.767},
    {&VelocityState::rateRms, 2, 0, std::numbers::pi},
}};

// Pose and velocity-state reports share one shape: PV u16, the table's fields, then a raw u32 timestamp on
// the bit after them.
template <const auto& Fields, class T> Bytes encodeStamped(std::uint16_t id, const T& m) {
    constexpr std::uint32_t stampBit = 1u << Fields.size();
    Bytes out;
    auto w = start(out, id);
    w.u16(std::uint16_t(presenceOf<Fields>(m) | (m.timestamp ? stampBit : 0u)));
    putFields<Fields>(w, m);
    if (m.timestamp)
        w.u32(*m.timestamp);
    return out;
}
template <const auto& Fields, class T> Result<T> decodeStamped(ByteSpan p, std::uint16_t id) {
    auto r = open(p, id);
    if (!r)
        return makeError(r.error());
    T m;
    const std::uint32_t pv = r->u16();
    getFields<Fields>(*r, pv, 0, m);
    if (pv & (1u << Fields.size()))
        m.timestamp = r->u32();
    return finish(*r, m, id);
}

} // namespace

Bytes encodeWrench(std::uint16_t id, const WrenchEffort& m) {
    Bytes out;
    auto w = start(out, id);
    w.u16(std::uint16_t(presenceOf<kWrenchFields>(m)));
    putFields<kWrenchFields>(w, m);
    return out;
}
Result<WrenchEffort> decodeWrench(ByteSpan p, std::uint16_t id) {
    auto r = open(p, id);
    if (!r)
        return makeError(r.error());
    WrenchEffort m;
    const std::uint32_t pv = r->u16();
    getFields<kWrenchFields>(*r, pv, 0, m);
    return finish(*r, m, id);
}

Bytes encodeVelocityCommand(std::uint16_t id, const VelocityCommand& m) {
    Bytes out;
    auto w = start(out, id);
    w.u8(std::uint8_t(presenceOf<kVelocityCommandFields>(m)));
    w.u8(m.commandType);
    putFields<kVelocityCommandFields>(w, m);
    return out;
}
Result<VelocityCommand> decodeVelocityCommand(ByteSpan p, std::uint16_t id) {
    auto r = open(p, id);
    if (!r)
        return makeError(r.error());
    VelocityCommand m;
    const std::uint32_t pv = r->u8();
    m.commandType = r->u8();
    getFields<kVelocityCommandFields>(*r, pv, 0, m);
    return finish(*r, m, id);
}

Bytes encodeQueryPv16(std::uint16_t id, std::uint16_t presence) {
    return encodeU16(id, presence);
}
Result<std::uint16_t> decodeQueryPv16(ByteSpan p, std::uint16_t id) {
    return decodeU16(p, id);
}
Bytes encodeQueryVelocityCommand(std::uint8_t presence, std::uint8_t commandType) {
    Bytes out;
    auto w = start(out, msg::QueryVelocityCommand);
    w.u8(presence);
    w.u8(commandType);
    return out;
}

Bytes encode(const GlobalPose& m, std::uint16_t id) {
    return encodeStamped<kGlobalPoseFields>(id, m);
}
Result<GlobalPose> decodeGlobalPose(ByteSpan p, std::uint16_t id) {
    return decodeStamped<kGlobalPoseFields, GlobalPose>(p, id);
}
Bytes encode(const LocalPose& m, std::uint16_t id) {
    return encodeStamped<kLocalPoseFields>(id, m);
}
Result<LocalPose> decodeLocalPose(ByteSpan p, std::uint16_t id) {
    return decodeStamped<kLocalPoseFields, LocalPose>(p, id);
}
Bytes encode(const VelocityState& m) {
    return encodeStamped<kVelocityStateFields>(msg::ReportVelocityState, m);
}
Result<VelocityState> decodeVelocityState(ByteSpan p) {
    return decodeStamped<kVelocityStateFields, VelocityState>(p, msg::ReportVelocityState);
}

} // namespace ocu::jaus
