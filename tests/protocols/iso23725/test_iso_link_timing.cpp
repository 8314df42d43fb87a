// Link timing of the ISO 23725 WebSocket (research note §2 [I]) on a fake clock: a ping every 5 s, dead after
// 15 s without any received frame, reconnect backoff 1 -> 30 s with +-20 % jitter, reset after a success.
#include "protocols/iso23725/LinkTiming.h"

#include <QtTest>

using namespace ocu;
using namespace ocu::iso23725;
using namespace std::chrono_literals;
using Action = KeepAlive::Action;

class TestLinkTiming : public QObject {
    Q_OBJECT
private slots:
    void pingsEveryIntervalAndDiesAfterSilence() {
        FakeClock clock;
        KeepAlive k(5s, 15s);
        const auto t0 = clock.now();
        k.start(t0);
        QCOMPARE(k.deadline(), t0 + 5s);
        QCOMPARE(k.poll(t0 + 4999ms), Action::None);
        QCOMPARE(k.poll(t0 + 5s), Action::SendPing);
        QCOMPARE(k.poll(t0 + 5s), Action::None); // one ping per interval
        QCOMPARE(k.deadline(), t0 + 10s);
        QCOMPARE(k.poll(t0 + 10s), Action::SendPing);
        QCOMPARE(k.deadline(), t0 + 15s); // next ping and death coincide
        QCOMPARE(k.poll(t0 + 14999ms), Action::None);
        QCOMPARE(k.poll(t0 + 15s), Action::Dead); // death wins over a due ping
        QCOMPARE(k.silentFor(t0 + 15s), Duration(15s));
    }

    void anyFrameKeepsTheLinkAlive() {
        KeepAlive k(5s, 15s);
        const TimePoint t0{std::chrono::hours(2)};
        k.start(t0);
        k.received(t0 + 12s); // a pong or any data frame
        QCOMPARE(k.poll(t0 + 15s), Action::SendPing);
        QCOMPARE(k.deadline(), t0 + 20s);
        QCOMPARE(k.poll(t0 + 26999ms), Action::SendPing); // the 20 s and 25 s pings, one action
        QCOMPARE(k.deadline(), t0 + 27s);
        QCOMPARE(k.poll(t0 + 27s), Action::Dead);
    }

    void latePollSendsOnePingNotABurst() {
        KeepAlive k(5s, 60s);
        const TimePoint t0{std::chrono::hours(2)};
        k.start(t0);
        QCOMPARE(k.poll(t0 + 23s), Action::SendPing);
        QCOMPARE(k.poll(t0 + 23s), Action::None);
        QCOMPARE(k.deadline(), t0 + 25s);
    }

    void backoffDoublesToTheCapWithoutJitter() {
        ReconnectBackoff b(1000ms, 30000ms, 0.0, 7);
        std::vector<std::int64_t> got;
        for (int i = 0; i < 8; ++i)
            got.push_back(b.next().count());
        QCOMPARE(got, (std::vector<std::int64_t>{1000, 2000, 4000, 8000, 16000, 30000, 30000, 30000}));
        b.reset();
        QCOMPARE(b.next().count(), std::int64_t(1000));
    }

    void backoffJitterStaysWithinBoundsAndVaries() {
        ReconnectBackoff b(1000ms, 30000ms, 0.2, 42);
        const double base[] = {1000, 2000, 4000, 8000, 16000, 30000, 30000};
        for (double expected : base) {
            const double d = static_cast<double>(b.next().count());
            QVERIFY2(d >= expected * 0.8 - 1 && d <= expected * 1.2 + 1, qPrintable(QString::number(d)));
        }
        // Two consoles with different seeds do not retry in lockstep.
        ReconnectBackoff c1(1000ms, 30000ms, 0.2, 1), c2(1000ms, 30000ms, 0.2, 2);
        int differ = 0;
        for (int i = 0; i < 6; ++i)
            differ += c1.next() != c2.next();
        QVERIFY(differ >= 5);
    }
};

QTEST_GUILESS_MAIN(TestLinkTiming)
#include "test_iso_link_timing.moc"
