// FmsCore on a fake clock, no sockets: the fleet definition goes first, commands are refused while down,
// the all-stop acknowledgement and status timeouts raise their alarms exactly at the deadline, state comes
// only from MachineAllStopV1, interface diagnostics are sent every period and on error (rate-limited), and a
// separate map-service socket (Q10) carries the map exchange.
#include "protocols/iso23725/FmsCore.h"

#include <QtTest>

#include <fstream>
#include <sstream>

using namespace ocu;
using namespace ocu::iso23725;
using namespace std::chrono_literals;

namespace {

const Guid kFms = "0f1e2d3c-4b5a-4968-8776-a5b4c3d2e1f0";
const Guid kTruck = "c3a51f7e-0d24-4b9a-8f63-1e2d4c5b6a78";
const Guid kLight = "5a6b7c8d-9e0f-4a1b-8c2d-3e4f5a6b7c8d";
const Guid kUnknownTruck = "11111111-2222-4333-8444-555555555555";

struct Outbound final : FmsOutbound {
    bool mainOpen = true;
    bool mapOpen = true;
    std::vector<std::string> main;
    std::vector<std::string> map;
    bool sendMain(std::string text) override {
        if (!mainOpen)
            return false;
        main.push_back(std::move(text));
        return true;
    }
    bool sendMap(std::string text) override {
        if (!mapOpen)
            return false;
        map.push_back(std::move(text));
        return true;
    }
};

struct Listener final : IsoListener {
    std::vector<std::pair<IsoSeverity, std::string>> events;
    std::vector<std::string> order; // "link:UP", "allstop:UNKNOWN", "machine" ...
    std::vector<AllStopStatus> allStops;
    std::vector<std::vector<std::string>> discrepancies;
    int maps = 0;
    void onLinkState(const std::string&, LinkState s, const std::string&) override {
        order.push_back(std::string("link:") + nameFor(s));
    }
    void onMachineChanged(const IsoMachineSnapshot&) override { order.push_back("machine"); }
    void onAllStopChanged(const std::string&, const AllStopStatus& s) override {
        allStops.push_back(s);
        order.push_back(std::string("allstop:") + nameFor(s.state));
    }
    void onMapChanged(const std::string&, const MapModel&) override { ++maps; }
    void onFleetDiscrepancies(const std::string&, const std::vector<FleetDiscrepancy>& items) override {
        discrepancies.push_back(discrepancyTexts(items));
    }
    void onEvent(IsoSeverity s, const std::string& text) override { events.emplace_back(s, text); }
    int count(IsoSeverity s, const std::string& part) const {
        int n = 0;
        for (auto& [sev, text] : events)
            if (sev == s && text.find(part) != std::string::npos)
                ++n;
        return n;
    }
};

// The body of the only member of one sent frame.
template <class T> std::optional<T> bodyOf(const std::string& frame) {
    auto env = decodeMessage(frame);
    if (!env || env->members.size() != 1)
        return std::nullopt;
    if (auto* p = std::get_if<T>(&env->members.front().body))
        return *p;
    return std::nullopt;
}
template <class T> std::vector<T> allOf(const std::vector<std::string>& frames) {
    std::vector<T> out;
    for (auto& f : frames)
        if (auto b = bodyOf<T>(f))
            out.push_back(*b);
    return out;
}

std::string fromAhs(const Body& body, std::optional<Guid> eq = std::nullopt) {
    return encodeMessage(body, eq);
}

IsoConfig config() {
    IsoConfig c;
    c.fmsId = kFms;
    Equipment truck{kTruck, "HT01", "HaulTruck", "OEM", "793F", true, 12.9, 7.6};
    Equipment light{kLight, "LV07", "LightVehicle", "OEM", "Hilux", false, 5.3, 1.9};
    c.fleet = {truck, light};
    return c;
}

FleetDefinitionV2 ahsFleet() {
    FleetDefinitionV2 f;
    f.ahsId = "7d1f3c2a-5b8e-4c61-9a0d-2e4f6b8c1a37";
    f.equipment.push_back(Equipment{kTruck, "HT01", "HaulTruck", "OEM", "793F", true, 12.9, 7.6});
    return f;
}

struct Fixture {
    explicit Fixture(IsoLinkConfig link = IsoLinkConfig{"ahs", {}, {}}) : cfg(config()) {
        session = std::make_unique<FmsCore>(cfg, std::move(link), listener, counters, clock, out);
    }
    IsoConfig cfg;
    FakeClock clock;
    Counters counters;
    Listener listener;
    Outbound out;
    std::unique_ptr<FmsCore> session;

    void connect() {
        session->opened("127.0.0.1:9000");
        session->text(fromAhs(ahsFleet()));
        session->text(fromAhs(MachineAllStopV1{"Off", std::nullopt}));
    }
    void advance(std::chrono::milliseconds d) {
        clock.advance(d);
        session->poll();
    }
};

std::string mapExample() {
    std::ifstream in(OCU_ISO_TEST_DATA "/map_example.osm");
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

} // namespace

class TestFmsCore : public QObject {
    Q_OBJECT
private slots:
    void fleetDefinitionFirstWithMannedMachinesOnly() {
        Fixture f;
        f.session->opened("peer");
        QCOMPARE(f.out.main.size(), std::size_t(1));
        auto fleet = bodyOf<FleetDefinitionV2>(f.out.main.front());
        QVERIFY(fleet);
        QCOMPARE(fleet->ahsId, kFms);
        QCOMPARE(fleet->equipment.size(), std::size_t(1)); // the autonomous truck is expected, not sent
        QCOMPARE(fleet->equipment.front().equipmentId, kLight);
    }

    void discrepancyReported() {
        Fixture f;
        f.session->opened("peer");
        auto fleet = ahsFleet();
        fleet.equipment.front().type = "WaterCart";
        f.session->text(fromAhs(fleet));
        QCOMPARE(f.listener.discrepancies.size(), std::size_t(1));
        QCOMPARE(f.listener.discrepancies.front().size(), std::size_t(1));
        QCOMPARE(f.listener.discrepancies.front().front(),
                 std::string("machine " + kTruck + ": type WaterCart at the AHS, HaulTruck at the FMS"));
        // One report per discrepancy, not two: no event mentions it.
        QCOMPARE(f.listener.count(IsoSeverity::Warning, "WaterCart"), 0);
        QCOMPARE(f.listener.count(IsoSeverity::Info, "WaterCart"), 0);
    }

    void commandsRefusedWhileDown() {
        Fixture f;
        QVERIFY(!f.session->allStopApply()); // never connected: UNKNOWN
        f.connect();
        f.session->closed("peer went away");
        const auto sent = f.out.main.size();
        QVERIFY(!f.session->allStopApply());
        QVERIFY(!f.session->resetAssignment(kTruck));
        QVERIFY(!f.session->fetchMap());
        QCOMPARE(f.out.main.size(), sent); // nothing queued for later (§2.1 rule 1)
        QCOMPARE(f.counters.get("cmd.refused.link_down"), std::uint64_t(4));
        QCOMPARE(f.listener.count(IsoSeverity::Warning, "all-stop Apply refused: link 'ahs' is DOWN"), 1);
    }

    // Up, but the socket does not take the frame (closing under us): not sent, with the reason.
    void allStopNotTakenBySocketIsNotSent() {
        Fixture f;
        f.connect();
        f.out.mainOpen = false;
        QVERIFY(!f.session->allStopApply());
        QVERIFY2(f.session->lastRefusal().find("did not take the frame") != std::string::npos,
                 f.session->lastRefusal().c_str());
        QCOMPARE(f.counters.get("allstop.apply"), std::uint64_t(0));
        QVERIFY(!f.session->allStop().pendingId);
        f.out.mainOpen = true;
        QVERIFY(f.session->allStopApply());
        QCOMPARE(allOf<MachineAllStopRequestV1>(f.out.main).size(), std::size_t(1));
    }

    // Assignments only while the AHS lets the FMS dispatch the truck; AHS -> FMS asks for work.
    void assignmentOnlyWhileCustodianIsFms() {
        Fixture f;
        f.connect();
        const auto sent = f.out.main.size();
        const std::vector<AssignmentItem> load{AssignmentItem{"", "Load", 4201, {}, {}, {}}};
        QVERIFY(!f.session->requestAssignment(kTruck, load)); // custodian not reported yet
        QCOMPARE(f.session->lastRefusal(), std::string("HT01 has not reported its DispatchingCustodian yet"));
        f.session->text(fromAhs(MachineDispatchAvailabilityV1{"AHS", std::nullopt, std::nullopt}, kTruck));
        QVERIFY(!f.session->requestAssignment(kTruck, load));
        QCOMPARE(f.session->lastRefusal(),
                 std::string("HT01 is dispatched by the AHS (DispatchingCustodian AHS)"));
        QCOMPARE(f.out.main.size(), sent); // nothing on the wire
        QVERIFY(!f.session->machines().at(kTruck).needsAssignment);
        f.session->text(fromAhs(MachineDispatchAvailabilityV1{"FMS", std::nullopt, std::nullopt}, kTruck));
        QVERIFY(f.session->machines().at(kTruck).needsAssignment);
        QCOMPARE(f.listener.count(IsoSeverity::Warning, "HT01 needs an assignment (custodian AHS -> FMS"), 1);
        QVERIFY(f.session->requestAssignment(kTruck, load));
        auto req = bodyOf<HaulTruckAssignmentRequestV2>(f.out.main.back());
        QVERIFY(req);
        QCOMPARE(req->items.size(), std::size_t(1));
        QVERIFY(isGuid(req->items[0].assignmentId));
        QCOMPARE(req->items[0].task, std::string("Load"));
        QVERIFY(!req->items[0].route); // no MapConnectivityV1 yet: no route of ours
        QCOMPARE(*decodeMessage(f.out.main.back())->header.equipmentId, kTruck);
        f.session->text(fromAhs(HaulTruckAssignmentResponseV1{{AssignmentResponseItem{
                                    req->items[0].assignmentId, "Accepted", {}}}},
                                kTruck));
        QVERIFY(!f.session->machines().at(kTruck).needsAssignment);
        // Bad tasks never leave.
        QVERIFY(!f.session->requestAssignment(kTruck, {AssignmentItem{"", "Dig", 4201, {}, {}, {}}}));
        QCOMPARE(f.session->lastRefusal(),
                 std::string("task 'Dig' is not one of Load, Offload, Fuel, Park, Wait"));
        QVERIFY(!f.session->requestAssignment(kTruck, {}));
        QVERIFY(!f.session->requestAssignment(kUnknownTruck, load));
        QCOMPARE(allOf<HaulTruckAssignmentRequestV2>(f.out.main).size(), std::size_t(1));
    }

    // Once MapConnectivityV1 is known, destinations are routed from the truck's current way; an
    // unreachable or unknown one is refused before sending.
    void unreachableDestinationRefusedAndRoutesFilledIn() {
        Fixture f;
        f.connect();
        f.session->text(fromAhs(MachineDispatchAvailabilityV1{"FMS", std::nullopt, std::nullopt}, kTruck));
        auto conn = decodeMessage(
            R"({"Protocol":"ISO23725","Version":1,"Timestamp":"2025-03-14T02:15:01.000Z","MapConnectivityV1":[)"
            R"({"WayId":4101,"WayType":"Area","AreaProperty":{"DefaultTask":"Offload","Name":"North Waste Dump"},"Connection":[{"WayId":2001}]},)"
            R"({"WayId":2001,"WayType":"Road","RoadProperty":{"Length":1840.5,"Name":"North Ramp"},"Connection":[{"WayId":4101},{"WayId":4201}]},)"
            R"({"WayId":4201,"WayType":"Area","AreaProperty":{"DefaultTask":"Load","Name":"Pit 3 Bench 480"},"Connection":[{"WayId":2001}]},)"
            R"({"WayId":4301,"WayType":"Area","AreaProperty":{"DefaultTask":"Park","Name":"Closed bay"},"Connection":[]}]})");
        QVERIFY(conn);
        f.session->text(encodeMessage(*conn));
        QCOMPARE(f.session->routes().size(), std::size_t(4));
        f.session->text(
            fromAhs(HaulTruckProductionStateV2{std::nullopt, 4101, "Autonomous", "Parked"}, kTruck));
        const auto sent = f.out.main.size();
        QVERIFY(!f.session->requestAssignment(kTruck, {AssignmentItem{"", "Park", 4301, {}, {}, {}}}));
        QCOMPARE(
            f.session->lastRefusal(),
            std::string("task Park: destination way 4301 unreachable from way 4101 over MapConnectivityV1"));
        QVERIFY(!f.session->requestAssignment(kTruck, {AssignmentItem{"", "Load", 9999, {}, {}, {}}}));
        QCOMPARE(f.session->lastRefusal(),
                 std::string("destination way 9999 is not in the AHS's MapConnectivityV1"));
        // A future task is routed from the previous destination: 4201 -> 4301 is unreachable too.
        QVERIFY(!f.session->requestAssignment(kTruck, {AssignmentItem{"", "Load", 4201, {}, {}, {}},
                                                       AssignmentItem{"", "Park", 4301, {}, {}, {}}}));
        QCOMPARE(f.out.main.size(), sent);
        QCOMPARE(f.counters.get("cmd.refused"), std::uint64_t(3));
        // Load at 4201 then offload at 4101: both routed over 2001.
        QVERIFY(f.session->requestAssignment(kTruck, {AssignmentItem{"", "Load", 4201, {}, {}, {}},
                                                      AssignmentItem{"", "Offload", 4101, {}, {}, {}}}));
        auto req = bodyOf<HaulTruckAssignmentRequestV2>(f.out.main.back());
        QVERIFY(req);
        QCOMPARE(*req->items[0].route, (std::vector<WayRef>{{2001}}));
        QCOMPARE(*req->items[1].route, (std::vector<WayRef>{{2001}}));
        // An operator's route that breaks is refused; one that holds is sent as given.
        QVERIFY(!f.session->requestAssignment(
            kTruck, {AssignmentItem{"", "Load", 4201, {}, {}, std::vector<WayRef>{{4301}}}}));
        QVERIFY(f.session->lastRefusal().find("route breaks") != std::string::npos);
    }

    // §5 #22 [I]: a Rejected after an Accepted is the AHS giving the task up: a warning, the response
    // replaced.
    void unsolicitedRejectedIsAWithdrawal() {
        Fixture f;
        f.connect();
        f.session->text(fromAhs(MachineDispatchAvailabilityV1{"FMS", std::nullopt, std::nullopt}, kTruck));
        QVERIFY(f.session->requestAssignment(kTruck, {AssignmentItem{"", "Load", 4201, {}, {}, {}}}));
        const Guid id = bodyOf<HaulTruckAssignmentRequestV2>(f.out.main.back())->items[0].assignmentId;
        f.session->text(
            fromAhs(HaulTruckAssignmentResponseV1{{AssignmentResponseItem{id, "Accepted", {}}}}, kTruck));
        f.session->text(fromAhs(HaulTruckAssignmentResponseV1{{AssignmentResponseItem{
                                    id, "Rejected", std::string("shovel SH01 down")}}},
                                kTruck));
        const auto& m = f.session->machines().at(kTruck);
        QCOMPARE(m.assignmentResponses.size(), std::size_t(1));
        QCOMPARE(m.assignmentResponses[0].response, std::string("Rejected"));
        QCOMPARE(*m.assignmentResponses[0].detail, std::string("shovel SH01 down"));
        QCOMPARE(f.listener.count(IsoSeverity::Warning,
                                  "can no longer be done: Rejected by the AHS (shovel SH01 down)"),
                 1);
        QCOMPARE(f.counters.get("assignment.withdrawn"), std::uint64_t(1));
    }

    // What went on the wire, for assignment, reset and map fetch: up, but the socket does not take the frame.
    void assignmentResetAndFetchNotTakenBySocketAreNotSent() {
        Fixture f;
        f.connect();
        f.session->text(fromAhs(MachineDispatchAvailabilityV1{"FMS", std::nullopt, std::nullopt}, kTruck));
        f.out.mainOpen = false;
        QVERIFY(!f.session->requestAssignment(kTruck, {AssignmentItem{"", "Load", 4201, {}, {}, {}}}));
        QVERIFY(f.session->lastRefusal().find("did not take the frame") != std::string::npos);
        QVERIFY(f.session->machines().at(kTruck).requestedAssignments.empty());
        QVERIFY(!f.session->resetAssignment(kTruck));
        QVERIFY(f.session->lastRefusal().find("did not take the frame") != std::string::npos);
        QVERIFY(!f.session->fetchMap());
        QVERIFY(f.session->lastRefusal().find("did not take the frame") != std::string::npos);
        QCOMPARE(f.counters.get("assignment.request"), std::uint64_t(0));
        QCOMPARE(f.counters.get("map.fetch"), std::uint64_t(0));
        f.out.mainOpen = true;
        QVERIFY(f.session->resetAssignment(kTruck));
        QVERIFY(f.session->fetchMap());
        QCOMPARE(allOf<HaulTruckAssignmentResetV1>(f.out.main).size(), std::size_t(1));
        QCOMPARE(allOf<MapCommandV1>(f.out.main).size(), std::size_t(1));
    }

    void closeMakesStateUnknownBeforeLinkDown() {
        Fixture f;
        f.connect();
        f.session->text(fromAhs(MachineAutonomyModeV1{"Autonomous"}, kTruck));
        QVERIFY(f.session->machines().at(kTruck).stateKnown);
        f.listener.order.clear();
        f.session->closed("gone");
        QCOMPARE(f.session->allStop().state, AllStopState::Unknown);
        QVERIFY(!f.session->machines().at(kTruck).stateKnown);
        QCOMPARE(f.listener.order, (std::vector<std::string>{"allstop:UNKNOWN", "machine", "link:DOWN"}));
    }

    void allStopAckTimeoutExactlyAtDeadline() {
        Fixture f;
        f.connect();
        QVERIFY(f.session->allStopApply());
        auto req = bodyOf<MachineAllStopRequestV1>(f.out.main.back());
        QVERIFY(req);
        QCOMPARE(req->modeAllStop, std::string("Apply"));
        QVERIFY(isGuid(req->modeAllStopId));
        f.advance(1999ms);
        QCOMPARE(f.counters.get("allstop.timeout"), std::uint64_t(0));
        f.advance(1ms);
        QCOMPARE(f.counters.get("allstop.timeout"), std::uint64_t(1));
        QCOMPARE(f.listener.count(IsoSeverity::Error, "all-stop not acknowledged on ahs"), 1);
        f.advance(10s); // an alarm is raised once, not on every poll
        QCOMPARE(f.counters.get("allstop.timeout"), std::uint64_t(1));
        QCOMPARE(f.session->allStop().state, AllStopState::Off); // never assumed On
    }

    void acceptedButStatusNeverConfirmed() {
        Fixture f;
        f.connect();
        f.session->allStopApply();
        auto id = bodyOf<MachineAllStopRequestV1>(f.out.main.back())->modeAllStopId;
        f.advance(500ms);
        f.session->text(fromAhs(MachineAllStopResponseV1{"Accepted", id, std::nullopt}));
        // The response is not the state (§7.7).
        QCOMPARE(f.session->allStop().state, AllStopState::Off);
        f.advance(4999ms);
        QCOMPARE(f.counters.get("allstop.timeout"), std::uint64_t(0)); // the ack deadline was cancelled
        f.advance(1ms);
        QCOMPARE(f.listener.count(IsoSeverity::Error, "all-stop accepted but status not confirmed on ahs"),
                 1);
    }

    void applyConfirmedThenRemoved() {
        Fixture f;
        f.connect();
        f.session->allStopApply();
        auto id = bodyOf<MachineAllStopRequestV1>(f.out.main.back())->modeAllStopId;
        f.session->text(fromAhs(MachineAllStopResponseV1{"Accepted", id, std::nullopt}));
        f.advance(300ms);
        f.session->text(fromAhs(MachineAllStopV1{"On", id}));
        QCOMPARE(f.session->allStop().state, AllStopState::On);
        QVERIFY(!f.session->allStop().external);
        f.advance(30s);
        QCOMPARE(f.counters.get("allstop.timeout"), std::uint64_t(0));

        QVERIFY(f.session->allStopRemove());
        auto rm = bodyOf<MachineAllStopRequestV1>(f.out.main.back());
        QCOMPARE(rm->modeAllStop, std::string("Remove"));
        QCOMPARE(rm->modeAllStopId, id); // the Apply id is reused [OA-iso]
        f.session->text(fromAhs(MachineAllStopResponseV1{"Accepted", id, std::nullopt}));
        f.session->text(fromAhs(MachineAllStopV1{"Off", id}));
        QCOMPARE(f.session->allStop().state, AllStopState::Off);
        QVERIFY(!f.session->allStop().pendingId);
        f.advance(30s);
        QCOMPARE(f.counters.get("allstop.timeout"), std::uint64_t(0));
    }

    void externalAndUnsupportedAllStop() {
        Fixture f;
        f.connect();
        f.session->text(fromAhs(MachineAllStopV1{"On", "11111111-2222-4333-8444-555555555555"}));
        QVERIFY(f.session->allStop().external);
        QCOMPARE(
            f.listener.count(IsoSeverity::Warning, "(external, id 11111111-2222-4333-8444-555555555555)"), 1);
        f.session->allStopApply();
        auto id = bodyOf<MachineAllStopRequestV1>(f.out.main.back())->modeAllStopId;
        f.session->text(
            fromAhs(MachineAllStopResponseV1{"Rejected", id, std::string("all-stop not supported")}));
        QVERIFY(!f.session->allStop().supported);
        QCOMPARE(f.listener.count(IsoSeverity::Error, "rejected by ahs (all-stop not supported)"), 1);
    }

    void noAlarmAfterTheLinkWentDown() {
        Fixture f;
        f.connect();
        f.session->allStopApply();
        f.session->closed("gone");
        f.advance(10s);
        QCOMPARE(f.counters.get("allstop.timeout"), std::uint64_t(0));
    }

    void periodicInterfaceDiagnostic() {
        Fixture f;
        f.connect();
        f.session->text("{not json");
        const auto before = allOf<InterfaceDiagnosticV1>(f.out.main).size(); // the error report
        QCOMPARE(before, std::size_t(1));
        f.advance(59999ms);
        QCOMPARE(allOf<InterfaceDiagnosticV1>(f.out.main).size(), before);
        f.advance(1ms);
        auto diags = allOf<InterfaceDiagnosticV1>(f.out.main);
        QCOMPARE(diags.size(), before + 1);
        auto& m = diags.back().measurement;
        QCOMPARE(m.size(), std::size_t(4));
        QCOMPARE(m[0].name, std::string("MessagesReceived"));
        QCOMPARE(*m[0].value, 3.0); // fleet, all-stop status, the invalid frame
        QCOMPARE(m[2].name, std::string("MessagesRejected"));
        QCOMPARE(*m[2].value, 1.0);
        QCOMPARE(m[3].name, std::string("MachinesKnown"));
        QCOMPARE(*m[3].value, 1.0);
        // A poll long overdue sends one diagnostic, not a burst, and keeps the 60 s cadence.
        f.advance(150s);
        QCOMPARE(allOf<InterfaceDiagnosticV1>(f.out.main).size(), before + 2);
        f.advance(29999ms); // 240 s after the connection
        QCOMPARE(allOf<InterfaceDiagnosticV1>(f.out.main).size(), before + 2);
        f.advance(1ms);
        QCOMPARE(allOf<InterfaceDiagnosticV1>(f.out.main).size(), before + 3);
        // None while down.
        f.session->closed("gone");
        f.advance(600s);
        QCOMPARE(allOf<InterfaceDiagnosticV1>(f.out.main).size(), before + 3);
    }

    void errorDiagnosticsNameMemberAndAreRateLimited() {
        Fixture f;
        f.connect();
        // A member failing validation: the report names the member and the message's timestamp.
        // (no raw string literals here: moc 6.4 mis-tokenises this one and drops the test class)
        nlohmann::json bad = {{"Protocol", "ISO23725"},
                              {"Version", 1},
                              {"Timestamp", "2025-03-14T02:15:07.412Z"},
                              {"EquipmentId", kTruck},
                              {"MachineAutonomyModeV1", {{"AutonomyMode", "Flying"}}}};
        f.session->text(bad.dump());
        auto d = allOf<InterfaceDiagnosticV1>(f.out.main);
        QCOMPARE(d.size(), std::size_t(1));
        QCOMPARE(d[0].message.size(), std::size_t(1));
        QCOMPARE(d[0].message[0].severity, std::string("Error"));
        QCOMPARE(d[0].message[0].code, std::string("InvalidMember"));
        QCOMPARE(*d[0].message[0].refMember, std::string("MachineAutonomyModeV1"));
        QCOMPARE(d[0].message[0].refTimestamp->text, std::string("2025-03-14T02:15:07.412Z"));
        QVERIFY(d[0].message[0].detail->find("Flying") != std::string::npos);

        // 30 more bad frames within the next second: nothing more until the interval has passed, then one
        // report with 20 entries and the rest counted.
        for (int i = 0; i < 30; ++i)
            f.session->text("[1,2");
        QCOMPARE(allOf<InterfaceDiagnosticV1>(f.out.main).size(), std::size_t(1));
        f.advance(999ms);
        QCOMPARE(allOf<InterfaceDiagnosticV1>(f.out.main).size(), std::size_t(1));
        f.advance(1ms);
        d = allOf<InterfaceDiagnosticV1>(f.out.main);
        QCOMPARE(d.size(), std::size_t(2));
        QCOMPARE(d[1].message.size(), std::size_t(20));
        QCOMPARE(d[1].message[0].code, std::string("InvalidJson"));
        QCOMPARE(d[1].measurement.size(), std::size_t(1));
        QCOMPARE(d[1].measurement[0].name, std::string("ErrorsNotDetailed"));
        QCOMPARE(*d[1].measurement[0].value, 10.0);
        QCOMPARE(f.counters.get("rx.rejected.invalid_json"), std::uint64_t(30));
        // The good state survived the bad input.
        QCOMPARE(f.session->machines().size(), std::size_t(1));
        QCOMPARE(f.session->state(), LinkState::Up);
    }

    void wrongDirectionReported() {
        Fixture f;
        f.connect();
        f.session->text(fromAhs(MachineAllStopRequestV1{"Apply", "11111111-2222-4333-8444-555555555555"}));
        auto d = allOf<InterfaceDiagnosticV1>(f.out.main);
        QCOMPARE(d.size(), std::size_t(1));
        QCOMPARE(d[0].message[0].code, std::string("WrongDirection"));
        QCOMPARE(*d[0].message[0].refMember, std::string("MachineAllStopRequestV1"));
        QCOMPARE(f.counters.get("rx.rejected.wrong_direction"), std::uint64_t(1));
    }

    // Unknown members, binary frames and out-of-standard protocol names are warnings the
    // operator sees, at most one per cause and minute per link, each counted.
    void peerMisbehaviourIsVisibleAndRateLimited() {
        Fixture f;
        f.connect();
        std::string frame = fromAhs(MachineAllStopV1{"Off", std::nullopt});
        const auto brace = frame.rfind('}');
        QVERIFY(brace != std::string::npos);
        // A vendor's extra member beside a known one (the envelope's members sit in the outer object).
        std::string unknown = frame;
        const auto member = unknown.find("\"MachineAllStopV1\"");
        QVERIFY(member != std::string::npos);
        unknown.insert(member, "\"VendorBlinkV9\":{\"Rate\":3},");
        for (int i = 0; i < 5; ++i)
            f.session->text(unknown);
        for (int i = 0; i < 3; ++i)
            f.session->binaryFrame(42);
        QCOMPARE(f.counters.get("rx.unknown_member"), std::uint64_t(5));
        QCOMPARE(f.listener.count(IsoSeverity::Warning, "unknown member 'VendorBlinkV9'"), 1);
        QCOMPARE(f.listener.count(IsoSeverity::Warning, "binary WebSocket frame of 42 bytes"), 1);
        f.advance(61s);
        f.session->text(unknown);
        QCOMPARE(f.listener.count(IsoSeverity::Warning, "unknown member 'VendorBlinkV9'"), 2);
        QCOMPARE(f.listener.count(IsoSeverity::Warning, "4 more of this kind"), 1);
        std::string other = frame;
        const auto proto = other.find("ISO23725");
        QVERIFY(proto != std::string::npos);
        other.replace(proto, 8, "ACME-AHS");
        f.session->text(other);
        QCOMPARE(f.counters.get("rx.out_of_standard"), std::uint64_t(1));
        QCOMPARE(f.listener.count(IsoSeverity::Warning, "protocol other than ISO23725"), 1);
    }

    void lateEventsDoNotOverwriteNewerState() {
        Fixture f;
        f.connect();
        const std::int64_t t0 = 1741918560000; // 2025-03-14T02:16:00Z
        f.session->text(encodeMessage(HaulTruckProductionStateV2{std::nullopt, 2001, "Autonomous", "Hauling"},
                                      kTruck, t0 + 1000));
        f.session->text(encodeMessage(HaulTruckProductionStateV2{std::nullopt, 4201, "Autonomous", "Loading"},
                                      kTruck, t0));
        QCOMPARE(f.session->machines().at(kTruck).production->productionState, std::string("Hauling"));
        QCOMPARE(f.counters.get("rx.late_event"), std::uint64_t(1));
    }

    void separateMapServiceCarriesTheMap() {
        IsoLinkConfig link{"ahs", {}, {}};
        link.ws.url = "ws://127.0.0.1:1/iso23725";
        link.mapWs.url = "ws://127.0.0.1:2/map";
        Fixture f(link);
        QVERIFY(f.session->separateMapService());
        f.connect();
        QVERIFY(!f.session->fetchMap()); // the map socket is not up yet
        QCOMPARE(f.counters.get("cmd.refused.link_down"), std::uint64_t(1));

        f.session->mapOpened("127.0.0.1:2");
        QVERIFY(f.out.map.empty()); // the service speaks first (§10.6.1 [I])
        f.session->mapText(fromAhs(MapServiceV1{1}));
        QCOMPARE(f.out.map.size(), std::size_t(1));
        QCOMPARE(bodyOf<MapCommandV1>(f.out.map.back())->scope, std::string("/summary"));
        QCOMPARE(allOf<MapCommandV1>(f.out.main).size(), std::size_t(0)); // nothing on the main socket

        auto model = parseMapDocument({mapExample()});
        QVERIFY(model.ok());
        auto chunks = writeOsmChunks(*model, 3, 18300);
        QVERIFY(chunks.size() >= 3);
        MapSummaryV1 s;
        s.timestamp = makeTimestamp(1741918560000);
        s.changeSetMap = 18300;
        s.changeSetWay = 18300;
        s.nodeCount = static_cast<std::int64_t>(model->nodes.size());
        s.wayCount = static_cast<std::int64_t>(model->ways.size());
        s.documentCount = static_cast<std::int64_t>(chunks.size());
        f.session->mapText(fromAhs(s)); // no map yet: fetch everything
        QCOMPARE(bodyOf<MapCommandV1>(f.out.map.back())->scope, std::string("/"));
        f.session->mapText(fromAhs(s));
        // Chunks on the main socket are not the map service's.
        f.session->text(chunks[0]);
        QCOMPARE(f.counters.get("rx.rejected.map_on_wrong_channel"), std::uint64_t(1));
        for (auto& c : chunks)
            f.session->mapText(c);
        QCOMPARE(f.listener.maps, 1);
        QVERIFY(f.session->map());
        QCOMPARE(f.session->map()->nodes.size(), model->nodes.size());

        // The map service going down interrupts nothing on the main link and keeps the map.
        f.session->mapClosed("restart");
        QCOMPARE(f.session->state(), LinkState::Up);
        QVERIFY(f.session->map());
        QVERIFY(!f.session->fetchMap());
    }

    void mapServiceThatNeverIdentifiesIsAskedAnyway() {
        IsoLinkConfig link{"ahs", {}, {}};
        link.mapWs.url = "ws://127.0.0.1:2/map";
        Fixture f(link);
        f.session->mapOpened("127.0.0.1:2");
        f.advance(4999ms);
        QVERIFY(f.out.map.empty());
        f.advance(1ms);
        QCOMPARE(f.out.map.size(), std::size_t(1));
        QCOMPARE(bodyOf<MapCommandV1>(f.out.map.back())->scope, std::string("/summary"));
        QCOMPARE(f.counters.get("map_service.unidentified"), std::uint64_t(1));
        f.advance(60s); // asked once
        QCOMPARE(f.out.map.size(), std::size_t(1));
        // An identified service is not nagged.
        f.session->mapClosed("restart");
        f.session->mapOpened("127.0.0.1:2");
        f.session->mapText(fromAhs(MapServiceV1{1}));
        f.advance(60s);
        QCOMPARE(f.out.map.size(), std::size_t(2));
        QCOMPARE(f.counters.get("map_service.unidentified"), std::uint64_t(1));
    }
};

QTEST_GUILESS_MAIN(TestFmsCore)
#include "test_iso_fms_core.moc"
