// The automatic dispatcher end to end over loopback against the simulated AHS: the automatic dispatcher
// switched on by the headless command {"cmd":"auto_dispatch","on":true} assigns the idle FMS trucks through
// the CommandGate (audited, origin "auto-dispatch"); a truck it sent to a shovel reports the assignment
// Active and completes a load-haul-dump cycle counted by the production model; a truck the AHS dispatches
// (custodian AHS) is never assigned; switched off, no request leaves the console any more.
#include "app/HeadlessMonitor.h"
#include "app/modules/IsoHeadless.h"
#include "app/modules/IsoProduction.h"
#include "models/AlarmModel.h"
#include "models/AutoDispatcher.h"
#include "models/CommandGate.h"
#include "models/ProductionModel.h"
#include "models/bridges/IsoBridge.h"
#include "models/bridges/IsoDispatchSource.h"
#include "sim/iso23725/SimulatedAhs.h"
#include "tests/support/IsoSimConsole.h"

#include <QBuffer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

using namespace ocu;

namespace {

constexpr int kWait = 60000;

sim::SimulatedAhsConfig ahsConfig() {
    return isosim::ahsConfig(3, 10, 60);
}

iso23725::IsoConfig consoleConfig(const std::string& url) {
    return isosim::consoleConfig(url, std::chrono::milliseconds(5000), 1600);
}

} // namespace

class TestAutoDispatchE2e : public QObject {
    Q_OBJECT
private slots:
    void autoDispatchAssignsAndCompletesACycle() {
        sim::SimulatedAhs ahs(ahsConfig());
        QVERIFY(ahs.start());
        const auto view = ahs.dispatchView();
        AlarmModel alarms;
        CommandGate gate{&alarms};
        IsoBridge bridge(consoleConfig(ahs.url()), GeoFrame(ahsConfig().origin));
        ProductionModel* production = attachProductionModel(&bridge);
        gate.addBridge(&bridge);
        alarms.addBridge(&bridge);
        // As the ISO module owns them: the dispatch source and the dispatcher are children of the bridge.
        auto* source = new IsoDispatchSource(&bridge, &bridge);
        auto* dispatcher = new AutoDispatcher(source, &gate, &bridge);
        dispatcher->setAlarms(&alarms);
        QBuffer out;
        out.open(QIODevice::ReadWrite);
        HeadlessMonitor monitor{nullptr, &alarms, &gate};
        monitor.setOutput(&out);
        registerIsoHeadless(monitor.commands(),
                            {&bridge, production, dispatcher, nullptr}); // as the ISO module does
        auto run = [&](const QJsonObject& cmd) {
            QSignalSpy spy(&monitor, &HeadlessMonitor::commandHandled);
            monitor.handleLine(QJsonDocument(cmd).toJson(QJsonDocument::Compact));
            if (spy.isEmpty() && !spy.wait(kWait))
                return QJsonObject{};
            return QJsonDocument::fromJson(spy.first().first().toByteArray()).object();
        };
        // Every assignment request the console sent, per truck (from the audit lines of the gate).
        QHash<QString, int> autoAssigns;
        QStringList otherAssigns;
        connect(&gate, &CommandGate::commandFinished, this,
                [&](const CommandResult& r, const QString& origin) {
                    if (r.action != QLatin1String("assign"))
                        return;
                    for (const auto& t : r.targets)
                        if (origin == QLatin1String("auto-dispatch"))
                            autoAssigns[targetId(t)] += 1;
                        else
                            otherAssigns << targetId(t);
                });
        QVERIFY(bridge.start().isEmpty());

        const QString id0 = QStringLiteral("iso23725:") + QString::fromStdString(view.trucks[0].id);
        const QString id2 = QStringLiteral("iso23725:") + QString::fromStdString(view.trucks[2].id);
        auto truck = [&](const QString& id) { return bridge.dispatchState(id); };
        QTRY_VERIFY_WITH_TIMEOUT(truck(id0) && truck(id0)->custodian == QLatin1String("FMS"), kWait);
        QTRY_VERIFY_WITH_TIMEOUT(!bridge.destinations().isEmpty(), kWait);
        // Truck 2 is dispatched by the AHS: never by the console.
        ahs.setTruckCustodian(2, "AHS");
        QTRY_VERIFY_WITH_TIMEOUT(truck(id2) && truck(id2)->custodian == QLatin1String("AHS"), kWait);

        // Off by default: the state command says so and nothing was sent.
        QJsonObject st = run({{QStringLiteral("cmd"), QStringLiteral("auto_dispatch")}});
        QVERIFY2(st.value(QStringLiteral("ok")).toBool(), QJsonDocument(st).toJson().constData());
        QCOMPARE(st.value(QStringLiteral("on")).toBool(), false);
        QVERIFY(autoAssigns.isEmpty());
        // A wrong argument is refused.
        QVERIFY(!run({{QStringLiteral("cmd"), QStringLiteral("auto_dispatch")}, {QStringLiteral("on"), 1}})
                     .value(QStringLiteral("ok"))
                     .toBool());

        const QJsonObject on =
            run({{QStringLiteral("cmd"), QStringLiteral("auto_dispatch")}, {QStringLiteral("on"), true}});
        QVERIFY2(on.value(QStringLiteral("ok")).toBool() && on.value(QStringLiteral("on")).toBool(),
                 QJsonDocument(on).toJson().constData());
        QVERIFY(dispatcher->isOn());

        // Truck 0 (FMS, no task): assigned automatically; Accepted; it reports the assignment Active.
        QTRY_VERIFY_WITH_TIMEOUT(autoAssigns.value(id0) >= 1, kWait);
        QTRY_VERIFY_WITH_TIMEOUT(truck(id0)->assignmentStatus == QLatin1String("Active") &&
                                     !truck(id0)->requested.isEmpty() &&
                                     truck(id0)->assignmentId == truck(id0)->requested.front().assignmentId,
                                 kWait);
        const IsoDispatchState first = *truck(id0);
        const IsoAssignmentResponse* answer = first.response(first.assignmentId);
        QVERIFY(answer);
        QCOMPARE(answer->response, QStringLiteral("Accepted"));
        QVERIFY(first.task == QLatin1String("Load") || first.task == QLatin1String("Offload"));

        // The cycle completes (loaded at a shovel, dumped at a dump, all on the console's assignments) and is
        // counted for that truck.
        QTRY_VERIFY_WITH_TIMEOUT(
            [&] {
                for (const auto& t : production->trucks())
                    if (t.key == id0 && t.loads >= 1 && t.cycle.cycles >= 1)
                        return true;
                return false;
            }(),
            kWait * 3);
        QVERIFY2(autoAssigns.value(id0) >= 2, qPrintable(QString::number(autoAssigns.value(id0))));
        QVERIFY(otherAssigns.isEmpty());
        QCOMPARE(autoAssigns.value(id2), 0); // custodian AHS: never
        QVERIFY(truck(id2)->requested.isEmpty());
        // What it did is in the event log.
        bool logged = false;
        for (int i = 0; i < alarms.rowCount(); ++i)
            logged = logged || (alarms.eventAt(i).source == QLatin1String("auto-dispatch") &&
                                alarms.eventAt(i).text.contains(QStringLiteral("— sent")));
        QVERIFY(logged);
        QVERIFY(dispatcher->lastAction().contains(QStringLiteral("sent")) ||
                dispatcher->lastAction().contains(QStringLiteral("rejected")));

        // Off: no request leaves the console any more, while the trucks keep working and going idle.
        const QJsonObject off =
            run({{QStringLiteral("cmd"), QStringLiteral("auto_dispatch")}, {QStringLiteral("on"), false}});
        QVERIFY(off.value(QStringLiteral("ok")).toBool());
        QCOMPARE(off.value(QStringLiteral("on")).toBool(), false);
        QTest::qWait(300); // results of requests sent just before are still counted
        const auto requests = ahs.counters().get("sim.assign.requests");
        int total = 0;
        for (int n : std::as_const(autoAssigns))
            total += n;
        QTest::qWait(3000);
        int after = 0;
        for (int n : std::as_const(autoAssigns))
            after += n;
        QCOMPARE(after, total);
        QCOMPARE(ahs.counters().get("sim.assign.requests"), requests);
        bridge.stop();
    }
};

QTEST_MAIN(TestAutoDispatchE2e)
#include "test_auto_dispatch_e2e.moc"
