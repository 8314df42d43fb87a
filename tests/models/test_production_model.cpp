// The production model counts what the trucks report. A load counts at the dump (its weight,
// else the payload reported at loading, else unknown), attributed to the truck, the shovel it was loaded at
// and the dump; a cycle without a dump counts as the load; the cycle breakdown sums the cycles' state times
// by part; reports before the shift are not counted; tonnes over the shift stay in time order with late
// reports.
#include "models/ProductionModel.h"

#include <QSignalSpy>
#include <QtTest>

using namespace ocu;

namespace {

constexpr qint64 kStart = 1'741'910'400'000; // shift start
constexpr qint64 kMin = 60'000;

ProductionReport state(const QString& truck, const QString& s, qint64 way, qint64 at) {
    ProductionReport r;
    r.kind = ProductionReport::Kind::State;
    r.truckId = truck;
    r.truckName = truck.toUpper();
    r.state = s;
    r.wayId = way;
    r.unixMs = at;
    return r;
}

ProductionReport payload(const QString& truck, std::optional<double> t, qint64 at) {
    ProductionReport r;
    r.kind = ProductionReport::Kind::Payload;
    r.truckId = truck;
    r.truckName = truck.toUpper();
    r.tonnes = t;
    r.unixMs = at;
    return r;
}

ProductionReport dump(const QString& truck, qint64 way, std::optional<double> t, qint64 at) {
    ProductionReport r;
    r.kind = ProductionReport::Kind::Dump;
    r.truckId = truck;
    r.truckName = truck.toUpper();
    r.wayId = way;
    r.dumpWayId = way;
    r.tonnes = t;
    r.unixMs = at;
    return r;
}

// A cycle: return 300 s, queue 60, spot 30, load 120, haul 600, dump 45.
ProductionReport cycle(const QString& truck, qint64 load, qint64 dumpWay, std::optional<double> t, qint64 at,
                       double queue = 60) {
    ProductionReport r;
    r.kind = ProductionReport::Kind::Cycle;
    r.truckId = truck;
    r.truckName = truck.toUpper();
    r.loadWayId = load;
    r.dumpWayId = dumpWay;
    r.tonnes = t;
    r.unixMs = at;
    qint64 s = at - 1'155'000;
    for (auto [name, sec] : {std::pair<const char*, double>{"Driving", 300},
                             {"Queued", queue},
                             {"Spotting", 30},
                             {"Loading", 120},
                             {"Hauling", 600},
                             {"Dumping", 45}}) {
        r.periods.push_back({QString::fromLatin1(name), s, sec});
        s += qint64(sec * 1000);
    }
    return r;
}

const ProductionTally* find(const QVector<ProductionTally>& v, const QString& key) {
    for (const auto& t : v)
        if (t.key == key)
            return &t;
    return nullptr;
}

} // namespace

class TestProductionModel : public QObject {
    Q_OBJECT
private slots:
    void loadsAndTonnesPerTruckShovelDump() {
        ProductionModel m;
        m.setShift(kStart, kStart + 12 * 60 * kMin);
        m.setAreaName(4101, QStringLiteral("Shovel 1"));
        m.setAreaName(4201, QStringLiteral("Dump 1"));
        QSignalSpy changed(&m, &ProductionModel::changed);
        // Truck a: loaded at 4101 (its Loading state's way), 250 t reported at loading, dump reports 248 t.
        m.addReport(state(QStringLiteral("a"), QStringLiteral("Loading"), 4101, kStart + 5 * kMin));
        m.addReport(payload(QStringLiteral("a"), 250, kStart + 7 * kMin));
        m.addReport(dump(QStringLiteral("a"), 4201, 248, kStart + 20 * kMin));
        m.addReport(cycle(QStringLiteral("a"), 4101, 4201, 248, kStart + 20 * kMin + 1));
        // Truck b: the dump's weight is null: the payload's 230 t count.
        m.addReport(state(QStringLiteral("b"), QStringLiteral("Loading"), 4102, kStart + 6 * kMin));
        m.addReport(payload(QStringLiteral("b"), 230, kStart + 8 * kMin));
        m.addReport(dump(QStringLiteral("b"), 4201, std::nullopt, kStart + 25 * kMin));
        // Truck c: no payload, no weight: a load of unknown tonnes.
        m.addReport(dump(QStringLiteral("c"), 4202, std::nullopt, kStart + 26 * kMin));
        // Truck d: an AHS sending cycles only: the cycle is the load.
        m.addReport(cycle(QStringLiteral("d"), 4102, 4202, 270, kStart + 30 * kMin, 0));
        QVERIFY(changed.count() >= 5);

        QCOMPARE(m.shift().loads, 4);
        QCOMPARE(m.shift().tonnes, 248.0 + 230 + 270);
        QCOMPARE(m.shift().loadsWithoutTonnes, 1);
        QCOMPARE(m.trucks().size(), 4);
        QCOMPARE(find(m.trucks(), QStringLiteral("a"))->tonnes, 248.0);
        QCOMPARE(find(m.trucks(), QStringLiteral("a"))->name, QStringLiteral("A"));
        QCOMPARE(find(m.trucks(), QStringLiteral("b"))->tonnes, 230.0);
        QCOMPARE(find(m.shovels(), QStringLiteral("4101"))->loads, 1);
        QCOMPARE(find(m.shovels(), QStringLiteral("4101"))->name, QStringLiteral("Shovel 1"));
        QCOMPARE(find(m.shovels(), QStringLiteral("4102"))->loads, 2); // b and d
        QCOMPARE(find(m.shovels(), QStringLiteral("4102"))->tonnes, 500.0);
        QCOMPARE(find(m.shovels(), QStringLiteral("unknown"))->loads, 1); // c: never reported loading
        QCOMPARE(find(m.dumps(), QStringLiteral("4201"))->loads, 2);
        QCOMPARE(find(m.dumps(), QStringLiteral("4201"))->name, QStringLiteral("Dump 1"));
        QCOMPARE(find(m.dumps(), QStringLiteral("4202"))->tonnes, 270.0);
        // A name learnt later renames the tally.
        m.setAreaName(4102, QStringLiteral("Shovel 2"));
        QCOMPARE(find(m.shovels(), QStringLiteral("4102"))->name, QStringLiteral("Shovel 2"));

        // Cycle breakdown: a and d (d had no queue).
        const auto& c = m.shift().cycle;
        QCOMPARE(c.cycles, 2);
        QCOMPARE(c.seconds[CycleBreakdown::Queue], 60.0);
        QCOMPARE(c.average(CycleBreakdown::Queue), 30.0);
        QCOMPARE(c.average(CycleBreakdown::Haul), 600.0);
        QCOMPARE(c.average(CycleBreakdown::Return), 300.0);
        QCOMPARE(c.averageTotal(), (300 + 60 + 30 + 120 + 600 + 45 + 300 + 0 + 30 + 120 + 600 + 45) / 2.0);
        QCOMPARE(find(m.dumps(), QStringLiteral("4202"))->cycle.cycles, 1);
        QCOMPARE(find(m.trucks(), QStringLiteral("a"))->cycle.average(CycleBreakdown::Spot), 30.0);

        // Tonnes over the shift: cumulative at each dump, in time order.
        const auto& series = m.tonnesOverShift();
        QCOMPARE(series.size(), 4);
        QCOMPARE(series.last().y(), 748.0);
        QCOMPARE(m.loadsOverShift().last().y(), 4.0);
    }

    void lateReportsKeepTheSeriesInOrderAndEarlierOnesAreNotCounted() {
        ProductionModel m;
        m.setShift(kStart, kStart + 60 * kMin);
        m.addReport(dump(QStringLiteral("a"), 4201, 200, kStart + 30 * kMin));
        m.addReport(dump(QStringLiteral("b"), 4201, 100, kStart + 10 * kMin)); // late, earlier in the shift
        m.addReport(dump(QStringLiteral("c"), 4201, 999, kStart - kMin));      // before the shift
        QCOMPARE(m.shift().loads, 2);
        QCOMPARE(m.reportsIgnored(), 1);
        const auto& s = m.tonnesOverShift();
        QCOMPARE(s.size(), 2);
        QCOMPARE(s[0], QPointF(double(kStart + 10 * kMin), 100));
        QCOMPARE(s[1], QPointF(double(kStart + 30 * kMin), 300));
    }

    // A truck seen first mid-cycle (loaded, hauling): its first dump goes to the unknown shovel until the
    // cycle names the load area; that cycle, seen in part only, stays out of the breakdown.
    void partialFirstCycleAttributesButIsNotAveraged() {
        ProductionModel m;
        m.setShift(kStart, kStart + 60 * kMin);
        m.addReport(dump(QStringLiteral("a"), 4201, 250, kStart + 5 * kMin));
        QCOMPARE(find(m.shovels(), QStringLiteral("unknown"))->loads, 1);
        ProductionReport c = cycle(QStringLiteral("a"), 4102, 4201, 250, kStart + 5 * kMin + 1);
        c.periods = {{QStringLiteral("Hauling"), kStart + kMin, 200},
                     {QStringLiteral("Dumping"), kStart + 4 * kMin, 45}};
        m.addReport(c);
        QVERIFY(!find(m.shovels(), QStringLiteral("unknown")));
        QCOMPARE(find(m.shovels(), QStringLiteral("4102"))->loads, 1);
        QCOMPARE(find(m.shovels(), QStringLiteral("4102"))->tonnes, 250.0);
        QCOMPARE(m.shift().cycle.cycles, 0);
        QCOMPARE(m.partialCycles(), 1);
        QCOMPARE(m.shift().loads, 1);
        // The next, whole cycle is averaged.
        m.addReport(dump(QStringLiteral("a"), 4201, 260, kStart + 25 * kMin));
        m.addReport(cycle(QStringLiteral("a"), 4102, 4201, 260, kStart + 25 * kMin + 1));
        QCOMPARE(m.shift().cycle.cycles, 1);
        QCOMPARE(find(m.shovels(), QStringLiteral("4102"))->loads, 2);
    }

    void planIsSpreadOverTheShift() {
        ProductionModel m;
        m.setShift(kStart, kStart + 100 * kMin);
        m.setPlanTonnes(10000);
        QCOMPARE(m.plannedTonnesAt(kStart - 1), 0.0);
        QCOMPARE(m.plannedTonnesAt(kStart + 25 * kMin), 2500.0);
        QCOMPARE(m.plannedTonnesAt(kStart + 200 * kMin), 10000.0);
        m.setPlanTonnes(-5);
        QCOMPARE(m.planTonnes(), 0.0);
    }

    void clearStartsANewShift() {
        ProductionModel m;
        m.setShift(kStart, kStart + 60 * kMin);
        m.addReport(dump(QStringLiteral("a"), 4201, 200, kStart + kMin));
        m.clear();
        QCOMPARE(m.shift().loads, 0);
        QVERIFY(m.trucks().isEmpty());
        QVERIFY(m.tonnesOverShift().isEmpty());
        QCOMPARE(m.shiftEnd() - m.shiftStart(), 60 * kMin);
    }
};

QTEST_GUILESS_MAIN(TestProductionModel)
#include "test_production_model.moc"
