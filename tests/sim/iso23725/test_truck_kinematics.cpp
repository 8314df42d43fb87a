// A simulated haul truck's motion on its own, stepped in simulated seconds: the route's length, poses and
// ways; acceleration to the cruise speed, braking, and the approach that stops it at the route's end.
#include "sim/iso23725/TruckKinematics.h"

#include <QtTest>

#include <cmath>

using namespace ocu;
using namespace ocu::sim;

namespace {

// An L-shaped route: 100 m north on way 1, then 50 m east on way 2 (which starts where way 1 ends).
Route lRoute() {
    Route r;
    r.addLeg(1, {{0, 0, 0}, {0, 50, 0}, {0, 100, 0}});
    r.addLeg(2, {{0, 100, 0}, {25, 100, 0}, {50, 100, -5}});
    return r;
}

} // namespace

class TestTruckKinematics : public QObject {
    Q_OBJECT
private slots:
    void routeLengthAndPoses() {
        const Route r = lRoute();
        QVERIFY(!r.empty());
        QCOMPARE(r.length(), 150.0); // horizontal: the 5 m descent does not count
        QCOMPARE(r.legWays(), (std::vector<std::int64_t>{1, 2}));

        auto p = r.poseAt(0);
        QVERIFY(p);
        QCOMPARE(p->position.n, 0.0);
        QCOMPARE(*p->headingDeg, 0.0); // north
        QCOMPARE(p->wayId, std::int64_t(1));

        p = r.poseAt(75);
        QCOMPARE(p->position.e, 0.0);
        QCOMPARE(p->position.n, 75.0);
        QCOMPARE(p->wayId, std::int64_t(1));

        p = r.poseAt(137.5); // half way along the last stretch: east and half the descent
        QCOMPARE(p->position.e, 37.5);
        QCOMPARE(p->position.n, 100.0);
        QCOMPARE(p->position.u, -2.5);
        QCOMPARE(*p->headingDeg, 90.0);
        QCOMPARE(p->wayId, std::int64_t(2));

        p = r.poseAt(1000); // clamped to the end
        QCOMPARE(p->position.e, 50.0);
        QCOMPARE(p->position.n, 100.0);
        p = r.poseAt(-10); // and to the start
        QCOMPARE(p->position.n, 0.0);

        QVERIFY(!Route().poseAt(0));
    }

    // The joint between two legs (same point twice) has no direction: the stretch's heading is unknown there,
    // and the truck keeps the heading it had.
    void degenerateStretchKeepsTheHeading() {
        const Route r = lRoute();
        const auto joint = r.poseAt(100);
        QCOMPARE(joint->wayId, std::int64_t(1));
        TruckMotion m;
        m.setRoute(r);
        m.placeAt(99);
        QCOMPARE(m.headingDeg(), 0.0);
        m.placeAt(100);
        QCOMPARE(m.headingDeg(), 0.0);
        m.placeAt(101);
        QCOMPARE(m.headingDeg(), 90.0);
        QCOMPARE(m.wayId(), std::int64_t(2));
    }

    // From rest the speed rises at the acceleration limit up to the cruise speed and stays there.
    void acceleratesToCruise() {
        Route r;
        r.addLeg(7, {{0, 0, 0}, {0, 2000, 0}});
        TruckMotion m;
        m.setRoute(r);
        double t = 0;
        for (int i = 0; i < 50; ++i) { // 5 s at 10 Hz
            m.drive(0.1, 10.0, 2.0);
            t += 0.1;
            QVERIFY(std::fabs(m.speed() - std::min(t, 10.0)) < 1e-9);
        }
        for (int i = 0; i < 100; ++i)
            m.drive(0.1, 10.0, 2.0);
        QCOMPARE(m.speed(), 10.0);
        QVERIFY(std::fabs(m.distance() - (0.5 * 10 * 10 + 10 * 5)) < 0.6); // accelerate 10 s, cruise 5 s
        QCOMPARE(m.wayId(), std::int64_t(7));
        QVERIFY(!m.arrived());
    }

    // Cruise 0 brakes at the given deceleration to a standstill, which holds.
    void brakesToAStop() {
        Route r;
        r.addLeg(7, {{0, 0, 0}, {0, 2000, 0}});
        TruckMotion m;
        m.setRoute(r);
        for (int i = 0; i < 200; ++i)
            m.drive(0.1, 10.0, 2.0);
        QCOMPARE(m.speed(), 10.0);
        for (int i = 1; i <= 40; ++i) {
            m.drive(0.1, 0.0, 3.0);
            QVERIFY(std::fabs(m.speed() - std::max(0.0, 10.0 - 0.3 * i)) < 1e-9);
        }
        const double stoppedAt = m.distance();
        QCOMPARE(m.speed(), 0.0);
        for (int i = 0; i < 20; ++i)
            m.drive(0.1, 0.0, 3.0);
        QCOMPARE(m.distance(), stoppedAt);
    }

    // The approach: near the end the speed is capped so the truck could stop there (plus a creep speed); it
    // arrives without passing the end by more than the tolerance, and the distance never goes backwards.
    void slowsDownToArriveAtTheEnd() {
        Route r;
        r.addLeg(3, {{0, 0, 0}, {300, 0, 0}});
        const DriveLimits limits;
        TruckMotion m(limits);
        m.setRoute(r);
        double last = 0;
        int steps = 0;
        while (!m.arrived() && steps < 10000) {
            m.drive(0.1, 12.0, 2.0);
            ++steps;
            QVERIFY(m.distance() >= last);
            last = m.distance();
            const double before = m.remaining() + m.speed() * 0.1; // remaining when the step began
            QVERIFY(m.speed() <=
                    std::sqrt(2 * limits.approachDecel * std::max(0.0, before)) + limits.creepSpeed + 1e-9);
        }
        QVERIFY(m.arrived());
        QVERIFY(m.distance() <= r.length() + limits.creepSpeed * 0.1);
        QVERIFY2(m.speed() <= 2.0, qPrintable(QString::number(m.speed()))); // crawling in, not at cruise
        m.halt();
        QCOMPARE(m.speed(), 0.0);
        QCOMPARE(m.position().e, 300.0 - std::max(0.0, r.length() - m.distance()));
    }

    // A new route starts from its beginning; the speed carries over (a truck that arrived is halted first).
    void newRouteStartsAtItsBeginning() {
        TruckMotion m;
        m.setRoute(lRoute());
        m.placeAt(120);
        QCOMPARE(m.wayId(), std::int64_t(2));
        Route back;
        back.addLeg(9, {{50, 100, 0}, {50, 0, 0}});
        m.setRoute(back);
        QCOMPARE(m.distance(), 0.0);
        QCOMPARE(m.remaining(), 100.0);
        m.placeAt(0);
        QCOMPARE(m.wayId(), std::int64_t(9));
        QCOMPARE(m.headingDeg(), 180.0);
    }
};

QTEST_GUILESS_MAIN(TestTruckKinematics)
#include "test_truck_kinematics.moc"
