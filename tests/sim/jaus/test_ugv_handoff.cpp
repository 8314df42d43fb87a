// The simulated UGV's Enhanced Access Control 1.1 on its own, with a FakeClock and the consoles played by
// hand: the immediate answers (nobody in control, too low an authority, the controller itself, an
// emergency), the queue forwarded to the controller as RequestReleaseControl, the controller's GRANTED
// (control passes, at most one), DENIED and WAIT, the request and decision timeouts, a withdrawn request,
// answers from a console that does not hold the vehicle, the timeout queries, and a UGV configured without
// the service.
#include <QtTest>

#include "protocols/jaus/MessagesHandoff.h"
#include "sim/jaus/UgvCore.h"

using namespace ocu;
using namespace ocu::jaus;
using namespace ocu::sim;

namespace {

const JausId kA{200, 1, 1}, kB{201, 1, 1}, kC{202, 1, 1};

struct Sent {
    JausId from, to;
    Bytes payload;
    std::uint16_t id() const { return peekMessageId(payload); }
};

struct Capture : JausOutput {
    std::vector<Sent> sent;
    void send(const JausId& dst, const Bytes& p, SendOptions) override { sent.push_back({{}, dst, p}); }
    void sendFrom(const JausId& src, const JausId& dst, const Bytes& p, SendOptions) override {
        sent.push_back({src, dst, p});
    }
    std::string sendOrWhy(const JausId& dst, const Bytes& p, SendOptions o) override {
        send(dst, p, o);
        return {};
    }
    // Messages with this ID to `to`, in order.
    std::vector<Bytes> to(const JausId& to, std::uint16_t id) const {
        std::vector<Bytes> out;
        for (const Sent& s : sent)
            if (s.to == to && s.id() == id)
                out.push_back(s.payload);
        return out;
    }
};

struct Rig {
    FakeClock clock;
    Counters counters;
    Capture out;
    UgvCore ugv;
    explicit Rig(bool eac = true) : ugv(config(eac), out, clock, counters) { ugv.tick(); }
    static SimulatedUgvConfig config(bool eac) {
        SimulatedUgvConfig c;
        c.enhancedAccessControl = eac;
        c.accessTimeoutS = 1000; // control is not what these tests time out
        return c;
    }
    JausId mob() const { return ugv.mobility(); }
    void from(const JausId& src, const Bytes& payload) { ugv.handle(src, mob(), payload); }
    void run(double seconds) {
        for (int i = 0; i < int(seconds * 10); ++i) {
            clock.advance(std::chrono::milliseconds(100));
            ugv.tick();
        }
    }
    // The last ConfirmHandoffRequest to `to`.
    std::optional<ConfirmHandoffRequest> answerTo(const JausId& to) const {
        auto all = out.to(to, msg::ConfirmHandoffRequest);
        if (all.empty())
            return std::nullopt;
        auto d = decodeConfirmHandoffRequest(all.back());
        return d ? std::optional(*d) : std::nullopt;
    }
    std::optional<RequestReleaseControl> forwardedTo(const JausId& to) const {
        auto all = out.to(to, msg::RequestReleaseControl);
        if (all.empty())
            return std::nullopt;
        auto d = decodeRequestReleaseControl(all.back());
        return d ? std::optional(*d) : std::nullopt;
    }
    // A holds the UGV, B asks: returns B's queue ID.
    std::uint8_t heldByAAskedByB() {
        from(kA, encodeU8(msg::RequestControl, 205));
        from(kB, encode(RequestHandoff{205, "OCU-201: please"}));
        auto a = answerTo(kB);
        return a && a->code == HandoffCode::Queued ? a->id : 0;
    }
};

} // namespace

class TestUgvHandoff : public QObject {
    Q_OBJECT
private slots:
    void offeredOnTheMobilityComponentAndItsTimeoutsAnswered() {
        Rig rig;
        rig.from(kB, encodeEmpty(msg::QueryHandoffTimeout));
        rig.from(kB, encodeEmpty(msg::QueryEnhancedTimeout));
        QCOMPARE(rig.out.to(kB, msg::ReportHandoffTimeout).back(), (Bytes{0x36, 0xff, 60}));
        QCOMPARE(rig.out.to(kB, msg::ReportEnhancedTimeout).back(), (Bytes{0x37, 0xff, 5}));
        // Without the service: not listed, requests unanswered.
        Rig plain(false);
        plain.from(kA, encodeU8(msg::RequestControl, 205));
        plain.from(kB, encode(RequestHandoff{205, "x"}));
        QVERIFY(!plain.answerTo(kB));
        QVERIFY(!plain.forwardedTo(kA));
    }

    void immediateAnswers() {
        Rig rig;
        rig.from(kB, encode(RequestHandoff{205, "x"}));
        QCOMPARE(rig.answerTo(kB)->code, HandoffCode::Denied); // nobody holds it: RequestControl instead
        QCOMPARE(rig.answerTo(kB)->id, kNoHandoffId);
        rig.from(kA, encodeU8(msg::RequestControl, 205));
        rig.from(kB, encode(RequestHandoff{100, "x"}));
        QCOMPARE(rig.answerTo(kB)->code, HandoffCode::InsufficientAuthority);
        rig.from(kA, encode(RequestHandoff{210, "x"}));
        QCOMPARE(rig.answerTo(kA)->code, HandoffCode::Granted); // the controller sets its authority
        QCOMPARE(int(rig.ugv.state().controllerAuthority), 210);
        rig.ugv.enterEmergency();
        rig.from(kB, encode(RequestHandoff{205, "x"}));
        QCOMPARE(rig.answerTo(kB)->code, HandoffCode::NotAvailable);
        QVERIFY(!rig.forwardedTo(kA));
    }

    void grantedPassesControl() {
        Rig rig;
        const std::uint8_t idB = rig.heldByAAskedByB();
        QVERIFY(idB != 0 && idB != kNoHandoffId);
        auto fwd = rig.forwardedTo(kA);
        QVERIFY(fwd && fwd->requests.size() == 1);
        QCOMPARE(fwd->requests[0].requester, kB);
        QCOMPARE(QString::fromStdString(fwd->requests[0].explanation), QStringLiteral("OCU-201: please"));
        // C asks too: the whole queue goes to A again.
        rig.from(kC, encode(RequestHandoff{205, "c"}));
        const std::uint8_t idC = rig.answerTo(kC)->id;
        QCOMPARE(rig.forwardedTo(kA)->requests.size(), std::size_t(2));
        // A grants both: only the first GRANTED counts, the second is DENIED.
        rig.from(kA,
                 encode(ConfirmReleaseControl{{{idB, ReleaseCode::Granted}, {idC, ReleaseCode::Granted}}}));
        QCOMPARE(rig.ugv.state().controller, kB);
        QCOMPARE(rig.out.to(kA, msg::RejectControl).back(), (Bytes{0x10, 0x00, 0x00}));
        QCOMPARE(rig.answerTo(kB)->code, HandoffCode::Granted);
        QCOMPARE(rig.answerTo(kC)->code, HandoffCode::Denied);
        // B's RequestControl that follows is confirmed.
        rig.from(kB, encodeU8(msg::RequestControl, 205));
        QCOMPARE(rig.out.to(kB, msg::ConfirmControl).back(), (Bytes{0x0f, 0x00, 0x00}));
        // A is no longer the controller: its answers are ignored.
        rig.from(kC, encode(RequestHandoff{205, "again"}));
        const std::uint8_t idC2 = rig.answerTo(kC)->id;
        QCOMPARE(rig.forwardedTo(kB)->requests.size(), std::size_t(1));
        rig.from(kA, encode(ConfirmReleaseControl{{{idC2, ReleaseCode::Granted}}}));
        QCOMPARE(rig.ugv.state().controller, kB);
        QCOMPARE(rig.answerTo(kC)->code, HandoffCode::Queued);
    }

    void deniedWaitAndWithdrawn() {
        Rig rig;
        const std::uint8_t id = rig.heldByAAskedByB();
        // WAIT is passed on so the requester can tell "the holder is deciding" from "nobody has looked".
        rig.from(kA, encode(ConfirmReleaseControl{{{id, ReleaseCode::Wait}}}));
        QCOMPARE(rig.answerTo(kB)->code, HandoffCode::Deferred);
        rig.from(kA, encode(ConfirmReleaseControl{{{id, ReleaseCode::Denied}}}));
        QCOMPARE(rig.answerTo(kB)->code, HandoffCode::Denied);
        QCOMPARE(rig.ugv.state().controller, kA);
        QVERIFY(rig.forwardedTo(kA)->requests.empty()); // the holder's prompt goes

        const std::uint8_t again = [&] {
            rig.from(kB, encode(RequestHandoff{205, "x"}));
            return rig.answerTo(kB)->id;
        }();
        rig.from(kB, encodeU8(msg::RemoveHandoffRequest, again));
        QCOMPARE(rig.answerTo(kB)->code, HandoffCode::Denied);
        QVERIFY(rig.forwardedTo(kA)->requests.empty());
    }

    void requestAndDecisionTimeouts() {
        Rig rig;
        const std::uint8_t id = rig.heldByAAskedByB();
        // Not re-asserted within 5 s: TIMEOUT, and A's queue is empty again.
        rig.run(4.8);
        QCOMPARE(rig.answerTo(kB)->code, HandoffCode::Queued);
        rig.run(0.4);
        QCOMPARE(rig.answerTo(kB)->code, HandoffCode::Timeout);
        QCOMPARE(rig.answerTo(kB)->id, id);
        QVERIFY(rig.forwardedTo(kA)->requests.empty());

        // Re-asserted every 1.5 s but A never answers: TIMEOUT after the 60 s decision timeout.
        rig.from(kB, encode(RequestHandoff{205, "x"}));
        for (int i = 0; i < 39; ++i) {
            rig.run(1.5);
            rig.from(kB, encode(RequestHandoff{205, "x"}));
            QVERIFY2(rig.answerTo(kB)->code == HandoffCode::Queued, qPrintable(QString::number(i)));
        }
        rig.run(2);
        QCOMPARE(rig.answerTo(kB)->code, HandoffCode::Timeout);
        QCOMPARE(rig.ugv.state().controller, kA);
    }
};

QTEST_APPLESS_MAIN(TestUgvHandoff)
#include "test_ugv_handoff.moc"
