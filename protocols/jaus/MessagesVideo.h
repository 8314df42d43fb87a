#pragma once
// JAUS video messages (AEP-4818 §9.1.2-9.1.8, §9.3.3): the IOP Digital Resource Discovery service
// (urn:jaus:jss:iop:DigitalResourceDiscovery 1.1), the AS6060 Visual Sensor and Digital Video services
// (environmentSensing 1.0) and the AS6057A pan-tilt joint position / velocity services (manipulator 2.0).
// Layouts and IDs from shared/research/jaus-services-extra.md §1, §2, §4 (JSIDL). Same rules as Messages.h:
// little-endian, presence vectors first, scaled integers; decoders accept any presence vector and ignore
// trailing bytes, they fail only when a field that must be present is missing. Codecs in MessagesVideo.cpp.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "protocols/common/Bytes.h"
#include "protocols/common/Result.h"
#include "protocols/jaus/JudpCodec.h"

namespace ocu::jaus {

namespace msg {
// IOP Digital Resource Discovery 1.1 (the AS6060-style 2.0 variant has the same bodies under other IDs).
inline constexpr std::uint16_t QueryDigitalResourceEndpoint = 0xE702,
                               RegisterDigitalResourceEndpoint = 0xE703,
                               RemoveDigitalResourceEndpoint = 0xE704, ReportDigitalResourceEndpoint = 0xF702,
                               ConfirmDigitalResourceEndpoint = 0xF703;
// Visual Sensor / Digital Video (AS6060 environmentSensing 1.0)
inline constexpr std::uint16_t ConfirmSensorConfiguration = 0x0801, ControlDigitalVideoSensorStream = 0x0805,
                               QuerySensorGeometricProperties = 0x2805,
                               QueryVisualSensorCapabilities = 0x2806,
                               QueryVisualSensorConfiguration = 0x2807,
                               QueryDigitalVideoSensorCapabilities = 0x2808,
                               QueryDigitalVideoSensorConfiguration = 0x2809,
                               ReportSensorGeometricProperties = 0x4805,
                               ReportVisualSensorCapabilities = 0x4806,
                               ReportVisualSensorConfiguration = 0x4807,
                               ReportDigitalVideoSensorCapabilities = 0x4808,
                               ReportDigitalVideoSensorConfiguration = 0x4809;
// Pan-tilt (AS6057A manipulator 2.0): joint 1 = pan, joint 2 = tilt (AEP-4818 §9.3.3).
inline constexpr std::uint16_t SetPanTiltJointPositions = 0x0622, SetPanTiltJointVelocity = 0x0623,
                               QueryPanTiltJointPositions = 0x2622, QueryPanTiltJointVelocity = 0x2623,
                               ReportPanTiltJointPositions = 0x4622, ReportPanTiltJointVelocity = 0x4623;
} // namespace msg

// Names of the IDs above ("unknown" for others); messageName() falls back to it.
const char* videoMessageName(std::uint16_t id);

// ---- Digital Resource Discovery -------------------------------------------------------------------------
enum class ServerType : std::uint8_t { Rtsp = 0, Mpeg2Ts = 1, Ftp = 2, Sftp = 3, FtpOverSsh = 4, Http = 5 };
struct DigitalResourceEndpoint {
    std::uint8_t serverType = 0; // ServerType; 9-255 reserved or program-specific, kept as received
    std::string url;             // str8
    std::optional<JausId> host;  // PV bit 0: the component whose Visual Sensor / Digital Video serve it
    std::optional<std::uint16_t> resourceId; // PV bit 1: for visual sensors the SensorID
    bool operator==(const DigitalResourceEndpoint&) const = default;
};
struct RegisterDigitalResourceEndpoint {
    std::uint8_t requestId = 0;
    DigitalResourceEndpoint endpoint;
};
struct RemoveDigitalResourceEndpoint {
    std::uint8_t endpointId = 0; // the ID the Confirm returned
    std::uint8_t requestId = 0;
};
struct ConfirmDigitalResourceEndpoint { // answers Register and Remove; no status field
    std::uint8_t endpointId = 0;
    std::uint8_t requestId = 0;
};
struct ReportDigitalResourceEndpoint {
    std::vector<DigitalResourceEndpoint> endpoints; // count u8
};

// ---- Visual Sensor / Digital Video ----------------------------------------------------------------------
// Queries 0x2806/0x2807 (query PV u16) and 0x2808/0x2809 (query PV u8): count u16 x {SensorID; PV}.
// SensorID 0 = every sensor (2.0, also sent to 1.0 servers by FKIE clients).
struct SensorQuery {
    std::uint16_t sensorId = 0;
    std::uint16_t presence = 0xFFFF;
};
struct QuerySensors {
    std::vector<SensorQuery> sensors{SensorQuery{}};
};

struct VisualSensorCapabilities {
    std::uint16_t sensorId = 0;
    std::string name; // mandatory: the human-readable camera name
    // PV u16 bits 0-14 in order; the u8 fields are bit sets / enums as on the wire.
    std::optional<std::uint8_t> supportedStates, zoomModes, focusModes, whiteBalance, imagingModes,
        exposureModes, meteringModes;
    std::optional<double> minShutterSpeed, maxShutterSpeed, minAperture, maxAperture; // s; f-number
    std::optional<double> minFocalLength, maxFocalLength;                             // m
    std::optional<std::uint8_t> lightSensitivityLevels, imageStabilization;
};
struct ReportVisualSensorCapabilities {
    std::vector<VisualSensorCapabilities> sensors;
};

enum class SensorState : std::uint8_t { Active = 0, Standby = 1, Off = 2 };
struct VisualSensorConfiguration {
    std::uint16_t sensorId = 0;
    // PV u16 bits 0-15 in order.
    std::optional<std::uint8_t> sensorState, zoomMode;
    std::optional<double> zoomLevel;                  // %
    std::optional<double> focalLength;                // m
    std::optional<double> horizontalFov, verticalFov; // rad
    std::optional<std::uint8_t> focusMode;
    std::optional<double> focusValue; // %
    std::optional<std::uint8_t> whiteBalance, imagingMode, exposureMode, meteringMode;
    std::optional<double> shutterSpeed, aperture;
    std::optional<std::uint8_t> lightSensitivity, imageStabilization;
};
struct ReportVisualSensorConfiguration {
    std::vector<VisualSensorConfiguration> sensors;
};

struct DigitalVideoCapabilities {
    std::uint16_t sensorId = 0;
    // PV u8 bits 0-5.
    std::optional<std::uint16_t> minBitRate, maxBitRate;    // kbit/s
    std::optional<std::uint8_t> minFrameRate, maxFrameRate; // frames/s
    std::optional<std::uint32_t> supportedFrameSizes;       // bit i = FrameSize i
    std::optional<std::uint8_t> supportedFormats;           // bit 6 = MPEG-4 AVC (H.264)
};
struct ReportDigitalVideoCapabilities {
    std::vector<DigitalVideoCapabilities> sensors;
};

// FrameSize values (AS6060): 7 640x480, 15 852x480, 27 1280x720, 28 1920x1080, ...
inline constexpr std::uint8_t kFrameSize640x480 = 7, kFrameSize1280x720 = 27, kFrameSize1920x1080 = 28;
inline constexpr std::uint8_t kFormatH264 = 6; // DigitalFormat MPEG-4 AVC
struct DigitalVideoConfiguration {
    std::uint16_t sensorId = 0;
    // PV u8 bits 0-4.
    std::optional<std::uint16_t> minBitRate, maxBitRate; // kbit/s
    std::optional<std::uint8_t> frameRate, frameSize, format;
};
struct ReportDigitalVideoConfiguration {
    std::vector<DigitalVideoConfiguration> sensors;
};

enum class StreamState : std::uint8_t { Play = 0, Pause = 1, Stop = 2 };
struct ControlDigitalVideoSensorStream {
    std::uint16_t sensorId = 0;
    StreamState state = StreamState::Play;
};

// 0x2805: count u16 x {SensorID}. 0x4805: count u16 x {SensorID; variant}: 0 none, 1 static, 2 on a
// manipulator (AEP-4818 V1.JAUS-57: a camera on a pan-tilt reports the host's JAUS ID and joint).
struct SensorGeometry {
    std::uint16_t sensorId = 0;
    std::uint8_t kind = 0;                 // vtag 0 none, 1 static, 2 on a manipulator
    JausId manipulator;                    // kind 2
    std::uint8_t joint = 0;                // kind 2
    double x = 0, y = 0, z = 0;            // m, [-30, 30]
    double qd = 1, qa = 0, qb = 0, qc = 0; // unit quaternion, scalar first, [-1, 1]
};
struct QuerySensorGeometricProperties {
    std::vector<std::uint16_t> sensorIds{0};
};
struct ReportSensorGeometricProperties {
    std::vector<SensorGeometry> sensors;
};

// ---- Pan-tilt ---------------------------------------------------------------------------------------------
// Positions u32[-8π, 8π] rad; velocities u32[-10π, 10π] rad/s. Query bodies are empty.
struct PanTiltJoints {
    double pan = 0, tilt = 0;
};

// ---- Encoders / decoders (payload = ID + body) ----------------------------------------------------------
Bytes encode(const RegisterDigitalResourceEndpoint& m);
Bytes encode(const RemoveDigitalResourceEndpoint& m);
Bytes encode(const ConfirmDigitalResourceEndpoint& m);
Bytes encode(const ReportDigitalResourceEndpoint& m);
Bytes encodeSensorQuery(std::uint16_t id, const QuerySensors& m); // 0x2806-0x2809 (PV width by ID)
Bytes encode(const ReportVisualSensorCapabilities& m);
Bytes encode(const ReportVisualSensorConfiguration& m);
Bytes encode(const ReportDigitalVideoCapabilities& m);
Bytes encode(const ReportDigitalVideoConfiguration& m);
Bytes encode(const ControlDigitalVideoSensorStream& m);
Bytes encode(const QuerySensorGeometricProperties& m);
Bytes encode(const ReportSensorGeometricProperties& m);
Bytes encodePanTiltPositions(std::uint16_t id, const PanTiltJoints& m);  // 0x0622, 0x4622
Bytes encodePanTiltVelocities(std::uint16_t id, const PanTiltJoints& m); // 0x0623, 0x4623

Result<RegisterDigitalResourceEndpoint> decodeRegisterDigitalResourceEndpoint(ByteSpan payload);
Result<RemoveDigitalResourceEndpoint> decodeRemoveDigitalResourceEndpoint(ByteSpan payload);
Result<ConfirmDigitalResourceEndpoint> decodeConfirmDigitalResourceEndpoint(ByteSpan payload);
Result<ReportDigitalResourceEndpoint> decodeReportDigitalResourceEndpoint(ByteSpan payload);
Result<QuerySensors> decodeSensorQuery(ByteSpan payload, std::uint16_t id);
Result<ReportVisualSensorCapabilities> decodeReportVisualSensorCapabilities(ByteSpan payload);
Result<ReportVisualSensorConfiguration> decodeReportVisualSensorConfiguration(ByteSpan payload);
Result<ReportDigitalVideoCapabilities> decodeReportDigitalVideoCapabilities(ByteSpan payload);
Result<ReportDigitalVideoConfiguration> decodeReportDigitalVideoConfiguration(ByteSpan payload);
Result<ControlDigitalVideoSensorStream> decodeControlDigitalVideoSensorStream(ByteSpan payload);
Result<QuerySensorGeometricProperties> decodeQuerySensorGeometricProperties(ByteSpan payload);
Result<ReportSensorGeometricProperties> decodeReportSensorGeometricProperties(ByteSpan payload);
Result<PanTiltJoints> decodePanTiltPositions(ByteSpan payload, std::uint16_t id);
Result<PanTiltJoints> decodePanTiltVelocities(ByteSpan payload, std::uint16_t id);

} // namespace ocu::jaus
