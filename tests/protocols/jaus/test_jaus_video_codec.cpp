// The video message codecs (Digital Resource Discovery, Visual Sensor, Digital Video, pan-tilt)
// against the byte vectors of shared/research/jaus-services-extra.md §1.2, §2.2, §2.3, §4, in both
// directions, plus records with missing optional fields and malformed input.
#include <QtTest>

#include <numbers>
#include <random>

#include "protocols/jaus/Messages.h"
#include "protocols/jaus/MessagesVideo.h"

using namespace ocu;
using namespace ocu::jaus;

namespace {

Bytes hex(const std::string& s) {
    Bytes out;
    for (std::size_t i = 0; i + 1 < s.size(); i += 2)
        out.push_back(std::uint8_t(std::stoi(s.substr(i, 2), nullptr, 16)));
    return out;
}
std::string hexOf(const std::string& ascii) {
    static const char* d = "0123456789abcdef";
    std::string out;
    for (unsigned char c : ascii) {
        out += d[c >> 4];
        out += d[c & 15];
    }
    return out;
}
QString toHex(const Bytes& b) {
    return QString::fromLatin1(
        QByteArray(reinterpret_cast<const char*>(b.data()), qsizetype(b.size())).toHex());
}

const std::string kUrl = "rtsp://192.168.1.10:8554/front";

} // namespace

class TestJausVideoCodec : public QObject {
    Q_OBJECT
private slots:
    // §1.2: Register rtsp://192.168.1.10:8554/front hosted by 258.1.40, SensorID 1000, RequestID 5.
    void registerEndpointVector() {
        RegisterDigitalResourceEndpoint m;
        m.requestId = 5;
        m.endpoint.serverType = 0;
        m.endpoint.url = kUrl;
        m.endpoint.host = JausId{258, 1, 40};
        m.endpoint.resourceId = 1000;
        const Bytes want = hex("03e7"
                               "05"
                               "03"
                               "00"
                               "1e" +
                               hexOf(kUrl) +
                               "28010201"
                               "e803");
        QCOMPARE(toHex(encode(m)), toHex(want));
        auto d = decodeRegisterDigitalResourceEndpoint(want);
        QVERIFY(d);
        QCOMPARE(d->requestId, 5);
        QVERIFY(d->endpoint == m.endpoint);
    }
    void confirmVector() {
        const Bytes want = hex("03f70105");
        QCOMPARE(toHex(encode(ConfirmDigitalResourceEndpoint{1, 5})), toHex(want));
        auto d = decodeConfirmDigitalResourceEndpoint(want);
        QVERIFY(d);
        QCOMPARE(d->endpointId, 1);
        QCOMPARE(d->requestId, 5);
        QCOMPARE(toHex(encode(RemoveDigitalResourceEndpoint{1, 6})), QStringLiteral("04e70106"));
        QCOMPARE(toHex(encodeEmpty(msg::QueryDigitalResourceEndpoint)), QStringLiteral("02e7"));
    }
    void reportWithAndWithoutOptionalFields() {
        ReportDigitalResourceEndpoint m;
        DigitalResourceEndpoint full{0, kUrl, JausId{258, 1, 40}, 1000};
        DigitalResourceEndpoint bare{0, "rtsp://10.0.0.7/cam", std::nullopt, std::nullopt}; // PV 0
        m.endpoints = {full, bare};
        const Bytes want = hex("02f7"
                               "02"
                               "03001e" +
                               hexOf(kUrl) + "28010201e803" + "0000" + "13" + hexOf("rtsp://10.0.0.7/cam"));
        QCOMPARE(toHex(encode(m)), toHex(want));
        auto d = decodeReportDigitalResourceEndpoint(want);
        QVERIFY(d);
        QCOMPARE(d->endpoints.size(), std::size_t(2));
        QVERIFY(d->endpoints[0] == full);
        QVERIFY(d->endpoints[1] == bare);
        // Truncated inside the second record: an error, never a half-read endpoint.
        Bytes cut(want.begin(), want.end() - 4);
        QVERIFY(!decodeReportDigitalResourceEndpoint(cut));
    }
    // §2.2 / §2.3: ControlDigitalVideoSensorStream Play sensor 1000 = 05 08 E8 03 00.
    void controlStreamVector() {
        const Bytes want = hex("0508e80300");
        QCOMPARE(toHex(encode(ControlDigitalVideoSensorStream{1000, StreamState::Play})), toHex(want));
        auto d = decodeControlDigitalVideoSensorStream(want);
        QVERIFY(d);
        QCOMPARE(d->sensorId, 1000);
        QVERIFY(d->state == StreamState::Play);
        QVERIFY(!decodeControlDigitalVideoSensorStream(hex("0508e80307"))); // no state 7
    }
    // The configuration record of §2.3's example (PV u16 = b0, SensorID 1000, Active), in a Report.
    void visualSensorConfigurationRecord() {
        ReportVisualSensorConfiguration m;
        VisualSensorConfiguration c;
        c.sensorId = 1000;
        c.sensorState = 0;
        m.sensors = {c};
        const Bytes want = hex("0748"
                               "0100"
                               "0100"
                               "e803"
                               "00");
        QCOMPARE(toHex(encode(m)), toHex(want));
        auto d = decodeReportVisualSensorConfiguration(want);
        QVERIFY(d);
        QCOMPARE(d->sensors.size(), std::size_t(1));
        QCOMPARE(d->sensors[0].sensorId, 1000);
        QCOMPARE(*d->sensors[0].sensorState, 0);
        QVERIFY(!d->sensors[0].horizontalFov);
        // With a field of fov: bit 4, u32[-π, π]; 0 rad = 0x80000000.
        c.horizontalFov = 0.0;
        m.sensors = {c};
        QCOMPARE(toHex(encode(m)), QStringLiteral("0748010011 00e80300 00000080").remove(QLatin1Char(' ')));
    }
    void queriesAllSensors() {
        // SensorID 0 = all, PV 0xFFFF (u16 for Visual Sensor, u8 for Digital Video).
        QCOMPARE(toHex(encodeSensorQuery(msg::QueryVisualSensorCapabilities, QuerySensors{})),
                 QStringLiteral("062801000000ffff"));
        QCOMPARE(toHex(encodeSensorQuery(msg::QueryDigitalVideoSensorCapabilities, QuerySensors{})),
                 QStringLiteral("0828010000 00ff").remove(QLatin1Char(' ')));
        auto q = decodeSensorQuery(hex("0728020001000300e903ff00"), msg::QueryVisualSensorConfiguration);
        QVERIFY(q);
        QCOMPARE(q->sensors.size(), std::size_t(2));
        QCOMPARE(q->sensors[1].sensorId, 1001);
        QCOMPARE(q->sensors[1].presence, 0x00ff);
        QCOMPARE(toHex(encode(QuerySensorGeometricProperties{})), QStringLiteral("052801000000"));
    }
    void visualSensorCapabilities() {
        ReportVisualSensorCapabilities m;
        VisualSensorCapabilities a;
        a.sensorId = 1000;
        a.name = "front";
        a.supportedStates = 0x03; // Active, Standby
        a.imagingModes = 0x01;    // Color
        VisualSensorCapabilities b;
        b.sensorId = 1001;
        b.name = "rear";
        m.sensors = {a, b};
        // PV 0x0011 (b0, b4); name str8; then the two u8 fields in bit order.
        const Bytes want = hex("0648"
                               "0200"
                               "1100"
                               "e803"
                               "05" +
                               hexOf("front") +
                               "03"
                               "01" +
                               "0000"
                               "e903"
                               "04" +
                               hexOf("rear"));
        QCOMPARE(toHex(encode(m)), toHex(want));
        auto d = decodeReportVisualSensorCapabilities(want);
        QVERIFY(d);
        QCOMPARE(d->sensors.size(), std::size_t(2));
        QCOMPARE(QString::fromStdString(d->sensors[0].name), QStringLiteral("front"));
        QCOMPARE(*d->sensors[0].supportedStates, 3);
        QCOMPARE(*d->sensors[0].imagingModes, 1);
        QCOMPARE(QString::fromStdString(d->sensors[1].name), QStringLiteral("rear"));
        // Scaled fields decode within one step: focal length u32[0,2] m.
        a.minFocalLength = 0.004;
        m.sensors = {a};
        auto e = decodeReportVisualSensorCapabilities(encode(m));
        QVERIFY(e);
        QVERIFY(std::abs(*e->sensors[0].minFocalLength - 0.004) < 1e-8);
        // A PV bit this decoder cannot size (bit 15): the message is refused, not misread.
        QVERIFY(!decodeReportVisualSensorCapabilities(hex("064801000080e80300")));
    }
    void digitalVideo() {
        ReportDigitalVideoCapabilities caps;
        DigitalVideoCapabilities c;
        c.sensorId = 1000;
        c.maxBitRate = 4000;
        c.maxFrameRate = 30;
        c.supportedFrameSizes = (1u << kFrameSize640x480) | (1u << kFrameSize1280x720);
        c.supportedFormats = 1u << kFormatH264;
        caps.sensors = {c};
        // PV 0x3A (b1, b3, b4, b5).
        QCOMPARE(toHex(encode(caps)), QStringLiteral("084801003ae803a00f1e8000000840"));
        auto d = decodeReportDigitalVideoCapabilities(encode(caps));
        QVERIFY(d);
        QCOMPARE(*d->sensors[0].supportedFrameSizes, c.supportedFrameSizes.value());
        QVERIFY(!d->sensors[0].minBitRate);

        ReportDigitalVideoConfiguration conf;
        DigitalVideoConfiguration k;
        k.sensorId = 1001;
        k.frameRate = 15;
        k.frameSize = kFrameSize640x480;
        k.format = kFormatH264;
        conf.sensors = {k};
        QCOMPARE(toHex(encode(conf)), QStringLiteral("094801001ce9030f0706"));
        auto e = decodeReportDigitalVideoConfiguration(encode(conf));
        QVERIFY(e);
        QCOMPARE(*e->sensors[0].frameSize, kFrameSize640x480);
    }
    void geometry() {
        ReportSensorGeometricProperties m;
        SensorGeometry none;
        none.sensorId = 1001;
        SensorGeometry onPt;
        onPt.sensorId = 1000;
        onPt.kind = 2;
        onPt.manipulator = JausId{126, 4, 2};
        onPt.joint = 2;
        onPt.z = 0.3;
        m.sensors = {none, onPt};
        const Bytes b = encode(m);
        // Record 1: SensorID, vtag 0, nested empty variant 0.
        QCOMPARE(toHex(Bytes(b.begin(), b.begin() + 8)), QStringLiteral("05480200e9030000"));
        // Record 2 starts with SensorID, vtag 2, host 126.4.2, joint 2.
        QCOMPARE(toHex(Bytes(b.begin() + 8, b.begin() + 15)), QStringLiteral("e803027e000402"));
        QCOMPARE(b.size(), std::size_t(8 + 2 + 1 + 5 + 12 + 16));
        auto d = decodeReportSensorGeometricProperties(b);
        QVERIFY(d);
        QCOMPARE(d->sensors.size(), std::size_t(2));
        QCOMPARE(d->sensors[0].kind, 0);
        QCOMPARE(d->sensors[1].kind, 2);
        QVERIFY(d->sensors[1].manipulator == (JausId{126, 4, 2}));
        QVERIFY(std::abs(d->sensors[1].z - 0.3) < 1e-6);
        QVERIFY(std::abs(d->sensors[1].qd - 1) < 1e-6);
        QVERIFY(!decodeReportSensorGeometricProperties(hex("05480100e80309"))); // vtag 9
    }
    // §4 examples: pan 0 = 00 00 00 80, +π/2 = FF FF FF 87, -0.5 rad = F2 19 74 7D.
    void panTiltVectors() {
        const double pi = std::numbers::pi;
        QCOMPARE(toHex(encodePanTiltPositions(msg::SetPanTiltJointPositions, {0.0, pi / 2})),
                 QStringLiteral("22060000 0080ffff ff87").remove(QLatin1Char(' ')));
        QCOMPARE(toHex(encodePanTiltPositions(msg::ReportPanTiltJointPositions, {-0.5, 0.0})),
                 QStringLiteral("2246f219747d00000080"));
        auto p = decodePanTiltPositions(hex("2246f219747dffffff87"), msg::ReportPanTiltJointPositions);
        QVERIFY(p);
        QVERIFY(std::abs(p->pan + 0.5) < 2e-8);
        QVERIFY(std::abs(p->tilt - pi / 2) < 2e-8);
        // JTS truncation (FF FF FF 7F) is one LSB from zero.
        auto t = decodePanTiltPositions(hex("2246ffffff7f00000080"), msg::ReportPanTiltJointPositions);
        QVERIFY(t && std::abs(t->pan) < 2e-8);
        // Velocities u32[-10π, 10π]: 0 = 0x80000000; the full range saturates.
        QCOMPARE(toHex(encodePanTiltVelocities(msg::SetPanTiltJointVelocity, {0.0, 1000.0})),
                 QStringLiteral("230600000080ffffffff"));
        auto v = decodePanTiltVelocities(encodePanTiltVelocities(msg::SetPanTiltJointVelocity, {0.25, -0.1}),
                                         msg::SetPanTiltJointVelocity);
        QVERIFY(v && std::abs(v->pan - 0.25) < 1e-7 && std::abs(v->tilt + 0.1) < 1e-7);
        QVERIFY(!decodePanTiltPositions(hex("224600000080"), msg::ReportPanTiltJointPositions)); // short
        QVERIFY(!decodePanTiltPositions(hex("2246f219747dffffff87"), msg::ReportPanTiltJointVelocity));
    }
    void names() {
        QCOMPARE(QString::fromLatin1(messageName(msg::RegisterDigitalResourceEndpoint)),
                 QStringLiteral("RegisterDigitalResourceEndpoint"));
        QCOMPARE(QString::fromLatin1(messageName(msg::ReportPanTiltJointPositions)),
                 QStringLiteral("ReportPanTiltJointPositions"));
    }
    // Random bytes behind every video message ID: the decoders answer (value or error), never crash or
    // read past the input.
    void randomInputNeverCrashes() {
        std::mt19937 rng(18);
        const std::uint16_t ids[] = {0xF702, 0xE703, 0x4806, 0x4807, 0x4808, 0x4809,
                                     0x4805, 0x2806, 0x2805, 0x0805, 0x4622};
        int decoded = 0;
        for (int i = 0; i < 20000; ++i) {
            Bytes b(2 + rng() % 40);
            for (auto& x : b)
                x = std::uint8_t(rng());
            const std::uint16_t id = ids[i % std::size(ids)];
            b[0] = std::uint8_t(id);
            b[1] = std::uint8_t(id >> 8);
            decoded += bool(decodeReportDigitalResourceEndpoint(b)) +
                       bool(decodeRegisterDigitalResourceEndpoint(b)) +
                       bool(decodeReportVisualSensorCapabilities(b)) +
                       bool(decodeReportVisualSensorConfiguration(b)) +
                       bool(decodeReportDigitalVideoCapabilities(b)) +
                       bool(decodeReportDigitalVideoConfiguration(b)) +
                       bool(decodeReportSensorGeometricProperties(b)) +
                       bool(decodeSensorQuery(b, msg::QueryVisualSensorCapabilities)) +
                       bool(decodeQuerySensorGeometricProperties(b)) +
                       bool(decodeControlDigitalVideoSensorStream(b)) +
                       bool(decodePanTiltPositions(b, msg::ReportPanTiltJointPositions));
        }
        QVERIFY(decoded > 0); // some random bodies are valid
    }
};

QTEST_APPLESS_MAIN(TestJausVideoCodec)
#include "test_jaus_video_codec.moc"
