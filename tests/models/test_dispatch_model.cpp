// Issue 15 §3: the dispatch table model. Rows in id order from the source, incremental updates (one
// dataChanged over the changed rows, inserts and removals), the "needs assignment" cue, the assignment column
// telling the reported status apart from the answer to this console's request, the ETA (route length over the
// reported speed, the nominal speed below 1 m/s), the route cache, "in state" from the report time, and the
// queues per shovel and dump.
#include "models/DispatchModel.h"
#include "models/FleetModel.h"
#include "models/testing/FakeDispatchSource.h"

#include <QSignalSpy>
#include <QtTest>

using namespace ocu;

namespace {
DispatchTruck truck(const QString& n) {
    DispatchTruck t;
    t.id = QStringLiteral("iso23725:") + n;
    t.link = QStringLiteral("ahs");
    t.name = n;
    t.stateKnown = true;
    t.custodian = QStringLiteral("FMS");
    t.autonomyMode = QStringLiteral("Autonomous");
    return t;
}
QString cell(const DispatchModel& m, int row, int col) {
    return m.data(m.index(row, col)).toString();
}
} // namespace

class TestDispatchModel : public QObject {
    Q_OBJECT
private slots:
    void rowsInIdOrderAndIncrementalUpdates() {
        FakeDispatchSource src;
        src.setTrucks({truck("T3"), truck("T1")}, false);
        DispatchModel m;
        m.setSource(&src);
        QCOMPARE(m.rowCount(), 2);
        QCOMPARE(cell(m, 0, DispatchModel::ColTruck), QStringLiteral("T1"));
        QCOMPARE(cell(m, 1, DispatchModel::ColTruck), QStringLiteral("T3"));
        QCOMPARE(cell(m, 0, DispatchModel::ColCustodian), QStringLiteral("FMS"));
        QCOMPARE(cell(m, 0, DispatchModel::ColAssignment), QStringLiteral("—"));

        QSignalSpy changed(&m, &QAbstractItemModel::dataChanged);
        QSignalSpy inserted(&m, &QAbstractItemModel::rowsInserted);
        QSignalSpy removed(&m, &QAbstractItemModel::rowsRemoved);
        // An update of one truck: one dataChanged over its row only.
        DispatchTruck t3 = truck("T3");
        t3.productionState = QStringLiteral("Hauling");
        t3.payloadTonnes = 212.4;
        src.setTrucks({t3});
        QCOMPARE(changed.size(), 1);
        QCOMPARE(changed[0][0].toModelIndex().row(), 1);
        QCOMPARE(changed[0][1].toModelIndex().row(), 1);
        QCOMPARE(cell(m, 1, DispatchModel::ColProduction), QStringLiteral("Hauling"));
        QCOMPARE(cell(m, 1, DispatchModel::ColPayload), QStringLiteral("212 t"));
        QCOMPARE(cell(m, 0, DispatchModel::ColPayload), QStringLiteral("—")); // null payload is never 0

        // A new truck goes in id order; a removed one leaves.
        src.setTrucks({truck("T2")});
        QCOMPARE(inserted.size(), 1);
        QCOMPARE(inserted[0][1].toInt(), 1);
        QCOMPARE(cell(m, 1, DispatchModel::ColTruck), QStringLiteral("T2"));
        QCOMPARE(m.rowOf(QStringLiteral("iso23725:T3")), 2);
        src.removeTruck(QStringLiteral("iso23725:T1"));
        QCOMPARE(removed.size(), 1);
        QCOMPARE(m.rowCount(), 2);
        QCOMPARE(m.rowOf(QStringLiteral("iso23725:T2")), 0);
        QCOMPARE(m.rowOf(QStringLiteral("iso23725:T1")), -1);

        // Link down: the custodian is not known then.
        DispatchTruck down = truck("T2");
        down.stateKnown = false;
        src.setTrucks({down});
        QCOMPARE(cell(m, 0, DispatchModel::ColCustodian), QStringLiteral("link down"));
    }

    void needsAssignmentCueAndAnswers() {
        FakeDispatchSource src;
        DispatchTruck t = truck("T1");
        t.needsAssignment = true;
        src.setTrucks({t, truck("T2")}, false);
        DispatchModel m;
        m.setSource(&src);
        QCOMPARE(m.needsAssignmentCount(), 1);
        QCOMPARE(cell(m, 0, DispatchModel::ColAssignment), QStringLiteral("NEEDS ASSIGNMENT"));
        QVERIFY(m.data(m.index(0, DispatchModel::ColEta), Qt::BackgroundRole).isValid());
        QVERIFY(!m.data(m.index(1, DispatchModel::ColEta), Qt::BackgroundRole).isValid());
        QVERIFY(m.data(m.index(0, 0), DispatchModel::NeedsAssignmentRole).toBool());

        // Our request is answered Rejected while the truck still reports its old Active assignment.
        t.needsAssignment = false;
        t.assignmentId = QStringLiteral("old");
        t.assignmentStatus = QStringLiteral("Active");
        t.task = QStringLiteral("Load");
        t.destinationId = 4201;
        t.requestedAssignmentId = QStringLiteral("new");
        t.requestedTask = QStringLiteral("Offload");
        t.requestedDestination = 4201;
        t.lastResponse = QStringLiteral("Rejected");
        t.lastResponseDetail = QStringLiteral("destination 4201 is not a dump area");
        src.setTrucks({t});
        QCOMPARE(m.needsAssignmentCount(), 0);
        QCOMPARE(cell(m, 0, DispatchModel::ColAssignment), QStringLiteral("Active · Rejected"));
        QVERIFY(m.data(m.index(0, DispatchModel::ColAssignment), Qt::ToolTipRole)
                    .toString()
                    .contains(QStringLiteral("not a dump area")));
        QCOMPARE(cell(m, 0, DispatchModel::ColDestination), QStringLiteral("way 4201"));
        QCOMPARE(cell(m, 0, DispatchModel::ColTask), QStringLiteral("Load"));
        // Accepted and now reported: the status alone.
        t.assignmentId = QStringLiteral("new");
        t.lastResponse = QStringLiteral("Accepted");
        t.destinationName = QStringLiteral("Pit 1 shovel 1");
        src.setTrucks({t});
        QCOMPARE(cell(m, 0, DispatchModel::ColAssignment), QStringLiteral("Active"));
        QCOMPARE(cell(m, 0, DispatchModel::ColDestination), QStringLiteral("Pit 1 shovel 1"));
    }

    void etaFromRouteAndSpeed() {
        FakeDispatchSource src;
        DispatchTruck t = truck("T1");
        t.assignmentId = QStringLiteral("a");
        t.assignmentStatus = QStringLiteral("Active");
        t.destinationId = 9;
        t.wayId = 1;
        src.routes.insert(t.id, DispatchRoute{QStringLiteral("ahs"), {1, 2, 9}, 600.0, {}, false});
        src.setTrucks({t}, false);
        FleetModel fleet;
        DispatchModel m;
        m.setFleet(&fleet);
        m.setSource(&src);
        // Stopped (no fleet row): nominal 25 km/h -> 600 m in 86.4 s, shown with "~".
        QCOMPARE(cell(m, 0, DispatchModel::ColEta), QStringLiteral("~1:26"));
        MachineState ms;
        ms.id = t.id;
        ms.protocol = Protocol::Iso23725;
        ms.speed = 10.0;
        fleet.upsert({ms});
        QCOMPARE(cell(m, 0, DispatchModel::ColEta), QStringLiteral("1:00")); // 600 m at 10 m/s
        QCOMPARE(m.data(m.index(0, 0), DispatchModel::EtaSecondsRole).toDouble(), 60.0);
        // The route is cached: asked once until the truck's way, destination or assignment changes.
        const int calls = src.routeCalls;
        cell(m, 0, DispatchModel::ColEta);
        QCOMPARE(src.routeCalls, calls);
        t.productionState = QStringLiteral("Hauling"); // no route input changed
        src.setTrucks({t});
        cell(m, 0, DispatchModel::ColEta);
        QCOMPARE(src.routeCalls, calls);
        t.wayId = 2;
        src.routes.insert(t.id, DispatchRoute{QStringLiteral("ahs"), {2, 9}, 300.0, {}, false});
        src.setTrucks({t});
        QCOMPARE(cell(m, 0, DispatchModel::ColEta), QStringLiteral("0:30"));
        QCOMPARE(src.routeCalls, calls + 1);
        // No route: no ETA, the reason in the tooltip.
        src.routes.remove(t.id);
        t.assignmentStatus = QStringLiteral("Completed");
        src.setTrucks({t});
        QCOMPARE(cell(m, 0, DispatchModel::ColEta), QStringLiteral("—"));
        QVERIFY(m.data(m.index(0, DispatchModel::ColEta), Qt::ToolTipRole)
                    .toString()
                    .contains(QStringLiteral("no active assignment")));
    }

    void timeInStateFromTheReport() {
        FakeDispatchSource src;
        DispatchTruck t = truck("T1");
        t.productionState = QStringLiteral("Loading");
        t.productionSinceMs = 1'000'000;
        src.setTrucks({t}, false);
        DispatchModel m;
        qint64 now = 1'000'000 + 125'000;
        m.setClock([&now] { return now; });
        m.setSource(&src);
        QCOMPARE(cell(m, 0, DispatchModel::ColInState), QStringLiteral("2:05"));
        QSignalSpy changed(&m, &QAbstractItemModel::dataChanged);
        now += 3'600'000;
        m.refreshTimes();
        QCOMPARE(changed.size(), 1);
        QCOMPARE(changed[0][0].toModelIndex().column(), int(DispatchModel::ColInState));
        QCOMPARE(cell(m, 0, DispatchModel::ColInState), QStringLiteral("1 h 02"));
    }

    void queuesPerShovelAndDump() {
        FakeDispatchSource src;
        src.setAreas({{QStringLiteral("ahs"), 10, QStringLiteral("Shovel A"), QStringLiteral("Load")},
                      {QStringLiteral("ahs"), 11, QStringLiteral("Shovel B"), QStringLiteral("Load")},
                      {QStringLiteral("ahs"), 20, QStringLiteral("Crusher"), QStringLiteral("Offload")},
                      {QStringLiteral("ahs"), 30, QStringLiteral("Park"), QStringLiteral("Park")}});
        auto at = [](const QString& n, qint64 way, const QString& state) {
            DispatchTruck t = truck(n);
            t.wayId = way;
            t.productionState = state;
            return t;
        };
        auto going = [](const QString& n, qint64 way, qint64 dest, const QString& status) {
            DispatchTruck t = truck(n);
            t.wayId = way;
            t.assignmentId = n;
            t.assignmentStatus = status;
            t.destinationId = dest;
            return t;
        };
        src.setTrucks(
            {at("T1", 10, QStringLiteral("Loading")), at("T2", 10, QStringLiteral("Queued")),
             going("T3", 5, 10, QStringLiteral("Active")), going("T4", 5, 11, QStringLiteral("Pending")),
             going("T5", 5, 20, QStringLiteral("Completed")), at("T6", 20, QStringLiteral("Dumping"))},
            false);
        DispatchModel m;
        m.setSource(&src);
        DispatchQueueModel q(&m);
        QCOMPARE(q.rowCount(), 3); // the park area is no queue
        const auto* a = q.queueOf(QStringLiteral("ahs"), 10);
        QVERIFY(a);
        QCOMPARE(a->atArea, QStringList({"T1", "T2"}));
        QCOMPARE(a->enRoute, QStringList({"T3"}));
        QCOMPARE(q.queueOf(QStringLiteral("ahs"), 11)->enRoute, QStringList({"T4"}));
        QCOMPARE(q.queueOf(QStringLiteral("ahs"), 20)->enRoute, QStringList()); // Completed: not coming
        QCOMPARE(q.queueOf(QStringLiteral("ahs"), 20)->atArea, QStringList({"T6"}));
        const int row = int(std::find_if(q.queues().begin(), q.queues().end(),
                                         [](const auto& x) { return x.area.wayId == 10; }) -
                            q.queues().begin());
        QCOMPARE(q.data(q.index(row, DispatchQueueModel::ColAtArea)).toInt(), 2);
        QCOMPARE(q.data(q.index(row, DispatchQueueModel::ColTrucks)).toString(),
                 QStringLiteral("at: T1, T2; coming: T3"));
        // T3 arrives: it moves from coming to at.
        DispatchTruck t3 = going("T3", 10, 10, QStringLiteral("Active"));
        src.setTrucks({t3});
        QCOMPARE(q.queueOf(QStringLiteral("ahs"), 10)->atArea, QStringList({"T1", "T2", "T3"}));
        QVERIFY(q.queueOf(QStringLiteral("ahs"), 10)->enRoute.isEmpty());
    }
};

QTEST_MAIN(TestDispatchModel)
#include "test_dispatch_model.moc"
