// The ISO 23725 bridge's operator text for a haul truck's work: production state and way, payload (null stays
// unavailable, never 0 t), sensor flags, assignment, last dump; nothing when nothing was reported.
#include "models/bridges/IsoBridge.h"

#include <QtTest>

using namespace ocu;
using namespace ocu::iso23725;

class TestIsoBridge : public QObject {
    Q_OBJECT
private slots:
    void nothingReportedGivesNoText() {
        IsoMachineSnapshot m;
        QVERIFY(isoWorkText(m).isEmpty());
    }

    void everyReportedPartIsShown() {
        IsoMachineSnapshot m;
        m.production = HaulTruckProductionStateV2{std::nullopt, 2001, "Autonomous", "Hauling"};
        m.payload = HaulTruckPayloadV1{289, 4.5, std::nullopt};
        m.sensor = HaulTruckProductionStateSensorV1{true, false, true, 289, false, false};
        m.assignment =
            HaulTruckAssignmentV1{"e41a7c2b-6d3f-4b58-a9e0-7f1c2d3b4a56", "Active", "Offload", 4101};
        m.lastDump = HaulTruckDumpV1{std::nullopt, 4102, 280, std::nullopt, std::nullopt};
        QCOMPARE(isoWorkText(m),
                 QStringLiteral("Hauling on way 2001 · payload 289 t · loaded · park brake on · "
                                "assignment Active (Offload at way 4101) · last dump 280 t at "
                                "way 4102"));
    }

    void unavailableValuesAreLeftOut() {
        IsoMachineSnapshot m;
        m.production = HaulTruckProductionStateV2{std::nullopt, std::nullopt, "Autonomous", "Queued"};
        m.payload = HaulTruckPayloadV1{std::nullopt, std::nullopt, std::nullopt};
        m.sensor = HaulTruckProductionStateSensorV1{false, true, std::nullopt, std::nullopt, {}, {}};
        QCOMPARE(isoWorkText(m), QStringLiteral("Queued · empty · body raised"));
    }
};

QTEST_GUILESS_MAIN(TestIsoBridge)
#include "test_iso_bridge.moc"
