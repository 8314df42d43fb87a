// VideoClient on its own with a FakeClock: Digital Resource Discovery is queried every second
// until a report arrives, then every 10 s; RTSP entries become endpoints, others are left out; names come
// from the host's Visual Sensor capabilities and the pan-tilt mount from its geometry; configured streams are
// published beside them. Pan-tilt: control of the unit follows control of the vehicle (RequestControl,
// Resume after the confirmation, ReleaseControl when the vehicle's control ends); rates stream at 10 Hz while
// refreshed and go to zero (several times) when not; position polled.
#include <QtTest>

#include "protocols/jaus/clients/VideoClient.h"
#include "tests/protocols/jaus/clients/ClientRig.h"

using namespace ocu;
using namespace ocu::jaus;
using namespace ocu::jaus::test;

namespace {

const JausId kPm{126, 1, 1}, kCam{126, 4, 1}, kPt{126, 4, 2};

struct VideoRig : ClientRig {
    VideoClient video{ctx};
    explicit VideoRig(JausConfig c = rigConfig()) : ClientRig(std::move(c)) {
        video.registerMessages(table);
        table.onVehicleMessage(msg::ConfirmControl, [this](RemoteSubsystem& r, const JausId& s, ByteSpan p) {
            QVERIFY(video.handleControlMessage(r, s, msg::ConfirmControl, p));
        });
        table.onVehicleMessage(msg::RejectControl, [this](RemoteSubsystem& r, const JausId& s, ByteSpan p) {
            QVERIFY(video.handleControlMessage(r, s, msg::RejectControl, p));
        });
    }
    // A vehicle with DRD on its platform manager, a camera component and a pan-tilt unit.
    RemoteSubsystem& camVehicle(bool withVisualSensor = true) {
        RemoteSubsystem& r = vehicle();
        std::vector<ServiceRecord> cam{{"urn:jaus:jss:core:Transport", 1, 1}};
        if (withVisualSensor)
            cam.push_back({"urn:jaus:jss:environmentSensing:DigitalVideo", 1, 0});
        r.snap.services = {
            {1, {{1, {{"urn:jaus:jss:iop:DigitalResourceDiscovery", 1, 1}}}}},
            {4, {{1, cam}, {2, {{"urn:jaus:jss:manipulator:PanTiltJointVelocityDriver", 2, 0}}}}},
        };
        video.onServicesKnown(r);
        return r;
    }
    void run(RemoteSubsystem& r, double seconds) {
        runFor(seconds, [&](TimePoint now) { video.tick(r, now); });
    }
    int sentTo(std::uint16_t id, const JausId& to) const {
        return int(std::count_if(out.sent.begin(), out.sent.end(),
                                 [&](const Sent& s) { return s.id() == id && s.destination == to; }));
    }
};

ReportDigitalResourceEndpoint report() {
    ReportDigitalResourceEndpoint m;
    m.endpoints = {{0, "rtsp://127.0.0.1:9000/front", kCam, 1000},
                   {0, "rtsp://127.0.0.1:9000/rear", kCam, 1001},
                   {6, "https://127.0.0.1/still.jpg", kCam, 7}};
    return m;
}

} // namespace

class TestVideoClient : public QObject {
    Q_OBJECT
private slots:
    void discoveryRetriesThenRefreshes() {
        VideoRig rig;
        RemoteSubsystem& r = rig.camVehicle();
        rig.run(r, 3.5); // silent DRD: asked every second
        QCOMPARE(rig.sentTo(msg::QueryDigitalResourceEndpoint, kPm), 4);
        QVERIFY(rig.deliver(r, encode(report()), kPm));
        QCOMPARE(r.snap.videoEndpoints.size(), std::size_t(2)); // the HTTPS still image is not a stream
        QCOMPARE(QString::fromStdString(r.snap.videoEndpoints[0].url),
                 QStringLiteral("rtsp://127.0.0.1:9000/front"));
        QCOMPARE(r.snap.videoEndpoints[1].sensorId, 1001);
        rig.out.sent.clear();
        rig.run(r, 9.5);
        QCOMPARE(rig.sentTo(msg::QueryDigitalResourceEndpoint, kPm), 0);
        rig.run(r, 1.0);
        QCOMPARE(rig.sentTo(msg::QueryDigitalResourceEndpoint, kPm), 1);
    }

    // An empty report: the cameras may not have registered yet, so the client keeps asking every second
    // (for 30 s) rather than waiting for the slow refresh.
    void emptyReportKeepsAsking() {
        VideoRig rig;
        RemoteSubsystem& r = rig.camVehicle();
        rig.run(r, 0.05);
        rig.deliver(r, encode(ReportDigitalResourceEndpoint{}), kPm);
        rig.out.sent.clear();
        rig.run(r, 5);
        QCOMPARE(rig.sentTo(msg::QueryDigitalResourceEndpoint, kPm), 5);
        QVERIFY(r.snap.videoEndpoints.empty());
        rig.deliver(r, encode(report()), kPm);
        QCOMPARE(r.snap.videoEndpoints.size(), std::size_t(2));
        rig.out.sent.clear();
        rig.run(r, 5);
        QCOMPARE(rig.sentTo(msg::QueryDigitalResourceEndpoint, kPm), 0);
    }

    void namesAndMountFromTheHost() {
        VideoRig rig;
        RemoteSubsystem& r = rig.camVehicle();
        rig.run(r, 0.05);
        rig.deliver(r, encode(report()), kPm);
        rig.run(r, 0.05);
        QCOMPARE(rig.sentTo(msg::QueryVisualSensorCapabilities, kCam), 1);
        QCOMPARE(rig.sentTo(msg::QuerySensorGeometricProperties, kCam), 1);
        ReportVisualSensorCapabilities caps;
        VisualSensorCapabilities front, rear;
        front.sensorId = 1000;
        front.name = "front";
        rear.sensorId = 1001;
        rear.name = "rear";
        caps.sensors = {front, rear};
        rig.deliver(r, encode(caps), kCam);
        ReportSensorGeometricProperties geo;
        SensorGeometry g;
        g.sensorId = 1000;
        g.kind = 2;
        g.manipulator = kPt;
        g.joint = 2;
        geo.sensors = {g};
        rig.deliver(r, encode(geo), kCam);
        QCOMPARE(QString::fromStdString(r.snap.videoEndpoints[0].name), QStringLiteral("front"));
        QCOMPARE(QString::fromStdString(r.snap.videoEndpoints[1].name), QStringLiteral("rear"));
        QVERIFY(r.snap.videoEndpoints[0].panTilt);
        QVERIFY(!r.snap.videoEndpoints[1].panTilt);
        rig.out.sent.clear();
        rig.run(r, 5);
        QCOMPARE(rig.sentTo(msg::QueryVisualSensorCapabilities, kCam), 0); // answered: not asked again
    }

    void noVisualSensorNoQuestions() {
        VideoRig rig;
        RemoteSubsystem& r = rig.camVehicle(false);
        rig.run(r, 0.05);
        rig.deliver(r, encode(report()), kPm);
        rig.run(r, 5);
        QCOMPARE(rig.out.count(msg::QueryVisualSensorCapabilities), 0);
        QCOMPARE(r.snap.videoEndpoints.size(), std::size_t(2));
        QVERIFY(r.snap.videoEndpoints[0].name.empty());
    }

    void configuredBesideAnnounced() {
        JausConfig c = rigConfig();
        VideoEndpoint ve;
        ve.url = "rtsp://10.0.0.9/mast";
        ve.configured = true;
        c.configuredVideo[126] = {ve};
        VideoRig rig(c);
        RemoteSubsystem& r = rig.vehicle();
        rig.video.heard(r); // before its services are known
        QCOMPARE(r.snap.videoEndpoints.size(), std::size_t(1));
        QVERIFY(r.snap.videoEndpoints[0].configured);
    }

    void panTiltFollowsVehicleControl() {
        VideoRig rig;
        RemoteSubsystem& r = rig.camVehicle();
        rig.run(r, 0.05);
        rig.deliver(r, encode(report()), kPm);
        ReportSensorGeometricProperties geo;
        SensorGeometry g;
        g.sensorId = 1000;
        g.kind = 2;
        g.manipulator = kPt;
        geo.sensors = {g};
        rig.deliver(r, encode(geo), kCam);
        // Not controlling the vehicle: no control of the unit, commands refused.
        rig.run(r, 1);
        QCOMPARE(rig.sentTo(msg::RequestControl, kPt), 0);
        QVERIFY(!rig.video.panTilt(126, 1000, 0.5, 0));
        // Vehicle controlled: the unit is asked for control; commands wait for its confirmation.
        r.snap.controlledByUs = true;
        rig.run(r, 0.05);
        QCOMPARE(rig.sentTo(msg::RequestControl, kPt), 1);
        QVERIFY(!rig.video.panTilt(126, 1000, 0.5, 0));
        QVERIFY(QString::fromStdString(rig.ctx.lastRefusal()).contains(QStringLiteral("not confirmed")));
        rig.deliver(r, encodeU8(msg::ConfirmControl, 0), kPt);
        QCOMPARE(rig.sentTo(msg::Resume, kPt), 1);
        QVERIFY(r.snap.panTilts.at(0).controlledByUs);
        // The camera not on the unit is refused; the one on it goes out at once and streams at 10 Hz.
        QVERIFY(!rig.video.panTilt(126, 1001, 0.5, 0));
        // Repeated at a held key's rate: one event, every outcome still refused with its reason.
        const int events = rig.rec.count(EventKind::CommandRefused);
        QVERIFY(!rig.video.panTilt(126, 1001, 0.5, 0));
        QCOMPARE(rig.rec.count(EventKind::CommandRefused), events);
        QVERIFY(QString::fromStdString(rig.ctx.lastRefusal()).contains(QStringLiteral("not on a pan-tilt")));
        rig.out.sent.clear();
        QVERIFY(rig.video.panTilt(126, 1000, 0.5, -0.25));
        QCOMPARE(rig.sentTo(msg::SetPanTiltJointVelocity, kPt), 1);
        auto v = decodePanTiltVelocities(rig.out.last(msg::SetPanTiltJointVelocity)->payload,
                                         msg::SetPanTiltJointVelocity);
        QVERIFY(v && std::abs(v->pan - 0.5) < 1e-6 && std::abs(v->tilt + 0.25) < 1e-6);
        rig.run(r, 0.3);
        QCOMPARE(rig.sentTo(msg::SetPanTiltJointVelocity, kPt), 4);
        // Not refreshed within drive_command_timeout_s (0.5 s): zero, three times, then silence.
        rig.run(r, 1.5);
        std::vector<PanTiltJoints> sent;
        for (auto& s : rig.out.sent)
            if (s.id() == msg::SetPanTiltJointVelocity)
                sent.push_back(*decodePanTiltVelocities(s.payload, msg::SetPanTiltJointVelocity));
        QVERIFY(sent.size() >= 6);
        for (std::size_t i = sent.size() - 3; i < sent.size(); ++i)
            QVERIFY(std::abs(sent[i].pan) < 1e-6 && std::abs(sent[i].tilt) < 1e-6);
        const int n = rig.sentTo(msg::SetPanTiltJointVelocity, kPt);
        rig.run(r, 1);
        QCOMPARE(rig.sentTo(msg::SetPanTiltJointVelocity, kPt), n);
        QVERIFY(rig.sentTo(msg::QueryPanTiltJointPositions, kPt) >= 5);
        // Positions reported land in the snapshot.
        rig.deliver(r, encodePanTiltPositions(msg::ReportPanTiltJointPositions, {0.4, -0.1}), kPt);
        QVERIFY(std::abs(*r.snap.panTilts.at(0).pan - 0.4) < 1e-6);
        // Vehicle control ends: zero and ReleaseControl to the unit.
        r.snap.controlledByUs = false;
        rig.out.sent.clear();
        rig.run(r, 0.05);
        QCOMPARE(rig.sentTo(msg::ReleaseControl, kPt), 1);
        QCOMPARE(rig.sentTo(msg::SetPanTiltJointVelocity, kPt), 1);
        QVERIFY(!r.snap.panTilts.at(0).controlledByUs);
    }
};

QTEST_APPLESS_MAIN(TestVideoClient)
#include "test_video_client.moc"
