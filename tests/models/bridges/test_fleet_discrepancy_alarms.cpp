// Fleet discrepancies reach the operator as one alarm per cause: the real FmsCore (fake clock,
// no sockets) checks an AHS fleet of 1,000 trucks the FMS does not know plus one with a different type; the
// console shows two alarms, "1,000 machines of the AHS are not in the FMS fleet" with the 1,000 machines in
// its details, and nothing else (before, every discrepancy came twice: as "discrepancy" and as "info").
#include "models/AlarmModel.h"
#include "models/bridges/FleetDiscrepancyAlarms.h"
#include "protocols/iso23725/FmsCore.h"

#include <QtTest>

#include <cstdio>

using namespace ocu;
using namespace ocu::iso23725;

namespace {

const Guid kFms = "0f1e2d3c-4b5a-4968-8776-a5b4c3d2e1f0";
const Guid kTruck = "c3a51f7e-0d24-4b9a-8f63-1e2d4c5b6a78";

struct NoOutbound final : FmsOutbound {
    bool sendMain(std::string) override { return true; }
    bool sendMap(std::string) override { return true; }
};

// What IsoBridge does with the two callbacks (IsoBridge::onFleetDiscrepancies / onEvent), on the test thread.
struct ToAlarms final : IsoListener {
    AlarmModel* alarms = nullptr;
    void onFleetDiscrepancies(const std::string& link, const std::vector<FleetDiscrepancy>& items) override {
        for (const FleetEvent& e : fleetDiscrepancyAlarms(link, items))
            alarms->add(e);
    }
    void onEvent(IsoSeverity, const std::string& text) override {
        alarms->add(makeEvent(EventSeverity::Info, EventKind::Info, {}, QString::fromStdString(text),
                              QStringLiteral("iso23725")));
    }
};

Guid guidOf(int i) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "aaaaaaaa-bbbb-4ccc-8ddd-%012d", i);
    return buf;
}

} // namespace

class TestFleetDiscrepancyAlarms : public QObject {
    Q_OBJECT
private slots:
    void thousandUnknownMachinesAreOneAlarm() {
        AlarmModel alarms;
        ToAlarms listener;
        listener.alarms = &alarms;
        IsoConfig cfg;
        cfg.fmsId = kFms;
        cfg.fleet = {Equipment{kTruck, "HT01", "HaulTruck", "OEM", "793F", true, 12.9, 7.6}};
        FakeClock clock;
        Counters counters;
        NoOutbound out;
        FmsCore core(cfg, IsoLinkConfig{"ahs", {}, {}}, listener, counters, clock, out);
        core.opened("127.0.0.1:9000");
        const int before = alarms.rowCount(); // connection events, if any

        FleetDefinitionV2 fleet;
        fleet.ahsId = "7d1f3c2a-5b8e-4c61-9a0d-2e4f6b8c1a37";
        fleet.equipment.push_back(Equipment{kTruck, "HT01", "WaterCart", "OEM", "793F", true, 12.9, 7.6});
        for (int i = 0; i < 1000; ++i)
            fleet.equipment.push_back(
                Equipment{guidOf(i), "T" + std::to_string(i), "HaulTruck", "OEM", "793F", true, 12.9, 7.6});
        core.text(encodeMessage(fleet));

        QCOMPARE(alarms.rowCount() - before, 2); // one per cause, no "info" twin
        int group = -1, single = -1;
        for (int r = before; r < alarms.rowCount(); ++r) {
            QCOMPARE(alarms.eventAt(r).kind, EventKind::Discrepancy);
            (alarms.eventAt(r).itemCount == 1000 ? group : single) = r;
        }
        QVERIFY(group >= 0 && single >= 0);
        QLocale locale;
        locale.setNumberOptions({});
        const FleetEvent& g = alarms.eventAt(group);
        QCOMPARE(g.text, QStringLiteral("%1 machines of the AHS are not in the FMS fleet on ahs")
                             .arg(locale.toString(1000)));
        QCOMPARE(g.details.size(), 1000);
        QVERIFY(g.details.front().contains(QStringLiteral("T0 (aaaaaaaa-bbbb-4ccc-8ddd-000000000000")));
        QCOMPARE(alarms.keyAt(group), QStringLiteral("fleet.not_in_fms|ahs|iso23725"));
        QCOMPARE(effectivePriority(g), AlarmPriority::Medium);
        const FleetEvent& s = alarms.eventAt(single);
        QCOMPARE(s.itemCount, 1);
        QVERIFY(s.text.contains(QStringLiteral("type WaterCart at the AHS, HaulTruck at the FMS")));
        QCOMPARE(alarms.keyAt(single), QStringLiteral("fleet.type_differs|ahs|iso23725"));
        QCOMPARE(alarms.unacknowledgedCount(), 2);

        // The AHS sends its fleet again with one truck fewer: the same two alarms, updated, no new rows.
        fleet.equipment.pop_back();
        core.text(encodeMessage(fleet));
        QCOMPARE(alarms.rowCount() - before, 2);
        QCOMPARE(alarms.eventAt(group).itemCount, 999);
        QCOMPARE(alarms.eventAt(group).details.size(), 999);
        QCOMPARE(alarms.occurrencesAt(group), 2);
        QCOMPARE(alarms.unacknowledgedCount(), 2);
    }

    void detailsAreBounded() {
        std::vector<FleetDiscrepancy> items(6000,
                                            FleetDiscrepancy{DiscrepancyCause::MissingFromAhs, "x", "y"});
        const auto evs = fleetDiscrepancyAlarms("ahs", items);
        QCOMPARE(evs.size(), 1);
        QCOMPARE(evs.front().itemCount, 6000);
        QCOMPARE(evs.front().details.size(), 5001); // 5,000 lines and "… and 1,000 more"
        QVERIFY(evs.front().details.back().contains(QStringLiteral("more")));
    }
};

QTEST_GUILESS_MAIN(TestFleetDiscrepancyAlarms)
#include "test_fleet_discrepancy_alarms.moc"
