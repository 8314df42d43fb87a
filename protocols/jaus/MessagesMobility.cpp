// Mobility messages (AS6009): wrench effort, velocity command, global/local pose, velocity state.
#include "protocols/jaus/Messages.h"

#include <numbers>

#include "protocols/jaus/MessageSupport.h"

namespace ocu::jaus {

using namespace codec;

namespace {

constexpr double kPi = std::numbers::pi;

} // namespace

// ---- mobility ----
Bytes encodeWrench(std::uint16_t id, const WrenchEffort& m) {
    PvWriter pv;
    const std::optional<double>* prop[] = {&m.propLinX, &m.propLinY, &m.propLinZ,
                                           &m.propRotX, &m.propRotY, &m.propRotZ};
    const std::optional<double>* res[] = {&m.resLinX, &m.resLinY, &m.resLinZ,
                                          &m.resRotX, &m.resRotY, &m.resRotZ};
    for (auto* f : prop)
        pv.mark(*f);
    for (auto* f : res)
        pv.mark(*f);
    Bytes out;
    auto w = start(out, id);
    w.u16(std::uint16_t(pv.pv));
    for (auto* f : prop)
        putU16s(w, *f, -100, 100);
    for (auto* f : res)
        putU8s(w, *f, 0, 100);
    return out;
}
Result<WrenchEffort> decodeWrench(ByteSpan p, std::uint16_t id) {
    auto r = open(p, id);
    if (!r)
        return makeError(r.error());
    WrenchEffort m;
    std::optional<double>* prop[] = {&m.propLinX, &m.propLinY, &m.propLinZ,
                                     &m.propRotX, &m.propRotY, &m.propRotZ};
    std::optional<double>* res[] = {&m.resLinX, &m.resLinY, &m.resLinZ, &m.resRotX, &m.resRotY, &m.resRotZ};
    const std::uint32_t pv = r->u16();
    for (int i = 0; i < 6; ++i)
        getU16s(*r, pv, i, *prop[i], -100, 100);
    for (int i = 0; i < 6; ++i)
        getU8s(*r, pv, 6 + i, *res[i], 0, 100);
    return finish(*r, m, id);
}

Bytes encodeVelocityCommand(std::uint16_t id, const VelocityCommand& m) {
    PvWriter pv;
    pv.mark(m.vx);
    pv.mark(m.vy);
    pv.mark(m.vz);
    pv.mark(m.rollRate);
    pv.mark(m.pitchRate);
    pv.mark(m.yawRate);
    Bytes out;
    auto w = start(out, id);
    w.u8(std::uint8_t(pv.pv));
    w.u8(m.commandType);
    putU32s(w, m.vx, -327.68, 327.67);
    putU32s(w, m.vy, -327.68, 327.67);
    putU32s(w, m.vz, -327.68, 327.67);
    putU16s(w, m.rollRate, -32.768, 32.767);
    putU16s(w, m.pitchRate, -32.768, 32.767);
    putU16s(w, m.yawRate, -32.768, 32.767);
    return out;
}
Result<VelocityCommand> decodeVelocityCommand(ByteSpan p, std::uint16_t id) {
    auto r = open(p, id);
    if (!r)
        return makeError(r.error());
    VelocityCommand m;
    const std::uint32_t pv = r->u8();
    m.commandType = r->u8();
    getU32s(*r, pv, 0, m.vx, -327.68, 327.67);
    getU32s(*r, pv, 1, m.vy, -327.68, 327.67);
    getU32s(*r, pv, 2, m.vz, -327.68, 327.67);
    getU16s(*r, pv, 3, m.rollRate, -32.768, 32.767);
    getU16s(*r, pv, 4, m.pitchRate, -32.768, 32.767);
    getU16s(*r, pv, 5, m.yawRate, -32.768, 32.767);
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
    PvWriter pv;
    pv.mark(m.lat);
    pv.mark(m.lon);
    pv.mark(m.alt);
    pv.mark(m.positionRms);
    pv.mark(m.roll);
    pv.mark(m.pitch);
    pv.mark(m.yaw);
    pv.mark(m.attitudeRms);
    pv.mark(m.timestamp);
    Bytes out;
    auto w = start(out, id);
    w.u16(std::uint16_t(pv.pv));
    putU32s(w, m.lat, -90, 90);
    putU32s(w, m.lon, -180, 180);
    putU32s(w, m.alt, -10000, 35000);
    putU32s(w, m.positionRms, 0, 100);
    putU16s(w, m.roll, -kPi, kPi);
    putU16s(w, m.pitch, -kPi, kPi);
    putU16s(w, m.yaw, -kPi, kPi);
    putU16s(w, m.attitudeRms, 0, kPi);
    if (m.timestamp)
        w.u32(*m.timestamp);
    return out;
}
Result<GlobalPose> decodeGlobalPose(ByteSpan p, std::uint16_t id) {
    auto r = open(p, id);
    if (!r)
        return makeError(r.error());
    GlobalPose m;
    const std::uint32_t pv = r->u16();
    getU32s(*r, pv, 0, m.lat, -90, 90);
    getU32s(*r, pv, 1, m.lon, -180, 180);
    getU32s(*r, pv, 2, m.alt, -10000, 35000);
    getU32s(*r, pv, 3, m.positionRms, 0, 100);
    getU16s(*r, pv, 4, m.roll, -kPi, kPi);
    getU16s(*r, pv, 5, m.pitch, -kPi, kPi);
    getU16s(*r, pv, 6, m.yaw, -kPi, kPi);
    getU16s(*r, pv, 7, m.attitudeRms, 0, kPi);
    if (pv & (1u << 8))
        m.timestamp = r->u32();
    return finish(*r, m, id);
}
Bytes encode(const LocalPose& m, std::uint16_t id) {
    PvWriter pv;
    pv.mark(m.x);
    pv.mark(m.y);
    pv.mark(m.z);
    pv.mark(m.positionRms);
    pv.mark(m.roll);
    pv.mark(m.pitch);
    pv.mark(m.yaw);
    pv.mark(m.attitudeRms);
    pv.mark(m.timestamp);
    Bytes out;
    auto w = start(out, id);
    w.u16(std::uint16_t(pv.pv));
    putU32s(w, m.x, -100000, 100000);
    putU32s(w, m.y, -100000, 100000);
    putU32s(w, m.z, -100000, 100000);
    putU32s(w, m.positionRms, 0, 100);
    putU16s(w, m.roll, -kPi, kPi);
    putU16s(w, m.pitch, -kPi, kPi);
    putU16s(w, m.yaw, -kPi, kPi);
    putU16s(w, m.attitudeRms, 0, kPi);
    if (m.timestamp)
        w.u32(*m.timestamp);
    return out;
}
Result<LocalPose> decodeLocalPose(ByteSpan p, std::uint16_t id) {
    auto r = open(p, id);
    if (!r)
        return makeError(r.error());
    LocalPose m;
    const std::uint32_t pv = r->u16();
    getU32s(*r, pv, 0, m.x, -100000, 100000);
    getU32s(*r, pv, 1, m.y, -100000, 100000);
    getU32s(*r, pv, 2, m.z, -100000, 100000);
    getU32s(*r, pv, 3, m.positionRms, 0, 100);
    getU16s(*r, pv, 4, m.roll, -kPi, kPi);
    getU16s(*r, pv, 5, m.pitch, -kPi, kPi);
    getU16s(*r, pv, 6, m.yaw, -kPi, kPi);
    getU16s(*r, pv, 7, m.attitudeRms, 0, kPi);
    if (pv & (1u << 8))
        m.timestamp = r->u32();
    return finish(*r, m, id);
}
Bytes encode(const VelocityState& m) {
    PvWriter pv;
    pv.mark(m.vx);
    pv.mark(m.vy);
    pv.mark(m.vz);
    pv.mark(m.velocityRms);
    pv.mark(m.rollRate);
    pv.mark(m.pitchRate);
    pv.mark(m.yawRate);
    pv.mark(m.rateRms);
    pv.mark(m.timestamp);
    Bytes out;
    auto w = start(out, msg::ReportVelocityState);
    w.u16(std::uint16_t(pv.pv));
    putU32s(w, m.vx, -327.68, 327.67);
    putU32s(w, m.vy, -327.68, 327.67);
    putU32s(w, m.vz, -327.68, 327.67);
    putU32s(w, m.velocityRms, 0, 100);
    putU16s(w, m.rollRate, -32.768, 32.767);
    putU16s(w, m.pitchRate, -32.768, 32.767);
    putU16s(w, m.yawRate, -32.768, 32.767);
    putU16s(w, m.rateRms, 0, kPi);
    if (m.timestamp)
        w.u32(*m.timestamp);
    return out;
}
Result<VelocityState> decodeVelocityState(ByteSpan p) {
    auto r = open(p, msg::ReportVelocityState);
    if (!r)
        return makeError(r.error());
    VelocityState m;
    const std::uint32_t pv = r->u16();
    getU32s(*r, pv, 0, m.vx, -327.68, 327.67);
    getU32s(*r, pv, 1, m.vy, -327.68, 327.67);
    getU32s(*r, pv, 2, m.vz, -327.68, 327.67);
    getU32s(*r, pv, 3, m.velocityRms, 0, 100);
    getU16s(*r, pv, 4, m.rollRate, -32.768, 32.767);
    getU16s(*r, pv, 5, m.pitchRate, -32.768, 32.767);
    getU16s(*r, pv, 6, m.yawRate, -32.768, 32.767);
    getU16s(*r, pv, 7, m.rateRms, 0, kPi);
    if (pv & (1u << 8))
        m.timestamp = r->u32();
    return finish(*r, m, msg::ReportVelocityState);
}

} // namespace ocu::jaus
