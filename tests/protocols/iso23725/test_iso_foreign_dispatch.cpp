// The console's dispatch frames as a foreign AHS receives them. The peer
// (foreign/ForeignAhs, written from the research note's tables, no code shared with sim/) records the frames
// verbatim; each is compared with the JSON the tables prescribe, written out by hand here: member names,
// value types (integers as integers), nothing more and nothing less. Refusals (custodian not FMS or not
// reported, unreachable destination) put nothing on the wire and say why.
#include "protocols/iso23725/IsoStack.h"
#include "tests/protocols/iso23725/IsoTestSupport.h"
#include "tests/protocols/iso23725/foreign/ForeignAhs.h"
#include "tests/support/JsonFrames.h"

#include <nlohmann/json.hpp>

#include <QtTest>

#include <future>
#include <regex>

using namespace isotest;
using isosim::withoutTimestamp;
using nlohmann::json;

namespace {

const std::string kTruck = "c3a51f7e-0d24-4b9a-8f63-1e2d4c5b6a78";
const std::string kShovel = "a2d4f6b8-1c3e-4a5b-9d7f-0e2c4b6a8d13";
const std::string kLoadId = "e41a7c2b-6d3f-4b58-a9e0-7f1c2d3b4a56";
const std::string kDumpId = "f52b8d3c-7e40-4c69-b0f1-8a2d3e4c5b67";

struct Listener : Recorder {
    std::atomic<int> connectivity{0};
    void onConnectivity(const std::string&, const MapConnectivityV1&) override { ++connectivity; }
};

IsoConfig consoleConfig(const std::string& url) {
    IsoConfig c;
    c.fmsId = "0f1e2d3c-4b5a-4968-8776-a5b4c3d2e1f0";
    c.links.push_back(IsoLinkConfig{"ahs", {}, {}});
    c.links[0].ws.url = url;
    c.links[0].ws.backoffMin = std::chrono::milliseconds(100);
    c.links[0].ws.backoffMax = std::chrono::milliseconds(400);
    return c;
}

struct Session {
    explicit Session(foreign::ForeignAhsOptions o = {})
        : peer(std::move(o)), stack(consoleConfig(peer.url()), rec) {}
    foreign::ForeignAhs peer;
    Listener rec;
    IsoStack stack;
    bool up() {
        return stack.start() && waitFor([&] { return rec.link("ahs") == LinkState::Up; }) &&
               waitFor([&] { return rec.connectivity.load() > 0; }); // the last frame of the peer's snapshot
    }
};

} // namespace

class TestIsoForeignDispatch : public QObject {
    Q_OBJECT
private slots:
    // Rows 21 and 23, §6 examples 21 and 23: what the peer receives, byte for byte as the tables say.
    void assignmentAndResetAsTheTablesSay() {
        Session s;
        QVERIFY(s.up());
        std::vector<AssignmentItem> items{AssignmentItem{kLoadId, "Load", 4201, kShovel, std::nullopt,
                                                         std::nullopt}, // the console routes it
                                          AssignmentItem{kDumpId, "Offload", 4101, std::nullopt, std::nullopt,
                                                         std::vector<WayRef>{{2001}}}};
        auto o = outcome([&](auto done) { s.stack.requestAssignment("ahs", kTruck, items, done); });
        QCOMPARE(o.size(), std::size_t(1));
        QCOMPARE(o[0].target, "iso23725:" + kTruck);
        QVERIFY2(o[0].sent, o[0].reason.c_str());
        const std::string frame = s.peer.waitFor("HaulTruckAssignmentRequestV2");
        QVERIFY(!frame.empty());
        const json expected = json::parse(R"({"Protocol":"ISO23725","Version":1,
            "EquipmentId":"c3a51f7e-0d24-4b9a-8f63-1e2d4c5b6a78",
            "HaulTruckAssignmentRequestV2":[
              {"AssignmentId":"e41a7c2b-6d3f-4b58-a9e0-7f1c2d3b4a56","Task":"Load","DestinationId":4201,
               "DestinationEquipmentId":"a2d4f6b8-1c3e-4a5b-9d7f-0e2c4b6a8d13","RouteV1":[{"WayId":2001}]},
              {"AssignmentId":"f52b8d3c-7e40-4c69-b0f1-8a2d3e4c5b67","Task":"Offload","DestinationId":4101,
               "RouteV1":[{"WayId":2001}]}]})");
        QVERIFY2(withoutTimestamp(frame) == expected, frame.c_str());
        // Integers on the wire, not decimals; one JSON object per text frame.
        QVERIFY(frame.find("\"DestinationId\":4201,") != std::string::npos ||
                frame.find("\"DestinationId\":4201}") != std::string::npos);
        QVERIFY(frame.find("\"WayId\":2001}") != std::string::npos);
        QCOMPARE(frame.front(), '{');
        QCOMPARE(frame.back(), '}');

        // The peer's Accepted (row 22) and Active (row 24) are what the console shows.
        QVERIFY(waitFor([&] {
            return s.rec.machinesWith([](const IsoMachineSnapshot& m) {
                return m.assignment && m.assignment->status == "Active" &&
                       m.assignment->assignmentId == std::optional<Guid>(kLoadId) &&
                       m.assignmentResponses.size() == 2 && m.assignmentResponses[0].response == "Accepted";
            }) == 1;
        }));

        // Row 23: the reset names the truck in the header and carries a fresh ResetId, nothing else.
        o = outcome([&](auto done) { s.stack.resetAssignment("ahs", kTruck, done); });
        QVERIFY(o.size() == 1 && o[0].sent);
        const std::string reset = s.peer.waitFor("HaulTruckAssignmentResetV1");
        QVERIFY(!reset.empty());
        json r = withoutTimestamp(reset);
        QVERIFY(r.contains("HaulTruckAssignmentResetV1"));
        const std::string resetId = r["HaulTruckAssignmentResetV1"]["ResetId"].get<std::string>();
        QVERIFY(std::regex_match(
            resetId, std::regex("[0-9a-f]{8}-[0-9a-f]{4}-4[0-9a-f]{3}-[89ab][0-9a-f]{3}-[0-9a-f]{12}")));
        QCOMPARE(r, json::parse(R"({"Protocol":"ISO23725","Version":1,"EquipmentId":")" + kTruck +
                                R"(","HaulTruckAssignmentResetV1":{"ResetId":")" + resetId + R"("}})"));

        // Row 13: the map fetch is sent (the socket took it) as MapCommandV1 GET "/".
        o = outcome([&](auto done) { s.stack.fetchMap("ahs", done); });
        QCOMPARE(o[0].target, std::string("iso23725 link ahs"));
        QVERIFY2(o[0].sent, o[0].reason.c_str());
        const std::string fetch = s.peer.waitFor(R"("Scope":"/")");
        QCOMPARE(withoutTimestamp(fetch),
                 json::parse(
                     R"({"Protocol":"ISO23725","Version":1,"MapCommandV1":{"Method":"GET","Scope":"/"}})"));
    }

    // Row 21's other members: DestinationSpotId instead of DestinationEquipmentId, AssignmentIds the console
    // makes (lower-case GUIDs, one per task), RouteV1 computed over the peer's MapConnectivityV1 (the ways in
    // between, neither the truck's way nor the destination; a future task starts at the previous destination)
    // and left out when there is no way in between; both destination members together are refused unsent.
    void spotTaskAndRoutesAsTheTablesSay() {
        Session s;
        QVERIFY(s.up());
        std::vector<AssignmentItem> items{
            AssignmentItem{"", "Load", 4201, std::nullopt, std::int64_t(7), std::nullopt},
            AssignmentItem{"", "Offload", 4101, std::nullopt, std::nullopt, std::nullopt},
            AssignmentItem{"", "Wait", 4101, std::nullopt, std::nullopt, std::nullopt}};
        auto o = outcome([&](auto done) { s.stack.requestAssignment("ahs", kTruck, items, done); });
        QVERIFY(o.size() == 1);
        QVERIFY2(o[0].sent, o[0].reason.c_str());
        const std::string frame = s.peer.waitFor("HaulTruckAssignmentRequestV2");
        QVERIFY(!frame.empty());
        json got = withoutTimestamp(frame);
        QVERIFY2(got.is_object() && got["HaulTruckAssignmentRequestV2"].is_array() &&
                     got["HaulTruckAssignmentRequestV2"].size() == 3,
                 frame.c_str());
        const std::regex guid("[0-9a-f]{8}-[0-9a-f]{4}-4[0-9a-f]{3}-[89ab][0-9a-f]{3}-[0-9a-f]{12}");
        std::vector<std::string> ids;
        for (const auto& a : got["HaulTruckAssignmentRequestV2"]) {
            QVERIFY2(a.contains("AssignmentId") && a["AssignmentId"].is_string(), frame.c_str());
            ids.push_back(a["AssignmentId"].get<std::string>());
            QVERIFY2(std::regex_match(ids.back(), guid), ids.back().c_str());
        }
        QVERIFY(ids[0] != ids[1] && ids[1] != ids[2] && ids[0] != ids[2]);
        const json expected =
            json::parse(R"({"Protocol":"ISO23725","Version":1,"EquipmentId":")" + kTruck +
                        R"(","HaulTruckAssignmentRequestV2":[
              {"AssignmentId":")" +
                        ids[0] +
                        R"(","Task":"Load","DestinationId":4201,"DestinationSpotId":7,
               "RouteV1":[{"WayId":2001}]},
              {"AssignmentId":")" +
                        ids[1] +
                        R"(","Task":"Offload","DestinationId":4101,"RouteV1":[{"WayId":2001}]},
              {"AssignmentId":")" +
                        ids[2] + R"(","Task":"Wait","DestinationId":4101}]})");
        QVERIFY2(got == expected, frame.c_str());
        QVERIFY(frame.find("\"DestinationSpotId\":7") != std::string::npos); // an integer, not 7.0 or "7"

        // Both destination members: refused with the rule, nothing more on the wire.
        const std::size_t before = s.peer.received().size();
        o = outcome([&](auto done) {
            s.stack.requestAssignment(
                "ahs", kTruck, {AssignmentItem{"", "Load", 4201, kShovel, std::int64_t(7), std::nullopt}},
                done);
        });
        QVERIFY(o.size() == 1 && !o[0].sent);
        QVERIFY2(o[0].reason.find("mutually exclusive") != std::string::npos, o[0].reason.c_str());
        QTest::qWait(200);
        const auto after = s.peer.received();
        for (std::size_t i = before; i < after.size(); ++i)
            QVERIFY2(after[i].find("HaulTruckAssignmentRequestV2") == std::string::npos, after[i].c_str());
    }

    // Refused before sending, with the reason; the peer receives nothing of it.
    void refusalsPutNothingOnTheWire() {
        {
            Session s; // 4301 has no way in: unreachable from the truck's way 4101
            QVERIFY(s.up());
            auto o = outcome([&](auto done) {
                s.stack.requestAssignment("ahs", kTruck, {AssignmentItem{"", "Park", 4301, {}, {}, {}}},
                                          done);
            });
            QVERIFY(o.size() == 1 && !o[0].sent);
            QCOMPARE(o[0].reason,
                     std::string("task Park: destination way 4301 unreachable from way 4101 over "
                                 "MapConnectivityV1"));
        }
        for (const std::string custodian : {"", "AHS"}) {
            foreign::ForeignAhsOptions opt;
            opt.custodian = custodian; // a peer that never says, or keeps the truck to itself
            Session s(opt);
            QVERIFY(s.up());
            auto o = outcome([&](auto done) {
                s.stack.requestAssignment("ahs", kTruck, {AssignmentItem{"", "Load", 4201, {}, {}, {}}},
                                          done);
            });
            QVERIFY(o.size() == 1 && !o[0].sent);
            QCOMPARE(o[0].reason,
                     custodian.empty()
                         ? std::string("HT01 has not reported its DispatchingCustodian yet")
                         : std::string("HT01 is dispatched by the AHS (DispatchingCustodian AHS)"));
            s.stack.stop();
            for (const auto& f : s.peer.received())
                QVERIFY2(f.find("HaulTruckAssignmentRequestV2") == std::string::npos, f.c_str());
        }
    }

    // A peer that never answers: the request was still sent (the outcome says so) and the console shows no
    // assignment, because only the AHS's reports make one.
    void unansweredRequestShowsNoAssignment() {
        foreign::ForeignAhsOptions opt;
        opt.answerAssignments = false;
        Session s(opt);
        QVERIFY(s.up());
        auto o = outcome([&](auto done) {
            s.stack.requestAssignment("ahs", kTruck, {AssignmentItem{"", "Load", 4201, {}, {}, {}}}, done);
        });
        QVERIFY(o.size() == 1 && o[0].sent);
        QVERIFY(!s.peer.waitFor("HaulTruckAssignmentRequestV2").empty());
        QTest::qWait(300);
        auto machines = s.stack.machines("ahs");
        QCOMPARE(machines.size(), std::size_t(1));
        QVERIFY(!machines[0].assignment);
        QVERIFY(machines[0].assignmentResponses.empty());
        QCOMPARE(machines[0].requestedAssignments.size(), std::size_t(1));
    }
};

QTEST_APPLESS_MAIN(TestIsoForeignDispatch)
#include "test_iso_foreign_dispatch.moc"
