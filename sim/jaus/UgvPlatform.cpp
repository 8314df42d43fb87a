// The simulated UGV's IOP platform services on the Core Mobility Component, where its access control is
// (jaus-autonomy.md §6.2, §6.3, §7, §9, §13 item 8): Platform Mode (standard, training, maintenance),
// Platform State (Operational and Emergency may be asked for, as FKIE's server by default; the reported state
// follows the Management state: Init -> Initialize, Emergency -> Emergency, Failure -> System Abort),
// Illumination (headlights, turn signals, running and brake lights, IR source; no backup lights, no
// visible-light source) and Odometry (PLATFORM = every metre the kinematics drove, TRIP_A-C since their
// reset). Every Set needs control (each service inherits AccessControl); there is no comms-lost policy
// service.
#include <algorithm>
#include <cmath>

#include "protocols/common/Log.h"
#include "protocols/jaus/MessagesPlatformServices.h"
#include "sim/jaus/UgvCore.h"
#include "sim/jaus/UgvSupport.h"

namespace ocu::sim {

using namespace ocu::jaus;
using ugv::kLog;

namespace {

constexpr std::uint32_t kLights = light::Headlights | light::LeftTurnSignal | light::RightTurnSignal |
                                  light::RunningLights | light::BrakeLights | light::IrLightSource;
// The configuration's mask: b0-7 share the state's positions.
constexpr std::uint32_t kLightsConfiguration = kLights;
const std::vector<std::uint8_t> kModes{0, 1, 2};

} // namespace

std::uint8_t UgvCore::platformState() const {
    switch (m_s.management) {
    case ManagementState::Init:
        return std::uint8_t(PlatformState::Initialize);
    case ManagementState::Emergency:
        return std::uint8_t(PlatformState::Emergency);
    case ManagementState::Failure:
        return std::uint8_t(PlatformState::SystemAbort);
    case ManagementState::Shutdown:
        return std::uint8_t(PlatformState::Shutdown);
    default:
        return std::uint8_t(PlatformState::Operational);
    }
}

std::uint32_t UgvCore::odometerM(std::uint8_t type) const {
    double d = m_s.odometer;
    if (type >= std::uint8_t(OdometryType::TripA) && type <= std::uint8_t(OdometryType::TripC))
        d -= m_platform.tripStart[type - std::uint8_t(OdometryType::TripA)];
    return std::uint32_t(std::clamp(std::floor(d), 0.0, 4294967295.0));
}

void UgvCore::registerPlatform() {
    const JausId mob = mobility();
    m_platform.lights = m_cfg.lights & kLights;
    m_table.onCommand(msg::SetPlatformMode, mob, [this](const JausId&, const JausId& src, ByteSpan p) {
        auto mode = decodeU8(p, msg::SetPlatformMode);
        if (!mode)
            return rejectMalformed(mode.error());
        if (!isController(src))
            return m_counters.add("rx.refused.not_controller");
        if (std::find(kModes.begin(), kModes.end(), *mode) != kModes.end())
            m_platform.mode = *mode;
    });
    m_table.onQuery(msg::QueryPlatformMode, mob, [this](const JausId&, ByteSpan) {
        return encode(ReportPlatformMode{m_platform.mode, 1});
    });
    m_table.onQuery(msg::QuerySupportedPlatformModes, mob,
                    [](const JausId&, ByteSpan) { return encode(ReportSupportedPlatformModes{kModes}); });

    m_table.onCommand(msg::SetPlatformState, mob, [this](const JausId& c, const JausId& src, ByteSpan p) {
        auto state = decodeU8(p, msg::SetPlatformState);
        if (!state)
            return rejectMalformed(state.error());
        // Controlled: only the controller; not controlled: only Operational, from whoever set the emergency
        // (JSIDL guards, jaus-autonomy.md §6.3).
        const bool asked = m_s.controller.subsystem ? isController(src)
                                                    : *state == std::uint8_t(PlatformState::Operational) &&
                                                          m_platform.emergencyBy == src;
        if (!asked)
            return m_counters.add("rx.refused.not_controller");
        ConfirmPlatformStateRequest answer{*state, std::uint8_t(PlatformStateAnswer::Transitioning)};
        if (*state == std::uint8_t(PlatformState::Emergency)) {
            m_platform.emergencyBy = src;
            m_table.handle(c, src, msg::SetEmergency, encodeU16(msg::SetEmergency, 1)); // as FKIE's server
        } else if (*state == std::uint8_t(PlatformState::Operational)) {
            m_table.handle(c, src, msg::ClearEmergency, encodeU16(msg::ClearEmergency, 1));
            m_platform.emergencyBy = JausId{};
        } else {
            answer.code = std::uint8_t(PlatformStateAnswer::InvalidState);
        }
        send(c, src, encode(answer));
    });
    m_table.onQuery(msg::QueryPlatformState, mob, [this](const JausId&, ByteSpan) {
        return encodeU8(msg::ReportPlatformState, platformState());
    });

    m_table.onCommand(msg::SetIlluminationState, mob, [this](const JausId&, const JausId& src, ByteSpan p) {
        auto bits = decodeIllumination(p, msg::SetIlluminationState);
        if (!bits)
            return rejectMalformed(bits.error());
        if (!isController(src))
            return m_counters.add("rx.refused.not_controller");
        m_platform.lights = *bits & kLights; // absent lights report 0 (AEP-4818 §9.2.2)
        logInfo(kLog, m_cfg.callSign + ": lights " + std::to_string(m_platform.lights));
    });
    m_table.onQuery(msg::QueryIlluminationState, mob, [this](const JausId&, ByteSpan) {
        return encodeIllumination(msg::ReportIlluminationState, m_platform.lights);
    });
    m_table.onQuery(msg::QueryIlluminationConfiguration, mob, [](const JausId&, ByteSpan) {
        return encodeIllumination(msg::ReportIlluminationConfiguration, kLightsConfiguration);
    });

    m_table.onCommand(msg::ResetOdometry, mob, [this](const JausId&, const JausId& src, ByteSpan p) {
        auto type = decodeU8(p, msg::ResetOdometry);
        if (!type)
            return rejectMalformed(type.error());
        if (!isController(src))
            return m_counters.add("rx.refused.not_controller");
        if (*type >= std::uint8_t(OdometryType::TripA) && *type <= std::uint8_t(OdometryType::TripC))
            m_platform.tripStart[*type - std::uint8_t(OdometryType::TripA)] = m_s.odometer; // PLATFORM: never
    });
    m_table.onQuery(msg::QueryOdometry, mob, [this](const JausId&, ByteSpan p) -> std::optional<Bytes> {
        auto type = decodeU8(p, msg::QueryOdometry);
        if (!type || *type < std::uint8_t(OdometryType::Platform) ||
            *type > std::uint8_t(OdometryType::TripC))
            return std::nullopt;
        return encode(ReportOdometry{*type, odometerM(*type)});
    });
}

} // namespace ocu::sim
