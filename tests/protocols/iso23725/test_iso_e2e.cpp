// OCU (IsoStack, FMS side) <-> simulated AHS over ws:// on loopback: fleet definitions first, positions,
// fleet discrepancies, all-stop Apply/Remove with the trucks stopping, the chunked map, assignments, own
// positions, map re-fetch on change, kill/restart of the AHS (UNKNOWN, refused commands, snapshot rebuild)
// and malformed input.
#include "sim/iso23725/IsoDemo.h"
#include "tests/protocols/iso23725/IsoTestSupport.h"

#include "protocols/common/Udp.h"

#include <QtTest>

using namespace isotest;
using namespace ocu::sim;

namespace {

SimulatedAhsConfig simConfig() {
    SimulatedAhsConfig c;
    c.truckCount = 6;
    c.positionRateHz = 10;
    c.timeScale = 4;
    c.pingInterval = std::chrono::milliseconds(500);
    c.deadAfter = std::chrono::milliseconds(3000);
    return c;
}

void fastLink(IsoConfig& cfg) {
    for (auto& l : cfg.links) {
        l.ws.backoffMin = std::chrono::milliseconds(100);
        l.ws.backoffMax = std::chrono::milliseconds(400);
        l.ws.pingInterval = std::chrono::milliseconds(500);
        l.ws.deadAfter = std::chrono::milliseconds(3000);
    }
}

} // namespace

class TestIsoEndToEnd : public QObject {
    Q_OBJECT
private slots:
    void fullSession() {
        auto demo = startIsoDemo(simConfig());
        QVERIFY2(demo.ahs, demo.error.c_str());
        auto& ahs = *demo.ahs;
        auto fleet = ahs.fleet();
        QCOMPARE(int(fleet.size()), 6);
        // Discrepancies: an autonomous truck the AHS does not have, and a different HID for one it has.
        demo.config.fleet.push_back(Equipment{"11111111-2222-4333-8444-555555555555", "HT999", "HaulTruck",
                                              "Komatsu", "930E", true, 15.6, 9.1});
        for (auto& e : demo.config.fleet)
            if (e.equipmentId == fleet[1].equipmentId)
                e.hid = "HT-OLD";
        fastLink(demo.config);
        Recorder rec;
        IsoStack stack(demo.config, rec);
        QVERIFY(stack.start());
        QVERIFY(waitFor([&] { return rec.link("ahs") == LinkState::Up; }));

        // Fleet definitions exchanged first, both ways.
        QVERIFY(waitFor([&] { return !ahs.stats().fmsFirstMessages.empty(); }));
        QCOMPARE(ahs.stats().fmsFirstMessages.front(), std::string("FleetDefinitionV2"));
        QVERIFY(waitFor([&] { return ahs.counters().get("sim.rx.fms_fleet") == 1; }));
        QCOMPARE(stack.counters().get("rx.first_not_fleet_definition"), 0u);

        // Positions flow for every truck.
        QVERIFY(waitFor(
            [&] { return rec.machinesWith([](auto& m) { return m.position && m.stateKnown; }) == 6; }));
        QVERIFY(waitFor(
            [&] { return rec.machinesWith([](auto& m) { return m.autonomyMode == "Autonomous"; }) == 6; }));
        QVERIFY(waitFor(
            [&] { return rec.machinesWith([](auto& m) { return m.dispatchingCustodian == "FMS"; }) == 6; }));
        QVERIFY(waitFor(
            [&] { return rec.machinesWith([](auto& m) { return m.diagnostics.has_value(); }) == 6; }));
        auto before = stack.counters().get("rx.positions");
        QVERIFY(waitFor([&] { return stack.counters().get("rx.positions") > before + 30; }));

        // Discrepancies reported as events.
        QVERIFY(waitFor(
            [&] { return rec.hasDiscrepancy("HT999 (11111111-2222-4333-8444-555555555555) is missing"); }));
        QVERIFY(waitFor([&] {
            return rec.hasDiscrepancy("HID '" + fleet[1].hid + "' at the AHS, 'HT-OLD' at the FMS");
        }));
        QVERIFY(
            waitFor([&] { return rec.with([&] { return rec.discrepancies.size(); }) == std::size_t(2); }));

        // The map of >= 3 chunks arrives complete, with progress, and the connectivity graph.
        QVERIFY(waitFor([&] { return rec.with([&] { return rec.maps; }) >= 1; }));
        auto map = stack.map("ahs");
        QVERIFY(map);
        QVERIFY(map->summary.documentCount >= 3);
        QCOMPARE(std::int64_t(map->nodes.size()), map->summary.nodeCount);
        QCOMPARE(std::int64_t(map->ways.size()), map->summary.wayCount);
        QVERIFY(!map->lanes.empty());
        QVERIFY(map->areas.size() >= 5);
        QVERIFY(rec.with([&] { return rec.progress.size(); }) >= std::size_t(map->summary.documentCount));
        QVERIFY(waitFor([&] { return stack.map("ahs")->connectivity.size() > 5; }));
        QVERIFY(map->warnings.empty());
        // Geo-referenced around the configured origin.
        QVERIFY(std::abs(map->origin.lat - (-23.36)) < 0.01);

        // All-stop Apply: status On (only from MachineAllStopV1), and every truck comes to rest.
        QVERIFY(waitFor([&] { return rec.allStop() == AllStopState::Off; })); // the AHS's status first
        QVERIFY(sentOne(outcome([&](auto done) { stack.allStopApply("ahs", done); })));
        QVERIFY(waitFor([&] { return rec.allStop() == AllStopState::On; }));
        auto st = stack.allStop("ahs");
        QVERIFY(!st.external);
        QVERIFY(st.activeId.has_value());
        QVERIFY(waitFor([&] {
            auto v = ahs.truckSpeedsKmh();
            return std::all_of(v.begin(), v.end(), [](double s) { return s == 0.0; });
        }));
        QVERIFY(waitFor(
            [&] { return rec.machinesWith([](auto& m) { return m.autonomyMode == "AllStop"; }) == 6; }));
        QVERIFY(waitFor([&] {
            return rec.machinesWith([](auto& m) { return m.position && m.position->speedKmh == 0.0; }) == 6;
        }));
        // Remove with the same id: Off, and the trucks resume.
        QVERIFY(sentOne(outcome([&](auto done) { stack.allStopRemove("ahs", done); })));
        QVERIFY(waitFor([&] { return rec.allStop() == AllStopState::Off; }));
        QVERIFY(waitFor([&] { return ahs.counters().get("sim.allstop.off") == 1u; }));
        QVERIFY(waitFor([&] { return ahs.stats().movingTrucks > 0; }));
        QVERIFY(!rec.hasEvent("rejected"));

        // Assignments: a valid one accepted, an invalid one rejected with the AHS's reason; reset.
        auto loadArea = map->areas.front();
        for (auto id : map->areas)
            if (map->way(id)->defaultTask() == "load")
                loadArea = id;
        QVERIFY(sentOne(outcome([&](auto done) {
            stack.requestAssignment("ahs", fleet[0].equipmentId,
                                    {AssignmentItem{"", "Load", loadArea, {}, {}, {}}}, done);
        })));
        QVERIFY(waitFor([&] {
            return rec.machinesWith([&](auto& m) {
                return m.equipmentId == fleet[0].equipmentId && m.assignment &&
                       m.assignment->status == "Active";
            }) == 1;
        }));
        QVERIFY(waitFor([&] { return rec.hasEvent("Accepted"); })); // the response is its own message
        // Sent (the console checks form, the AHS the area's kind) and rejected by the AHS.
        QVERIFY(sentOne(outcome([&](auto done) {
            stack.requestAssignment("ahs", fleet[1].equipmentId,
                                    {AssignmentItem{"", "Offload", loadArea, {}, {}, {}}}, done);
        })));
        QVERIFY(waitFor([&] { return rec.hasEvent("is not a dump area"); }));
        QVERIFY(
            sentOne(outcome([&](auto done) { stack.resetAssignment("ahs", fleet[0].equipmentId, done); })));
        QVERIFY(waitFor([&] {
            return rec.machinesWith([&](auto& m) {
                return m.equipmentId == fleet[0].equipmentId && m.assignment &&
                       m.assignment->status == "Cancelled";
            }) == 1;
        }));

        // Own manned-machine positions are sent when configured.
        stack.setOwnPosition("a2d4f6b8-1c3e-4a5b-9d7f-0e2c4b6a8d13", -23.36, 119.73, 500, 90, 0);
        QVERIFY(waitFor([&] { return ahs.counters().get("sim.rx.fms_positions") >= 2; }));

        // Map edited at the AHS: new summary, re-fetched.
        ahs.bumpMapChangeSet();
        QVERIFY(waitFor([&] { return stack.counters().get("map.complete") >= 2; }));
        QVERIFY(
            waitFor([&] { return stack.map("ahs")->summary.changeSetMap == map->summary.changeSetMap + 1; }));
        QCOMPARE(ahs.counters().get("sim.rx.rejected"), 0u);
        stack.stop();
    }

    void killAndRestart() {
        auto cfg = simConfig();
        auto ahs = std::make_unique<SimulatedAhs>(cfg);
        QVERIFY(ahs->start());
        const auto port = ahs->port();
        IsoConfig ic;
        ic.links.push_back(IsoLinkConfig{"ahs", {}, {}});
        ic.links[0].ws.url = ahs->url();
        fastLink(ic);
        Recorder rec;
        IsoStack stack(ic, rec);
        QVERIFY(stack.start());
        QVERIFY(waitFor(
            [&] { return rec.machinesWith([](auto& m) { return m.stateKnown && m.position; }) == 6; }));
        QVERIFY(waitFor([&] { return rec.allStop() == AllStopState::Off; }));

        ahs->stop(); // killed
        QVERIFY(waitFor([&] { return rec.link("ahs") == LinkState::Down; }));
        QCOMPARE(rec.allStop(), AllStopState::Unknown);
        QCOMPARE(rec.machinesWith([](auto& m) { return m.stateKnown; }), 0);
        // Commands are refused while down, never queued.
        QVERIFY(refusedOne(outcome([&](auto done) { stack.allStopApply("ahs", done); }),
                           ocu::OutcomeReason::LinkDown));
        QVERIFY(waitFor([&] { return rec.hasEvent("all-stop Apply refused: link 'ahs' is DOWN"); }));
        QCOMPARE(stack.counters().get("cmd.refused.link_down"), 1u);
        ahs.reset();

        cfg.port = port; // restarted on the same port
        auto again = std::make_unique<SimulatedAhs>(cfg);
        QVERIFY2(again->start(), again->lastError().c_str());
        QVERIFY(waitFor([&] { return rec.link("ahs") == LinkState::Up; }));
        // State rebuilt from the new snapshot; the refused Apply was not sent later.
        QVERIFY(waitFor(
            [&] { return rec.machinesWith([](auto& m) { return m.stateKnown && m.position; }) == 6; }));
        QVERIFY(waitFor([&] { return rec.allStop() == AllStopState::Off; }));
        QCOMPARE(again->counters().get("sim.allstop.on"), 0u);
        QVERIFY(stack.counters().get("ws.sessions.opened") >= 2);
        stack.stop();
    }

    void malformedInput() {
        auto cfg = simConfig();
        SimulatedAhs ahs(cfg);
        QVERIFY(ahs.start());
        IsoConfig ic;
        ic.links.push_back(IsoLinkConfig{"ahs", {}, {}});
        ic.links[0].ws.url = ahs.url();
        fastLink(ic);
        Recorder rec;
        IsoStack stack(ic, rec);
        QVERIFY(stack.start());
        QVERIFY(
            waitFor([&] { return rec.machinesWith([](auto& m) { return m.position.has_value(); }) == 6; }));
        auto truck = ahs.fleet()[0].equipmentId;

        ahs.sendRaw("{not json");
        QVERIFY(waitFor([&] { return stack.counters().get("rx.rejected.invalid_json") == 1; }));
        ahs.sendRawBinary(std::string("\x00\x01\x02", 3));
        QVERIFY(waitFor([&] { return stack.counters().get("rx.rejected.binary") == 1; }));
        // ... and the operator sees it, after its counter on the io thread: wait for it.
        QVERIFY(waitFor([&] { return rec.hasEvent("binary WebSocket frame of 3 bytes from ahs ignored"); }));
        ahs.sendRaw(
            R"({"Protocol":"ISO23725","Version":1,"Timestamp":"2025-03-14T02:17:42.210Z","EquipmentId":")" +
            truck + R"(","MachineAutonomyModeV1":{"AutonomyMode":5}})");
        QVERIFY(waitFor([&] { return stack.counters().get("rx.rejected.invalid_member") == 1; }));
        // Counted first, then reported (io thread): wait for the event too.
        QVERIFY(waitFor([&] {
            return rec.hasEvent(
                "MachineAutonomyModeV1.AutonomyMode: expected an enumeration string, got number");
        }));
        ahs.sendRaw(
            R"({"Protocol":"Vendor-X","Version":1,"Timestamp":"2025-03-14T02:17:42.210Z","FooV9":{"a":1}})");
        QVERIFY(waitFor([&] { return stack.counters().get("rx.unknown_member") == 1; }));
        ahs.sendRaw("<osm version=\"0.6\" sequence=\"1\"/>");
        QVERIFY(waitFor([&] { return stack.counters().get("rx.rejected.unexpected_map_chunk") == 1; }));
        // Through all of that the link stayed up and data kept flowing.
        QCOMPARE(rec.link("ahs"), LinkState::Up);
        QCOMPARE(stack.counters().get("ws.sessions.opened"), 1u);
        auto before = stack.counters().get("rx.positions");
        QVERIFY(waitFor([&] { return stack.counters().get("rx.positions") > before + 10; }));

        // A 20 MiB frame exceeds the 16 MiB maximum: counted, the connection is closed (1009) and
        // re-established.
        ahs.sendRaw(std::string(20u * 1024u * 1024u, ' '));
        QVERIFY(waitFor([&] { return stack.counters().get("rx.rejected.too_big") == 1; },
                        std::chrono::seconds(40)));
        QVERIFY(waitFor([&] {
            return stack.counters().get("ws.sessions.opened") == 2 && rec.link("ahs") == LinkState::Up;
        }));
        QVERIFY(waitFor([&] { return rec.machinesWith([](auto& m) { return m.stateKnown; }) == 6; }));
        stack.stop();
    }

    void silentPeerDeclaredDead() {
        auto cfg = simConfig();
        SimulatedAhs ahs(cfg);
        QVERIFY(ahs.start());
        IsoConfig ic;
        ic.links.push_back(IsoLinkConfig{"ahs", {}, {}});
        ic.links[0].ws.url = ahs.url();
        fastLink(ic);
        ic.links[0].ws.pingInterval = std::chrono::milliseconds(200);
        ic.links[0].ws.deadAfter = std::chrono::milliseconds(1000);
        Recorder rec;
        IsoStack stack(ic, rec);
        QVERIFY(stack.start());
        QVERIFY(waitFor([&] { return rec.machinesWith([](auto& m) { return m.stateKnown; }) == 6; }));
        // No frames and no pongs from the AHS for twice dead_after.
        ahs.freezeFor(2 * ic.links[0].ws.deadAfter);
        QVERIFY(waitFor([&] { return stack.counters().get("ws.dead") == 1; }, std::chrono::seconds(5)));
        QVERIFY(waitFor([&] { return rec.hasEvent("link dead: no frame for"); }));
        QCOMPARE(rec.allStop(), AllStopState::Unknown); // set before the link-down event is raised
        // After the stall the client reconnects and rebuilds its state.
        QVERIFY(waitFor([&] {
            return stack.counters().get("ws.sessions.opened") >= 2 && rec.link("ahs") == LinkState::Up;
        }));
        QVERIFY(waitFor([&] { return rec.machinesWith([](auto& m) { return m.stateKnown; }) == 6; }));
        stack.stop();
    }

    // Q10: the map service on its own socket (IsoDemo wires the link's mapUrl); interface diagnostics flow
    // both ways; the production sensor arrives with the snapshot.
    void separateMapServiceAndDiagnostics() {
        auto cfg = simConfig();
        cfg.separateMapService = true;
        cfg.interfaceDiagnosticPeriod = std::chrono::milliseconds(300);
        auto demo = startIsoDemo(cfg);
        QVERIFY2(demo.ahs, demo.error.c_str());
        auto& ahs = *demo.ahs;
        QCOMPARE(demo.config.links[0].mapWs.url, ahs.mapUrl());
        fastLink(demo.config);
        demo.config.interfaceDiagnosticPeriod = std::chrono::milliseconds(300);
        Recorder rec;
        IsoStack stack(demo.config, rec);
        QVERIFY(stack.start());
        QVERIFY(waitFor([&] { return stack.counters().get("map.complete") == 1; }));
        QCOMPARE(stack.mapServiceState("ahs"), LinkState::Up);
        QVERIFY(stack.map("ahs")->summary.documentCount >= 3);
        QCOMPARE(stack.counters().get("map_service.opened"), 1u);
        QCOMPARE(stack.counters().get("rx.rejected.map_on_wrong_channel"), 0u);
        QCOMPARE(ahs.counters().get("sim.map.elsewhere"), 0u); // never asked the main socket for the map
        QVERIFY(waitFor([&] {
            return rec.machinesWith([](auto& m) { return m.sensor.has_value(); }) == 6 &&
                   rec.machinesWith([](auto& m) { return m.stateKnown; }) == 6;
        }));
        // A map edit reaches the console through the map service only.
        ahs.bumpMapChangeSet();
        QVERIFY(waitFor([&] { return stack.counters().get("map.complete") >= 2; }));
        // Diagnostics both ways: the AHS's periodic ones arrive, ours reach the AHS.
        QVERIFY(waitFor([&] { return stack.counters().get("rx.interface_diagnostic") >= 2; }));
        QVERIFY(waitFor([&] { return stack.counters().get("tx.interface_diagnostic.periodic") >= 2; }));
        QVERIFY(waitFor([&] { return ahs.counters().get("sim.rx.interface_diagnostic") >= 2; }));
        QCOMPARE(ahs.counters().get("sim.rx.rejected"), 0u);
        // A garbage frame from the AHS: the console answers with an Error diagnostic, the link stays up.
        ahs.sendRaw("{\"Protocol\":\"ISO23725\",");
        QVERIFY(waitFor([&] { return stack.counters().get("tx.interface_diagnostic.error") == 1; }));
        QCOMPARE(stack.linkState("ahs"), LinkState::Up);
        stack.stop();
    }

    void refusedWhenNeverConnected() {
        IsoConfig ic;
        ic.links.push_back(IsoLinkConfig{"nowhere", {}, {}});
        ic.links[0].ws.url = "ws://127.0.0.1:" + std::to_string(ocu::findFreeTcpPort()) + "/iso23725";
        fastLink(ic);
        Recorder rec;
        IsoStack stack(ic, rec);
        QVERIFY(stack.start());
        QVERIFY(waitFor([&] { return stack.counters().get("link.connect_failed") >= 3; }));
        QCOMPARE(rec.link("nowhere"), LinkState::Down);
        QVERIFY(refusedOne(outcome([&](auto done) { stack.fetchMap("nowhere", done); }),
                           ocu::OutcomeReason::LinkDown));
        QVERIFY(refusedOne(outcome([&](auto done) { stack.allStopRemove("nowhere", done); }),
                           ocu::OutcomeReason::LinkDown));
        QCOMPARE(stack.counters().get("cmd.refused.link_down"), 2u);
        QVERIFY(refusedOne(outcome([&](auto done) { stack.allStopApply("other", done); }),
                           ocu::OutcomeReason::UnknownTarget));
        QVERIFY(waitFor([&] { return rec.hasEvent("no ISO 23725 link named 'other'"); }));
        stack.stop();
    }
};

QTEST_GUILESS_MAIN(TestIsoEndToEnd)
#include "test_iso_e2e.moc"
