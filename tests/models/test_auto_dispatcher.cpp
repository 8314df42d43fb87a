// The automatic dispatcher on a hand-made dispatch source, through a real
// CommandGate to a fake bridge. Who is idle (custodian FMS, link up, no Pending/Active task or asking for
// work), where it goes (empty: the shovel with the shortest queue; loaded: the dump with the shortest queue;
// ties by route length; unreachable areas skipped), every assignment through the gate (audited, origin
// "auto-dispatch"), one request per truck until it is answered, a Rejected area avoided, a refused send said
// so, nothing while off, and its events.
#include "models/AlarmModel.h"
#include "models/AutoDispatcher.h"
#include "models/CommandGate.h"
#include "models/testing/FakeDispatchSource.h"
#include "models/testing/FakeFleetBridge.h"

#include <QJsonArray>
#include <QSignalSpy>
#include <QtTest>

using namespace ocu;

namespace {

const QString kLink = QStringLiteral("ahs");

DispatchTruck truck(const QString& n) {
    DispatchTruck t;
    t.id = QStringLiteral("iso23725:") + n;
    t.link = kLink;
    t.name = n;
    t.stateKnown = true;
    t.custodian = QStringLiteral("FMS");
    t.autonomyMode = QStringLiteral("Autonomous");
    t.wayId = 1;
    t.loaded = false;
    return t;
}
DispatchTruck busy(const QString& n, qint64 dest, qint64 way = 1) {
    DispatchTruck t = truck(n);
    t.assignmentId = n + QStringLiteral("-a");
    t.assignmentStatus = QStringLiteral("Active");
    t.task = QStringLiteral("Load");
    t.destinationId = dest;
    t.wayId = way;
    return t;
}

struct Rig {
    Rig() {
        gate.addBridge(&bridge);
        src.setAreas({{kLink, 10, QStringLiteral("Shovel A"), QStringLiteral("Load")},
                      {kLink, 11, QStringLiteral("Shovel B"), QStringLiteral("Load")},
                      {kLink, 20, QStringLiteral("Crusher"), QStringLiteral("Offload")},
                      {kLink, 21, QStringLiteral("Dump North"), QStringLiteral("Offload")},
                      {kLink, 30, QStringLiteral("Park"), QStringLiteral("Park")}});
        auto_.setAlarms(&alarms);
        auto_.setClock(clock);
    }
    // The assign calls that reached the bridge: "truck name -> way".
    QStringList assigned() const {
        QStringList out;
        for (const auto& c : bridge.calls())
            if (c.name == QLatin1String("assign")) {
                const QJsonObject task = c.args.value(QStringLiteral("tasks")).toArray().at(0).toObject();
                out << QStringLiteral("%1 %2 %3")
                           .arg(c.id.section(QLatin1Char(':'), 1))
                           .arg(task.value(QStringLiteral("task")).toString())
                           .arg(qint64(task.value(QStringLiteral("destination")).toDouble()));
            }
        return out;
    }
    QString lastAssignmentId() const {
        QString id;
        for (const auto& c : bridge.calls())
            if (c.name == QLatin1String("assign"))
                id = c.args.value(QStringLiteral("tasks"))
                         .toArray()
                         .at(0)
                         .toObject()
                         .value(QStringLiteral("assignment_id"))
                         .toString();
        return id;
    }
    AlarmModel alarms;
    CommandGate gate{&alarms};
    FakeFleetBridge bridge{Protocol::Iso23725};
    FakeDispatchSource src;
    std::shared_ptr<ManualModelClock> clock = std::make_shared<ManualModelClock>(1'000'000);
    AutoDispatcher auto_{&src, &gate};
};

} // namespace

class TestAutoDispatcher : public QObject {
    Q_OBJECT
private slots:
    void shortestQueueForIdleFmsTrucks() {
        Rig r;
        DispatchTruck queued = truck("Q1");
        queued.wayId = 10; // at shovel A
        DispatchTruck loadedIdle = truck("L1");
        loadedIdle.loaded = true;
        DispatchTruck atCrusher = truck("C1");
        atCrusher.wayId = 20;
        atCrusher.loaded = true;
        DispatchTruck ahs = truck("X1");
        ahs.custodian = QStringLiteral("AHS");
        DispatchTruck down = truck("X2");
        down.stateKnown = false;
        DispatchTruck refused = truck("X3");
        r.src.refusals.insert(refused.id, QStringLiteral("link ahs is down"));
        DispatchTruck asking = busy("N1", 11);
        asking.needsAssignment = true;
        // Queues before: shovel A 2 (Q1 at it, B1 coming), shovel B 1 (B2 coming), crusher 1 (C1 at it),
        // dump north 0. N1 also counts for B while its old assignment is Active.
        r.src.setTrucks({queued, busy("B1", 10), busy("B2", 11), loadedIdle, atCrusher, ahs, down, refused,
                         asking, truck("E1"), truck("E2")},
                        false);
        // E1 and E2 tie on the shovels at some point: E2's route to shovel A is shorter.
        r.src.previews.insert(QStringLiteral("iso23725:E2/10"),
                              DispatchRoute{kLink, {1, 10}, 100, {}, false});
        r.src.previews.insert(QStringLiteral("iso23725:E2/11"),
                              DispatchRoute{kLink, {1, 5, 11}, 900, {}, false});

        QStringList plan;
        for (const auto& d : r.auto_.plan())
            plan << QStringLiteral("%1 %2 %3 q%4").arg(d.truckName, d.task).arg(d.area.wayId).arg(d.queue);
        // In name order: C1 is at the crusher but has no task: it is idle and loaded -> the empty dump.
        // E1: A 2, B 2 (B2 + N1) -> tie, no routes known -> by name: Shovel A. E2: A 3, B 2 -> B.
        // L1: crusher 1 (C1 counted at it), dump north 1 (C1 sent there) -> tie -> name: Crusher.
        // N1 asks for work (its Active task does not hold it) -> B 3 vs A 3 -> name: A.
        // Q1 sits at shovel A without a task: idle too -> B (3) vs A (4).
        QCOMPARE(plan, QStringList({"C1 Offload 21 q0", "E1 Load 10 q2", "E2 Load 11 q2", "L1 Offload 20 q1",
                                    "N1 Load 10 q3", "Q1 Load 11 q3"}));
        QVERIFY(r.bridge.calls().isEmpty()); // planning sends nothing; off sends nothing
        r.auto_.step();
        QVERIFY(r.bridge.calls().isEmpty());

        QSignalSpy acted(&r.auto_, &AutoDispatcher::acted);
        r.auto_.setOn(true, QStringLiteral("test"));
        QVERIFY(r.auto_.isOn());
        QTRY_COMPARE(r.assigned().size(), 6);
        QCOMPARE(r.assigned(), QStringList({"C1 Offload 21", "E1 Load 10", "E2 Load 11", "L1 Offload 20",
                                            "N1 Load 10", "Q1 Load 11"}));
        // Every one through the gate: audited with the origin, and said as a line and an event.
        QTRY_COMPARE(r.auto_.assignmentsSent(), 6);
        QVERIFY(acted.size() >= 7);
        QCOMPARE(acted[0][0].toString(), QStringLiteral("Auto dispatch ON (test): idle FMS trucks go to the "
                                                        "shortest queue"));
        bool audited = false, event = false;
        for (int i = 0; i < r.alarms.rowCount(); ++i) {
            const FleetEvent& e = r.alarms.eventAt(i);
            audited = audited || (e.kind == EventKind::Audit && e.source == QLatin1String("auto-dispatch"));
            event = event || e.text.contains(QStringLiteral("E2: Load at Shovel B (queue 2) — sent"));
        }
        QVERIFY(audited);
        QVERIFY(event);
        QVERIFY(r.auto_.lastAction().contains(QStringLiteral("sent")));

        // One request per truck until it is answered: another step sends nothing new.
        r.auto_.step();
        QCOMPARE(r.assigned().size(), 6);
    }

    void answersRejectionsAndOff() {
        Rig r;
        r.src.setTrucks({truck("E1")}, false);
        r.auto_.setOn(true);
        QTRY_COMPARE(r.assigned(), QStringList({"E1 Load 10"}));
        const QString first = r.lastAssignmentId();
        QVERIFY(!first.isEmpty());

        // The truck rejects it: shovel A is avoided for it, shovel B is tried.
        DispatchTruck e1 = truck("E1");
        e1.requestedAssignmentId = first;
        e1.requestedTask = QStringLiteral("Load");
        e1.requestedDestination = 10;
        e1.lastResponse = QStringLiteral("Rejected");
        e1.lastResponseDetail = QStringLiteral("area closed");
        r.src.setTrucks({e1});
        QTRY_COMPARE(r.assigned(), QStringList({"E1 Load 10", "E1 Load 11"}));
        QVERIFY(r.auto_.lastAction().contains(QStringLiteral("sent")));
        bool rejectedEvent = false;
        for (int i = 0; i < r.alarms.rowCount(); ++i)
            rejectedEvent = rejectedEvent || r.alarms.eventAt(i).text.contains(
                                                 QStringLiteral("E1 rejected way 10: area closed"));
        QVERIFY(rejectedEvent);

        // Accepted and reported Active: not idle any more, nothing new.
        const QString second = r.lastAssignmentId();
        DispatchTruck going = busy("E1", 11);
        going.assignmentId = second;
        going.requestedAssignmentId = second;
        going.lastResponse = QStringLiteral("Accepted");
        r.src.setTrucks({going});
        r.clock->advance(60'000);
        r.auto_.step();
        QCOMPARE(r.assigned().size(), 2);

        // Completed and loaded: to a dump.
        DispatchTruck done = going;
        done.assignmentStatus = QStringLiteral("Completed");
        done.loaded = true;
        r.src.setTrucks({done});
        QTRY_COMPARE(r.assigned().size(), 3);
        QCOMPARE(r.assigned().last(), QStringLiteral("E1 Offload 20"));

        // No answer at all: after the answer timeout the truck is free again, that dump avoided.
        r.clock->advance(AutoDispatcher::kAnswerTimeoutMs + 1);
        r.auto_.step();
        QCOMPARE(r.assigned().size(), 4);
        QCOMPARE(r.assigned().last(), QStringLiteral("E1 Offload 21"));

        // Off: it stops at once; an idle truck now gets nothing.
        QSignalSpy state(&r.auto_, &AutoDispatcher::stateChanged);
        r.auto_.setOn(false, QStringLiteral("test"));
        QCOMPARE(state.size(), 1);
        QCOMPARE(state[0][0].toBool(), false);
        r.src.setTrucks({truck("E2")});
        r.clock->advance(120'000);
        QTest::qWait(50);
        r.auto_.step();
        QCOMPARE(r.assigned().size(), 4);
        QVERIFY(r.auto_.lastAction().contains(QStringLiteral("Auto dispatch OFF (test)")));
    }

    void unreachableAndRefusedSends() {
        Rig r;
        // Shovel A cannot be reached from where E1 is: B is chosen although A's queue is shorter.
        r.src.previews.insert(
            QStringLiteral("iso23725:E1/10"),
            DispatchRoute{kLink, {}, 0, QStringLiteral("no route from way 1 to way 10"), false});
        r.src.setTrucks({truck("E1"), busy("B1", 11)}, false);
        const auto plan = r.auto_.plan();
        QCOMPARE(plan.size(), 1);
        QCOMPARE(plan[0].area.wayId, qint64(11));
        QCOMPARE(plan[0].queue, 1);

        // The bridge refuses the command (nothing on the wire): said so, the truck is not held as waiting.
        r.bridge.refusedCommands << QStringLiteral("assign");
        QSignalSpy acted(&r.auto_, &AutoDispatcher::acted);
        r.auto_.setOn(true);
        QTRY_VERIFY(r.auto_.lastAction().contains(QStringLiteral("NOT sent")));
        QVERIFY(r.auto_.lastAction().contains(QStringLiteral("insufficient authority")));
        QCOMPARE(r.auto_.assignmentsSent(), 0);
        QCOMPARE(r.assigned().size(), 1); // it reached the bridge, which refused it
        // Not again at once (a refused command is an alarm: never one per step), but after kRetryMs.
        r.bridge.refusedCommands.clear();
        r.auto_.step();
        QCOMPARE(r.assigned().size(), 1);
        r.clock->advance(AutoDispatcher::kRetryMs + 1);
        r.auto_.step();
        QTRY_COMPARE(r.auto_.assignmentsSent(), 1);
        QCOMPARE(r.assigned().size(), 2);
    }
};

QTEST_MAIN(TestAutoDispatcher)
#include "test_auto_dispatcher.moc"
