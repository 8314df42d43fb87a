// Hand-off of control between two consoles through a foreign vehicle's Enhanced Access Control 1.1
// (tests/protocols/jaus/foreign/ForeignHandoff.h: written from the research note, sharing no code with the
// simulated UGV), over loopback. Console A (200) holds the vehicle, console B (201) asks at the same
// authority: the vehicle queues the request and forwards it to A, which accepts (B takes control with its
// RequestControl, A sees it released), denies, or does not answer (the vehicle's TIMEOUT); the vehicle's
// answers arrive late (a busy stack) in the accepted case; a vehicle policy that denies every request and a
// requester below the vehicle's default authority are refused without asking A; B withdraws a request; A
// asks B to wait, in the three ways vehicles pass a WAIT on.
#include <QtTest>

#include <mutex>

#include "protocols/common/Log.h"
#include "protocols/common/Udp.h"
#include "protocols/jaus/JausStack.h"
#include "tests/protocols/jaus/foreign/ForeignJausVehicle.h"
#include "tests/support/JausLoopback.h"
#include "tests/support/StackWaits.h"

using namespace ocu;
using namespace ocu::jaus;
using stacktest::Outcomes;
using stacktest::waitFor;

namespace {

constexpr std::uint16_t kRequestHandoff = 0xFF31, kRemoveHandoffRequest = 0xFF34,
                        kConfirmReleaseControl = 0xFF39;

struct Listener : JausListener {
    std::mutex mutex;
    std::vector<std::string> handoffEvents;
    void onSubsystemChanged(const SubsystemSnapshot&) override {}
    void onEvent(const JausEvent& e) override {
        if (e.kind != EventKind::HandoffChanged)
            return;
        std::lock_guard lock(mutex);
        handoffEvents.push_back(e.text);
    }
    bool saw(const std::string& part) {
        std::lock_guard lock(mutex);
        for (const std::string& t : handoffEvents)
            if (t.find(part) != std::string::npos)
                return true;
        return false;
    }
};

struct Console {
    explicit Console(JausConfig c) : stack(std::move(c), listener) { stack.start(); }
    ~Console() { stack.stop(); }
    std::optional<SubsystemSnapshot> snap() { return stack.snapshot(126); }
    HandoffStatus handoff() {
        auto s = snap();
        return s ? s->handoff : HandoffStatus{};
    }
    bool controls() {
        auto s = snap();
        return s && s->controlledByUs;
    }
    JausId id() const { return stack.config().ownId(); }
    static bool sent(Outcomes& o) {
        auto r = o.get();
        if (!r || r->size() != 1)
            return false;
        if (!r->front().sent)
            qWarning("%s", r->front().reason.c_str());
        return r->front().sent;
    }
    Listener listener;
    JausStack stack;
};

foreign::VehicleOptions vehicleOptions(const foreign::HandoffOptions& handoff) {
    foreign::VehicleOptions o;
    o.services = {"urn:jaus:jss:mobility:LocalPoseSensor", "urn:jaus:jss:iop:EnhancedAccessControl"};
    o.answerQueryControl = true; // who holds it: FKIE's access control answers QueryControl
    o.handoffComponent = o.component;
    o.handoff = handoff;
    return o;
}

struct ForeignRig {
    explicit ForeignRig(const foreign::HandoffOptions& handoff, std::uint8_t askerAuthority = 205)
        : vehicle(vehicleOptions(handoff)), group(findFreeUdpPort()) {
        holder = std::make_unique<Console>(config(200, 205));
        asker = std::make_unique<Console>(config(201, askerAuthority));
    }
    JausConfig config(std::uint16_t ss, std::uint8_t authority) const {
        JausConfig c;
        c.subsystemId = ss;
        c.callSign = "OCU-" + std::to_string(ss);
        c.authority = authority;
        c.driveCommandTimeoutS = 0;
        c.statusPollHz = 2;
        c.accessTimeoutS = 3;
        c.transport = jaustest::loopback(group);
        c.transport.staticEndpoints.push_back(
            StaticEndpoint{JausId{126, 0xFF, 0xFF}, "127.0.0.1", vehicle.port(), false});
        return c;
    }
    // A holds the vehicle; both consoles know it offers Enhanced Access Control and who holds it.
    bool ready() {
        for (Console* c : {holder.get(), asker.get()})
            if (!waitFor([&] { return c->handoff().offered; }))
                return false;
        holder->stack.requestControl(126, {});
        if (!waitFor([&] { return holder->controls(); }))
            return false;
        return waitFor([&] {
            auto s = asker->snap();
            return s && s->controller == holder->id();
        });
    }
    bool request(const std::string& reason) {
        Outcomes o;
        asker->stack.handoffRequest(126, reason, o.callback());
        return Console::sent(o);
    }
    // B asks; A is shown the request (who and why), B waits queued. Returns its queue ID, or -1.
    int ask() {
        if (!request("need the vehicle"))
            return -1;
        if (!waitFor([&] { return !holder->handoff().prompts.empty(); }))
            return -1;
        const HandoffPrompt p = holder->handoff().prompts.front();
        if (!(p.requester == asker->id()) || p.explanation != "OCU-201: need the vehicle" ||
            p.authority != 205)
            return -1;
        if (!waitFor([&] { return asker->handoff().phase == HandoffPhase::Queued; }))
            return -1;
        return p.id;
    }
    bool answer(int id, bool accept) {
        Outcomes o;
        holder->stack.handoffAnswer(126, std::uint8_t(id), accept, o.callback());
        return Console::sent(o);
    }
    foreign::ForeignJausVehicle vehicle;
    std::uint16_t group;
    std::unique_ptr<Console> holder, asker;
};

foreign::HandoffOptions shortTimeouts() {
    foreign::HandoffOptions h;
    h.decisionTimeoutS = 3; // the timeout test waits it out
    return h;
}

} // namespace

class TestJausHandoffForeign : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { setLogThreshold(LogLevel::Error); }

    // Every answer of the vehicle 1.5 s late; B's re-assertions keep the request alive past the 5 s request
    // timeout; A accepts; B takes control with its own RequestControl.
    void acceptedWithLateAnswers() {
        foreign::HandoffOptions h;
        h.decisionTimeoutS = 30;
        h.answerDelayMs = 1500;
        ForeignRig rig(h);
        QVERIFY(rig.ready());
        // The timeouts as the vehicle reports them, late too.
        QVERIFY(waitFor([&] { return rig.holder->handoff().decisionTimeoutS == 30.0; }));
        QCOMPARE(rig.asker->handoff().requestTimeoutS, 5.0);
        const int id = rig.ask();
        QVERIFY(id > 0 && id < 255);
        QTest::qWait(5500);
        QCOMPARE(rig.asker->handoff().phase, HandoffPhase::Queued);
        QCOMPARE(rig.vehicle.handoffsQueued(), std::size_t(1));
        QVERIFY(rig.vehicle.received(kRequestHandoff) >= 3); // re-asserted every third of 5 s
        QCOMPARE(rig.holder->handoff().prompts.size(), std::size_t(1));
        QVERIFY(rig.answer(id, true));
        QVERIFY(waitFor([&] { return rig.asker->handoff().phase == HandoffPhase::Completed; }, 10));
        QVERIFY(rig.asker->controls());
        QCOMPARE(rig.vehicle.controller(), rig.asker->id().value());
        QCOMPARE(rig.vehicle.handoffsGranted(), 1);
        QCOMPARE(rig.vehicle.receivedFrom(kConfirmReleaseControl, rig.holder->id().value()), 1);
        // A released it (its RejectControl came late, as the rest), and does not take it back.
        QVERIFY(waitFor([&] { return !rig.holder->controls(); }));
        QCOMPARE(rig.holder->snap()->access, AccessState::ControlReleased);
        QVERIFY(rig.holder->listener.saw("hand-off of FOREIGN-126 to 201.1.1 granted"));
        QVERIFY(rig.asker->listener.saw("granted by 200.1.1"));
        QTest::qWait(3500); // past the vehicle's 3 s access timeout: B re-requests, A does not
        QCOMPARE(rig.vehicle.controller(), rig.asker->id().value());
        QVERIFY(rig.holder->handoff().prompts.empty());
    }

    void deniedByTheHolder() {
        ForeignRig rig(shortTimeouts());
        QVERIFY(rig.ready());
        const int id = rig.ask();
        QVERIFY(id > 0);
        QVERIFY(rig.answer(id, false));
        QVERIFY(waitFor([&] { return rig.asker->handoff().phase == HandoffPhase::Denied; }));
        QVERIFY(QString::fromStdString(rig.asker->handoff().reason).contains("denied by 200.1.1"));
        QVERIFY(rig.holder->handoff().prompts.empty());
        QVERIFY(waitFor([&] { return rig.vehicle.handoffsQueued() == 0; }));
        QTest::qWait(500);
        QVERIFY(rig.holder->controls());
        QVERIFY(!rig.asker->controls());
        QCOMPARE(rig.vehicle.controller(), rig.holder->id().value());
    }

    void holderSilentTimesOut() {
        ForeignRig rig(shortTimeouts());
        QVERIFY(rig.ready());
        QVERIFY(rig.ask() > 0);
        QVERIFY(waitFor([&] { return rig.asker->handoff().phase == HandoffPhase::TimedOut; }, 8));
        QVERIFY(QString::fromStdString(rig.asker->handoff().reason).contains("did not answer within 3 s"));
        QVERIFY(waitFor([&] { return rig.holder->handoff().prompts.empty(); }));
        QVERIFY(rig.holder->listener.saw("not answered within 3 s"));
        QVERIFY(rig.holder->controls());
        QCOMPARE(rig.vehicle.controller(), rig.holder->id().value());
    }

    // The vehicle's policy refuses every hand-off: DENIED at once, A is never asked.
    void vehiclePolicyDenies() {
        foreign::HandoffOptions h = shortTimeouts();
        h.denyAll = true;
        ForeignRig rig(h);
        QVERIFY(rig.ready());
        QVERIFY(rig.request("need the vehicle"));
        QVERIFY(waitFor([&] { return rig.asker->handoff().phase == HandoffPhase::Denied; }));
        QTest::qWait(500);
        QVERIFY(rig.holder->handoff().prompts.empty());
        QVERIFY(rig.holder->controls());
    }

    // Below the vehicle's default authority: INSUFFICIENT_AUTHORITY, said as such.
    void insufficientAuthorityRefused() {
        foreign::HandoffOptions h = shortTimeouts();
        h.defaultAuthority = 210;
        ForeignRig rig(h, 205);
        QVERIFY(rig.ready());
        QVERIFY(rig.request("need the vehicle"));
        QVERIFY(waitFor([&] { return rig.asker->handoff().phase == HandoffPhase::Refused; }));
        QVERIFY(QString::fromStdString(rig.asker->handoff().reason).contains("below the vehicle's default"));
        QVERIFY(rig.holder->handoff().prompts.empty());
    }

    // B withdraws its queued request: RemoveHandoffRequest with its queue ID; A's prompt goes.
    void requestWithdrawn() {
        ForeignRig rig(shortTimeouts());
        QVERIFY(rig.ready());
        const int id = rig.ask();
        QVERIFY(id > 0);
        Outcomes o;
        rig.asker->stack.handoffCancel(126, o.callback());
        QVERIFY(Console::sent(o));
        QVERIFY(waitFor([&] { return rig.asker->handoff().phase == HandoffPhase::Cancelled; }));
        QVERIFY(waitFor([&] { return rig.vehicle.received(kRemoveHandoffRequest) == 1; }));
        QVERIFY(waitFor([&] { return rig.holder->handoff().prompts.empty(); }));
        QCOMPARE(rig.vehicle.handoffsQueued(), std::size_t(0));
        QVERIFY(rig.holder->controls());
    }

    // A answers WAIT half-way through the 4 s decision time: the request stays, its decision time starts
    // again (alive past the first 4 s), B keeps it up and shows the wait where the vehicle says so (DEFERRED,
    // or FKIE's private 7; FKIE's EAC answers QUEUED again, which B cannot tell from its re-assertions'
    // answers); A then accepts.
    void holderAsksToWait_data() {
        QTest::addColumn<int>("code");
        QTest::addColumn<bool>("shown");
        QTest::newRow("DEFERRED") << 5 << true;
        QTest::newRow("FKIE's private WAIT") << 7 << true;
        QTest::newRow("QUEUED again") << 4 << false;
    }
    void holderAsksToWait() {
        QFETCH(int, code);
        QFETCH(bool, shown);
        foreign::HandoffOptions h;
        h.decisionTimeoutS = 4;
        h.waitAnswer = std::uint8_t(code);
        ForeignRig rig(h);
        QVERIFY(rig.ready());
        const int id = rig.ask();
        QVERIFY(id > 0);
        QTest::qWait(2000);
        Outcomes o;
        rig.holder->stack.handoffWait(126, std::uint8_t(id), o.callback());
        QVERIFY(Console::sent(o));
        QVERIFY(waitFor(
            [&] { return rig.vehicle.receivedFrom(kConfirmReleaseControl, rig.holder->id().value()); }));
        QVERIFY(rig.holder->listener.saw("hand-off of FOREIGN-126 to 201.1.1: asked to wait"));
        QCOMPARE(rig.holder->handoff().prompts.size(), std::size_t(1));
        QVERIFY(rig.holder->handoff().prompts.front().waited);
        if (shown) {
            QVERIFY(waitFor([&] { return rig.asker->handoff().phase == HandoffPhase::Waiting; }));
            QVERIFY(rig.asker->listener.saw("200.1.1 asks to wait for FOREIGN-126"));
        }
        QTest::qWait(3000); // 5 s after the request: past the first decision time, within the second
        const HandoffPhase phase = rig.asker->handoff().phase;
        QVERIFY2(phase == (shown ? HandoffPhase::Waiting : HandoffPhase::Queued), nameFor(phase));
        QCOMPARE(rig.vehicle.handoffsQueued(), std::size_t(1));
        QCOMPARE(rig.holder->handoff().prompts.size(), std::size_t(1));
        QVERIFY(rig.answer(id, true));
        QVERIFY(waitFor([&] { return rig.asker->handoff().phase == HandoffPhase::Completed; }));
        QCOMPARE(rig.vehicle.controller(), rig.asker->id().value());
    }
};

QTEST_MAIN(TestJausHandoffForeign)
#include "test_jaus_handoff_foreign.moc"
