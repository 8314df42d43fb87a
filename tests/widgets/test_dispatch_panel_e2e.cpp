// Dispatch through the GUI: the dispatch panel over IsoBridge and the CommandGate against the
// simulated AHS on loopback. Assign from the panel: the result line says the truck got it (sent), then the
// truck's answer (Accepted) and the Active assignment it reports; the route and ETA of the active task and
// the shovel's queue follow. A truck the AHS dispatches (custodian AHS) cannot be assigned: Assign is
// disabled with the reason, and a request anyway is refused by the bridge (NOT sent, nothing reaches the
// AHS); handed back, it carries the needs-assignment cue. With the link down the panel says so and a request
// is refused.
#include "models/AlarmModel.h"
#include "models/CommandGate.h"
#include "models/FleetModel.h"
#include "models/FleetSelection.h"
#include "models/bridges/IsoBridge.h"
#include "models/bridges/IsoDispatchSource.h"
#include "sim/iso23725/SimulatedAhs.h"
#include "tests/support/IsoSimConsole.h"
#include "widgets/dispatch/DispatchPanel.h"

#include <QComboBox>
#include <QLabel>
#include <QPushButton>
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

} // namespace

class TestDispatchPanelE2e : public QObject {
    Q_OBJECT
private slots:
    void assignFromThePanel() {
        sim::SimulatedAhs ahs(ahsConfig());
        QVERIFY(ahs.start());
        const auto view = ahs.dispatchView();
        AlarmModel alarms;
        CommandGate gate(&alarms);
        IsoBridge bridge(consoleConfig(ahs.url()), GeoFrame(ahsConfig().origin));
        gate.addBridge(&bridge);
        FleetModel fleet;
        fleet.addBridge(&bridge);
        FleetSelection selection(&fleet);
        IsoDispatchSource source(&bridge);
        DispatchPanel panel(&source, &gate, &selection);
        QStringList questions;
        panel.setConfirm([&questions](const QString& title, const QString&) {
            questions << title;
            return true;
        });
        panel.resize(1200, 500);
        panel.show();
        QVERIFY(bridge.start().isEmpty());

        const QString id0 = QStringLiteral("iso23725:") + QString::fromStdString(view.trucks[0].id);
        const QString id1 = QStringLiteral("iso23725:") + QString::fromStdString(view.trucks[1].id);
        DispatchModel* model = panel.model();
        auto row = [&](const QString& id) { return model->rowOf(id); };
        auto cell = [&](const QString& id, int col) {
            return row(id) < 0 ? QString() : model->data(model->index(row(id), col)).toString();
        };
        QTRY_VERIFY_WITH_TIMEOUT(
            row(id0) >= 0 && cell(id0, DispatchModel::ColCustodian) == QLatin1String("FMS") &&
                row(id1) >= 0 && cell(id1, DispatchModel::ColCustodian) == QLatin1String("FMS"),
            kWait);
        QCOMPARE(model->rowCount(), 3);
        // The destinations are the areas of the AHS's MapConnectivityV1; pick the first shovel.
        const QString shovelFeature = QStringLiteral("ahs/%1").arg(view.loadAreas[0]);
        QTRY_VERIFY_WITH_TIMEOUT(panel.destinationBox()->findData(shovelFeature) >= 0, kWait);
        QTRY_VERIFY_WITH_TIMEOUT(!cell(id0, DispatchModel::ColProduction).isEmpty() &&
                                     cell(id0, DispatchModel::ColProduction) != QLatin1String("—"),
                                 kWait);
        panel.setCurrentTruck(id0);
        panel.destinationBox()->setCurrentIndex(panel.destinationBox()->findData(shovelFeature));
        QCOMPARE(panel.taskBox()->currentText(), QStringLiteral("Load"));
        QVERIFY(panel.assignButton()->isEnabled());
        QVERIFY(!panel.refusalLabel()->isVisible());
        // Before sending: the route the truck would drive (the preview on the map) ends at the shovel.
        DispatchArea shovel;
        for (const auto& a : source.areas())
            if (a.featureId() == shovelFeature)
                shovel = a;
        const DispatchRoute preview = source.routeTo(id0, shovel);
        QVERIFY2(!preview.ways.isEmpty(), qPrintable(preview.error));
        QCOMPARE(preview.ways.last(), view.loadAreas[0]);

        // Assign: sent (the truck is the target), then the truck's own answer and the assignment it reports.
        const auto requestsBefore = ahs.counters().get("sim.assign.requests");
        QTest::mouseClick(panel.assignButton(), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(panel.resultLabel()->text().contains(QStringLiteral(": sent")), kWait);
        QTRY_VERIFY_WITH_TIMEOUT(panel.resultLabel()->text().contains(QStringLiteral("answered Accepted")),
                                 kWait);
        QTRY_COMPARE_WITH_TIMEOUT(cell(id0, DispatchModel::ColAssignment), QStringLiteral("Active"), kWait);
        QCOMPARE(cell(id0, DispatchModel::ColTask), QStringLiteral("Load"));
        QCOMPARE(ahs.counters().get("sim.assign.requests"), requestsBefore + 1);
        QVERIFY(questions.isEmpty()); // a truck without a task: no question
        // Its route (the ways of the request, from where the truck is) ends at the shovel; the ETA is shown.
        QTRY_VERIFY_WITH_TIMEOUT(!model->routeOf(row(id0)).ways.isEmpty(), kWait);
        QCOMPARE(model->routeOf(row(id0)).ways.last(), view.loadAreas[0]);
        QVERIFY(cell(id0, DispatchModel::ColEta) != QLatin1String("—"));
        // The shovel's queue has it (coming, or already there).
        const auto* queue = panel.queueModel()->queueOf(QStringLiteral("ahs"), view.loadAreas[0]);
        QVERIFY(queue);
        const QString name0 = model->truckAt(row(id0)).name;
        QVERIFY(queue->enRoute.contains(name0) || queue->atArea.contains(name0));

        // Custodian AHS: Assign disabled with the reason; a request anyway is refused, nothing reaches the
        // AHS.
        ahs.setTruckCustodian(1, "AHS");
        panel.setCurrentTruck(id1);
        QTRY_VERIFY_WITH_TIMEOUT(
            panel.refusalLabel()->text().contains(QStringLiteral("dispatched by the AHS")), kWait);
        QVERIFY(!panel.assignButton()->isEnabled());
        const auto requestsAhs = ahs.counters().get("sim.assign.requests");
        panel.assignCurrent();
        QTRY_VERIFY_WITH_TIMEOUT(panel.resultLabel()->text().contains(QStringLiteral("NOT sent")), kWait);
        QVERIFY2(panel.resultLabel()->text().contains(QStringLiteral("DispatchingCustodian AHS")),
                 qPrintable(panel.resultLabel()->text()));
        QTest::qWait(300);
        QCOMPARE(ahs.counters().get("sim.assign.requests"), requestsAhs);
        // Handed back to the FMS: the truck asks for work, the row and the header show the cue.
        ahs.setTruckCustodian(1, "FMS");
        QTRY_VERIFY_WITH_TIMEOUT(
            model->data(model->index(row(id1), 0), DispatchModel::NeedsAssignmentRole).toBool(), kWait);
        QCOMPARE(cell(id1, DispatchModel::ColAssignment), QStringLiteral("NEEDS ASSIGNMENT"));
        QVERIFY(panel.findChild<QLabel*>(QStringLiteral("label-needs-assignment"))
                    ->text()
                    .contains(QStringLiteral("need an assignment")));
        QTRY_VERIFY_WITH_TIMEOUT(panel.assignButton()->isEnabled(), kWait);

        // Link down: the panel says so, and a request is refused with the reason, never queued.
        const auto port = ahs.port();
        ahs.stop();
        QTRY_VERIFY_WITH_TIMEOUT(panel.refusalLabel()->text().contains(QStringLiteral("is down")), kWait);
        QVERIFY(!panel.assignButton()->isEnabled());
        QTRY_COMPARE_WITH_TIMEOUT(cell(id1, DispatchModel::ColCustodian), QStringLiteral("link down"), kWait);
        panel.assignCurrent();
        QTRY_VERIFY_WITH_TIMEOUT(panel.resultLabel()->text().contains(QStringLiteral("NOT sent")) &&
                                     panel.resultLabel()->text().contains(QStringLiteral("is down")),
                                 kWait);
        auto cfg = ahsConfig();
        cfg.port = port;
        sim::SimulatedAhs second(cfg);
        QVERIFY(second.start());
        QTRY_VERIFY_WITH_TIMEOUT(bridge.linkStatus(QStringLiteral("iso23725:ahs"))->state == LinkState::Up,
                                 kWait);
        QTest::qWait(500);
        QCOMPARE(second.counters().get("sim.assign.requests"), std::uint64_t(0));
        bridge.stop();
        second.stop();
    }
};

QTEST_MAIN(TestDispatchPanelE2e)
#include "test_dispatch_panel_e2e.moc"
