// Dispatch end to end over loopback: the console (IsoBridge behind the CommandGate, driven by the
// headless monitor's JSON commands) against the simulated AHS. A load task is sent (the result names the
// truck as a target sent), Accepted and Active as the AHS reports; a task the AHS cannot do comes back
// Rejected with its detail; a truck dispatched by the AHS cannot be assigned (refused before sending, with
// the reason) and asks for work when handed back; an accepted task the AHS gives up shows the unsolicited
// Rejected; with the link down assignments are refused, never queued.
#include "app/HeadlessMonitor.h"
#include "app/modules/IsoHeadless.h"
#include "models/AlarmModel.h"
#include "models/CommandGate.h"
#include "models/bridges/IsoBridge.h"
#include "sim/iso23725/SimulatedAhs.h"
#include "tests/support/IsoSimConsole.h"

#include <QBuffer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

using namespace ocu;

namespace {

constexpr int kWait = 30000;

sim::SimulatedAhsConfig ahsConfig() {
    return isosim::ahsConfig(3, 2);
}

iso23725::IsoConfig consoleConfig(const std::string& url) {
    return isosim::consoleConfig(url);
}

struct Console {
    explicit Console(const std::string& url) : bridge(consoleConfig(url), GeoFrame(ahsConfig().origin)) {
        gate.addBridge(&bridge);
        alarms.addBridge(&bridge);
        out.open(QIODevice::ReadWrite);
        monitor.setOutput(&out);
        registerIsoHeadless(monitor.commands(),
                            {&bridge, nullptr, nullptr, nullptr}); // as the ISO module does
    }
    AlarmModel alarms;
    CommandGate gate{&alarms};
    IsoBridge bridge;
    HeadlessMonitor monitor{nullptr, &alarms, &gate};
    QBuffer out;

    // Sends one command line and waits for its result line.
    QJsonObject run(const QJsonObject& cmd) {
        QSignalSpy spy(&monitor, &HeadlessMonitor::commandHandled);
        monitor.handleLine(QJsonDocument(cmd).toJson(QJsonDocument::Compact));
        if (spy.isEmpty() && !spy.wait(kWait))
            return {};
        return QJsonDocument::fromJson(spy.first().first().toByteArray()).object();
    }
    std::optional<IsoDispatchState> truck(const std::string& guid) const {
        return bridge.dispatchState(QStringLiteral("iso23725:") + QString::fromStdString(guid));
    }
};

QJsonObject assignCmd(const QString& id, const QString& task, qint64 destination) {
    return QJsonObject{{QStringLiteral("cmd"), QStringLiteral("assign")},
                       {QStringLiteral("id"), id},
                       {QStringLiteral("task"), task},
                       {QStringLiteral("destination"), double(destination)}};
}

QJsonObject onlyTarget(const QJsonObject& result) {
    const QJsonArray t = result.value(QStringLiteral("targets")).toArray();
    return t.size() == 1 ? t.first().toObject() : QJsonObject{};
}

} // namespace

class TestIsoDispatch : public QObject {
    Q_OBJECT
private slots:
    void assignOverTheWire() {
        sim::SimulatedAhs ahs(ahsConfig());
        QVERIFY(ahs.start());
        const auto view = ahs.dispatchView();
        QCOMPARE(view.trucks.size(), std::size_t(3));
        Console c(ahs.url());
        QVERIFY(c.bridge.start().isEmpty());
        const std::string t0 = view.trucks[0].id, t1 = view.trucks[1].id;
        const QString id0 = QStringLiteral("iso23725:") + QString::fromStdString(t0);
        const QString id1 = QStringLiteral("iso23725:") + QString::fromStdString(t1);
        QTRY_VERIFY_WITH_TIMEOUT(c.truck(t0) && c.truck(t0)->custodian == QLatin1String("FMS") &&
                                     c.truck(t1) && c.truck(t1)->custodian == QLatin1String("FMS") &&
                                     !c.truck(t0)->productionState.isEmpty(),
                                 kWait);
        // The areas of the AHS's MapConnectivityV1 are the destinations to pick from.
        QTRY_VERIFY_WITH_TIMEOUT(!c.bridge.destinations().isEmpty(), kWait);
        const qint64 shovel = view.loadAreas[0];
        QString shovelName;
        for (const auto& d : c.bridge.destinations())
            if (d.wayId == shovel) {
                QCOMPARE(d.defaultTask, QStringLiteral("Load"));
                shovelName = d.name;
            }
        QVERIFY(!shovelName.isEmpty());
        QVERIFY(c.bridge.assignRefusal(id0).isEmpty());

        // A load task: sent (the truck is the target), Accepted, then Active as the AHS reports it.
        const QJsonObject r = c.run(assignCmd(id0, QStringLiteral("Load"), shovel));
        QVERIFY2(r.value(QStringLiteral("ok")).toBool(), QJsonDocument(r).toJson().constData());
        QCOMPARE(onlyTarget(r).value(QStringLiteral("id")).toString(), id0);
        QVERIFY(onlyTarget(r).value(QStringLiteral("sent")).toBool());
        const QString assignmentId = r.value(QStringLiteral("tasks"))
                                         .toArray()
                                         .first()
                                         .toObject()
                                         .value(QStringLiteral("assignment_id"))
                                         .toString();
        QVERIFY(!assignmentId.isEmpty());
        QTRY_VERIFY_WITH_TIMEOUT(c.truck(t0)->response(assignmentId) &&
                                     c.truck(t0)->response(assignmentId)->response ==
                                         QLatin1String("Accepted"),
                                 kWait);
        QTRY_COMPARE_WITH_TIMEOUT(c.truck(t0)->assignmentStatus, QStringLiteral("Active"), kWait);
        QCOMPARE(c.truck(t0)->assignmentId, assignmentId);
        QCOMPARE(c.truck(t0)->task, QStringLiteral("Load"));
        QCOMPARE(*c.truck(t0)->destinationId, shovel);
        QCOMPARE(c.truck(t0)->destinationName, shovelName);
        QCOMPARE(c.truck(t0)->requested.size(), 1);
        QVERIFY(c.truck(t0)->requested[0].route.has_value()); // routed over MapConnectivityV1 by the console

        // A task the AHS cannot do (offload at a shovel): sent, and Rejected with the AHS's detail.
        const QJsonObject bad = c.run(assignCmd(id1, QStringLiteral("Offload"), shovel));
        QVERIFY(bad.value(QStringLiteral("ok")).toBool());
        const QString badId = bad.value(QStringLiteral("tasks"))
                                  .toArray()
                                  .first()
                                  .toObject()
                                  .value(QStringLiteral("assignment_id"))
                                  .toString();
        QTRY_VERIFY_WITH_TIMEOUT(c.truck(t1)->response(badId), kWait);
        QCOMPARE(c.truck(t1)->response(badId)->response, QStringLiteral("Rejected"));
        QCOMPARE(c.truck(t1)->response(badId)->detail,
                 QStringLiteral("destination %1 is not a dump area").arg(shovel));

        // The headless production view lists what the trucks reported.
        const QJsonObject prod = c.run({{QStringLiteral("cmd"), QStringLiteral("production")}});
        QVERIFY(prod.value(QStringLiteral("ok")).toBool());
        QCOMPARE(prod.value(QStringLiteral("trucks")).toArray().size(), 3);
        bool sawRejection = false;
        for (const auto& v : prod.value(QStringLiteral("trucks")).toArray()) {
            const QJsonObject t = v.toObject();
            QVERIFY(!t.value(QStringLiteral("production_state")).toString().isEmpty());
            for (const auto& x : t.value(QStringLiteral("responses")).toArray())
                sawRejection = sawRejection || x.toObject()
                                                   .value(QStringLiteral("detail"))
                                                   .toString()
                                                   .contains(QStringLiteral("not a dump area"));
            if (t.value(QStringLiteral("id")).toString() == id0)
                QCOMPARE(t.value(QStringLiteral("assignment"))
                             .toObject()
                             .value(QStringLiteral("status"))
                             .toString(),
                         QStringLiteral("Active"));
        }
        QVERIFY(sawRejection);

        // The AHS gives the accepted task up (its road closed): the unsolicited Rejected replaces the
        // Accepted.
        ahs.setWayClosed(view.loadAreas[0], true);
        QTRY_VERIFY_WITH_TIMEOUT(c.truck(t0)->response(assignmentId)->response == QLatin1String("Rejected"),
                                 kWait);
        QVERIFY(
            c.truck(t0)->response(assignmentId)->detail.contains(QStringLiteral("can no longer be done")));
        QTRY_COMPARE_WITH_TIMEOUT(c.truck(t0)->assignmentStatus, QStringLiteral("Cancelled"), kWait);
        // ...and the console now refuses that destination itself, before sending (unreachable), once the
        // re-sent MapConnectivityV1 is in.
        const auto requestsBefore = ahs.counters().get("sim.assign.requests");
        QJsonObject unreachable;
        QTRY_VERIFY_WITH_TIMEOUT((unreachable = c.run(assignCmd(id1, QStringLiteral("Load"), shovel)),
                                  !unreachable.value(QStringLiteral("ok")).toBool()),
                                 kWait);
        QVERIFY2(onlyTarget(unreachable)
                     .value(QStringLiteral("reason"))
                     .toString()
                     .contains(QStringLiteral("unreachable")),
                 QJsonDocument(unreachable).toJson().constData());
        ahs.setWayClosed(view.loadAreas[0], false);

        // Custodian AHS: assignment disabled and refused with the reason; nothing reaches the AHS.
        ahs.setTruckCustodian(1, "AHS");
        QTRY_COMPARE_WITH_TIMEOUT(c.truck(t1)->custodian, QStringLiteral("AHS"), kWait);
        QVERIFY(c.bridge.assignRefusal(id1).contains(QStringLiteral("dispatched by the AHS")));
        const QJsonObject refused = c.run(assignCmd(id1, QStringLiteral("Load"), shovel));
        QVERIFY(!refused.value(QStringLiteral("ok")).toBool());
        QVERIFY(!onlyTarget(refused).value(QStringLiteral("sent")).toBool());
        QVERIFY2(onlyTarget(refused)
                     .value(QStringLiteral("reason"))
                     .toString()
                     .contains(QStringLiteral("is dispatched by the AHS (DispatchingCustodian AHS)")),
                 QJsonDocument(refused).toJson().constData());
        // Handed back: the truck asks for work.
        ahs.setTruckCustodian(1, "FMS");
        QTRY_VERIFY_WITH_TIMEOUT(c.truck(t1)->needsAssignment, kWait);
        QVERIFY(c.bridge.assignRefusal(id1).isEmpty());
        const QJsonObject again = c.run(assignCmd(id1, QStringLiteral("Load"), shovel));
        QVERIFY(again.value(QStringLiteral("ok")).toBool());
        QTRY_VERIFY_WITH_TIMEOUT(!c.truck(t1)->needsAssignment, kWait);
        QTRY_VERIFY_WITH_TIMEOUT(ahs.counters().get("sim.assign.requests") == requestsBefore + 1, kWait);

        // Reset: sent, and the AHS reports the assignment Cancelled.
        const QJsonObject reset =
            c.run({{QStringLiteral("cmd"), QStringLiteral("reset_assignment")}, {QStringLiteral("id"), id1}});
        QVERIFY(reset.value(QStringLiteral("ok")).toBool());
        QCOMPARE(onlyTarget(reset).value(QStringLiteral("id")).toString(), id1);
        QTRY_COMPARE_WITH_TIMEOUT(c.truck(t1)->assignmentStatus, QStringLiteral("Cancelled"), kWait);

        // Link down: refused with the reason, never queued (the AHS restarted on the same port gets nothing).
        const auto port = ahs.port();
        ahs.stop();
        QTRY_VERIFY_WITH_TIMEOUT(
            c.bridge.linkStatus(QStringLiteral("iso23725:ahs"))->state == LinkState::Down, kWait);
        QVERIFY(!c.bridge.assignRefusal(id0).isEmpty());
        const QJsonObject down = c.run(assignCmd(id0, QStringLiteral("Load"), shovel));
        QVERIFY(!down.value(QStringLiteral("ok")).toBool());
        QVERIFY2(
            onlyTarget(down).value(QStringLiteral("reason")).toString().contains(QStringLiteral("is down")),
            QJsonDocument(down).toJson().constData());
        const QJsonObject downReset =
            c.run({{QStringLiteral("cmd"), QStringLiteral("reset_assignment")}, {QStringLiteral("id"), id0}});
        QVERIFY(!downReset.value(QStringLiteral("ok")).toBool());
        auto cfg = ahsConfig();
        cfg.port = port;
        sim::SimulatedAhs second(cfg);
        QVERIFY(second.start());
        QTRY_VERIFY_WITH_TIMEOUT(c.bridge.linkStatus(QStringLiteral("iso23725:ahs"))->state == LinkState::Up,
                                 kWait);
        QTest::qWait(500);
        QCOMPARE(second.counters().get("sim.assign.requests"), std::uint64_t(0));
        c.bridge.stop();
        second.stop();
    }

    // Malformed assign arguments never reach the wire: refused by the bridge with what is wrong.
    void malformedAssignRefused() {
        sim::SimulatedAhs ahs(ahsConfig());
        QVERIFY(ahs.start());
        const auto view = ahs.dispatchView();
        Console c(ahs.url());
        QVERIFY(c.bridge.start().isEmpty());
        const QString id0 = QStringLiteral("iso23725:") + QString::fromStdString(view.trucks[0].id);
        QTRY_VERIFY_WITH_TIMEOUT(c.truck(view.trucks[0].id).has_value(), kWait);
        const QJsonObject noDest = c.run({{QStringLiteral("cmd"), QStringLiteral("assign")},
                                          {QStringLiteral("id"), id0},
                                          {QStringLiteral("task"), QStringLiteral("Load")},
                                          {QStringLiteral("destination"), QStringLiteral("north")}});
        QVERIFY(!noDest.value(QStringLiteral("ok")).toBool());
        QVERIFY(onlyTarget(noDest)
                    .value(QStringLiteral("reason"))
                    .toString()
                    .contains(QStringLiteral("\"destination\" must be a way id")));
        const QJsonObject badTask = c.run(assignCmd(id0, QStringLiteral("Dig"), view.loadAreas[0]));
        QVERIFY(!badTask.value(QStringLiteral("ok")).toBool());
        QVERIFY(onlyTarget(badTask)
                    .value(QStringLiteral("reason"))
                    .toString()
                    .contains(QStringLiteral("not one of Load")));
        const QJsonObject noId = c.run({{QStringLiteral("cmd"), QStringLiteral("assign")}});
        QVERIFY(!noId.value(QStringLiteral("ok")).toBool());
        QCOMPARE(noId.value(QStringLiteral("message")).toString(), QStringLiteral("missing \"id\""));
        QTest::qWait(300);
        QCOMPARE(ahs.counters().get("sim.assign.requests"), std::uint64_t(0));
        c.bridge.stop();
        ahs.stop();
    }
};

QTEST_MAIN(TestIsoDispatch)
#include "test_iso_dispatch.moc"
