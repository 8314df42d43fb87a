// Platform Mode, Platform State, Illumination and Odometry messages.
// Layouts: shared/research/jaus-autonomy.md §6.2, §6.3, §7, §9 (JSIDL).
#include "protocols/jaus/MessagesPlatformServices.h"

#include "protocols/jaus/MessageSupport.h"

namespace ocu::jaus {

using namespace codec;

const char* platformServicesMessageName(std::uint16_t id) {
    switch (id) {
    case msg::SetPlatformMode:
        return "SetPlatformMode";
    case msg::QueryPlatformMode:
        return "QueryPlatformMode";
    case msg::QuerySupportedPlatformModes:
        return "QuerySupportedPlatformModes";
    case msg::ReportPlatformMode:
        return "ReportPlatformMode";
    case msg::ReportSupportedPlatformModes:
        return "ReportSupportedPlatformModes";
    case msg::SetPlatformState:
        return "SetPlatformState";
    case msg::QueryPlatformState:
        return "QueryPlatformState";
    case msg::ConfirmPlatformStateRequest:
        return "ConfirmPlatformStateRequest";
    case msg::ReportPlatformState:
        return "ReportPlatformState";
    case msg::SetIlluminationState:
        return "SetIlluminationState";
    case msg::QueryIlluminationState:
        return "QueryIlluminationState";
    case msg::ReportIlluminationState:
        return "ReportIlluminationState";
    case msg::QueryIlluminationConfiguration:
        return "QueryIlluminationConfiguration";
    case msg::ReportIlluminationConfiguration:
        return "ReportIlluminationConfiguration";
    case msg::ResetOdometry:
        return "ResetOdometry";
    case msg::QueryOdometry:
        return "QueryOdometry";
    case msg::ReportOdometry:
        return "ReportOdometry";
    default:
        return nullptr;
    }
}

std::string platformModeName(std::uint8_t mode) {
    switch (mode) {
    case 0:
        return "standard";
    case 1:
        return "training";
    case 2:
        return "maintenance";
    default:
        return "program mode " + std::to_string(mode);
    }
}

const char* platformModeStatusName(std::uint8_t status) {
    switch (status) {
    case 0:
        return "initializing";
    case 1:
        return "active";
    case 2:
        return "exiting";
    default:
        return "unknown";
    }
}

std::string platformStateName(std::uint8_t state) {
    switch (state) {
    case 0:
        return "initialize";
    case 1:
        return "operational";
    case 2:
        return "shutdown";
    case 3:
        return "system abort";
    case 4:
        return "emergency";
    case 5:
        return "render useless";
    default:
        return "state " + std::to_string(state);
    }
}

std::uint32_t illuminationStateMaskOf(std::uint32_t c) {
    std::uint32_t mask = c & 0xFFu; // b0-7 share their positions
    for (int i = 0; i < 4; ++i) {
        if (c & (1u << (8 + i)))
            mask |= 0xFu << (8 + 4 * i); // variable light i+1: its 4-bit level
        if (c & (1u << (12 + i)))
            mask |= 1u << (24 + i); // high beams, parking, fog, hazard
    }
    return mask;
}

Bytes encode(const ReportPlatformMode& m) {
    Bytes out;
    auto w = start(out, msg::ReportPlatformMode);
    w.u8(m.mode);
    w.u8(m.status);
    return out;
}

Result<ReportPlatformMode> decodeReportPlatformMode(ByteSpan p) {
    auto r = open(p, msg::ReportPlatformMode);
    if (!r)
        return makeError(r.error());
    ReportPlatformMode m;
    m.mode = r->u8();
    m.status = r->u8();
    return finish(*r, m, msg::ReportPlatformMode);
}

Bytes encode(const ReportSupportedPlatformModes& m) {
    Bytes out;
    auto w = start(out, msg::ReportSupportedPlatformModes);
    const std::size_t n = std::min<std::size_t>(m.modes.size(), 255);
    w.u8(std::uint8_t(n));
    for (std::size_t i = 0; i < n; ++i)
        w.u8(m.modes[i]);
    return out;
}

Result<ReportSupportedPlatformModes> decodeReportSupportedPlatformModes(ByteSpan p) {
    auto r = open(p, msg::ReportSupportedPlatformModes);
    if (!r)
        return makeError(r.error());
    ReportSupportedPlatformModes m;
    const std::uint8_t n = r->u8();
    if (n > r->remaining())
        return makeError("truncated: ReportSupportedPlatformModes lists more modes than it carries");
    for (int i = 0; i < n; ++i)
        m.modes.push_back(r->u8());
    return finish(*r, m, msg::ReportSupportedPlatformModes);
}

Bytes encode(const ConfirmPlatformStateRequest& m) {
    Bytes out;
    auto w = start(out, msg::ConfirmPlatformStateRequest);
    w.u8(m.state);
    w.u8(m.code);
    return out;
}

Result<ConfirmPlatformStateRequest> decodeConfirmPlatformStateRequest(ByteSpan p) {
    auto r = open(p, msg::ConfirmPlatformStateRequest);
    if (!r)
        return makeError(r.error());
    ConfirmPlatformStateRequest m;
    m.state = r->u8();
    m.code = r->u8();
    return finish(*r, m, msg::ConfirmPlatformStateRequest);
}

Bytes encode(const ReportOdometry& m) {
    Bytes out;
    auto w = start(out, msg::ReportOdometry);
    w.u8(m.type);
    w.u32(m.distanceM);
    return out;
}

Result<ReportOdometry> decodeReportOdometry(ByteSpan p) {
    auto r = open(p, msg::ReportOdometry);
    if (!r)
        return makeError(r.error());
    ReportOdometry m;
    m.type = r->u8();
    m.distanceM = r->u32();
    return finish(*r, m, msg::ReportOdometry);
}

Bytes encodeIllumination(std::uint16_t id, std::uint32_t bits) {
    Bytes out;
    start(out, id).u32(bits);
    return out;
}

Result<std::uint32_t> decodeIllumination(ByteSpan p, std::uint16_t id) {
    auto r = open(p, id);
    if (!r)
        return makeError(r.error());
    const std::uint32_t bits = r->u32();
    return finish(*r, bits, id);
}

} // namespace ocu::jaus
