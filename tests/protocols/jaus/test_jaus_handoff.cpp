// Hand-off of control between two consoles end to end over loopback (AEP-4818 §6.3): two JausStacks with
// subsystem IDs 200 and 201 and the simulated UGV's Enhanced Access Control 1.1. Console A holds the UGV,
// console B asks for it at the same authority (which plain AccessControl would refuse): the vehicle forwards
// the request to A, whose operator sees who asks and why and accepts (control passes to B, A sees it
// released), denies (A keeps it, B is told), or does not answer (both see the decision timeout). Against the
// foreign vehicle, which offers no Enhanced Access Control, the console falls back to the ordinary
// pre-emption rules and says so.
#include <QtTest>

#include <mutex>

#include "protocols/common/Log.h"
#include "protocols/common/Udp.h"
#include "protocols/jaus/JausStack.h"
#include "sim/jaus/JausDemo.h"
#include "tests/protocols/jaus/foreign/ForeignJausVehicle.h"
#include "tests/support/JausLoopback.h"
#include "tests/support/StackWaits.h"

using namespace ocu;
using namespace ocu::jaus;
using stacktest::Outcomes;
using stacktest::waitFor;

namespace {

// Short on purpose: the timeout test waits it out. Whole seconds on the wire.
constexpr double kDecisionTimeoutS = 3;

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

JausConfig consoleConfig(std::uint16_t ss, std::uint8_t authority) {
    JausConfig c;
    c.subsystemId = ss;
    c.callSign = "OCU-" + std::to_string(ss);
    c.authority = authority;
    c.driveCommandTimeoutS = 0;
    return c;
}

struct Console {
    explicit Console(JausConfig c) : stack(std::move(c), listener) { stack.start(); }
    ~Console() { stack.stop(); }
    std::optional<SubsystemSnapshot> snap(std::uint16_t ss = 126) { return stack.snapshot(ss); }
    HandoffStatus handoff(std::uint16_t ss = 126) {
        auto s = snap(ss);
        return s ? s->handoff : HandoffStatus{};
    }
    bool controls(std::uint16_t ss = 126) {
        auto s = snap(ss);
        return s && s->controlledByUs;
    }
    JausId id() const { return stack.config().ownId(); }
    // Sent, or the reason in the failure message.
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

struct SimRig {
    explicit SimRig(double decisionTimeoutS = kDecisionTimeoutS)
        : decisionTimeoutS(decisionTimeoutS), demo(options(decisionTimeoutS)) {
        JausConfig a = consoleConfig(200, 205), b = consoleConfig(201, 205);
        demo.configure(a);
        demo.configure(b);
        holder = std::make_unique<Console>(a);
        asker = std::make_unique<Console>(b);
    }
    static sim::JausDemoOptions options(double decisionTimeoutS) {
        sim::JausDemoOptions o;
        o.count = 1;
        o.adjustUgv = [decisionTimeoutS](sim::SimulatedUgvConfig& c) {
            c.handoffDecisionTimeoutS = decisionTimeoutS;
        };
        return o;
    }
    sim::SimulatedUgv& ugv() { return *demo.find(126); }
    // A holds the UGV; both consoles know it offers Enhanced Access Control and who holds it.
    bool ready() {
        for (Console* c : {holder.get(), asker.get()})
            if (!waitFor([&] { return c->handoff().offered; }))
                return false;
        holder->stack.requestControl(126, {});
        if (!waitFor([&] { return holder->controls(); }))
            return false;
        return waitFor([&] {
            auto s = asker->snap();
            return s && s->controller == holder->id() &&
                   holder->handoff().decisionTimeoutS == decisionTimeoutS;
        });
    }
    // B asks; A is shown the request (who and why). Returns its queue ID, or -1.
    int ask() {
        Outcomes o;
        asker->stack.handoffRequest(126, "need the vehicle", o.callback());
        if (!Console::sent(o))
            return -1;
        if (!waitFor([&] { return !holder->handoff().prompts.empty(); }))
            return -1;
        const HandoffPrompt p = holder->handoff().prompts.front();
        if (!(p.requester == asker->id()) || p.explanation != "OCU-201: need the vehicle" ||
            p.authority != 205)
            return -1;
        if (!holder->listener.saw("201.1.1 asks for control of UGV-126"))
            return -1;
        if (!waitFor([&] { return asker->handoff().phase == HandoffPhase::Queued; }))
            return -1;
        return p.id;
    }
    double decisionTimeoutS;
    sim::JausDemo demo;
    std::unique_ptr<Console> holder, asker;
};

} // namespace

class TestJausHandoff : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { setLogThreshold(LogLevel::Error); }

    void handoffAccepted() {
        SimRig rig(20);
        QVERIFY(rig.ready());
        const int id = rig.ask();
        QVERIFY(id > 0);
        // Longer than the 5 s Handoff Request Timeout: B's re-assertions keep the request alive.
        QTest::qWait(5500);
        QCOMPARE(rig.asker->handoff().phase, HandoffPhase::Queued);
        QCOMPARE(rig.holder->handoff().prompts.size(), std::size_t(1));
        Outcomes answer;
        rig.holder->stack.handoffAnswer(126, std::uint8_t(id), true, answer.callback());
        QVERIFY(Console::sent(answer));
        QVERIFY(waitFor([&] { return rig.asker->handoff().phase == HandoffPhase::Completed; }));
        QVERIFY(rig.asker->controls());
        QCOMPARE(rig.ugv().state().controller, rig.asker->id());
        // The outcome on both consoles: A released it (no loss, no pre-emption), B holds it.
        QVERIFY(waitFor([&] { return !rig.holder->controls(); }));
        QCOMPARE(rig.holder->snap()->access, AccessState::ControlReleased);
        QVERIFY(rig.holder->listener.saw("hand-off of UGV-126 to 201.1.1 granted"));
        QVERIFY(rig.asker->listener.saw("granted by 200.1.1"));
        QVERIFY(rig.asker->listener.saw("control of UGV-126 handed over"));
        // A no longer asks for control: B keeps it past the access timeout.
        QTest::qWait(1500);
        QCOMPARE(rig.ugv().state().controller, rig.asker->id());
        QVERIFY(rig.holder->handoff().prompts.empty());
    }

    void handoffDenied() {
        SimRig rig;
        QVERIFY(rig.ready());
        const int id = rig.ask();
        QVERIFY(id > 0);
        Outcomes answer;
        rig.holder->stack.handoffAnswer(126, std::uint8_t(id), false, answer.callback());
        QVERIFY(Console::sent(answer));
        QVERIFY(waitFor([&] { return rig.asker->handoff().phase == HandoffPhase::Denied; }));
        QVERIFY(QString::fromStdString(rig.asker->handoff().reason).contains("denied by 200.1.1"));
        QVERIFY(rig.holder->handoff().prompts.empty());
        QVERIFY(rig.holder->listener.saw("hand-off of UGV-126 to 201.1.1 denied"));
        QTest::qWait(500);
        QVERIFY(rig.holder->controls());
        QVERIFY(!rig.asker->controls());
        QCOMPARE(rig.ugv().state().controller, rig.holder->id());
        // Answering again: nothing waits any more, refused with the reason.
        Outcomes again;
        rig.holder->stack.handoffAnswer(126, std::uint8_t(id), true, again.callback());
        auto r = again.get();
        QVERIFY(r && !r->front().sent);
        QCOMPARE(r->front().cause, OutcomeReason::InvalidArgument);
    }

    void handoffTimedOut() {
        SimRig rig;
        QVERIFY(rig.ready());
        QVERIFY(rig.ask() > 0);
        // Nobody answers on A: after the decision timeout the vehicle answers B TIMEOUT and A's prompt goes.
        QVERIFY(waitFor([&] { return rig.asker->handoff().phase == HandoffPhase::TimedOut; },
                        kDecisionTimeoutS + 5));
        QVERIFY(QString::fromStdString(rig.asker->handoff().reason).contains("did not answer within 3 s"));
        QVERIFY(waitFor([&] { return rig.holder->handoff().prompts.empty(); }));
        QVERIFY(rig.holder->listener.saw("not answered within 3 s"));
        QVERIFY(rig.holder->controls());
        QVERIFY(!rig.asker->controls());
    }

    void foreignVehicleWithoutEnhancedAccessControlFallsBackToPreemption() {
        foreign::ForeignJausVehicle v(foreign::VehicleOptions{});
        const std::uint16_t group = findFreeUdpPort();
        auto config = [&](std::uint16_t ss, std::uint8_t authority) {
            JausConfig c = consoleConfig(ss, authority);
            c.statusPollHz = 2;
            c.accessTimeoutS = 3;
            c.transport = jaustest::loopback(group);
            c.transport.staticEndpoints.push_back(
                StaticEndpoint{JausId{126, 0xFF, 0xFF}, "127.0.0.1", v.port(), false});
            return c;
        };
        Console a(config(200, 205)), b(config(201, 205)), c(config(202, 220));
        for (Console* k : {&a, &b, &c})
            QVERIFY(waitFor([&] {
                auto s = k->snap();
                return s && s->callSign == "FOREIGN-126" && !s->services.empty();
            }));
        QVERIFY(!b.handoff().offered);
        a.stack.requestControl(126, {});
        QVERIFY(waitFor([&] { return a.controls(); }));

        // Equal authority: the ordinary rules refuse it, and the console says why.
        Outcomes ob;
        b.stack.handoffRequest(126, "need it", ob.callback());
        QVERIFY(Console::sent(ob));
        QVERIFY(b.listener.saw("offers no Enhanced Access Control: the ordinary pre-emption rules apply"));
        QVERIFY(waitFor([&] { return b.handoff().phase == HandoffPhase::Refused; }));
        QVERIFY(QString::fromStdString(b.handoff().reason).contains("ordinary pre-emption"));
        QCOMPARE(v.controller(), a.id().value());
        QCOMPARE(v.received(0xFF31), 0); // no RequestHandoff to a vehicle that does not offer it

        // A higher authority pre-empts.
        Outcomes oc;
        c.stack.handoffRequest(126, "safety officer", oc.callback());
        QVERIFY(Console::sent(oc));
        QVERIFY(waitFor([&] { return c.handoff().phase == HandoffPhase::Completed; }));
        QCOMPARE(v.controller(), c.id().value());
        QVERIFY(QString::fromStdString(c.handoff().reason).contains("taken"));
    }
};

QTEST_MAIN(TestJausHandoff)
#include "test_jaus_handoff.moc"
