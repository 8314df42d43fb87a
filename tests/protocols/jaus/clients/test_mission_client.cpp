// MissionClient on its own with a FakeClock, the vehicle played by hand: the portable list upload
// (DeleteElement 65535, one SetElement or parts below 1.4 kB linked to the held tail), confirmations matched
// by RequestID (0 accepted), rejections with their reason, the read-back ("uploaded" only when equal), Resume
// before ExecuteList, progress from ReportActiveElement, pause/resume/abort, an emergency that stops the
// mission for good, link loss, local waypoints placed through the vehicle's own poses, and a list driver on a
// component of its own (its own control; the drive component let go while the mission runs).
#include <QtTest>

#include "tests/protocols/jaus/clients/MissionRig.h"

using namespace ocu;
using namespace ocu::jaus;
using namespace ocu::jaus::test;

class TestMissionClient : public QObject {
    Q_OBJECT

private slots:
    void uploadReadBackAndRunToTheEnd() {
        MissionRig rig;
        RemoteSubsystem& r = rig.missionVehicle();
        QVERIFY(rig.mission.upload(126, MissionRig::route(5), false));
        QCOMPARE(r.snap.mission.phase, MissionPhase::Uploading);
        const Sent* del = rig.out.last(msg::DeleteElement);
        QVERIFY(del);
        QCOMPARE(del->destination, ClientRig::mobility());
        QCOMPARE(decodeDeleteElement(del->payload)->uids, std::vector<std::uint16_t>{kAllUids});
        QVERIFY(!rig.out.last(msg::SetElement));
        rig.confirmLast(r, msg::DeleteElement);
        auto set = decodeSetElement(rig.out.last(msg::SetElement)->payload);
        QVERIFY(set);
        QCOMPARE(set->elements.size(), std::size_t(5));
        for (std::uint16_t i = 0; i < 5; ++i) {
            QCOMPARE(set->elements[i].uid, std::uint16_t(i + 1));
            QCOMPARE(set->elements[i].previous, i);
            QCOMPARE(set->elements[i].next, std::uint16_t(i < 4 ? i + 2 : 0));
            QCOMPARE(peekMessageId(set->elements[i].data), msg::SetLocalWaypoint);
        }
        // A confirmation of another request is not ours; RequestID 0 (the JTS example) is.
        rig.deliver(r, encodeU8(msg::ConfirmElementRequest, std::uint8_t(set->requestId + 7)));
        QVERIFY(!rig.out.last(msg::QueryElementCount));
        rig.deliver(r, encodeU8(msg::ConfirmElementRequest, 0));
        QVERIFY(rig.out.last(msg::QueryElementCount));
        QCOMPARE(r.snap.mission.phase, MissionPhase::Uploading); // not until the read-back is equal
        rig.answerReadBack(r, rig.uploaded(), ClientRig::mobility(), /*withFormat*/ false);
        QCOMPARE(r.snap.mission.phase, MissionPhase::Uploaded);
        QCOMPARE(rig.out.count(msg::QueryElement), 5);

        // Start: Resume first (the driver is in Standby), ExecuteList only once Ready is reported.
        QVERIFY(rig.mission.start(126, 0));
        QVERIFY(rig.out.last(msg::Resume));
        QVERIFY(!rig.out.last(msg::ExecuteList));
        rig.deliver(r, encode(ReportStatus{ManagementState::Ready, 0}));
        rig.run(r, 0.02);
        auto ex = decodeExecuteList(rig.out.last(msg::ExecuteList)->payload);
        QVERIFY(ex && ex->startUid && *ex->startUid == 1);
        QVERIFY(std::abs(ex->speed - 1.0) < 0.01);
        QCOMPARE(r.snap.mission.phase, MissionPhase::Uploaded); // nothing reported yet
        for (std::uint16_t uid = 1; uid <= 5; ++uid) {
            rig.deliver(r, encodeU16(msg::ReportActiveElement, uid));
            QCOMPARE(r.snap.mission.phase, MissionPhase::Running);
            QCOMPARE(r.snap.mission.activeIndex, int(uid - 1));
            QVERIFY(r.snap.mission.distanceToGoM);
        }
        rig.deliver(r, encodeU16(msg::ReportActiveElement, 0));
        QCOMPARE(r.snap.mission.phase, MissionPhase::Completed);
        QCOMPARE(r.snap.mission.lastSeenIndex, 4);
        // uploading, uploaded, running, completed
        QCOMPARE(rig.rec.count(EventKind::MissionChanged), 4);
    }

    void localWaypointsPlacedThroughTheVehiclesPoses() {
        MissionRig rig;
        RemoteSubsystem& r = rig.missionVehicle();
        // 11.1 m north of the vehicle: local X grows by as much, Y stays (the frames agree: equal yaws).
        QVERIFY(rig.mission.upload(126, {MissionPoint{48.1001, 11.5, 0, 2.0}}, false));
        rig.confirmLast(r, msg::DeleteElement);
        auto set = decodeSetElement(rig.out.last(msg::SetElement)->payload);
        auto w = decodeLocalWaypoint(set->elements[0].data);
        QVERIFY(w);
        QVERIFY2(std::abs(w->x - (12.5 + 11.12)) < 0.05, std::to_string(w->x).c_str());
        QVERIFY(std::abs(w->y + 3.25) < 0.05);
        QVERIFY(std::abs(*w->waypointTolerance - 2.0) < 0.01);
        // A frame turned by 90 degrees (JAUS++: X along the start heading): north becomes -Y.
        LocalPose l = *r.snap.localPose;
        l.yaw = 0.5 - 1.5707963;
        auto frame = MissionFrame::from(*r.snap.globalPose, l);
        auto [x, y] = frame->toLocal(48.1001, 11.5);
        QVERIFY(std::abs(x - 12.5) < 0.05 && std::abs(y - (-3.25 - 11.12)) < 0.05);
        auto [lat, lon] = frame->toGlobal(x, y);
        QVERIFY(std::abs(lat - 48.1001) < 1e-8 && std::abs(lon - 11.5) < 1e-8);
        // Without both poses a local mission cannot be placed.
        r.snap.localPose.reset();
        QVERIFY(!rig.mission.upload(126, MissionRig::route(2), false));
        QVERIFY(rig.ctx.lastRefusal().find("local position") != std::string::npos);
    }

    void globalMissionGoesToTheGlobalDriverByDefault() {
        MissionRig rig;
        RemoteSubsystem& r = rig.missionVehicle();
        rig.uploadAndVerify(r, 3, std::nullopt);
        QVERIFY(r.snap.mission.global);
        auto set = decodeSetElement(rig.out.last(msg::SetElement)->payload);
        auto g = decodeGlobalWaypoint(set->elements[2].data);
        QVERIFY(g && std::abs(g->lat - 48.1003) < 1e-6);
    }

    void largeListsGoInLinkedParts() {
        MissionRig rig;
        RemoteSubsystem& r = rig.missionVehicle();
        rig.uploadAndVerify(r, 300, false);
        std::vector<SetElement> parts;
        for (const Sent& s : rig.out.sent)
            if (s.id() == msg::SetElement)
                parts.push_back(*decodeSetElement(s.payload));
        QVERIFY(parts.size() >= 5);
        std::uint16_t tail = 0;
        for (const SetElement& p : parts) {
            QVERIFY(encode(p).size() <= 1400);
            QCOMPARE(p.elements.front().previous, tail);        // appended to the held tail
            QCOMPARE(p.elements.back().next, std::uint16_t(0)); // never a UID not held yet
            tail = p.elements.back().uid;
        }
        QCOMPARE(tail, std::uint16_t(300));
        QCOMPARE(rig.out.count(msg::QueryElement), 300);
    }

    void rejectedElementShowsTheReason() {
        MissionRig rig;
        RemoteSubsystem& r = rig.missionVehicle();
        QVERIFY(rig.mission.upload(126, MissionRig::route(5), false));
        rig.confirmLast(r, msg::DeleteElement);
        const std::uint8_t req = rig.out.last(msg::SetElement)->payload[2];
        rig.deliver(r, encode(RejectElementRequest{req, 3}));
        QCOMPARE(r.snap.mission.phase, MissionPhase::Rejected);
        QVERIFY2(r.snap.mission.reason.find("invalid next element (code 3)") != std::string::npos,
                 r.snap.mission.reason.c_str());
        QVERIFY(!rig.mission.start(126, 0));
    }

    void readBackThatDiffersIsNotUploaded() {
        MissionRig rig;
        RemoteSubsystem& r = rig.missionVehicle();
        QVERIFY(rig.mission.upload(126, MissionRig::route(3), false));
        rig.confirmLast(r, msg::DeleteElement);
        rig.confirmLast(r, msg::SetElement);
        auto held = rig.uploaded();
        LocalWaypoint moved = *decodeLocalWaypoint(held[1].data);
        moved.x += 0.5;
        held[1].data = encode(moved);
        rig.answerReadBack(r, held);
        QCOMPARE(r.snap.mission.phase, MissionPhase::Rejected);
        QVERIFY(r.snap.mission.reason.find("waypoint 2") != std::string::npos);
    }

    void silentVehicleIsNeverUploaded() {
        MissionRig rig;
        RemoteSubsystem& r = rig.missionVehicle();
        QVERIFY(rig.mission.upload(126, MissionRig::route(2), false));
        rig.run(r, 3.1); // DeleteElement never answered (JTS): goes on after 3 s
        QVERIFY(rig.out.last(msg::SetElement));
        rig.confirmLast(r, msg::SetElement);
        rig.run(r, 5);
        QCOMPARE(r.snap.mission.phase, MissionPhase::Rejected);
        QVERIFY(r.snap.mission.reason.find("not verified") != std::string::npos);
    }

    void executeListWithoutEffectIsRejected() {
        MissionRig rig;
        RemoteSubsystem& r = rig.missionVehicle();
        rig.uploadAndVerify(r, 2);
        QVERIFY(rig.mission.start(126, 1));
        rig.deliver(r, encode(ReportStatus{ManagementState::Ready, 0}));
        rig.run(r, 0.02);
        QCOMPARE(*decodeExecuteList(rig.out.last(msg::ExecuteList)->payload)->startUid, std::uint16_t(2));
        rig.run(r, 1);
        QVERIFY(rig.out.count(msg::QueryActiveElement) >= 2); // polled while starting
        rig.deliver(r, encodeU16(msg::ReportActiveElement, 0));
        rig.run(r, 2.5);
        QCOMPARE(r.snap.mission.phase, MissionPhase::Rejected);
        QVERIFY(r.snap.mission.reason.find("ExecuteList") != std::string::npos);
        // FKIE's refusal: RejectElementRequest with RequestID 0 after ExecuteList.
        MissionRig fk;
        RemoteSubsystem& f = fk.missionVehicle();
        fk.uploadAndVerify(f, 2);
        QVERIFY(fk.mission.start(126, 0));
        fk.deliver(f, encode(ReportStatus{ManagementState::Ready, 0}));
        fk.run(f, 0.02);
        fk.deliver(f, encode(RejectElementRequest{0, 5}));
        QCOMPARE(f.snap.mission.phase, MissionPhase::Rejected);
        QVERIFY(f.snap.mission.reason.find("element not found") != std::string::npos);
    }

    void pauseResumeAndAbort() {
        MissionRig rig;
        RemoteSubsystem& r = rig.missionVehicle();
        rig.uploadAndVerify(r, 5);
        rig.startRunning(r);
        rig.deliver(r, encodeU16(msg::ReportActiveElement, 3));
        QVERIFY(rig.mission.pause(126));
        QCOMPARE(rig.out.last(msg::Standby)->destination, ClientRig::mobility());
        QCOMPARE(r.snap.mission.phase, MissionPhase::Running); // until the vehicle reports Standby
        rig.deliver(r, encode(ReportStatus{ManagementState::Standby, 0}));
        rig.run(r, 0.02);
        QCOMPARE(r.snap.mission.phase, MissionPhase::Paused);
        const int executes = rig.out.count(msg::ExecuteList);
        QVERIFY(rig.mission.resume(126));
        QVERIFY(rig.out.last(msg::Resume));
        QCOMPARE(rig.out.count(msg::ExecuteList), executes);
        rig.deliver(r, encode(ReportStatus{ManagementState::Ready, 0}));
        rig.run(r, 0.02);
        QCOMPARE(*decodeExecuteList(rig.out.last(msg::ExecuteList)->payload)->startUid, std::uint16_t(3));
        rig.deliver(r, encodeU16(msg::ReportActiveElement, 3));
        QCOMPARE(r.snap.mission.phase, MissionPhase::Running);
        QVERIFY(rig.mission.abort(126));
        QCOMPARE(decodeDeleteElement(rig.out.last(msg::DeleteElement)->payload)->uids,
                 std::vector<std::uint16_t>{kAllUids});
        QVERIFY(rig.out.last(msg::Standby));
        rig.deliver(r, encodeU16(msg::ReportActiveElement, 0));
        QCOMPARE(r.snap.mission.phase, MissionPhase::Aborted);
        QVERIFY(!rig.mission.start(126, 0)); // the list is gone
    }

    void emergencyStopsTheMissionForGood() {
        MissionRig rig;
        RemoteSubsystem& r = rig.missionVehicle();
        rig.uploadAndVerify(r, 5);
        rig.startRunning(r);
        rig.deliver(r, encodeU16(msg::ReportActiveElement, 2));
        rig.deliver(r, encode(ReportStatus{ManagementState::Emergency, 0}));
        rig.run(r, 0.02);
        QCOMPARE(r.snap.mission.phase, MissionPhase::StoppedByEmergency);
        QVERIFY(r.snap.mission.reason.find("waypoint 2 of 5") != std::string::npos);
        const int executes = rig.out.count(msg::ExecuteList), resumes = rig.out.count(msg::Resume);
        rig.deliver(r, encode(ReportStatus{ManagementState::Standby, 0})); // cleared
        rig.deliver(r, encode(ReportStatus{ManagementState::Ready, 0}));
        rig.run(r, 5);
        QCOMPARE(rig.out.count(msg::ExecuteList), executes);
        QCOMPARE(rig.out.count(msg::Resume), resumes);
        QCOMPARE(r.snap.mission.phase, MissionPhase::StoppedByEmergency);
        // The operator may resume it explicitly, from the last waypoint seen (with control).
        if (!r.snap.controlledByUs) {
            rig.access.requestControl(126);
            rig.deliver(r, encodeU8(msg::ConfirmControl, 0));
        }
        QVERIFY(r.snap.controlledByUs);
        QVERIFY(rig.mission.resume(126));
        rig.run(r, 0.02);
        QCOMPARE(*decodeExecuteList(rig.out.last(msg::ExecuteList)->payload)->startUid, std::uint16_t(2));
    }

    void linkDownOrControlLostIsLost() {
        MissionRig rig;
        RemoteSubsystem& r = rig.missionVehicle();
        rig.uploadAndVerify(r, 5);
        rig.startRunning(r);
        rig.deliver(r, encodeU16(msg::ReportActiveElement, 4));
        r.snap.link = LinkState::Down;
        rig.run(r, 0.02);
        QCOMPARE(r.snap.mission.phase, MissionPhase::Lost);
        QCOMPARE(r.snap.mission.lastSeenIndex, 3);
        QVERIFY(r.snap.mission.reason.find("link down") != std::string::npos);

        MissionRig two;
        RemoteSubsystem& v = two.missionVehicle();
        two.uploadAndVerify(v, 5);
        two.startRunning(v);
        v.snap.controlledByUs = false;
        v.snap.controller = JausId{300, 1, 1};
        two.run(v, 0.02);
        QCOMPARE(v.snap.mission.phase, MissionPhase::Lost);
        QVERIFY(!v.snap.mission.ours);
    }

    // A list driver on a component of its own (the foreign peer's dialect, JAUS++'s 152.1.2): control of
    // that component, its ReportStatus kept apart from the vehicle's, and the drive component let go.
    void driverOnItsOwnComponent() {
        MissionRig rig;
        const JausId driver{126, 3, 5};
        RemoteSubsystem& r = rig.missionVehicle(driver, /*controlled*/ true);
        QVERIFY(rig.mission.upload(126, MissionRig::route(3), false));
        const Sent* rc = rig.out.last(msg::RequestControl);
        QCOMPARE(rc->destination, driver);
        QVERIFY(!rig.out.last(msg::DeleteElement));
        rig.deliver(r, encodeU8(msg::ConfirmControl, 0), driver);
        QCOMPARE(rig.out.last(msg::DeleteElement)->destination, driver);
        QVERIFY(r.snap.controlledByUs); // the vehicle's control is the access client's, untouched
        rig.confirmLast(r, msg::DeleteElement, driver);
        rig.confirmLast(r, msg::SetElement, driver);
        rig.answerReadBack(r, rig.uploaded(), driver);
        QCOMPARE(r.snap.mission.phase, MissionPhase::Uploaded);
        QVERIFY(rig.mission.start(126, 0));
        QCOMPARE(rig.out.last(msg::ReleaseControl)->destination, ClientRig::mobility());
        QCOMPARE(rig.out.last(msg::Resume)->destination, driver);
        rig.deliver(r, encode(ReportStatus{ManagementState::Ready, 0}), driver);
        QCOMPARE(r.snap.management,
                 std::optional<ManagementState>(ManagementState::Standby)); // not the vehicle's
        rig.run(r, 0.02);
        QCOMPARE(rig.out.last(msg::ExecuteList)->destination, driver);
        rig.deliver(r, encodeU16(msg::ReportActiveElement, 1), driver);
        QCOMPARE(r.snap.mission.phase, MissionPhase::Running);
        // Its control is kept by re-requests; a RejectControl from it loses the mission.
        rig.run(r, 2.5);
        QVERIFY(rig.out.count(msg::RequestControl) >= 3);
        rig.deliver(r, encodeU8(msg::RejectControl, 0), driver);
        rig.run(r, 0.02);
        QCOMPARE(r.snap.mission.phase, MissionPhase::Lost);
    }

    void monitorMayNotRunMissions() {
        MissionRig rig;
        RemoteSubsystem& r = rig.missionVehicle(ClientRig::mobility(), false);
        (void)r;
        JausConfig c = rigConfig(0);
        ClientRig mon(c);
        EventsClient events{mon.ctx};
        DriveClient drive{mon.ctx};
        AccessControlClient access{mon.ctx, drive};
        MissionClient mission{mon.ctx, events, access};
        mon.vehicle();
        QVERIFY(!mission.upload(126, MissionRig::route(2), std::nullopt));
        QCOMPARE(mon.ctx.lastRefusalCause(), OutcomeReason::NotPermitted);
        // Without the vehicle's control yet, the upload asks for it first.
        QVERIFY(rig.mission.upload(126, MissionRig::route(2), false));
        QCOMPARE(rig.out.last(msg::RequestControl)->destination, ClientRig::mobility());
        QVERIFY(!rig.out.last(msg::DeleteElement));
    }
};

QTEST_APPLESS_MAIN(TestMissionClient)
#include "test_mission_client.moc"
