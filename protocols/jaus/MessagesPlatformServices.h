#pragma once
// The IOP platform services an operator commands besides driving (AEP-4818 §6.2.5, §6.2.6, §9.2.2, §5.7):
// Platform Mode and Platform State (urn:jaus:jss:iop, 1.1), Illumination and Odometry
// (urn:jaus:jss:ugv, 1.0). Layouts and IDs from shared/research/jaus-autonomy.md §1, §6.2, §6.3, §7, §9
// (JSIDL). Same rules as Messages.h: little-endian, payload = ID + body; decoders ignore trailing bytes and
// fail only when a field that must be present is missing. Codecs in MessagesPlatformServices.cpp.
// CommsLostPolicyManager has no public layout (and two different IDs for SetCommsLostPolicy, §6.1): the
// console only detects the service, so it has no codec here.
#include <cstdint>
#include <string>
#include <vector>

#include "protocols/common/Bytes.h"
#include "protocols/common/Result.h"

namespace ocu::jaus {

namespace msg {
// iop:PlatformMode 1.1 and iop:PlatformState 1.1
inline constexpr std::uint16_t SetPlatformMode = 0xFF20, QueryPlatformMode = 0xFF21,
                               QuerySupportedPlatformModes = 0xFF22, ReportPlatformMode = 0xFF23,
                               ReportSupportedPlatformModes = 0xFF24, SetPlatformState = 0xFF25,
                               QueryPlatformState = 0xFF26, ConfirmPlatformStateRequest = 0xFF27,
                               ReportPlatformState = 0xFF28;
// ugv:IlluminationService 1.0
inline constexpr std::uint16_t SetIlluminationState = 0x0513, QueryIlluminationState = 0x2513,
                               ReportIlluminationState = 0x4513, QueryIlluminationConfiguration = 0x2514,
                               ReportIlluminationConfiguration = 0x4514;
// ugv:OdometryService 1.0 (the AEP's "0515 Query / 4516 Reset" are misprints, jaus-autonomy.md §9)
inline constexpr std::uint16_t ResetOdometry = 0x0515, QueryOdometry = 0x2515, ReportOdometry = 0x4515;
} // namespace msg

// Names of the IDs above (nullptr for others); messageName() falls back to it.
const char* platformServicesMessageName(std::uint16_t id);

// ---- Platform Mode --------------------------------------------------------------------------------------
// Mode u8: 0 Standard Operating (the default), 1 Training, 2 Maintenance, 175-255 program-specific.
enum class PlatformMode : std::uint8_t { StandardOperating = 0, Training = 1, Maintenance = 2 };
std::string platformModeName(std::uint8_t mode); // "standard", "training", "maintenance", "program mode N"
// Status of the mode: 0 Initializing, 1 Active, 2 Exiting.
const char* platformModeStatusName(std::uint8_t status);
struct ReportPlatformMode {
    std::uint8_t mode = 0;
    std::uint8_t status = 1;
    bool operator==(const ReportPlatformMode&) const = default;
};
struct ReportSupportedPlatformModes {
    std::vector<std::uint8_t> modes; // count u8
    bool operator==(const ReportSupportedPlatformModes&) const = default;
};

// ---- Platform State -------------------------------------------------------------------------------------
enum class PlatformState : std::uint8_t {
    Initialize = 0,
    Operational = 1,
    Shutdown = 2,
    SystemAbort = 3,
    Emergency = 4,
    RenderUseless = 5
};
std::string platformStateName(std::uint8_t state); // "initialize", ..., "state N" for others
// ConfirmPlatformStateRequest's code: 0 Transitioning, 1 InvalidState.
enum class PlatformStateAnswer : std::uint8_t { Transitioning = 0, InvalidState = 1 };
struct ConfirmPlatformStateRequest {
    std::uint8_t state = 0;
    std::uint8_t code = 0;
    bool operator==(const ConfirmPlatformStateRequest&) const = default;
};

// ---- Illumination ---------------------------------------------------------------------------------------
// The IlluminationState u32 bit field (1 = on). Variable lights 1-4 are 4-bit levels at bits 8, 12, 16, 20.
namespace light {
inline constexpr std::uint32_t Headlights = 1u << 0, LeftTurnSignal = 1u << 1, RightTurnSignal = 1u << 2,
                               RunningLights = 1u << 3, BrakeLights = 1u << 4, BackupLights = 1u << 5,
                               VisibleLightSource = 1u << 6, IrLightSource = 1u << 7, HighBeams = 1u << 24,
                               ParkingLights = 1u << 25, FogLights = 1u << 26, HazardLights = 1u << 27;
// The lights an operator may switch from this console: never VisibleLightSource, which AEP-4818 §9.2.2
// forbids for the whole vehicle.
inline constexpr std::uint32_t kOperatorSwitchable =
    Headlights | LeftTurnSignal | RightTurnSignal | RunningLights | BrakeLights | IrLightSource;
} // namespace light
// ReportIlluminationConfiguration's supported mask uses other positions above bit 7 (b8-11 variable lights
// 1-4, b12-15 high beams, parking, fog, hazard): mapped to the state's bit positions.
std::uint32_t illuminationStateMaskOf(std::uint32_t configuration);

// ---- Odometry -------------------------------------------------------------------------------------------
enum class OdometryType : std::uint8_t { Platform = 1, TripA = 2, TripB = 3, TripC = 4 };
struct ReportOdometry {
    std::uint8_t type = 1;
    std::uint32_t distanceM = 0; // metres, not scaled
    bool operator==(const ReportOdometry&) const = default;
};

// ---- Encoders (payload = ID + body) ---------------------------------------------------------------------
// SetPlatformMode, SetPlatformState, ReportPlatformState, ResetOdometry, QueryOdometry: encodeU8 of
// Messages.h; the empty queries: encodeEmpty.
Bytes encode(const ReportPlatformMode& m);
Bytes encode(const ReportSupportedPlatformModes& m);
Bytes encode(const ConfirmPlatformStateRequest& m);
Bytes encode(const ReportOdometry& m);
// SetIlluminationState, ReportIlluminationState or ReportIlluminationConfiguration: one u32.
Bytes encodeIllumination(std::uint16_t id, std::uint32_t bits);

// ---- Decoders (payload = ID + body; the ID must match) --------------------------------------------------
Result<ReportPlatformMode> decodeReportPlatformMode(ByteSpan payload);
Result<ReportSupportedPlatformModes> decodeReportSupportedPlatformModes(ByteSpan payload);
Result<ConfirmPlatformStateRequest> decodeConfirmPlatformStateRequest(ByteSpan payload);
Result<ReportOdometry> decodeReportOdometry(ByteSpan payload);
Result<std::uint32_t> decodeIllumination(ByteSpan payload, std::uint16_t id);

} // namespace ocu::jaus
