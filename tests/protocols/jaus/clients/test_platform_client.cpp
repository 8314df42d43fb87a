// PlatformClient on its own with a FakeClock, the vehicle played by hand: the services found by name in any
// namespace with their versions (a comms-lost policy service only detected), the reports in the snapshot,
// the emergency platform state refusing drive and mission commands, the lights switched from what the
// vehicle reports (never its visible-light source), control taken through the vehicle's access control or
// through a component's own, released after the last command, the odometer polled and its trip reset, and
// the refusals (monitor role, no service, a light the vehicle lacks, control not granted).
#include <QtTest>

#include "protocols/jaus/MessagesPlatformServices.h"
#include "protocols/jaus/clients/AccessControlClient.h"
#include "protocols/jaus/clients/DriveClient.h"
#include "protocols/jaus/clients/EventsClient.h"
#include "protocols/jaus/clients/PlatformClient.h"
#include "tests/protocols/jaus/clients/ClientRig.h"

using namespace ocu;
using namespace ocu::jaus;
using namespace ocu::jaus::test;

namespace {

struct PlatformRig : ClientRig {
    EventsClient events{ctx};
    DriveClient drive{ctx};
    AccessControlClient access{ctx, drive};
    PlatformClient platform{ctx, events, access};
    explicit PlatformRig(JausConfig c = rigConfig()) : ClientRig(std::move(c)) {
        for (ClientService* s : std::initializer_list<ClientService*>{&events, &drive, &access, &platform})
            s->registerMessages(table);
        access.setOtherControl([this](RemoteSubsystem& r, const JausId& src, std::uint16_t id, ByteSpan p) {
            return platform.handleControlMessage(r, src, id, p);
        });
    }
    // The platform services on the drive component ss.3.1, or the lights on a component ss.2.1 of their
    // own; a comms-lost policy service on the platform manager.
    RemoteSubsystem& platformVehicle(bool lightsOwnComponent = false) {
        RemoteSubsystem& r = vehicle();
        std::vector<ServiceRecord> mob{{"urn:jaus:jss:mobility:PrimitiveDriver", 1, 1},
                                       {"urn:jaus:jss:iop:PlatformMode", 1, 1},
                                       {"urn:jaus:jss:iop:PlatformState", 1, 1},
                                       {"urn:jaus:jss:ugv:OdometryService", 1, 0}};
        std::vector<NodeInfo> nodes{
            NodeInfo{1, {ComponentInfo{1, {{"urn:jaus:jss:iop:CommsLostPolicyManager", 1, 1}}}}}};
        const ServiceRecord lights{"urn:jaus:jss:ugv:IlluminationService", 1, 0};
        if (lightsOwnComponent)
            nodes.push_back(NodeInfo{2, {ComponentInfo{1, {lights}}}});
        else
            mob.push_back(lights);
        nodes.push_back(NodeInfo{3, {ComponentInfo{1, mob}}});
        r.snap.services = nodes;
        platform.onServicesKnown(r);
        return r;
    }
    void control(RemoteSubsystem& r) {
        access.requestControl(r.id());
        deliver(r, encodeU8(msg::ConfirmControl, 0));
        QVERIFY(r.snap.controlledByUs);
    }
    void run(RemoteSubsystem& r, double seconds) {
        runFor(seconds, [&](TimePoint now) {
            access.tick(r, now);
            platform.tick(r, now);
        });
    }
    std::uint32_t lastLights() const {
        const Sent* s = out.last(msg::SetIlluminationState);
        return s ? *decodeIllumination(s->payload, msg::SetIlluminationState) : 0xFFFFFFFFu;
    }
};

const JausId kLightsComponent{126, 2, 1};

} // namespace

class TestPlatformClient : public QObject {
    Q_OBJECT
private slots:
    void servicesFoundWithTheirVersions() {
        PlatformRig rig;
        RemoteSubsystem& r = rig.platformVehicle();
        const PlatformServicesStatus& ps = r.snap.platformServices;
        QVERIFY(ps.modeService.offered && ps.stateService.offered && ps.illuminationService.offered &&
                ps.odometryService.offered);
        QCOMPARE(ps.illuminationService.uri, std::string("urn:jaus:jss:ugv:IlluminationService"));
        QCOMPARE(ps.illuminationService.major, 1);
        QCOMPARE(ps.illuminationService.minor, 0);
        QVERIFY(ps.commsLostService.offered);
        QCOMPARE(ps.commsLostService.uri, std::string("urn:jaus:jss:iop:CommsLostPolicyManager"));
        QCOMPARE(ps.commsLostService.minor, 1);
        // Mode, state and lights on change (polled where the vehicle serves no events).
        QVERIFY(rig.events.state(126, msg::QueryPlatformState));
        QVERIFY(rig.events.state(126, msg::QueryPlatformMode));
        QVERIFY(rig.events.state(126, msg::QueryIlluminationState));
        // The odometer is polled at 1 Hz (PLATFORM and TRIP_A); capabilities asked for until answered.
        rig.run(r, 2.05);
        QCOMPARE(rig.out.count(msg::QueryOdometry), 6);
        QVERIFY(rig.out.count(msg::QuerySupportedPlatformModes) >= 1);
        QVERIFY(rig.out.count(msg::QueryIlluminationConfiguration) >= 1);
        rig.deliver(r, encode(ReportSupportedPlatformModes{{0, 2}}));
        rig.deliver(r, encodeIllumination(msg::ReportIlluminationConfiguration, 0x9F | (1u << 12)));
        const int asked = rig.out.count(msg::QuerySupportedPlatformModes);
        rig.run(r, 5);
        QCOMPARE(rig.out.count(msg::QuerySupportedPlatformModes), asked);
        QCOMPARE(ps.supportedModes, (std::vector<std::uint8_t>{0, 2}));
        QCOMPARE(*ps.lightsSupported, 0x9Fu | light::HighBeams);
    }

    void aVehicleWithoutTheServices() {
        PlatformRig rig;
        RemoteSubsystem& r = rig.vehicle();
        r.snap.services = {
            NodeInfo{3, {ComponentInfo{1, {{"urn:jaus:jss:mobility:PrimitiveDriver", 1, 1}}}}}};
        rig.platform.onServicesKnown(r);
        QVERIFY(!r.snap.platformServices.stateService.offered &&
                !r.snap.platformServices.commsLostService.offered);
        QVERIFY(!rig.platform.setLights(126, light::Headlights, light::Headlights));
        QCOMPARE(rig.ctx.lastRefusalCause(), OutcomeReason::NotSupported);
        QVERIFY(QString::fromStdString(rig.ctx.lastRefusal()).contains("IlluminationService"));
        QVERIFY(!rig.platform.setState(126, 4));
        QVERIFY(!rig.platform.queryOdometry(126));
        rig.run(r, 3);
        QCOMPARE(rig.out.count(msg::QueryOdometry), 0);
    }

    void reportsFillTheSnapshot() {
        PlatformRig rig;
        RemoteSubsystem& r = rig.platformVehicle();
        rig.deliver(r, encode(ReportPlatformMode{1, 1}));
        rig.deliver(r, encodeU8(msg::ReportPlatformState, 1));
        rig.deliver(
            r, encodeIllumination(msg::ReportIlluminationState, light::Headlights | light::IrLightSource));
        rig.deliver(r, encode(ReportOdometry{1, 1234}));
        rig.deliver(r, encode(ReportOdometry{2, 56}));
        const PlatformServicesStatus& ps = r.snap.platformServices;
        QCOMPARE(*ps.mode, std::uint8_t(1));
        QCOMPARE(*ps.state, std::uint8_t(1));
        QCOMPARE(*ps.lights, light::Headlights | light::IrLightSource);
        QCOMPARE(*ps.odometerM, 1234u);
        QCOMPARE(*ps.tripM, 56u);
        QCOMPARE(rig.rec.snapshots.back().platformServices, ps);
        // A malformed report is counted, the snapshot kept.
        rig.deliver(r, Bytes{0x28, 0xFF});
        QCOMPARE(*ps.state, std::uint8_t(1));
    }

    void emergencyStateRefusesDriveAndMission() {
        PlatformRig rig;
        RemoteSubsystem& r = rig.platformVehicle();
        QVERIFY(!rig.platform.refuseInEmergency(126, "driving"));
        rig.deliver(r, encodeU8(msg::ReportPlatformState, 4));
        QVERIFY(rig.platform.emergencyState(126));
        QVERIFY(rig.rec.count(EventKind::ManagementChanged) == 1);
        QVERIFY(rig.platform.refuseInEmergency(126, "driving"));
        QCOMPARE(rig.ctx.lastRefusalCause(), OutcomeReason::Refused);
        QVERIFY(QString::fromStdString(rig.ctx.lastRefusal()).contains("emergency platform state"));
        rig.deliver(r, encodeU8(msg::ReportPlatformState, 1));
        QVERIFY(!rig.platform.emergencyState(126));
        QCOMPARE(rig.rec.count(EventKind::ManagementChanged), 2);
    }

    void lightsSwitchedFromWhatTheVehicleReports() {
        PlatformRig rig;
        RemoteSubsystem& r = rig.platformVehicle();
        rig.control(r);
        // The vehicle reports running lights and its visible-light source on: both kept.
        rig.deliver(r, encodeIllumination(msg::ReportIlluminationState,
                                          light::RunningLights | light::VisibleLightSource));
        QVERIFY(rig.platform.setLights(126, light::Headlights | light::LeftTurnSignal, light::Headlights));
        QCOMPARE(rig.lastLights(), light::Headlights | light::RunningLights | light::VisibleLightSource);
        QCOMPARE(rig.out.sent.back().id(), msg::QueryIlluminationState); // read back, no confirmation exists
        // The snapshot still says what the vehicle reported, not what was asked.
        QCOMPARE(*r.snap.platformServices.lights, light::RunningLights | light::VisibleLightSource);
        // Never the whole vehicle's visible-light source, nor a light outside the switchable set.
        QVERIFY(!rig.platform.setLights(126, light::VisibleLightSource, 0));
        QCOMPARE(rig.ctx.lastRefusalCause(), OutcomeReason::InvalidArgument);
        QVERIFY(!rig.platform.setLights(126, light::HazardLights, light::HazardLights));
        // A light the vehicle says it lacks.
        rig.deliver(r, encodeIllumination(msg::ReportIlluminationConfiguration, light::Headlights));
        QVERIFY(!rig.platform.setLights(126, light::BrakeLights, light::BrakeLights));
        QCOMPARE(rig.ctx.lastRefusalCause(), OutcomeReason::NotSupported);
        QVERIFY(rig.platform.setLights(126, light::BrakeLights, 0)); // switching off is harmless
    }

    void controlRequestedFirstThenTheCommand() {
        PlatformRig rig;
        RemoteSubsystem& r = rig.platformVehicle();
        QVERIFY(rig.platform.setMode(126, 2));
        QCOMPARE(rig.out.count(msg::RequestControl), 1);
        QCOMPARE(rig.out.count(msg::SetPlatformMode), 0);
        rig.deliver(r, encodeU8(msg::ConfirmControl, 0));
        rig.run(r, 0.02);
        QCOMPARE(rig.out.count(msg::SetPlatformMode), 1);
        QCOMPARE(rig.out.last(msg::SetPlatformMode)->payload, encodeU8(msg::SetPlatformMode, 2));
        QVERIFY(rig.out.last(msg::QueryPlatformMode));
        // A mode the vehicle does not support is refused before the wire.
        rig.deliver(r, encode(ReportSupportedPlatformModes{{0, 1}}));
        QVERIFY(!rig.platform.setMode(126, 2));
        QCOMPARE(rig.ctx.lastRefusalCause(), OutcomeReason::NotSupported);
    }

    void controlNeverGranted() {
        PlatformRig rig;
        RemoteSubsystem& r = rig.platformVehicle();
        QVERIFY(rig.platform.resetTrip(126));
        rig.run(r, 5.1);
        QCOMPARE(rig.out.count(msg::ResetOdometry), 0);
        QVERIFY(rig.rec.count(EventKind::CommandRefused) >= 1);
        QVERIFY(QString::fromStdString(rig.rec.events.back().text).contains("not granted"));
    }

    void lightsOnAComponentOfTheirOwn() {
        PlatformRig rig;
        RemoteSubsystem& r = rig.platformVehicle(true);
        QVERIFY(rig.platform.setLights(126, light::Headlights, light::Headlights));
        const Sent* req = rig.out.last(msg::RequestControl);
        QVERIFY(req);
        QCOMPARE(req->destination, kLightsComponent);
        QVERIFY(!rig.access.wantsControl(126)); // the vehicle's own control is not asked for
        rig.deliver(r, encodeU8(msg::ConfirmControl, 0), kLightsComponent);
        QVERIFY(!r.snap.controlledByUs); // not the vehicle's control
        rig.run(r, 0.02);
        QCOMPARE(rig.out.last(msg::SetIlluminationState)->destination, kLightsComponent);
        QCOMPARE(rig.lastLights(), light::Headlights);
        // Kept while commands follow, released 3 s after the last.
        rig.run(r, 2);
        QCOMPARE(rig.out.count(msg::RequestControl), 2); // re-requested inside the access timeout
        rig.deliver(r, encodeU8(msg::ConfirmControl, 0), kLightsComponent);
        QVERIFY(rig.platform.setLights(126, light::Headlights, 0));
        QCOMPARE(rig.lastLights(), 0u);
        rig.run(r, 2.5);
        QCOMPARE(rig.out.count(msg::ReleaseControl), 0);
        rig.run(r, 1);
        QCOMPARE(rig.out.count(msg::ReleaseControl), 1);
        QCOMPARE(rig.out.last(msg::ReleaseControl)->destination, kLightsComponent);
        // Refused control drops the command with the reason.
        QVERIFY(rig.platform.setLights(126, light::Headlights, light::Headlights));
        const int sets = rig.out.count(msg::SetIlluminationState);
        rig.deliver(r, encodeU8(msg::ConfirmControl, 2), kLightsComponent);
        rig.run(r, 1);
        QCOMPARE(rig.out.count(msg::SetIlluminationState), sets);
        QVERIFY(QString::fromStdString(rig.rec.events.back().text).contains("insufficient authority"));
    }

    void platformStateConfirmation() {
        PlatformRig rig;
        RemoteSubsystem& r = rig.platformVehicle();
        rig.control(r);
        QVERIFY(rig.platform.setState(126, 2));
        QCOMPARE(rig.out.last(msg::SetPlatformState)->payload, encodeU8(msg::SetPlatformState, 2));
        const int queries = rig.out.count(msg::QueryPlatformState);
        rig.deliver(r, encode(ConfirmPlatformStateRequest{2, 1}));
        QVERIFY(QString::fromStdString(r.snap.platformServices.stateRefusal).contains("shutdown"));
        QCOMPARE(rig.rec.events.back().kind, EventKind::CommandRefused);
        QCOMPARE(rig.out.count(msg::QueryPlatformState), queries + 1);
        rig.deliver(r, encode(ConfirmPlatformStateRequest{4, 0}));
        QVERIFY(r.snap.platformServices.stateRefusal.empty());
        QVERIFY(!rig.platform.setState(126, 9));
        QCOMPARE(rig.ctx.lastRefusalCause(), OutcomeReason::InvalidArgument);
    }

    void odometryReadAndTripReset() {
        PlatformRig rig;
        RemoteSubsystem& r = rig.platformVehicle();
        rig.control(r);
        QVERIFY(rig.platform.queryOdometry(126));
        QCOMPARE(rig.out.count(msg::QueryOdometry), 2);
        QVERIFY(rig.platform.resetTrip(126));
        QCOMPARE(rig.out.last(msg::ResetOdometry)->payload, encodeU8(msg::ResetOdometry, 2));
        QCOMPARE(rig.out.sent.back().payload, encodeU8(msg::QueryOdometry, 2));
    }

    void monitorRoleMayNotCommand() {
        PlatformRig rig(rigConfig(0));
        rig.platformVehicle();
        QVERIFY(!rig.platform.setLights(126, light::Headlights, light::Headlights));
        QCOMPARE(rig.ctx.lastRefusalCause(), OutcomeReason::NotPermitted);
        QVERIFY(rig.platform.queryOdometry(126)); // reading needs no control
    }
};

QTEST_APPLESS_MAIN(TestPlatformClient)
#include "test_platform_client.moc"
