// HandoffClient on its own with a FakeClock, the vehicle's Enhanced Access Control played by hand. Requester:
// RequestHandoff with our authority and "<call sign>: <reason>", re-asserted within the vehicle's request
// timeout while queued, RequestControl after GRANTED and completed once control is confirmed; DENIED and
// TIMEOUT (the vehicle's, or none at all) end it; RemoveHandoffRequest withdraws it. Holder: a forwarded
// request becomes a prompt with who asks and why, answered GRANTED (our control then ends as a release, not a
// loss) or DENIED, or dropped when the decision timeout passes. Without Enhanced Access Control the ordinary
// pre-emption rules apply and the console says so.
#include <QtTest>

#include "protocols/jaus/MessagesHandoff.h"
#include "protocols/jaus/clients/AccessControlClient.h"
#include "protocols/jaus/clients/DriveClient.h"
#include "protocols/jaus/clients/HandoffClient.h"
#include "tests/protocols/jaus/clients/ClientRig.h"

using namespace ocu;
using namespace ocu::jaus;
using namespace ocu::jaus::test;

namespace {

const JausId kOtherConsole{201, 1, 1};

struct HandoffRig : ClientRig {
    DriveClient drive{ctx};
    AccessControlClient access{ctx, drive};
    HandoffClient handoff{ctx, access};
    HandoffRig() {
        drive.registerMessages(table);
        access.registerMessages(table);
        handoff.registerMessages(table);
    }
    // The vehicle of ClientRig; its Core Mobility Component offers Enhanced Access Control when `eac`.
    RemoteSubsystem& vehicleWith(bool eac) {
        RemoteSubsystem& r = vehicle();
        std::vector<ServiceRecord> services{{"urn:jaus:jss:core:AccessControl", 1, 1}};
        if (eac)
            services.push_back({"urn:jaus:jss:iop:EnhancedAccessControl", 1, 1});
        r.snap.services = {NodeInfo{3, {ComponentInfo{1, services}}}};
        handoff.onServicesKnown(r);
        return r;
    }
    // Another console holds the vehicle (ReportControl).
    void heldByOther(RemoteSubsystem& r) {
        QVERIFY(deliver(r, encode(ReportControl{kOtherConsole, 205})));
        QCOMPARE(r.snap.controller, kOtherConsole);
    }
    void run(RemoteSubsystem& r, double seconds) {
        runFor(seconds, [&](TimePoint now) {
            access.tick(r, now);
            drive.tick(r, now);
            handoff.tick(r, now);
        });
    }
    int handoffEvents() const { return rec.count(EventKind::HandoffChanged); }
    std::string lastEventText() const { return rec.events.empty() ? "" : rec.events.back().text; }
};

Bytes confirm(std::uint8_t id, HandoffCode code) {
    return encode(ConfirmHandoffRequest{id, code});
}

} // namespace

class TestHandoffClient : public QObject {
    Q_OBJECT

private slots:
    void requestQueuedReassertedGrantedCompleted() {
        HandoffRig rig;
        RemoteSubsystem& r = rig.vehicleWith(true);
        QVERIFY(r.snap.handoff.offered);
        QCOMPARE(r.snap.handoff.component, HandoffRig::mobility());
        // Both timeouts asked once the service is known.
        QCOMPARE(rig.out.count(msg::QueryEnhancedTimeout), 1);
        QCOMPARE(rig.out.count(msg::QueryHandoffTimeout), 1);
        rig.heldByOther(r);

        QVERIFY(rig.handoff.request(126, "need ctl"));
        const Sent* req = rig.out.last(msg::RequestHandoff);
        QVERIFY(req);
        QCOMPARE(req->destination, HandoffRig::mobility());
        auto decoded = decodeRequestHandoff(req->payload);
        QVERIFY(decoded);
        QCOMPARE(decoded->authority, std::uint8_t(205));
        QCOMPARE(QString::fromStdString(decoded->explanation), QStringLiteral("OCU-200: need ctl"));
        QCOMPARE(r.snap.handoff.phase, HandoffPhase::Requesting);

        QVERIFY(rig.deliver(r, confirm(3, HandoffCode::Queued)));
        QCOMPARE(r.snap.handoff.phase, HandoffPhase::Queued);
        QCOMPARE(r.snap.handoff.queueId, std::uint8_t(3));

        // Re-asserted within the Handoff Request Timeout (5 s): every third of it.
        const int before = rig.out.count(msg::RequestHandoff);
        rig.run(r, 10);
        QVERIFY2(rig.out.count(msg::RequestHandoff) - before >= 5,
                 qPrintable(QString::number(rig.out.count(msg::RequestHandoff) - before)));
        QCOMPARE(r.snap.handoff.phase, HandoffPhase::Queued);

        QVERIFY(rig.deliver(r, confirm(3, HandoffCode::Granted)));
        QCOMPARE(r.snap.handoff.phase, HandoffPhase::Granted);
        QVERIFY(rig.out.last(msg::RequestControl));
        QVERIFY(rig.access.wantsControl(126));
        const int afterGrant = rig.out.count(msg::RequestHandoff);
        QVERIFY(rig.deliver(r, encodeU8(msg::ConfirmControl, 0)));
        rig.run(r, 0.1);
        QCOMPARE(r.snap.handoff.phase, HandoffPhase::Completed);
        QVERIFY(r.snap.controlledByUs);
        QCOMPARE(rig.out.count(msg::RequestHandoff), afterGrant); // no more re-assertions
        QVERIFY(QString::fromStdString(r.snap.handoff.reason).contains("handed over"));
    }

    void reassertsWithinTheReportedRequestTimeout() {
        HandoffRig rig;
        RemoteSubsystem& r = rig.vehicleWith(true);
        rig.heldByOther(r);
        QVERIFY(rig.deliver(r, encodeU8(msg::ReportEnhancedTimeout, 3)));
        QVERIFY(rig.handoff.request(126, "x"));
        QVERIFY(rig.deliver(r, confirm(1, HandoffCode::Queued)));
        // Gaps between the re-assertions: never more than the 3 s the vehicle allows.
        std::vector<TimePoint> sentAt;
        std::size_t seen = rig.out.sent.size();
        rig.runFor(6, [&](TimePoint now) {
            rig.handoff.tick(r, now);
            for (; seen < rig.out.sent.size(); ++seen)
                if (rig.out.sent[seen].id() == msg::RequestHandoff)
                    sentAt.push_back(now);
        });
        QVERIFY(sentAt.size() >= 5);
        for (std::size_t i = 1; i < sentAt.size(); ++i)
            QVERIFY(sentAt[i] - sentAt[i - 1] <= std::chrono::milliseconds(1100));
    }

    void deniedEndsTheRequest() {
        HandoffRig rig;
        RemoteSubsystem& r = rig.vehicleWith(true);
        rig.heldByOther(r);
        QVERIFY(rig.handoff.request(126, "x"));
        QVERIFY(rig.deliver(r, confirm(2, HandoffCode::Queued)));
        QVERIFY(rig.deliver(r, confirm(2, HandoffCode::Denied)));
        QCOMPARE(r.snap.handoff.phase, HandoffPhase::Denied);
        QVERIFY(QString::fromStdString(r.snap.handoff.reason).contains("denied by 201.1.1"));
        const int sent = rig.out.count(msg::RequestHandoff);
        rig.run(r, 5);
        QCOMPARE(rig.out.count(msg::RequestHandoff), sent);
        QCOMPARE(rig.out.count(msg::RequestControl), 0);
        QVERIFY(!r.snap.controlledByUs);
    }

    void timeoutFromTheVehicleOrNoAnswerAtAll() {
        HandoffRig rig;
        RemoteSubsystem& r = rig.vehicleWith(true);
        rig.heldByOther(r);
        QVERIFY(rig.deliver(r, encodeU8(msg::ReportHandoffTimeout, 2)));
        QCOMPARE(r.snap.handoff.decisionTimeoutS, 2.0);
        QVERIFY(rig.handoff.request(126, "x"));
        QVERIFY(rig.deliver(r, confirm(4, HandoffCode::Queued)));
        QVERIFY(rig.deliver(r, confirm(4, HandoffCode::Timeout)));
        QCOMPARE(r.snap.handoff.phase, HandoffPhase::TimedOut);
        QVERIFY(QString::fromStdString(r.snap.handoff.reason).contains("did not answer within 2 s"));

        // A vehicle that never answers: the request ends on our side after the decision timeout and a margin.
        QVERIFY(rig.handoff.request(126, "again"));
        rig.run(r, 6.5);
        QCOMPARE(r.snap.handoff.phase, HandoffPhase::Requesting);
        rig.run(r, 1);
        QCOMPARE(r.snap.handoff.phase, HandoffPhase::TimedOut);
    }

    void cancelRemovesTheQueueEntry() {
        HandoffRig rig;
        RemoteSubsystem& r = rig.vehicleWith(true);
        rig.heldByOther(r);
        QVERIFY(!rig.handoff.cancel(126)); // nothing to withdraw
        QVERIFY(rig.handoff.request(126, "x"));
        QVERIFY(rig.deliver(r, confirm(5, HandoffCode::Queued)));
        QVERIFY(rig.handoff.cancel(126));
        const Sent* rm = rig.out.last(msg::RemoveHandoffRequest);
        QVERIFY(rm);
        QCOMPARE(rm->payload, (Bytes{0x34, 0xff, 0x05}));
        QCOMPARE(r.snap.handoff.phase, HandoffPhase::Cancelled);
        // The EAC's DENIED to a removed request changes nothing.
        QVERIFY(rig.deliver(r, confirm(5, HandoffCode::Denied)));
        QCOMPARE(r.snap.handoff.phase, HandoffPhase::Cancelled);
    }

    void refusalsAndTheMonitorRole() {
        HandoffRig rig;
        RemoteSubsystem& r = rig.vehicleWith(true);
        rig.heldByOther(r);
        QVERIFY(rig.handoff.request(126, "x"));
        QVERIFY(rig.deliver(r, confirm(kNoHandoffId, HandoffCode::InsufficientAuthority)));
        QCOMPARE(r.snap.handoff.phase, HandoffPhase::Refused);
        QVERIFY(!rig.handoff.request(77, "x")); // never heard of
        QCOMPARE(rig.ctx.lastRefusalCause(), OutcomeReason::UnknownTarget);

        // Nobody holds the vehicle: the EAC says so and the console asks for control directly.
        HandoffRig free;
        RemoteSubsystem& f = free.vehicleWith(true);
        QVERIFY(free.handoff.request(126, "x"));
        QVERIFY(free.deliver(f, confirm(kNoHandoffId, HandoffCode::Denied)));
        QCOMPARE(f.snap.handoff.phase, HandoffPhase::Preempting);
        QCOMPARE(free.out.count(msg::RequestControl), 1);
    }

    void withoutEnhancedAccessControlOrdinaryPreemption() {
        HandoffRig rig;
        RemoteSubsystem& r = rig.vehicleWith(false);
        QVERIFY(!r.snap.handoff.offered);
        rig.heldByOther(r);
        QVERIFY(rig.handoff.request(126, "x"));
        QCOMPARE(rig.out.count(msg::RequestHandoff), 0);
        QCOMPARE(rig.out.count(msg::RequestControl), 1);
        QCOMPARE(r.snap.handoff.phase, HandoffPhase::Preempting);
        QVERIFY(QString::fromStdString(r.snap.handoff.reason).contains("offers no Enhanced Access Control"));
        QVERIFY(QString::fromStdString(r.snap.handoff.reason).contains("pre-emption"));
        // Equal authority: refused by the ordinary rules, and the console says why.
        QVERIFY(rig.deliver(r, encodeU8(msg::ConfirmControl, 2)));
        rig.run(r, 0.1);
        QCOMPARE(r.snap.handoff.phase, HandoffPhase::Refused);
        QVERIFY(QString::fromStdString(r.snap.handoff.reason).contains("ordinary pre-emption"));
    }

    void holderGrants() {
        HandoffRig rig;
        RemoteSubsystem& r = rig.vehicleWith(true);
        QVERIFY(rig.access.requestControl(126));
        QVERIFY(rig.deliver(r, encodeU8(msg::ConfirmControl, 0)));
        QVERIFY(r.snap.controlledByUs);
        RequestReleaseControl fwd;
        fwd.requests.push_back({7, kOtherConsole, 205, "OCU-201: take over"});
        QVERIFY(rig.deliver(r, encode(fwd)));
        QCOMPARE(r.snap.handoff.prompts.size(), std::size_t(1));
        const HandoffPrompt& p = r.snap.handoff.prompts.front();
        QCOMPARE(p.requester, kOtherConsole);
        QCOMPARE(QString::fromStdString(p.explanation), QStringLiteral("OCU-201: take over"));
        QVERIFY(QString::fromStdString(rig.lastEventText()).contains("201.1.1 asks for control"));
        // The same queue forwarded again (a re-assertion): still one prompt, no new event.
        const int events = rig.handoffEvents();
        QVERIFY(rig.deliver(r, encode(fwd)));
        QCOMPARE(r.snap.handoff.prompts.size(), std::size_t(1));
        QCOMPARE(rig.handoffEvents(), events);

        QVERIFY(!rig.handoff.answer(126, 9, ReleaseCode::Granted)); // no such request
        QVERIFY(rig.handoff.answer(126, 7, ReleaseCode::Granted));
        const Sent* a = rig.out.last(msg::ConfirmReleaseControl);
        QVERIFY(a);
        QCOMPARE(a->payload, (Bytes{0x39, 0xff, 0x01, 0x07, 0x00}));
        QCOMPARE(a->destination, HandoffRig::mobility());
        QVERIFY(r.snap.handoff.prompts.empty());
        // The vehicle passes control on: a release, not a loss or a pre-emption; no re-request.
        QVERIFY(rig.deliver(r, encodeU8(msg::RejectControl, 0)));
        QVERIFY(!r.snap.controlledByUs);
        QCOMPARE(r.snap.access, AccessState::ControlReleased);
        // A re-request of ours that crossed the grant is refused by the vehicle: still a release.
        QVERIFY(rig.deliver(r, encodeU8(msg::ConfirmControl, 2)));
        QCOMPARE(r.snap.access, AccessState::ControlReleased);
        QCOMPARE(rig.rec.count(EventKind::ControlRejected), 0);
        QCOMPARE(rig.rec.count(EventKind::ControlLost), 0);
        QCOMPARE(rig.rec.count(EventKind::ControlPreempted), 0);
        const int requests = rig.out.count(msg::RequestControl);
        rig.run(r, 5);
        QCOMPARE(rig.out.count(msg::RequestControl), requests);
    }

    void holderDeniesAndPromptsTimeOut() {
        HandoffRig rig;
        RemoteSubsystem& r = rig.vehicleWith(true);
        QVERIFY(rig.access.requestControl(126));
        QVERIFY(rig.deliver(r, encodeU8(msg::ConfirmControl, 0)));
        RequestReleaseControl fwd;
        fwd.requests.push_back({1, kOtherConsole, 205, "a"});
        fwd.requests.push_back({2, JausId{202, 1, 1}, 210, "b"});
        QVERIFY(rig.deliver(r, encode(fwd)));
        QCOMPARE(r.snap.handoff.prompts.size(), std::size_t(2));
        QVERIFY(rig.handoff.answer(126, 1, ReleaseCode::Denied));
        QCOMPARE(rig.out.last(msg::ConfirmReleaseControl)->payload, (Bytes{0x39, 0xff, 0x01, 0x01, 0x01}));
        QCOMPARE(r.snap.handoff.prompts.size(), std::size_t(1));
        QVERIFY(r.snap.controlledByUs);

        // The other one is not answered: dropped once the decision timeout (here 10 s) passes, without a
        // message of ours (the vehicle answers the requester TIMEOUT).
        QVERIFY(rig.deliver(r, encodeU8(msg::ReportHandoffTimeout, 10)));
        const int answers = rig.out.count(msg::ConfirmReleaseControl);
        rig.runFor(9.5, [&](TimePoint now) {
            rig.handoff.tick(r, now);
            if (rig.out.last(msg::RequestControl))
                rig.deliver(r, encodeU8(msg::ConfirmControl, 0));
        });
        QCOMPARE(r.snap.handoff.prompts.size(), std::size_t(1));
        rig.runFor(1, [&](TimePoint now) { rig.handoff.tick(r, now); });
        QVERIFY(r.snap.handoff.prompts.empty());
        QCOMPARE(rig.out.count(msg::ConfirmReleaseControl), answers);
        QVERIFY(QString::fromStdString(rig.lastEventText()).contains("not answered within 10 s"));

        // The vehicle's queue without an entry we still show: withdrawn.
        QVERIFY(rig.deliver(r, encode(fwd)));
        QCOMPARE(r.snap.handoff.prompts.size(), std::size_t(2));
        QVERIFY(rig.deliver(r, encode(RequestReleaseControl{})));
        QVERIFY(r.snap.handoff.prompts.empty());
        QVERIFY(QString::fromStdString(rig.lastEventText()).contains("withdrawn"));
        // Dropped by the vehicle at the end of the decision time, a little before our own clock gets there:
        // said as the timeout it is.
        QVERIFY(rig.deliver(r, encode(fwd)));
        rig.runFor(9.8, [&](TimePoint) {});
        QVERIFY(rig.deliver(r, encode(RequestReleaseControl{})));
        QVERIFY(r.snap.handoff.prompts.empty());
        QVERIFY2(QString::fromStdString(rig.lastEventText()).contains("not answered within 10 s"),
                 rig.lastEventText().c_str());
    }
};

QTEST_APPLESS_MAIN(TestHandoffClient)
#include "test_handoff_client.moc"
