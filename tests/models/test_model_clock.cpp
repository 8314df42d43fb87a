// The models' one clock: the system clock is monotonic and starts at the wall clock, a manual clock moves
// only when told, a wall-clock stamp keeps its age on either, and a fleet row goes stale by its model's
// clock, not by real time passing.
#include "models/FleetModel.h"
#include "models/ModelClock.h"
#include "models/testing/FakeFleetBridge.h"

#include <QDateTime>
#include <QTest>

#include <cstdlib>

using namespace ocu;

class TestModelClock : public QObject {
    Q_OBJECT
private slots:
    void systemClockIsMonotonicAndStartsAtTheWallClock() {
        const auto clock = systemModelClock();
        QVERIFY(clock);
        QCOMPARE(systemModelClock().get(), clock.get()); // one per process
        const qint64 wall = QDateTime::currentMSecsSinceEpoch();
        QVERIFY2(std::abs(clock->nowMs() - wall) < 1000, qPrintable(QString::number(clock->nowMs() - wall)));
        qint64 last = clock->nowUs();
        for (int i = 0; i < 100000; ++i) {
            const qint64 t = clock->nowUs();
            QVERIFY(t >= last);
            last = t;
        }
        QVERIFY(std::abs(clock->nowUs() / 1000 - clock->nowMs()) <= 1);
        const qint64 before = clock->nowMs();
        QTest::qSleep(30);
        QVERIFY(clock->nowMs() - before >= 30);
    }

    void manualClockSetsAndAdvances() {
        ManualModelClock clock(100);
        QCOMPARE(clock.nowMs(), qint64(100));
        QCOMPARE(clock.nowUs(), qint64(100000));
        clock.advance(50);
        QCOMPARE(clock.nowMs(), qint64(150));
        clock.set(7);
        QCOMPARE(clock.nowMs(), qint64(7));
        QTest::qSleep(20);
        QCOMPARE(clock.nowMs(), qint64(7)); // real time does not move it
        QVERIFY(clockOrSystem(nullptr) == systemModelClock());
    }

    void wallStampKeepsItsAgeOnTheModelClock() {
        const ManualModelClock clock(1'000'000);
        const qint64 stamp = QDateTime::currentMSecsSinceEpoch() - 300;
        const qint64 onModel = wallStampToModelMs(clock, stamp);
        QVERIFY2(onModel <= 1'000'000 - 300 && onModel > 1'000'000 - 400,
                 qPrintable(QString::number(onModel)));
        QCOMPARE(wallStampToModelMs(clock, 0), qint64(0)); // "never" stays never
        QCOMPARE(wallStampToModelUs(clock, 0), qint64(0));
        const qint64 us = QDateTime::currentMSecsSinceEpoch() * 1000 - 2000;
        const qint64 usOnModel = wallStampToModelUs(clock, us);
        QVERIFY(usOnModel <= 1'000'000'000 - 2000 && usOnModel > 1'000'000'000 - 100'000);
        FakeFleetBridge bridge(Protocol::Jaus);
        bridge.setClock(std::make_shared<ManualModelClock>(1'000'000));
        QCOMPARE(bridge.clock().nowMs(), qint64(1'000'000));
        const qint64 received = bridge.modelTimeOfWallMs(stamp);
        QVERIFY(received <= 1'000'000 - 300 && received > 1'000'000 - 400);
    }

    void fleetRowGoesStaleByTheManualClockNotByWaiting() {
        auto clock = std::make_shared<ManualModelClock>(10'000);
        FleetModel model;
        model.setRefreshIntervalMs(0);
        model.setClock(clock);
        model.setStaleAfterMs(50);
        MachineState m;
        m.id = QStringLiteral("jaus:1");
        m.protocol = Protocol::Jaus;
        m.link = LinkState::Up;
        m.lastDataMs = clock->nowMs();
        model.upsert({m});
        QTest::qSleep(120); // well past the threshold in real time
        model.refresh();
        QVERIFY(!model.isStale(m.id));
        QCOMPARE(model.ageMsAt(0), qint64(0));
        clock->advance(50);
        model.refresh();
        QVERIFY(!model.isStale(m.id));
        clock->advance(1);
        model.refresh();
        QVERIFY(model.isStale(m.id));
        QCOMPARE(model.ageMsAt(0), qint64(51));

        // Null is the system clock again: the row's stamp (10 s after the epoch) is ancient there.
        model.setClock(nullptr);
        QVERIFY(std::abs(model.nowMs() - QDateTime::currentMSecsSinceEpoch()) < 1000);
        model.refresh();
        QVERIFY(model.rowCount() == 0 || model.isStale(m.id));
    }
};

QTEST_GUILESS_MAIN(TestModelClock)
#include "test_model_clock.moc"
