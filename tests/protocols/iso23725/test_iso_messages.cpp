// ISO 23725 codec: every catalogue example round-trips; each rejection names the member and the message;
// the tolerance rules of the note (§9) hold and can be switched off in InferredRules.
#include "protocols/iso23725/Messages.h"

#include "tests/protocols/iso23725/IsoTestData.h"

#include <QtTest>

#include <fstream>
#include <set>

using namespace ocu::iso23725;
using nlohmann::json;

namespace {

const char* kHdr = R"("Protocol":"ISO23725","Version":1,"Timestamp":"2025-03-14T02:15:07.412Z")";
const char* kEq = R"("EquipmentId":"c3a51f7e-0d24-4b9a-8f63-1e2d4c5b6a78")";

std::string msg(const std::string& body, bool withEquipment = false) {
    return std::string("{") + kHdr + (withEquipment ? std::string(",") + kEq : std::string()) + "," + body +
           "}";
}

const char* kPose =
    R"("Timestamp":"2025-03-14T02:15:07.380Z","Heading":87,"Latitude":-23.360114,)"
    R"("Longitude":119.730552,"Elevation":512.34,"LatitudeAccuracy":0.05,"LongitudeAccuracy":0.06,)"
    R"("ElevationAccuracy":0.11,"HeadingAccuracy":0.8,"Speed":34)";

} // namespace

class TestIsoMessages : public QObject {
    Q_OBJECT
private slots:
    void everyExampleRoundTrips() {
        auto examples = loadCatalogueExamples();
        QCOMPARE(int(examples.size()), 27);
        std::set<std::string> names;
        for (auto& text : examples) {
            auto r = decodeMessage(text);
            QVERIFY2(r.ok(), r.ok() ? "" : r.error().c_str());
            QVERIFY2(r->errors.empty(), text.c_str());
            for (auto& m : r->members)
                names.insert(std::string(memberName(m.body)));
            json back = toJson(*r);
            json orig = json::parse(text);
            QVERIFY2(back == orig, (orig.dump() + "\n!=\n" + back.dump()).c_str());
            // And the re-serialised text decodes to the same values.
            auto again = decodeMessage(back.dump());
            QVERIFY(again.ok());
            QCOMPARE(toJson(*again), back);
        }
        // Rows 1-13 and 15-24 of the catalogue (14 is the XML map document, tested in test_iso_map).
        for (const char* n : {"FleetDefinitionV2",
                              "MachineAllStopRequestV1",
                              "MachineAllStopResponseV1",
                              "MachineAllStopV1",
                              "MachinePositionV1",
                              "BasicMachineHealthV2",
                              "MachineAutonomyModeV1",
                              "MachineDispatchAvailabilityV1",
                              "MachineDiagnosticV2",
                              "MapConnectivityV1",
                              "MapServiceV1",
                              "MapSummaryV1",
                              "MapCommandV1",
                              "InterfaceDiagnosticV1",
                              "HaulTruckProductionCycleV1",
                              "HaulTruckProductionStateV2",
                              "HaulTruckProductionStateSensorV1",
                              "HaulTruckPayloadV1",
                              "HaulTruckDumpV1",
                              "HaulTruckAssignmentRequestV2",
                              "HaulTruckAssignmentResponseV1",
                              "HaulTruckAssignmentResetV1",
                              "HaulTruckAssignmentV1",
                              "MachineDiagnosticV3"})
            QVERIFY2(names.count(n), n);
    }

    // The assignment messages (§5 rows 21-24, §6 examples 21-24) byte for byte. The codec writes
    // members in name order (one canonical form); these vectors pin every byte, and the examples as the note
    // writes them (its member order) decode to the same values.
    void assignmentVectorsByteExact() {
        const Guid truck = "c3a51f7e-0d24-4b9a-8f63-1e2d4c5b6a78";
        const Guid a1 = "e41a7c2b-6d3f-4b58-a9e0-7f1c2d3b4a56", a2 = "f52b8d3c-7e40-4c69-b0f1-8a2d3e4c5b67";
        const HaulTruckAssignmentRequestV2 req{
            {AssignmentItem{a1,
                            "Load",
                            4201,
                            std::string("a2d4f6b8-1c3e-4a5b-9d7f-0e2c4b6a8d13"),
                            {},
                            std::vector<WayRef>{{2001}}},
             AssignmentItem{a2, "Offload", 4101, {}, std::int64_t(3), {}}}};
        const std::string reqText =
            R"({"EquipmentId":"c3a51f7e-0d24-4b9a-8f63-1e2d4c5b6a78","HaulTruckAssignmentRequestV2":[)"
            R"({"AssignmentId":"e41a7c2b-6d3f-4b58-a9e0-7f1c2d3b4a56","DestinationEquipmentId":"a2d4f6b8-1c3e-4a5b-9d7f-0e2c4b6a8d13",)"
            R"("DestinationId":4201,"RouteV1":[{"WayId":2001}],"Task":"Load"},)"
            R"({"AssignmentId":"f52b8d3c-7e40-4c69-b0f1-8a2d3e4c5b67","DestinationId":4101,"DestinationSpotId":3,"Task":"Offload"}],)"
            R"("Protocol":"ISO23725","Timestamp":"2025-03-14T02:20:30.000Z","Version":1})";
        QCOMPARE(encodeMessage(req, truck, 1741918830000), reqText);
        const HaulTruckAssignmentResponseV1 resp{
            {AssignmentResponseItem{a1, "Accepted", {}},
             AssignmentResponseItem{a2, "Rejected", std::string("Dump 4101 closed by AHS")}}};
        const std::string respText =
            R"({"EquipmentId":"c3a51f7e-0d24-4b9a-8f63-1e2d4c5b6a78","HaulTruckAssignmentResponseV1":[)"
            R"({"AssignmentId":"e41a7c2b-6d3f-4b58-a9e0-7f1c2d3b4a56","Response":"Accepted"},)"
            R"({"AssignmentId":"f52b8d3c-7e40-4c69-b0f1-8a2d3e4c5b67","Detail":"Dump 4101 closed by AHS","Response":"Rejected"}],)"
            R"("Protocol":"ISO23725","Timestamp":"2025-03-14T02:20:30.640Z","Version":1})";
        QCOMPARE(encodeMessage(resp, truck, 1741918830640), respText);
        QCOMPARE(encodeMessage(HaulTruckAssignmentResetV1{"6a8c0e24-4f6b-4d8e-9a2c-1b3d5f7a9c0e"}, truck,
                               1741920000000),
                 std::string(
                     R"({"EquipmentId":"c3a51f7e-0d24-4b9a-8f63-1e2d4c5b6a78","HaulTruckAssignmentResetV1":)"
                     R"({"ResetId":"6a8c0e24-4f6b-4d8e-9a2c-1b3d5f7a9c0e"},"Protocol":"ISO23725",)"
                     R"("Timestamp":"2025-03-14T02:40:00.000Z","Version":1})"));
        const HaulTruckAssignmentV1 active{a1, "Active", std::string("Load"), 4201};
        QCOMPARE(
            encodeMessage(active, truck, 1741918831000),
            std::string(R"({"EquipmentId":"c3a51f7e-0d24-4b9a-8f63-1e2d4c5b6a78","HaulTruckAssignmentV1":)"
                        R"({"AssignmentId":"e41a7c2b-6d3f-4b58-a9e0-7f1c2d3b4a56","DestinationId":4201,)"
                        R"("Status":"Active","Task":"Load"},"Protocol":"ISO23725",)"
                        R"("Timestamp":"2025-03-14T02:20:31.000Z","Version":1})"));
        // Idle: AssignmentId null (row 24), never left out.
        QCOMPARE(
            encodeMessage(HaulTruckAssignmentV1{std::nullopt, "Completed", {}, {}}, truck, 1741918831000),
            std::string(R"({"EquipmentId":"c3a51f7e-0d24-4b9a-8f63-1e2d4c5b6a78","HaulTruckAssignmentV1":)"
                        R"({"AssignmentId":null,"Status":"Completed"},"Protocol":"ISO23725",)"
                        R"("Timestamp":"2025-03-14T02:20:31.000Z","Version":1})"));
        // Decoding, from the note's examples in their own member order.
        auto r = decodeMessage(
            R"({"Protocol":"ISO23725","Version":1,"Timestamp":"2025-03-14T02:20:30.000Z","EquipmentId":"c3a51f7e-0d24-4b9a-8f63-1e2d4c5b6a78",)"
            R"("HaulTruckAssignmentRequestV2":[{"AssignmentId":"e41a7c2b-6d3f-4b58-a9e0-7f1c2d3b4a56","Task":"Load","DestinationId":4201,)"
            R"("DestinationEquipmentId":"a2d4f6b8-1c3e-4a5b-9d7f-0e2c4b6a8d13","RouteV1":[{"WayId":2001}]},)"
            R"({"AssignmentId":"f52b8d3c-7e40-4c69-b0f1-8a2d3e4c5b67","Task":"Offload","DestinationId":4101,"DestinationSpotId":3}]})");
        QVERIFY(r && r->errors.empty());
        QVERIFY(*r->find<HaulTruckAssignmentRequestV2>() == req);
        r = decodeMessage(
            R"({"Protocol":"ISO23725","Version":1,"Timestamp":"2025-03-14T02:20:30.640Z","EquipmentId":"c3a51f7e-0d24-4b9a-8f63-1e2d4c5b6a78",)"
            R"("HaulTruckAssignmentResponseV1":[{"AssignmentId":"e41a7c2b-6d3f-4b58-a9e0-7f1c2d3b4a56","Response":"Accepted"},)"
            R"({"AssignmentId":"f52b8d3c-7e40-4c69-b0f1-8a2d3e4c5b67","Response":"Rejected","Detail":"Dump 4101 closed by AHS"}]})");
        QVERIFY(r && r->errors.empty());
        QVERIFY(*r->find<HaulTruckAssignmentResponseV1>() == resp);
        r = decodeMessage(
            R"({"Protocol":"ISO23725","Version":1,"Timestamp":"2025-03-14T02:20:31.000Z","EquipmentId":"c3a51f7e-0d24-4b9a-8f63-1e2d4c5b6a78",)"
            R"("HaulTruckAssignmentV1":{"AssignmentId":"e41a7c2b-6d3f-4b58-a9e0-7f1c2d3b4a56","Status":"Active","Task":"Load","DestinationId":4201}})");
        QVERIFY(r && r->errors.empty());
        QVERIFY(*r->find<HaulTruckAssignmentV1>() == active);
        // Bad values are refused with the member named: a task outside the set, a status outside the set.
        r = decodeMessage(
            R"({"Protocol":"ISO23725","Version":1,"Timestamp":"2025-03-14T02:20:31.000Z","EquipmentId":"c3a51f7e-0d24-4b9a-8f63-1e2d4c5b6a78",)"
            R"("HaulTruckAssignmentV1":{"AssignmentId":null,"Status":"Done"}})");
        QVERIFY(r && r->errors.size() == 1);
        QVERIFY2(r->errors[0].find("HaulTruckAssignmentV1.Status") == 0, r->errors[0].c_str());
        r = decodeMessage(
            R"({"Protocol":"ISO23725","Version":1,"Timestamp":"2025-03-14T02:20:31.000Z","EquipmentId":"c3a51f7e-0d24-4b9a-8f63-1e2d4c5b6a78",)"
            R"("HaulTruckAssignmentRequestV2":[{"AssignmentId":"e41a7c2b-6d3f-4b58-a9e0-7f1c2d3b4a56","Task":"Dig","DestinationId":4201}]})");
        QVERIFY(r && r->errors.size() == 1);
        QVERIFY2(r->errors[0].find("HaulTruckAssignmentRequestV2[0].Task") == 0, r->errors[0].c_str());
    }

    void decodedValues() {
        auto r = decodeMessage(msg(std::string(R"("MachinePositionV1":{)") + kPose + "}", true));
        QVERIFY(r.ok());
        auto* p = r->find<MachinePositionV1>();
        QVERIFY(p);
        QCOMPARE(*p->pose.heading, 87);
        QCOMPARE(*p->pose.speed, 34);
        QCOMPARE(*p->pose.latitude, -23.360114);
        QCOMPARE(*p->timestamp.unixMs, 1741918507380LL);
        QCOMPARE(*r->header.equipmentId, std::string("c3a51f7e-0d24-4b9a-8f63-1e2d4c5b6a78"));
    }

    void nullMeansUnavailable() {
        auto r = decodeMessage(
            msg(R"("BasicMachineHealthV2":{"FuelLevel":null,"TotalMachineHour":null,"TotalEngineHour":12.5})",
                true));
        QVERIFY(r.ok());
        QVERIFY(r->errors.empty());
        auto* h = r->find<BasicMachineHealthV2>();
        QVERIFY(h);
        QVERIFY(!h->fuelLevel.has_value()); // never a default 0
        QVERIFY(!h->totalMachineHour.has_value());
        QCOMPARE(*h->totalEngineHour, 12.5);
        QCOMPARE(toJson(*r)["BasicMachineHealthV2"]["FuelLevel"], json(nullptr));
    }

    void rejections_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("error");
        QTest::newRow("missing shall member")
            << QString::fromStdString(msg(R"("MachineAllStopRequestV1":{"ModeAllStop":"Apply"})"))
            << "MachineAllStopRequestV1.ModeAllStopId: required member missing";
        QTest::newRow("wrong type")
            << QString::fromStdString(msg(R"("MachineAutonomyModeV1":{"AutonomyMode":3})", true))
            << "MachineAutonomyModeV1.AutonomyMode: expected an enumeration string, got number";
        QTest::newRow("wrong type number")
            << QString::fromStdString(
                   msg(R"("MachineDiagnosticV2":[{"ComponentId":"abc","FaultCode":1}])", true))
            << "MachineDiagnosticV2[0].ComponentId: expected a number, got string";
        QTest::newRow("enum outside set")
            << QString::fromStdString(msg(
                   R"("FleetDefinitionV2":{"AHSId":"7d1f3c2a-5b8e-4c61-9a0d-2e4f6b8c1a37","Equipment":[{"EquipmentId":"c3a51f7e-0d24-4b9a-8f63-1e2d4c5b6a78","HID":"H1","Type":"Hauler","OEM":"x","Model":"y","Autonomous":true,"Length":1,"Width":1}]})"))
            << "FleetDefinitionV2.Equipment[0].Type: 'Hauler' is not one of HaulTruck, Shovel, Excavator, "
               "Loader, "
               "LightVehicle, WaterCart, Grader, FuelTruck, LubeTruck, Dozer, RubberTireDozer, Drill, "
               "Crusher, "
               "Scraper, BellyDumper, EmergencyVehicle, Ambulance, Dragline, SurfaceMiner, Bus, Train, "
               "Trailer";
        QTest::newRow("malformed GUID")
            << QString::fromStdString(msg(
                   R"("MachineAllStopRequestV1":{"ModeAllStop":"Apply","ModeAllStopId":"0b7c3e5d-9a21"})"))
            << "MachineAllStopRequestV1.ModeAllStopId: malformed GUID '0b7c3e5d-9a21'";
        QTest::newRow("malformed timestamp")
            << QString::fromStdString(msg(
                   R"("MapSummaryV1":{"Timestamp":"yesterday","ChangeSetMap":1,"ChangeSetWay":1,"NodeCount":1,"WayCount":1,"DocumentCount":1})"))
            << "MapSummaryV1.Timestamp: malformed timestamp 'yesterday'";
        QTest::newRow("array null")
            << QString::fromStdString(msg(
                   R"("FleetDefinitionV2":{"AHSId":"7d1f3c2a-5b8e-4c61-9a0d-2e4f6b8c1a37","Equipment":null})"))
            << "FleetDefinitionV2.Equipment: must be an array (may be empty, not null)";
        QTest::newRow("top-level array null")
            << QString::fromStdString(msg(R"("MachineDiagnosticV2":null)", true))
            << "MachineDiagnosticV2: must be an array (may be empty, not null)";
        QTest::newRow("heading range")
            << QString::fromStdString(
                   msg(std::string(R"("MachinePositionV1":{)") +
                           "\"Timestamp\":\"2025-03-14T02:15:07.380Z\",\"Heading\":360,\"Latitude\":1,"
                           "\"Longitude\":1,\"Elevation\":1,\"LatitudeAccuracy\":1,\"LongitudeAccuracy\":1,"
                           "\"ElevationAccuracy\":1,\"HeadingAccuracy\":1,\"Speed\":1}",
                       true))
            << "MachinePositionV1.Heading: out of range 0-359: 360";
        QTest::newRow("missing header EquipmentId")
            << QString::fromStdString(msg(R"("MachineAutonomyModeV1":{"AutonomyMode":"Manual"})"))
            << "MachineAutonomyModeV1: header EquipmentId required for this message";
        QTest::newRow("non-null shall")
            << QString::fromStdString(
                   msg(R"("MachineDiagnosticV2":[{"ComponentId":null,"FaultCode":1}])", true))
            << "MachineDiagnosticV2[0].ComponentId: must not be null";
    }
    void rejections() {
        QFETCH(QString, text);
        QFETCH(QString, error);
        auto r = decodeMessage(text.toStdString());
        QVERIFY(r.ok()); // the frame itself is fine; the member is rejected
        QCOMPARE(r->errors.size(), std::size_t(1));
        QCOMPARE(QString::fromStdString(r->errors[0]), error);
        QVERIFY(r->members.empty());
    }

    void frameRejections() {
        auto bad = decodeMessage("{not json");
        QVERIFY(!bad.ok());
        QCOMPARE(QString::fromStdString(bad.error()), QString("message: invalid JSON"));
        auto arr = decodeMessage("[1,2]");
        QVERIFY(!arr.ok());
        QCOMPARE(QString::fromStdString(arr.error()), QString("message: expected a JSON object, got array"));
        auto noTs = decodeMessage(R"({"Protocol":"ISO23725","Version":1,"MapServiceV1":{"API":1}})");
        QVERIFY(!noTs.ok());
        QCOMPARE(QString::fromStdString(noTs.error()), QString("header.Timestamp: required member missing"));
        auto badTs = decodeMessage(
            R"({"Protocol":"ISO23725","Version":1,"Timestamp":"2025-13-01T00:00:00Z","MapServiceV1":{"API":1}})");
        QVERIFY(!badTs.ok());
        QCOMPARE(QString::fromStdString(badTs.error()),
                 QString("header.Timestamp: malformed timestamp '2025-13-01T00:00:00Z'"));
    }

    void goodMembersSurviveABadOne() {
        // A bad piggy-backed position must not drop the autonomy mode it came with.
        auto r = decodeMessage(msg(
            R"("MachineAutonomyModeV1":{"AutonomyMode":"Manual"},"MachinePositionV1":{"Heading":"north"})",
            true));
        QVERIFY(r.ok());
        QVERIFY(r->find<MachineAutonomyModeV1>());
        QCOMPARE(r->errors.size(), std::size_t(1));
        QVERIFY(r->errors[0].rfind("MachinePositionV1.", 0) == 0);
    }

    void lenientWhereTheNoteSaysSo() {
        // Seed example timestamp "…10.43.511Z" is repaired, with a warning.
        auto r = decodeMessage(
            R"({"Protocol":"ISO23725","Version":1,"Timestamp":"2018-10-31T09:30:10.43.511Z","FleetDefinitionV2":{"AHSId":"5318e44c-e9f0-42e2-9965-a4a1ff364f4b","Equipment":[]}})");
        QVERIFY(r.ok());
        QVERIFY(r->errors.empty());
        QCOMPARE(*r->header.timestamp.unixMs, parseTimestamp("2018-10-31T09:30:10.435Z", false).value());
        QVERIFY(!r->warnings.empty());
        // Numbers as strings, decimal speed, HeightAccuracy alias, AttachmentV1 alias, missing Version.
        auto p = decodeMessage(
            R"({"Protocol":"ISO23725","Timestamp":"2025-03-14T02:15:07.412Z","EquipmentID":"C3A51F7E-0D24-4B9A-8F63-1E2D4C5B6A78","MachinePositionV1":{"Timestamp":"2025-03-14T02:15:07.380Z","Heading":"222","Latitude":-23.36,"Longitude":119.73,"Elevation":512.3,"LatitudeAccuracy":0.1,"LongitudeAccuracy":0.1,"HeightAccuracy":0.2,"HeadingAccuracy":1,"Speed":"43.1","AttachmentV1":[]}})");
        QVERIFY(p.ok());
        QVERIFY2(p->errors.empty(), p->errors.empty() ? "" : p->errors[0].c_str());
        auto* pos = p->find<MachinePositionV1>();
        QCOMPARE(*pos->pose.heading, 222);
        QCOMPARE(*pos->pose.speed, 43);
        QCOMPARE(*pos->pose.elevationAccuracy, 0.2);
        QVERIFY(pos->attachment && pos->attachment->empty());
        QVERIFY(!p->header.version);
        QCOMPARE(*p->header.equipmentId, std::string("c3a51f7e-0d24-4b9a-8f63-1e2d4c5b6a78"));
        // Emits the table names.
        json out = toJson(*p);
        QVERIFY(out["MachinePositionV1"].contains("ElevationAccuracy"));
        QVERIFY(out["MachinePositionV1"].contains("Attachment"));
        QVERIFY(out.contains("EquipmentId"));
        // "GET" accepted in any case; status alias of Q4.
        auto c = decodeMessage(msg(
            R"("MapCommandV1":{"Method":"Get","Scope":"/"},"MachineAllStopStatusV1":{"ModeAllStop":"off","ModeAllStopId":null})"));
        QVERIFY(c.ok());
        QCOMPARE(c->find<MapCommandV1>()->method, std::string("GET"));
        QCOMPARE(c->find<MachineAllStopV1>()->modeAllStop, std::string("Off"));
    }

    void strictRulesRejectWhatLenientAccepts() {
        InferredRules strict;
        strict.acceptNumericStrings = false;
        strict.repairTimestamps = false;
        strict.acceptAliases = false;
        strict.acceptMissingVersion = false;
        auto r =
            decodeMessage(msg(R"("MachineDiagnosticV2":[{"ComponentId":"5","FaultCode":1}])", true), strict);
        QCOMPARE(r->errors.at(0),
                 std::string("MachineDiagnosticV2[0].ComponentId: expected a number, got string"));
        auto t = decodeMessage(
            R"({"Protocol":"ISO23725","Version":1,"Timestamp":"2018-10-31T09:30:10.43.511Z","MapServiceV1":{"API":1}})",
            strict);
        QVERIFY(!t.ok());
        auto v = decodeMessage(
            R"({"Protocol":"ISO23725","Timestamp":"2018-10-31T09:30:10Z","MapServiceV1":{"API":1}})", strict);
        QCOMPARE(QString::fromStdString(v.error()), QString("header.Version: required member missing"));
    }

    void unknownMembersAndProtocolsKept() {
        std::string text =
            R"({"Protocol":"Open-Autonomy","Version":1,"Timestamp":"2025-03-14T02:15:09.001Z","OutOfSyncV1":{"X":1},"MapServiceV1":{"API":2,"Vendor":"acme"}})";
        auto r = decodeMessage(text);
        QVERIFY(r.ok());
        QVERIFY(r->outOfStandard);
        QVERIFY(r->errors.empty());
        QCOMPARE(r->members.size(), std::size_t(2));
        QCOMPARE(r->find<UnknownMember>()->name, std::string("OutOfSyncV1"));
        QCOMPARE(r->find<MapServiceV1>()->api, 2);
        QCOMPARE(r->warnings.size(), std::size_t(3)); // protocol, unknown member, unknown field
        QCOMPARE(toJson(*r), json::parse(text));      // kept verbatim on re-serialisation
    }

    void encodeHelpers() {
        QCOMPARE(QString::fromStdString(formatTimestamp(1741918507412)), QString("2025-03-14T02:15:07.412Z"));
        QCOMPARE(*parseTimestamp("2025-03-14T04:15:07.412+02:00", false), 1741918507412LL);
        auto g = newGuid();
        QVERIFY(isGuid(g));
        QCOMPARE(g[14], '4');
        std::string s = encodeMessage(MachineAllStopRequestV1{"Apply", g}, std::nullopt, 1741918507412);
        auto r = decodeMessage(s);
        QVERIFY(r.ok());
        QCOMPARE(r->find<MachineAllStopRequestV1>()->modeAllStopId, g);
        QCOMPARE(r->header.timestamp.text, std::string("2025-03-14T02:15:07.412Z"));
    }
};

QTEST_GUILESS_MAIN(TestIsoMessages)
#include "test_iso_messages.moc"
