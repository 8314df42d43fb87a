// Core service messages (AS5710A): names, management, access control, one-integer bodies.
#include "protocols/jaus/Messages.h"
#include "protocols/jaus/MessagesHandoff.h"
#include "protocols/jaus/MessagesMission.h"
#include "protocols/jaus/MessagesPlatformServices.h"
#include "protocols/jaus/MessagesVideo.h"

#include "protocols/jaus/MessageSupport.h"

namespace ocu::jaus {

using namespace codec;

namespace {
// The names of the message families with tables of their own (mission, hand-off, video, platform services).
const char* familyMessageName(std::uint16_t id) {
    const char* name = missionMessageName(id);
    if (!name)
        name = platformServicesMessageName(id);
    if (!name)
        name = handoffMessageName(id);
    return name ? name : videoMessageName(id);
}
} // namespace

const char* messageName(std::uint16_t id) {
    switch (id) {
    case msg::SetAuthority:
        return "SetAuthority";
    case msg::Shutdown:
        return "Shutdown";
    case msg::Standby:
        return "Standby";
    case msg::Resume:
        return "Resume";
    case msg::Reset:
        return "Reset";
    case msg::SetEmergency:
        return "SetEmergency";
    case msg::ClearEmergency:
        return "ClearEmergency";
    case msg::RequestControl:
        return "RequestControl";
    case msg::ReleaseControl:
        return "ReleaseControl";
    case msg::ConfirmControl:
        return "ConfirmControl";
    case msg::RejectControl:
        return "RejectControl";
    case msg::CreateEvent:
        return "CreateEvent";
    case msg::UpdateEvent:
        return "UpdateEvent";
    case msg::CancelEvent:
        return "CancelEvent";
    case msg::ConfirmEventRequest:
        return "ConfirmEventRequest";
    case msg::RejectEventRequest:
        return "RejectEventRequest";
    case msg::RegisterServices:
        return "RegisterServices";
    case msg::QueryAuthority:
        return "QueryAuthority";
    case msg::QueryStatus:
        return "QueryStatus";
    case msg::QueryTimeout:
        return "QueryTimeout";
    case msg::QueryControl:
        return "QueryControl";
    case msg::QueryEvents:
        return "QueryEvents";
    case msg::QueryHeartbeatPulse:
        return "QueryHeartbeatPulse";
    case msg::QueryIdentification:
        return "QueryIdentification";
    case msg::QueryConfiguration:
        return "QueryConfiguration";
    case msg::QuerySubsystemList:
        return "QuerySubsystemList";
    case msg::QueryServices:
        return "QueryServices";
    case msg::QueryServiceList:
        return "QueryServiceList";
    case msg::ReportAuthority:
        return "ReportAuthority";
    case msg::ReportStatus:
        return "ReportStatus";
    case msg::ReportTimeout:
        return "ReportTimeout";
    case msg::ReportControl:
        return "ReportControl";
    case msg::ReportEvents:
        return "ReportEvents";
    case msg::Event:
        return "Event";
    case msg::ReportHeartbeatPulse:
        return "ReportHeartbeatPulse";
    case msg::ReportIdentification:
        return "ReportIdentification";
    case msg::ReportConfiguration:
        return "ReportConfiguration";
    case msg::ReportSubsystemList:
        return "ReportSubsystemList";
    case msg::ReportServices:
        return "ReportServices";
    case msg::ReportServiceList:
        return "ReportServiceList";
    case msg::SetWrenchEffort:
        return "SetWrenchEffort";
    case msg::QueryWrenchEffort:
        return "QueryWrenchEffort";
    case msg::ReportWrenchEffort:
        return "ReportWrenchEffort";
    case msg::SetVelocityCommand:
        return "SetVelocityCommand";
    case msg::QueryVelocityCommand:
        return "QueryVelocityCommand";
    case msg::ReportVelocityCommand:
        return "ReportVelocityCommand";
    case msg::QueryGlobalPose:
        return "QueryGlobalPose";
    case msg::ReportGlobalPose:
        return "ReportGlobalPose";
    case msg::QueryLocalPose:
        return "QueryLocalPose";
    case msg::ReportLocalPose:
        return "ReportLocalPose";
    case msg::QueryVelocityState:
        return "QueryVelocityState";
    case msg::ReportVelocityState:
        return "ReportVelocityState";
    case msg::QueryPlatformSpecifications:
        return "QueryPlatformSpecifications";
    case msg::ReportPlatformSpecifications:
        return "ReportPlatformSpecifications";
    case msg::QueryHealthSummary:
        return "QueryHealthSummary";
    case msg::UpdateHealthSummary:
        return "UpdateHealthSummary";
    case msg::ReportHealthSummary:
        return "ReportHealthSummary";
    default:
        return familyMessageName(id);
    }
}

const char* nameFor(ManagementState s) {
    switch (s) {
    case ManagementState::Init:
        return "INIT";
    case ManagementState::Ready:
        return "READY";
    case ManagementState::Standby:
        return "STANDBY";
    case ManagementState::Shutdown:
        return "SHUTDOWN";
    case ManagementState::Failure:
        return "FAILURE";
    case ManagementState::Emergency:
        return "EMERGENCY";
    }
    return "UNKNOWN";
}

// ---- simple bodies ----
Bytes encodeEmpty(std::uint16_t id) {
    Bytes out;
    start(out, id);
    return out;
}
Bytes encodeU8(std::uint16_t id, std::uint8_t v) {
    Bytes out;
    start(out, id).u8(v);
    return out;
}
Bytes encodeU16(std::uint16_t id, std::uint16_t v) {
    Bytes out;
    start(out, id).u16(v);
    return out;
}
Result<std::uint8_t> decodeU8(ByteSpan p, std::uint16_t id) {
    auto r = open(p, id);
    if (!r)
        return makeError(r.error());
    std::uint8_t v = r->u8();
    return finish(*r, v, id);
}
Result<std::uint16_t> decodeU16(ByteSpan p, std::uint16_t id) {
    auto r = open(p, id);
    if (!r)
        return makeError(r.error());
    std::uint16_t v = r->u16();
    return finish(*r, v, id);
}

Bytes encode(const ReportStatus& m) {
    Bytes out;
    auto w = start(out, msg::ReportStatus);
    w.u8(std::uint8_t(m.status));
    w.u32(m.reserved);
    return out;
}
Result<ReportStatus> decodeReportStatus(ByteSpan p) {
    auto r = open(p, msg::ReportStatus);
    if (!r)
        return makeError(r.error());
    ReportStatus m;
    auto s = r->u8();
    if (s > 5)
        return makeError("value: ReportStatus status " + std::to_string(s) + " out of range");
    m.status = ManagementState(s);
    // Reserved u32: tolerated when missing (some peers send only the status byte).
    if (r->remaining() >= 4)
        m.reserved = r->u32();
    return finish(*r, m, msg::ReportStatus);
}

Bytes encode(const ReportControl& m) {
    Bytes out;
    auto w = start(out, msg::ReportControl);
    w.u16(m.controller.subsystem);
    w.u8(m.controller.node);
    w.u8(m.controller.component);
    w.u8(m.authority);
    return out;
}
Result<ReportControl> decodeReportControl(ByteSpan p) {
    auto r = open(p, msg::ReportControl);
    if (!r)
        return makeError(r.error());
    ReportControl m;
    m.controller.subsystem = r->u16();
    m.controller.node = r->u8();
    m.controller.component = r->u8();
    m.authority = r->u8();
    return finish(*r, m, msg::ReportControl);
}

} // namespace ocu::jaus
