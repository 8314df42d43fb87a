// Production and dispatch against a foreign AHS (tests/protocols/iso23725/foreign,
// written from the research note's tables, sharing no code with sim/): one load-haul-dump cycle of production
// state, payload, sensor, dump and production cycle messages plus dispatch availability and map
// connectivity, in four dialects (as the tables' examples; every optional field left out; unknown extra
// members and fields; fields and header members in another order). The console's models show exactly those
// values: the bridge's dispatch view (what the dispatch panel shows) and the production model (loads,
// tonnes, cycle breakdown per truck, shovel and dump). Then what the console sends through its command gate
// (assignment request, reset) compared field for field with the tables; an answer that comes late; an
// unsolicited Rejected after an Accepted.
#include "app/modules/IsoProduction.h"
#include "models/AlarmModel.h"
#include "models/CommandGate.h"
#include "models/ProductionModel.h"
#include "models/bridges/IsoBridge.h"
#include "models/bridges/IsoDispatchSource.h"
#include "models/testing/CommandWait.h"
#include "tests/protocols/iso23725/foreign/ForeignAhs.h"
#include "tests/support/JsonFrames.h"

#include <nlohmann/json.hpp>

#include <QDateTime>
#include <QJsonArray>
#include <QtTest>

#include <regex>

using namespace ocu;
using isosim::withoutTimestamp;
using nlohmann::json;
using P = foreign::ForeignProduction;
using Dialect = foreign::ForeignAhsOptions::Dialect;

namespace {

constexpr int kWait = 30000;
const QString kTruck = QStringLiteral("iso23725:c3a51f7e-0d24-4b9a-8f63-1e2d4c5b6a78");

iso23725::IsoConfig consoleConfig(const std::string& url) {
    iso23725::IsoConfig c;
    c.fmsId = "0f1e2d3c-4b5a-4968-8776-a5b4c3d2e1f0";
    c.links.push_back(iso23725::IsoLinkConfig{"ahs", {}, {}});
    c.links[0].ws.url = url;
    c.links[0].ws.backoffMin = std::chrono::milliseconds(100);
    c.links[0].ws.backoffMax = std::chrono::milliseconds(400);
    return c;
}

struct Console {
    explicit Console(const foreign::ForeignAhsOptions& o)
        : peer(o), bridge(consoleConfig(peer.url()), GeoFrame(GeoPoint{-23.36, 119.73, 500.0})) {
        production = attachProductionModel(&bridge);
        // The peer's cycle happened on 2025-03-14 (the research note's examples): that is the shift.
        const qint64 start = QDateTime(QDate(2025, 3, 14), QTime(0, 0), Qt::UTC).toMSecsSinceEpoch();
        production->setShift(start, start + 12 * 3600 * 1000);
        gate.addBridge(&bridge);
    }
    foreign::ForeignAhs peer;
    AlarmModel alarms;
    CommandGate gate{&alarms};
    IsoBridge bridge;
    ProductionModel* production = nullptr;
    std::optional<IsoDispatchState> truck() const { return bridge.dispatchState(kTruck); }
    const ProductionTally* tally(const QVector<ProductionTally>& list, const QString& key) {
        m_keep = list;
        for (const auto& t : m_keep)
            if (t.key == key)
                return &t;
        return nullptr;
    }
    QVector<ProductionTally> m_keep;
};

} // namespace

class TestIsoForeignProduction : public QObject {
    Q_OBJECT
private slots:
    void productionAsTheForeignAhsReportsIt_data() {
        QTest::addColumn<int>("dialect");
        QTest::newRow("tables") << int(Dialect::Tables);
        QTest::newRow("optional fields missing") << int(Dialect::Minimal);
        QTest::newRow("unknown extra fields") << int(Dialect::Extra);
        QTest::newRow("fields in another order") << int(Dialect::Reordered);
    }
    void productionAsTheForeignAhsReportsIt() {
        QFETCH(int, dialect);
        const Dialect d = Dialect(dialect);
        const bool minimal = d == Dialect::Minimal;
        foreign::ForeignAhsOptions opt;
        opt.production = true;
        opt.dialect = d;
        Console c(opt);
        QVERIFY(c.bridge.start().isEmpty());
        // The last frame of the cycle: the truck drives empty on the ramp again.
        QTRY_VERIFY_WITH_TIMEOUT(c.truck() && c.truck()->productionState == QLatin1String(P::finalState),
                                 kWait);
        QTRY_VERIFY_WITH_TIMEOUT(c.production->shift().loads == 1, kWait);
        const IsoDispatchState t = *c.truck();
        QCOMPARE(t.name, QStringLiteral("HT01"));
        QCOMPARE(t.custodian, QStringLiteral("FMS"));
        QCOMPARE(t.autonomyMode, QStringLiteral("Autonomous"));
        QCOMPARE(t.wayId, std::optional<qint64>(P::haulWay));
        QCOMPARE(t.payloadTonnes, std::optional<double>(double(P::payload)));
        // Empty after the dump: the sensor says so, or (no sensor fields) the dump after the payload does.
        QCOMPARE(t.loaded, std::optional<bool>(false));
        // What the dispatch panel shows (the protocol-neutral row).
        const DispatchTruck row = toDispatchTruck(t);
        QCOMPARE(row.productionState, QStringLiteral("Driving"));
        QCOMPARE(row.payloadTonnes, std::optional<double>(289.0));
        // The map connectivity's areas, with their names and tasks.
        QTRY_VERIFY_WITH_TIMEOUT(c.bridge.destinations().size() >= 3, kWait);
        QStringList areas;
        for (const auto& a : IsoDispatchSource(&c.bridge).areas())
            areas << QStringLiteral("%1 %2 %3").arg(a.wayId).arg(a.name, a.defaultTask);
        areas.sort();
        QCOMPARE(areas, QStringList({"4101 North Waste Dump Offload", "4201 Pit 3 Bench 480 Load",
                                     "4301 Closed Bay Park"}));

        // Production: one load of 289 t (the dump's weight, or the payload at loading when the dump has
        // none) for the truck, its shovel and its dump; the cycle breakdown from the state times when sent.
        const ProductionTally& shift = c.production->shift();
        QCOMPARE(shift.loads, 1);
        QCOMPARE(shift.tonnes, double(P::payload));
        QCOMPARE(shift.loadsWithoutTonnes, 0);
        const ProductionTally* truck = c.tally(c.production->trucks(), kTruck);
        QVERIFY(truck);
        QCOMPARE(truck->loads, 1);
        QCOMPARE(truck->tonnes, double(P::payload));
        const ProductionTally* shovel = c.tally(c.production->shovels(), QString::number(P::loadWay));
        QVERIFY(shovel);
        QCOMPARE(shovel->loads, 1);
        QCOMPARE(shovel->name, QStringLiteral("Pit 3 Bench 480"));
        const ProductionTally* dump = c.tally(c.production->dumps(), QString::number(P::dumpWay));
        QVERIFY(dump);
        QCOMPARE(dump->tonnes, double(P::payload));
        QCOMPARE(dump->name, QStringLiteral("North Waste Dump"));
        if (minimal) {
            QCOMPARE(shift.cycle.cycles, 0); // no state times: nothing to break down (never made up)
        } else {
            QCOMPARE(shift.cycle.cycles, 1);
            QCOMPARE(shift.cycle.average(CycleBreakdown::Queue), 128.0);
            QCOMPARE(shift.cycle.average(CycleBreakdown::Load), 140.0);
            QCOMPARE(shift.cycle.average(CycleBreakdown::Haul), 1800.0);
            QCOMPARE(shift.cycle.average(CycleBreakdown::Dump), 159.0);
        }
        c.bridge.stop();
    }

    // What the console sends through its gate, field for field as the tables say (rows 21 and 23), to a peer
    // that answers late; then an unsolicited Rejected after the Accepted (row 22).
    void assignmentLateAnswerAndUnsolicitedReject() {
        foreign::ForeignAhsOptions opt;
        opt.answerDelayMs = 3000;
        opt.unsolicitedReject = "Pit 3 Bench 480 closed by AHS";
        opt.dialect = Dialect::Reordered;
        opt.production = true;
        Console c(opt);
        QVERIFY(c.bridge.start().isEmpty());
        QTRY_VERIFY_WITH_TIMEOUT(c.truck() && c.truck()->productionState == QLatin1String(P::finalState) &&
                                     c.bridge.destinations().size() >= 3,
                                 kWait);
        const QJsonObject args{
            {QStringLiteral("id"), kTruck},
            {QStringLiteral("tasks"), QJsonArray{QJsonObject{{QStringLiteral("task"), QStringLiteral("Load")},
                                                             {QStringLiteral("destination"), 4201},
                                                             {QStringLiteral("assignment_id"),
                                                              QString::fromLatin1(P::loadAssignment)}}}}};
        const CommandResult r = testing::gateResult([&](auto h) {
            c.gate.command(*parseOperatorCommand(QStringLiteral("assign"), args).command,
                           QStringLiteral("test"), h);
        });
        QVERIFY2(r.ok, qPrintable(r.message));
        QCOMPARE(r.targets.size(), 1);
        QCOMPARE(targetId(r.targets[0]), kTruck);
        const std::string frame = c.peer.waitFor("HaulTruckAssignmentRequestV2");
        QVERIFY(!frame.empty());
        // Row 21: from way 2001 the shovel is the next way: no way in between, so no RouteV1 (optional).
        QVERIFY2(withoutTimestamp(frame) == json::parse(R"({"Protocol":"ISO23725","Version":1,
            "EquipmentId":"c3a51f7e-0d24-4b9a-8f63-1e2d4c5b6a78",
            "HaulTruckAssignmentRequestV2":[{"AssignmentId":"e41a7c2b-6d3f-4b58-a9e0-7f1c2d3b4a56",
              "Task":"Load","DestinationId":4201}]})"),
                 frame.c_str());
        // The answer is late: until it comes the console shows the request and no answer.
        QVERIFY(c.truck()->responses.isEmpty());
        QCOMPARE(toDispatchTruck(*c.truck()).lastResponse, QString());
        QTRY_VERIFY_WITH_TIMEOUT(c.truck()->response(QString::fromLatin1(P::loadAssignment)), kWait);
        // Accepted and Active, then the unsolicited Rejected replaces the Accepted, with its detail.
        QTRY_VERIFY_WITH_TIMEOUT(c.truck()->response(QString::fromLatin1(P::loadAssignment))->response ==
                                     QLatin1String("Rejected"),
                                 kWait);
        const IsoAssignmentResponse* rej = c.truck()->response(QString::fromLatin1(P::loadAssignment));
        QCOMPARE(rej->detail, QStringLiteral("Pit 3 Bench 480 closed by AHS"));
        const DispatchTruck row = toDispatchTruck(*c.truck());
        QCOMPARE(row.lastResponse, QStringLiteral("Rejected"));
        QCOMPARE(row.lastResponseDetail, QStringLiteral("Pit 3 Bench 480 closed by AHS"));

        // Row 23: the reset.
        const CommandResult reset = testing::gateResult(
            [&](auto h) { c.gate.command(ResetAssignment{kTruck}, QStringLiteral("test"), h); });
        QVERIFY2(reset.ok, qPrintable(reset.message));
        const std::string rf = c.peer.waitFor("HaulTruckAssignmentResetV1");
        QVERIFY(!rf.empty());
        json j = withoutTimestamp(rf);
        const std::string resetId = j["HaulTruckAssignmentResetV1"]["ResetId"].get<std::string>();
        QCOMPARE(j,
                 json::parse(R"({"Protocol":"ISO23725","Version":1,"EquipmentId":"c3a51f7e-0d24-4b9a-8f63-)"
                             R"(1e2d4c5b6a78","HaulTruckAssignmentResetV1":{"ResetId":")" +
                             resetId + R"("}})"));
        c.bridge.stop();
    }
};

QTEST_MAIN(TestIsoForeignProduction)
#include "test_iso_foreign_production.moc"
