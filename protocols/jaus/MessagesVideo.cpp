// Video messages: Digital Resource Discovery, Visual Sensor, Digital Video, pan-tilt joints.
// Layouts: shared/research/jaus-services-extra.md §1.2, §2.2, §4 (JSIDL).
#include "protocols/jaus/MessagesVideo.h"

#include <array>
#include <numbers>

#include "protocols/jaus/MessageSupport.h"

namespace ocu::jaus {

using namespace codec;

namespace {

// A record's optional fields as data, in presence-vector bit order: either a raw unsigned integer (enums,
// bit sets, plain counts) or a scaled one uN[lo,hi]. Field i owns PV bit i.
template <class T> struct Field {
    int bytes = 1;
    std::optional<std::uint8_t> T::*u8 = nullptr;
    std::optional<std::uint16_t> T::*u16 = nullptr;
    std::optional<std::uint32_t> T::*u32 = nullptr;
    std::optional<double> T::*scaled = nullptr;
    double lo = 0, hi = 0;
};
template <class T> constexpr Field<T> raw8(std::optional<std::uint8_t> T::*m) {
    return Field<T>{1, m, nullptr, nullptr, nullptr, 0, 0};
}
template <class T> constexpr Field<T> raw16(std::optional<std::uint16_t> T::*m) {
    return Field<T>{2, nullptr, m, nullptr, nullptr, 0, 0};
}
template <class T> constexpr Field<T> raw32(std::optional<std::uint32_t> T::*m) {
    return Field<T>{4, nullptr, nullptr, m, nullptr, 0, 0};
}
template <class T> constexpr Field<T> scaled(int bytes, std::optional<double> T::*m, double lo, double hi) {
    return Field<T>{bytes, nullptr, nullptr, nullptr, m, lo, hi};
}

template <class T, std::size_t N> std::uint32_t presence(const std::array<Field<T>, N>& table, const T& m) {
    std::uint32_t pv = 0;
    for (std::size_t i = 0; i < N; ++i) {
        const Field<T>& f = table[i];
        const bool has = f.u8    ? (m.*f.u8).has_value()
                         : f.u16 ? (m.*f.u16).has_value()
                         : f.u32 ? (m.*f.u32).has_value()
                                 : (m.*f.scaled).has_value();
        pv |= std::uint32_t(has) << i;
    }
    return pv;
}

template <class T, std::size_t N>
void putAll(ByteWriter& w, const std::array<Field<T>, N>& table, const T& m) {
    for (const Field<T>& f : table) {
        if (f.u8) {
            if (m.*f.u8)
                w.u8(*(m.*f.u8));
        } else if (f.u16) {
            if (m.*f.u16)
                w.u16(*(m.*f.u16));
        } else if (f.u32) {
            if (m.*f.u32)
                w.u32(*(m.*f.u32));
        } else if (const auto& v = m.*f.scaled) {
            if (f.bytes == 4)
                w.u32(scaleToInt<std::uint32_t>(*v, f.lo, f.hi));
            else if (f.bytes == 2)
                w.u16(scaleToInt<std::uint16_t>(*v, f.lo, f.hi));
            else
                w.u8(scaleToInt<std::uint8_t>(*v, f.lo, f.hi));
        }
    }
}

template <class T, std::size_t N>
void getAll(ByteReader& r, const std::array<Field<T>, N>& table, std::uint32_t pv, T& m) {
    for (std::size_t i = 0; i < N; ++i) {
        if (!(pv & (1u << i)))
            continue;
        const Field<T>& f = table[i];
        if (f.u8)
            m.*f.u8 = r.u8();
        else if (f.u16)
            m.*f.u16 = r.u16();
        else if (f.u32)
            m.*f.u32 = r.u32();
        else if (f.bytes == 4)
            m.*f.scaled = intToScale<std::uint32_t>(r.u32(), f.lo, f.hi);
        else if (f.bytes == 2)
            m.*f.scaled = intToScale<std::uint16_t>(r.u16(), f.lo, f.hi);
        else
            m.*f.scaled = intToScale<std::uint8_t>(r.u8(), f.lo, f.hi);
    }
}

// A presence vector with bits beyond the table names fields this decoder cannot size: the record (and
// everything after it) cannot be read.
template <std::size_t N> bool knownBits(std::uint32_t pv) {
    return (pv >> N) == 0;
}

using Caps = VisualSensorCapabilities;
constexpr std::array<Field<Caps>, 15> kCapsFields{{
    raw8(&Caps::supportedStates),
    raw8(&Caps::zoomModes),
    raw8(&Caps::focusModes),
    raw8(&Caps::whiteBalance),
    raw8(&Caps::imagingModes),
    raw8(&Caps::exposureModes),
    raw8(&Caps::meteringModes),
    scaled(2, &Caps::minShutterSpeed, 0, 60),
    scaled(2, &Caps::maxShutterSpeed, 0, 60),
    scaled(2, &Caps::minAperture, 0.1, 128),
    scaled(2, &Caps::maxAperture, 0.1, 128),
    scaled(4, &Caps::minFocalLength, 0, 2),
    scaled(4, &Caps::maxFocalLength, 0, 2),
    raw8(&Caps::lightSensitivityLevels),
    raw8(&Caps::imageStabilization),
}};

using Conf = VisualSensorConfiguration;
constexpr std::array<Field<Conf>, 16> kConfFields{{
    raw8(&Conf::sensorState),
    raw8(&Conf::zoomMode),
    scaled(2, &Conf::zoomLevel, 0, 100),
    scaled(4, &Conf::focalLength, 0, 2),
    scaled(4, &Conf::horizontalFov, -std::numbers::pi, std::numbers::pi),
    scaled(4, &Conf::verticalFov, -std::numbers::pi, std::numbers::pi),
    raw8(&Conf::focusMode),
    scaled(2, &Conf::focusValue, 0, 100),
    raw8(&Conf::whiteBalance),
    raw8(&Conf::imagingMode),
    raw8(&Conf::exposureMode),
    raw8(&Conf::meteringMode),
    scaled(2, &Conf::shutterSpeed, 0, 60),
    scaled(2, &Conf::aperture, 0.1, 128),
    raw8(&Conf::lightSensitivity),
    raw8(&Conf::imageStabilization),
}};

using DvCaps = DigitalVideoCapabilities;
constexpr std::array<Field<DvCaps>, 6> kDvCapsFields{{
    raw16(&DvCaps::minBitRate),
    raw16(&DvCaps::maxBitRate),
    raw8(&DvCaps::minFrameRate),
    raw8(&DvCaps::maxFrameRate),
    raw32(&DvCaps::supportedFrameSizes),
    raw8(&DvCaps::supportedFormats),
}};

using DvConf = DigitalVideoConfiguration;
constexpr std::array<Field<DvConf>, 5> kDvConfFields{{
    raw16(&DvConf::minBitRate),
    raw16(&DvConf::maxBitRate),
    raw8(&DvConf::frameRate),
    raw8(&DvConf::frameSize),
    raw8(&DvConf::format),
}};

// count u16, then records; the count is capped at what fits a JUDP message anyway.
template <class Rec, class Put> Bytes encodeList(std::uint16_t id, const std::vector<Rec>& recs, Put put) {
    Bytes out;
    auto w = start(out, id);
    const std::size_t n = std::min<std::size_t>(recs.size(), 0xFFFF);
    w.u16(std::uint16_t(n));
    for (std::size_t i = 0; i < n; ++i)
        put(w, recs[i]);
    return out;
}
// Reads count u16 records; a record that cannot be read fails the whole message (nothing after it can be
// located).
template <class Msg, class Rec, class Get>
Result<Msg> decodeList(ByteSpan p, std::uint16_t id, std::vector<Rec> Msg::*list, Get get) {
    auto r = open(p, id);
    if (!r)
        return makeError(r.error());
    Msg m;
    const std::uint16_t n = r->u16();
    for (std::uint32_t i = 0; i < n && r->ok(); ++i) {
        Rec rec;
        if (!get(*r, rec))
            return makeError(std::string("value: ") + messageName(id) + " record " + std::to_string(i) +
                             " has presence bits this decoder cannot size");
        if (r->ok())
            (m.*list).push_back(std::move(rec));
    }
    return finish(*r, m, id);
}

void putEndpoint(ByteWriter& w, const DigitalResourceEndpoint& e) {
    w.u8(std::uint8_t((e.host ? 1 : 0) | (e.resourceId ? 2 : 0)));
    w.u8(e.serverType);
    putString8(w, e.url);
    if (e.host)
        w.u32(e.host->value());
    if (e.resourceId)
        w.u16(*e.resourceId);
}
void getEndpoint(ByteReader& r, DigitalResourceEndpoint& e) {
    const std::uint8_t pv = r.u8();
    e.serverType = r.u8();
    e.url = getString8(r);
    if (pv & 1)
        e.host = JausId::fromValue(r.u32());
    if (pv & 2)
        e.resourceId = r.u16();
}

constexpr double kPosLo = -8 * std::numbers::pi, kPosHi = 8 * std::numbers::pi,
                 kVelLo = -10 * std::numbers::pi, kVelHi = 10 * std::numbers::pi;

Bytes encodeJoints(std::uint16_t id, const PanTiltJoints& m, double lo, double hi) {
    Bytes out;
    auto w = start(out, id);
    w.u32(scaleToInt<std::uint32_t>(m.pan, lo, hi));
    w.u32(scaleToInt<std::uint32_t>(m.tilt, lo, hi));
    return out;
}
Result<PanTiltJoints> decodeJoints(ByteSpan p, std::uint16_t id, double lo, double hi) {
    auto r = open(p, id);
    if (!r)
        return makeError(r.error());
    PanTiltJoints m;
    m.pan = intToScale<std::uint32_t>(r->u32(), lo, hi);
    m.tilt = intToScale<std::uint32_t>(r->u32(), lo, hi);
    return finish(*r, m, id);
}

constexpr double kGeoPos = 30;

} // namespace

const char* videoMessageName(std::uint16_t id) {
    switch (id) {
    case msg::QueryDigitalResourceEndpoint:
        return "QueryDigitalResourceEndpoint";
    case msg::RegisterDigitalResourceEndpoint:
        return "RegisterDigitalResourceEndpoint";
    case msg::RemoveDigitalResourceEndpoint:
        return "RemoveDigitalResourceEndpoint";
    case msg::ReportDigitalResourceEndpoint:
        return "ReportDigitalResourceEndpoint";
    case msg::ConfirmDigitalResourceEndpoint:
        return "ConfirmDigitalResourceEndpoint";
    case msg::ConfirmSensorConfiguration:
        return "ConfirmSensorConfiguration";
    case msg::ControlDigitalVideoSensorStream:
        return "ControlDigitalVideoSensorStream";
    case msg::QuerySensorGeometricProperties:
        return "QuerySensorGeometricProperties";
    case msg::QueryVisualSensorCapabilities:
        return "QueryVisualSensorCapabilities";
    case msg::QueryVisualSensorConfiguration:
        return "QueryVisualSensorConfiguration";
    case msg::QueryDigitalVideoSensorCapabilities:
        return "QueryDigitalVideoSensorCapabilities";
    case msg::QueryDigitalVideoSensorConfiguration:
        return "QueryDigitalVideoSensorConfiguration";
    case msg::ReportSensorGeometricProperties:
        return "ReportSensorGeometricProperties";
    case msg::ReportVisualSensorCapabilities:
        return "ReportVisualSensorCapabilities";
    case msg::ReportVisualSensorConfiguration:
        return "ReportVisualSensorConfiguration";
    case msg::ReportDigitalVideoSensorCapabilities:
        return "ReportDigitalVideoSensorCapabilities";
    case msg::ReportDigitalVideoSensorConfiguration:
        return "ReportDigitalVideoSensorConfiguration";
    case msg::SetPanTiltJointPositions:
        return "SetPanTiltJointPositions";
    case msg::SetPanTiltJointVelocity:
        return "SetPanTiltJointVelocity";
    case msg::QueryPanTiltJointPositions:
        return "QueryPanTiltJointPositions";
    case msg::QueryPanTiltJointVelocity:
        return "QueryPanTiltJointVelocity";
    case msg::ReportPanTiltJointPositions:
        return "ReportPanTiltJointPositions";
    case msg::ReportPanTiltJointVelocity:
        return "ReportPanTiltJointVelocity";
    default:
        return "unknown";
    }
}

// ---- Digital Resource Discovery ----
Bytes encode(const RegisterDigitalResourceEndpoint& m) {
    Bytes out;
    auto w = start(out, msg::RegisterDigitalResourceEndpoint);
    w.u8(m.requestId);
    putEndpoint(w, m.endpoint);
    return out;
}
Result<RegisterDigitalResourceEndpoint> decodeRegisterDigitalResourceEndpoint(ByteSpan p) {
    auto r = open(p, msg::RegisterDigitalResourceEndpoint);
    if (!r)
        return makeError(r.error());
    RegisterDigitalResourceEndpoint m;
    m.requestId = r->u8();
    getEndpoint(*r, m.endpoint);
    return finish(*r, m, msg::RegisterDigitalResourceEndpoint);
}
Bytes encode(const RemoveDigitalResourceEndpoint& m) {
    Bytes out;
    auto w = start(out, msg::RemoveDigitalResourceEndpoint);
    w.u8(m.endpointId);
    w.u8(m.requestId);
    return out;
}
Result<RemoveDigitalResourceEndpoint> decodeRemoveDigitalResourceEndpoint(ByteSpan p) {
    auto r = open(p, msg::RemoveDigitalResourceEndpoint);
    if (!r)
        return makeError(r.error());
    RemoveDigitalResourceEndpoint m;
    m.endpointId = r->u8();
    m.requestId = r->u8();
    return finish(*r, m, msg::RemoveDigitalResourceEndpoint);
}
Bytes encode(const ConfirmDigitalResourceEndpoint& m) {
    Bytes out;
    auto w = start(out, msg::ConfirmDigitalResourceEndpoint);
    w.u8(m.endpointId);
    w.u8(m.requestId);
    return out;
}
Result<ConfirmDigitalResourceEndpoint> decodeConfirmDigitalResourceEndpoint(ByteSpan p) {
    auto r = open(p, msg::ConfirmDigitalResourceEndpoint);
    if (!r)
        return makeError(r.error());
    ConfirmDigitalResourceEndpoint m;
    m.endpointId = r->u8();
    m.requestId = r->u8();
    return finish(*r, m, msg::ConfirmDigitalResourceEndpoint);
}
Bytes encode(const ReportDigitalResourceEndpoint& m) {
    Bytes out;
    auto w = start(out, msg::ReportDigitalResourceEndpoint);
    const std::size_t n = std::min<std::size_t>(m.endpoints.size(), 255);
    w.u8(std::uint8_t(n));
    for (std::size_t i = 0; i < n; ++i)
        putEndpoint(w, m.endpoints[i]);
    return out;
}
Result<ReportDigitalResourceEndpoint> decodeReportDigitalResourceEndpoint(ByteSpan p) {
    auto r = open(p, msg::ReportDigitalResourceEndpoint);
    if (!r)
        return makeError(r.error());
    ReportDigitalResourceEndpoint m;
    const std::uint8_t n = r->u8();
    for (int i = 0; i < n && r->ok(); ++i) {
        DigitalResourceEndpoint e;
        getEndpoint(*r, e);
        if (r->ok())
            m.endpoints.push_back(std::move(e));
    }
    return finish(*r, m, msg::ReportDigitalResourceEndpoint);
}

// ---- Visual Sensor / Digital Video ----
Bytes encodeSensorQuery(std::uint16_t id, const QuerySensors& m) {
    const bool pv8 =
        id == msg::QueryDigitalVideoSensorCapabilities || id == msg::QueryDigitalVideoSensorConfiguration;
    return encodeList(id, m.sensors, [pv8](ByteWriter& w, const SensorQuery& q) {
        w.u16(q.sensorId);
        if (pv8)
            w.u8(std::uint8_t(q.presence));
        else
            w.u16(q.presence);
    });
}
Result<QuerySensors> decodeSensorQuery(ByteSpan p, std::uint16_t id) {
    const bool pv8 =
        id == msg::QueryDigitalVideoSensorCapabilities || id == msg::QueryDigitalVideoSensorConfiguration;
    auto r = open(p, id);
    if (!r)
        return makeError(r.error());
    QuerySensors m;
    m.sensors.clear();
    const std::uint16_t n = r->u16();
    for (std::uint32_t i = 0; i < n && r->ok(); ++i) {
        SensorQuery q;
        q.sensorId = r->u16();
        q.presence = pv8 ? r->u8() : r->u16();
        if (r->ok())
            m.sensors.push_back(q);
    }
    return finish(*r, m, id);
}

Bytes encode(const ReportVisualSensorCapabilities& m) {
    return encodeList(msg::ReportVisualSensorCapabilities, m.sensors, [](ByteWriter& w, const Caps& c) {
        w.u16(std::uint16_t(presence(kCapsFields, c)));
        w.u16(c.sensorId);
        putString8(w, c.name);
        putAll(w, kCapsFields, c);
    });
}
Result<ReportVisualSensorCapabilities> decodeReportVisualSensorCapabilities(ByteSpan p) {
    return decodeList(p, msg::ReportVisualSensorCapabilities, &ReportVisualSensorCapabilities::sensors,
                      [](ByteReader& r, Caps& c) {
                          const std::uint32_t pv = r.u16();
                          if (!knownBits<kCapsFields.size()>(pv))
                              return false;
                          c.sensorId = r.u16();
                          c.name = getString8(r);
                          getAll(r, kCapsFields, pv, c);
                          return true;
                      });
}

Bytes encode(const ReportVisualSensorConfiguration& m) {
    return encodeList(msg::ReportVisualSensorConfiguration, m.sensors, [](ByteWriter& w, const Conf& c) {
        w.u16(std::uint16_t(presence(kConfFields, c)));
        w.u16(c.sensorId);
        putAll(w, kConfFields, c);
    });
}
Result<ReportVisualSensorConfiguration> decodeReportVisualSensorConfiguration(ByteSpan p) {
    return decodeList(p, msg::ReportVisualSensorConfiguration, &ReportVisualSensorConfiguration::sensors,
                      [](ByteReader& r, Conf& c) {
                          const std::uint32_t pv = r.u16();
                          c.sensorId = r.u16();
                          getAll(r, kConfFields, pv, c);
                          return true;
                      });
}

Bytes encode(const ReportDigitalVideoCapabilities& m) {
    return encodeList(msg::ReportDigitalVideoSensorCapabilities, m.sensors,
                      [](ByteWriter& w, const DvCaps& c) {
                          w.u8(std::uint8_t(presence(kDvCapsFields, c)));
                          w.u16(c.sensorId);
                          putAll(w, kDvCapsFields, c);
                      });
}
Result<ReportDigitalVideoCapabilities> decodeReportDigitalVideoCapabilities(ByteSpan p) {
    return decodeList(p, msg::ReportDigitalVideoSensorCapabilities, &ReportDigitalVideoCapabilities::sensors,
                      [](ByteReader& r, DvCaps& c) {
                          const std::uint32_t pv = r.u8();
                          if (!knownBits<kDvCapsFields.size()>(pv))
                              return false;
                          c.sensorId = r.u16();
                          getAll(r, kDvCapsFields, pv, c);
                          return true;
                      });
}

Bytes encode(const ReportDigitalVideoConfiguration& m) {
    return encodeList(msg::ReportDigitalVideoSensorConfiguration, m.sensors,
                      [](ByteWriter& w, const DvConf& c) {
                          w.u8(std::uint8_t(presence(kDvConfFields, c)));
                          w.u16(c.sensorId);
                          putAll(w, kDvConfFields, c);
                      });
}
Result<ReportDigitalVideoConfiguration> decodeReportDigitalVideoConfiguration(ByteSpan p) {
    return decodeList(p, msg::ReportDigitalVideoSensorConfiguration,
                      &ReportDigitalVideoConfiguration::sensors, [](ByteReader& r, DvConf& c) {
                          const std::uint32_t pv = r.u8();
                          if (!knownBits<kDvConfFields.size()>(pv))
                              return false;
                          c.sensorId = r.u16();
                          getAll(r, kDvConfFields, pv, c);
                          return true;
                      });
}

Bytes encode(const ControlDigitalVideoSensorStream& m) {
    Bytes out;
    auto w = start(out, msg::ControlDigitalVideoSensorStream);
    w.u16(m.sensorId);
    w.u8(std::uint8_t(m.state));
    return out;
}
Result<ControlDigitalVideoSensorStream> decodeControlDigitalVideoSensorStream(ByteSpan p) {
    auto r = open(p, msg::ControlDigitalVideoSensorStream);
    if (!r)
        return makeError(r.error());
    ControlDigitalVideoSensorStream m;
    m.sensorId = r->u16();
    const std::uint8_t s = r->u8();
    if (r->ok() && s > 2)
        return makeError("value: ControlDigitalVideoSensorStream state " + std::to_string(s));
    m.state = StreamState(s);
    return finish(*r, m, msg::ControlDigitalVideoSensorStream);
}

Bytes encode(const QuerySensorGeometricProperties& m) {
    return encodeList(msg::QuerySensorGeometricProperties, m.sensorIds,
                      [](ByteWriter& w, std::uint16_t id) { w.u16(id); });
}
Result<QuerySensorGeometricProperties> decodeQuerySensorGeometricProperties(ByteSpan p) {
    auto r = open(p, msg::QuerySensorGeometricProperties);
    if (!r)
        return makeError(r.error());
    QuerySensorGeometricProperties m;
    m.sensorIds.clear();
    const std::uint16_t n = r->u16();
    for (std::uint32_t i = 0; i < n && r->ok(); ++i) {
        const std::uint16_t id = r->u16();
        if (r->ok())
            m.sensorIds.push_back(id);
    }
    return finish(*r, m, msg::QuerySensorGeometricProperties);
}

Bytes encode(const ReportSensorGeometricProperties& m) {
    return encodeList(msg::ReportSensorGeometricProperties, m.sensors,
                      [](ByteWriter& w, const SensorGeometry& g) {
                          w.u16(g.sensorId);
                          w.u8(g.kind);
                          if (g.kind == 0) {
                              w.u8(0); // the nested empty variant (jaus-services-extra.md §2.2)
                              return;
                          }
                          if (g.kind == 2) {
                              w.u16(g.manipulator.subsystem);
                              w.u8(g.manipulator.node);
                              w.u8(g.manipulator.component);
                              w.u8(g.joint);
                          }
                          for (double v : {g.x, g.y, g.z})
                              w.u32(scaleToInt<std::uint32_t>(v, -kGeoPos, kGeoPos));
                          for (double v : {g.qd, g.qa, g.qb, g.qc})
                              w.u32(scaleToInt<std::uint32_t>(v, -1, 1));
                      });
}
Result<ReportSensorGeometricProperties> decodeReportSensorGeometricProperties(ByteSpan p) {
    return decodeList(p, msg::ReportSensorGeometricProperties, &ReportSensorGeometricProperties::sensors,
                      [](ByteReader& r, SensorGeometry& g) {
                          g.sensorId = r.u16();
                          g.kind = r.u8();
                          if (g.kind == 0) {
                              r.u8();
                              return true;
                          }
                          if (g.kind > 2)
                              return false;
                          if (g.kind == 2) {
                              g.manipulator.subsystem = r.u16();
                              g.manipulator.node = r.u8();
                              g.manipulator.component = r.u8();
                              g.joint = r.u8();
                          }
                          for (double* v : {&g.x, &g.y, &g.z})
                              *v = intToScale<std::uint32_t>(r.u32(), -kGeoPos, kGeoPos);
                          for (double* v : {&g.qd, &g.qa, &g.qb, &g.qc})
                              *v = intToScale<std::uint32_t>(r.u32(), -1, 1);
                          return true;
                      });
}

// ---- pan-tilt ----
Bytes encodePanTiltPositions(std::uint16_t id, const PanTiltJoints& m) {
    return encodeJoints(id, m, kPosLo, kPosHi);
}
Bytes encodePanTiltVelocities(std::uint16_t id, const PanTiltJoints& m) {
    return encodeJoints(id, m, kVelLo, kVelHi);
}
Result<PanTiltJoints> decodePanTiltPositions(ByteSpan p, std::uint16_t id) {
    return decodeJoints(p, id, kPosLo, kPosHi);
}
Result<PanTiltJoints> decodePanTiltVelocities(ByteSpan p, std::uint16_t id) {
    return decodeJoints(p, id, kVelLo, kVelHi);
}

} // namespace ocu::jaus
