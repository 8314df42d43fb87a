// The dispatch table model. Rows in id order from the source, incremental updates (dataChanged
// only over the cells that changed, inserts and removals), the "needs assignment" cue, the assignment column
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
        auto clock = std::make_shared<ManualModelClock>(1'000'000 + 125'000);
        m.setClock(clock);
        m.setSource(&src);
        QCOMPARE(cell(m, 0, DispatchModel::ColInState), QStringLiteral("2:05"));
        QSignalSpy changed(&m, &QAbstractItemModel::dataChanged);
        clock->advance(3'600'000);
        m.refreshTimes();
        // Two columns depend on the clock or the reported speed: in state and ETA, each over all rows.
        QCOMPARE(changed.size(), 2);
        QCOMPARE(changed[0][0].toModelIndex().column(), int(DispatchModel::ColInState));
        QCOMPARE(changed[0][1].toModelIndex().column(), int(DispatchModel::ColInState));
        QCOMPARE(changed[1][0].toModelIndex().column(), int(DispatchModel::ColEta));
        QCOMPARE(changed[1][1].toModelIndex().column(), int(DispatchModel::ColEta));
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
        QSignalSpy queueChanged(&q, &QAbstractItemModel::dataChanged);
        src.setTrucks({t3});
        QCOMPARE(q.queueOf(QStringLiteral("ahs"), 10)->atArea, QStringList({"T1", "T2", "T3"}));
        QVERIFY(q.queueOf(QStringLiteral("ahs"), 10)->enRoute.isEmpty());
        // Only that queue's row changed.
        QCOMPARE(queueChanged.size(), 1);
        QCOMPARE(queueChanged[0][0].toModelIndex().row(), row);
        QCOMPARE(queueChanged[0][1].toModelIndex().row(), row);
        // A report that moves no truck between queues repaints no queue.
        DispatchTruck t6 = at("T6", 20, QStringLiteral("Dumping"));
        t6.payloadTonnes = 0;
        src.setTrucks({t6});
        QCOMPARE(queueChanged.size(), 1);

        // A long queue shows a handful of names and the count of the others; the tooltip has them all.
        QVector<DispatchTruck> many;
        for (int i = 0; i < 20; ++i)
            many << at(QStringLiteral("Q%1").arg(i, 2, 10, QLatin1Char('0')), 11, QStringLiteral("Queued"));
        src.setTrucks(many);
        const int rowB = int(std::find_if(q.queues().begin(), q.queues().end(),
                                          [](const auto& x) { return x.area.wayId == 11; }) -
                             q.queues().begin());
        const QString shown = q.data(q.index(rowB, DispatchQueueModel::ColTrucks)).toString();
        QVERIFY2(
            shown.startsWith(QStringLiteral("at: Q00, Q01, Q02, Q03, Q04, Q05, Q06, Q07 +12; coming: T4")),
            qPrintable(shown));
        QVERIFY(q.data(q.index(rowB, DispatchQueueModel::ColTrucks), Qt::ToolTipRole)
                    .toString()
                    .contains(QStringLiteral("Q19")));
    }

    // Rows are in truck-name order however they come: loaded at once (setSource) or one by one; the ids
    // (GUIDs on a real link) do not decide.
    void rowsInNameOrderOnLoadAndInsert() {
        FakeDispatchSource src;
        DispatchTruck b = truck("HT102"), a = truck("HT101"), c = truck("HT103");
        b.id = QStringLiteral("iso23725:0001"); // the smallest id has the middle name
        a.id = QStringLiteral("iso23725:0009");
        c.id = QStringLiteral("iso23725:0005");
        src.setTrucks({b, a}, false);
        DispatchModel m;
        m.setSource(&src);
        QCOMPARE(cell(m, 0, DispatchModel::ColTruck), QStringLiteral("HT101"));
        QCOMPARE(cell(m, 1, DispatchModel::ColTruck), QStringLiteral("HT102"));
        src.setTrucks({c});
        QCOMPARE(cell(m, 2, DispatchModel::ColTruck), QStringLiteral("HT103"));
        QCOMPARE(m.rowOf(QStringLiteral("iso23725:0001")), 1);
    }

    // dataChanged covers only the cells whose text changed (a view repaints those and nothing for rows out
    // of sight); consecutive rows with the same change are one signal; the "needs assignment" cue colours the
    // whole row; a report that changes nothing visible emits nothing.
    void dataChangedOnlyForChangedCells() {
        FakeDispatchSource src;
        QVector<DispatchTruck> all;
        for (int i = 0; i < 6; ++i) {
            DispatchTruck t = truck(QStringLiteral("T%1").arg(i));
            t.productionState = QStringLiteral("Hauling");
            t.payloadTonnes = 200;
            all << t;
        }
        src.setTrucks(all, false);
        DispatchModel m;
        m.setSource(&src);
        QSignalSpy changed(&m, &QAbstractItemModel::dataChanged);
        auto span = [&](int i) {
            return QStringLiteral("%1,%2-%3,%4")
                .arg(changed[i][0].toModelIndex().row())
                .arg(changed[i][0].toModelIndex().column())
                .arg(changed[i][1].toModelIndex().row())
                .arg(changed[i][1].toModelIndex().column());
        };

        // The same report again: nothing to repaint.
        src.setTrucks({all[2]});
        QCOMPARE(changed.size(), 0);
        // The payload of one truck rounds to the same text: nothing either.
        all[2].payloadTonnes = 200.2;
        src.setTrucks({all[2]});
        QCOMPARE(changed.size(), 0);

        // Production state of T1 and T2 (consecutive rows): one signal over the production column.
        all[1].productionState = QStringLiteral("Dumping");
        all[2].productionState = QStringLiteral("Dumping");
        src.setTrucks({all[2], all[1]});
        QCOMPARE(changed.size(), 1);
        QCOMPARE(span(0), QStringLiteral("1,%1-2,%1").arg(int(DispatchModel::ColProduction)));
        changed.clear();

        // T0 production + payload (adjacent columns), T4 payload only: two signals, each its own cells.
        all[0].productionState = QStringLiteral("Loading");
        all[0].payloadTonnes = 50;
        all[4].payloadTonnes = 230;
        src.setTrucks({all[0], all[4]});
        QCOMPARE(changed.size(), 2);
        QCOMPARE(span(0), QStringLiteral("0,%1-0,%2")
                              .arg(int(DispatchModel::ColProduction))
                              .arg(int(DispatchModel::ColPayload)));
        QCOMPARE(span(1), QStringLiteral("4,%1-4,%1").arg(int(DispatchModel::ColPayload)));
        changed.clear();

        // T3 asks for work: the whole row (its colour) changes.
        all[3].needsAssignment = true;
        src.setTrucks({all[3]});
        QCOMPARE(changed.size(), 1);
        QCOMPARE(span(0), QStringLiteral("3,0-3,%1").arg(int(DispatchModel::ColumnCount) - 1));
        QCOMPARE(cell(m, 3, DispatchModel::ColAssignment), QStringLiteral("NEEDS ASSIGNMENT"));
        changed.clear();

        // A new way: the ETA (route) changes, and only it.
        all[5].wayId = 7;
        src.setTrucks({all[5]});
        QCOMPARE(changed.size(), 1);
        QCOMPARE(span(0), QStringLiteral("5,%1-5,%1").arg(int(DispatchModel::ColEta)));
    }
};

QTEST_MAIN(TestDispatchModel)
#include "test_dispatch_model.moc"
