// FmsCore's positions path on a fake clock, no sockets: a machine whose state is known
// only moves, so its MachinePositionV1 is not a whole-snapshot change; positions wait for flushPositions()
// and leave as one onMachinePositions batch, latest per machine, in arrival order; anything else about a
// machine is still delivered at once, whole. Unavailable and late positions are not queued; a removed
// machine or a lost link drops its queued position. A listener that does not take batches sees each
// machine through onMachineChanged as before.
#include "protocols/iso23725/FmsCore.h"

#include <QtTest>

using namespace ocu;
using namespace ocu::iso23725;

namespace {

const Guid kTruck1 = "c3a51f7e-0d24-4b9a-8f63-1e2d4c5b6a78";
const Guid kTruck2 = "4e2f9a10-7b3c-4d5e-9f60-1a2b3c4d5e6f";
constexpr std::int64_t kT0 = 1'741'918'507'000;

struct Outbound final : FmsOutbound {
    bool sendMain(std::string) override { return true; }
    bool sendMap(std::string) override { return true; }
};

// Records whole changes and position batches (in the order they came).
struct BatchListener : IsoListener {
    struct Position {
        Guid id;
        double latitude;
        std::int64_t measured;
    };
    std::vector<std::string> calls; // "changed:<id>" or "batch:<n>"
    std::vector<std::vector<Position>> batches;
    std::vector<IsoMachineSnapshot> changed;
    std::vector<std::string> warnings;
    void onMachineChanged(const IsoMachineSnapshot& m) override {
        calls.push_back("changed:" + m.equipmentId);
        changed.push_back(m);
    }
    void onEvent(IsoSeverity s, const std::string& text) override {
        if (s == IsoSeverity::Warning)
            warnings.push_back(text);
    }
    void onMachinePositions(const std::string& link,
                            const std::vector<const IsoMachineSnapshot*>& machines) override {
        QCOMPARE(link, std::string("ahs"));
        std::vector<Position> b;
        for (const auto* m : machines) {
            QVERIFY(m->stateKnown);
            QVERIFY(m->position);
            b.push_back({m->equipmentId, m->position->latitude, m->position->measuredUnixMs.value_or(0)});
        }
        calls.push_back("batch:" + std::to_string(b.size()));
        batches.push_back(std::move(b));
    }
};

// Takes no batches: the default delivers each machine whole.
struct PlainListener : IsoListener {
    std::vector<IsoMachineSnapshot> changed;
    void onMachineChanged(const IsoMachineSnapshot& m) override { changed.push_back(m); }
};

std::string position(const Guid& id, double lat, std::int64_t measuredMs, bool available = true) {
    MachinePositionV1 p;
    p.timestamp = makeTimestamp(measuredMs);
    if (available) {
        p.pose.latitude = lat;
        p.pose.longitude = 119.73;
    }
    p.pose.elevation = 500.0;
    p.pose.heading = 90;
    p.pose.speed = 30;
    return encodeMessage(p, id, measuredMs);
}

FleetDefinitionV2 fleet(std::vector<Guid> ids) {
    FleetDefinitionV2 f;
    f.ahsId = "7d1f3c2a-5b8e-4c61-9a0d-2e4f6b8c1a37";
    int n = 1;
    for (auto& id : ids)
        f.equipment.push_back(
            Equipment{id, "HT0" + std::to_string(n++), "HaulTruck", "OEM", "793F", true, 12.9, 7.6});
    return f;
}

template <class L> struct Core {
    Core() : session(cfg, IsoLinkConfig{"ahs", {}, {}}, listener, counters, clock, out) {
        session.opened("127.0.0.1:9000");
        session.text(encodeMessage(fleet({kTruck1, kTruck2})));
        // The first member about each machine makes its state known (a whole change).
        session.text(encodeMessage(MachineAutonomyModeV1{"Autonomous"}, kTruck1));
        session.text(encodeMessage(MachineAutonomyModeV1{"Autonomous"}, kTruck2));
    }
    IsoConfig cfg;
    FakeClock clock;
    Counters counters;
    L listener;
    Outbound out;
    FmsCore session;
};

} // namespace

class TestIsoPositionBatches : public QObject {
    Q_OBJECT
private slots:
    void positionsWaitForTheBatch() {
        Core<BatchListener> c;
        c.listener.calls.clear();
        c.session.text(position(kTruck1, -23.1, kT0));
        c.session.text(position(kTruck2, -23.2, kT0));
        c.session.text(position(kTruck1, -23.3, kT0 + 100)); // newer: replaces the first in the batch
        QVERIFY(c.listener.calls.empty());
        QVERIFY(c.session.positionsPending());
        QCOMPARE(c.counters.get("rx.positions"), std::uint64_t(3));

        c.session.flushPositions();
        QCOMPARE(c.listener.calls, (std::vector<std::string>{"batch:2"}));
        const auto& b = c.listener.batches.front();
        QCOMPARE(b[0].id, kTruck1); // first arrival order
        QCOMPARE(b[0].latitude, -23.3);
        QCOMPARE(b[0].measured, kT0 + 100);
        QCOMPARE(b[1].id, kTruck2);
        QCOMPARE(b[1].latitude, -23.2);
        QVERIFY(!c.session.positionsPending());
        c.session.flushPositions(); // nothing new: no empty batch
        QCOMPARE(c.listener.batches.size(), std::size_t(1));
        QCOMPARE(c.counters.get("rx.position_batches"), std::uint64_t(1));
        // The core's own state is current at once (queries, the periodic diagnostic).
        QCOMPARE(c.session.machines().at(kTruck1).position->latitude, -23.3);
    }

    // Everything else about a machine is a whole change, delivered at once; its latest position is in it.
    void otherMembersStayImmediateAndWhole() {
        Core<BatchListener> c;
        c.listener.calls.clear();
        c.session.text(position(kTruck1, -23.1, kT0));
        c.session.text(encodeMessage(MachineDiagnosticV2{{DiagnosticEntry{555, 2110}}}, kTruck1));
        QCOMPARE(c.listener.calls, (std::vector<std::string>{"changed:" + kTruck1}));
        QCOMPARE(c.listener.changed.back().position->latitude, -23.1);
        QCOMPARE(c.listener.changed.back().diagnostics->size(), std::size_t(1));
    }

    // The first thing heard of a machine (here a position) makes its state known: a whole change at once.
    void firstPositionOfAnUnknownMachineIsWhole() {
        Core<BatchListener> c;
        const Guid fresh = "9a8b7c6d-5e4f-4a3b-8c2d-1e0f9a8b7c6d";
        c.session.text(encodeMessage(fleet({kTruck1, kTruck2, fresh})));
        c.listener.calls.clear();
        c.session.text(position(fresh, -23.4, kT0));
        QCOMPARE(c.listener.calls, (std::vector<std::string>{"changed:" + fresh}));
        QVERIFY(c.listener.changed.back().stateKnown);
        QVERIFY(!c.session.positionsPending());
    }

    void unavailableAndLatePositionsAreNotQueued() {
        Core<BatchListener> c;
        c.session.text(position(kTruck1, -23.1, kT0 + 1000));
        c.session.flushPositions();
        c.listener.calls.clear();
        c.session.text(position(kTruck1, -23.9, kT0));    // older than the one shown (§2.1 rule 2)
        c.session.text(position(kTruck2, 0, kT0, false)); // latitude/longitude null: unavailable
        QVERIFY(!c.session.positionsPending());
        c.session.flushPositions();
        QVERIFY(c.listener.calls.empty());
        QCOMPARE(c.counters.get("rx.late_position"), std::uint64_t(1));
        QCOMPARE(c.counters.get("rx.position_unavailable"), std::uint64_t(1));
        QCOMPARE(c.session.machines().at(kTruck1).position->latitude, -23.1);
    }

    // A machine dropped from a re-sent fleet definition leaves the batch with it (no dangling snapshot).
    void removedMachineLeavesTheBatch() {
        Core<BatchListener> c;
        c.session.text(position(kTruck1, -23.1, kT0));
        c.session.text(position(kTruck2, -23.2, kT0));
        c.session.text(encodeMessage(fleet({kTruck2})));
        c.listener.batches.clear();
        c.session.flushPositions();
        QCOMPARE(c.listener.batches.size(), std::size_t(1));
        QCOMPARE(c.listener.batches[0].size(), std::size_t(1));
        QCOMPARE(c.listener.batches[0][0].id, kTruck2);
    }

    // A lost link makes every machine unknown, whole; positions queued before are not sent after that.
    void lostLinkDropsTheBatch() {
        Core<BatchListener> c;
        c.session.text(position(kTruck1, -23.1, kT0));
        c.listener.calls.clear();
        c.session.closed("test");
        std::sort(c.listener.calls.begin(), c.listener.calls.end());
        QCOMPARE(c.listener.calls, (std::vector<std::string>{"changed:" + kTruck2, "changed:" + kTruck1}));
        QVERIFY(!c.listener.changed.back().stateKnown);
        QVERIFY(!c.session.positionsPending());
        c.session.flushPositions();
        QCOMPARE(c.listener.calls.size(), std::size_t(2));
    }

    // Every GUID an AHS named became a machine for good; machines outside the fleet definition
    // are capped per link, the rest is counted, warned about once a minute and allocates nothing.
    void machinesOutsideTheFleetAreCapped() {
        Core<BatchListener> c;
        const std::size_t cap = FmsCore::kMaxMachinesOutsideFleet;
        auto guid = [](int i) {
            char id[40];
            std::snprintf(id, sizeof id, "00000000-0000-4000-8000-%012d", i);
            return Guid(id);
        };
        for (int i = 0; i < int(cap) + 36; ++i)
            c.session.text(position(guid(i), -23.1, kT0 + i));
        QCOMPARE(c.session.machines().size(), 2 + cap);
        QCOMPARE(c.counters.get("rx.rejected.machine_cap"), std::uint64_t(36));
        const auto capWarnings =
            std::count_if(c.listener.warnings.begin(), c.listener.warnings.end(), [](const std::string& w) {
                return w.find("rx.rejected.machine_cap") != std::string::npos;
            });
        QCOMPARE(capWarnings, 1);
        // The admitted ones and the fleet's machines keep working.
        c.listener.calls.clear();
        c.session.text(position(guid(0), -23.2, kT0 + 1000));
        c.session.text(position(kTruck1, -23.3, kT0 + 1000));
        c.session.flushPositions();
        QCOMPARE(c.listener.calls, (std::vector<std::string>{"batch:2"}));
        QCOMPARE(c.session.machines().at(kTruck1).position->latitude, -23.3);
    }

    // A large batch leaves in steps (IsoStack hands a burst over in short io-thread handlers, ISO 23725 §7.6:
    // an all-stop requested meanwhile goes between two steps): the earliest arrivals first, the rest stays
    // pending; a pending machine that moves again keeps its place with its newest position, one already
    // handed over joins the end.
    void largeBatchLeavesInSteps() {
        Core<BatchListener> c;
        std::vector<Guid> ids{kTruck1, kTruck2};
        for (int i = 0; i < 98; ++i) {
            char id[40];
            std::snprintf(id, sizeof id, "00000000-0000-4000-8000-%012d", i);
            ids.emplace_back(id);
        }
        c.session.text(encodeMessage(fleet(ids)));
        for (std::size_t i = 2; i < ids.size(); ++i)
            c.session.text(encodeMessage(MachineAutonomyModeV1{"Autonomous"}, ids[i]));
        c.listener.calls.clear();
        for (std::size_t i = 0; i < ids.size(); ++i)
            c.session.text(position(ids[i], -23.0 - 0.001 * double(i), kT0));
        QCOMPARE(c.session.pendingPositions(), std::size_t(100));

        c.session.flushPositions(32);
        QCOMPARE(c.listener.calls, (std::vector<std::string>{"batch:32"}));
        QCOMPARE(c.session.pendingPositions(), std::size_t(68));
        for (std::size_t k = 0; k < 32; ++k)
            QCOMPARE(c.listener.batches[0][k].id, ids[k]);

        c.session.text(position(ids[0], -24.0, kT0 + 100));  // handed over already: joins the end
        c.session.text(position(ids[40], -24.1, kT0 + 100)); // still pending: keeps its place
        QCOMPARE(c.session.pendingPositions(), std::size_t(69));
        while (c.session.positionsPending())
            c.session.flushPositions(32);
        QCOMPARE(c.listener.calls, (std::vector<std::string>{"batch:32", "batch:32", "batch:32", "batch:5"}));
        QCOMPARE(c.listener.batches[1][0].id, ids[32]);
        QCOMPARE(c.listener.batches[1][8].id, ids[40]);
        QCOMPARE(c.listener.batches[1][8].latitude, -24.1);
        QCOMPARE(c.listener.batches[3].back().id, ids[0]);
        QCOMPARE(c.listener.batches[3].back().latitude, -24.0);
        QCOMPARE(c.counters.get("rx.position_batches"), std::uint64_t(4));
        c.session.flushPositions(0); // nothing handed over
        QCOMPARE(c.listener.calls.size(), std::size_t(4));
    }

    // A listener that takes no batches sees each moved machine through onMachineChanged, at the flush.
    void defaultListenerSeesWholeMachines() {
        Core<PlainListener> c;
        c.listener.changed.clear();
        c.session.text(position(kTruck1, -23.1, kT0));
        c.session.text(position(kTruck2, -23.2, kT0));
        QVERIFY(c.listener.changed.empty());
        c.session.flushPositions();
        QCOMPARE(c.listener.changed.size(), std::size_t(2));
        QCOMPARE(c.listener.changed[0].equipmentId, kTruck1);
        QCOMPARE(c.listener.changed[0].position->latitude, -23.1);
        QCOMPARE(c.listener.changed[0].autonomyMode, std::string("Autonomous"));
        QCOMPARE(c.listener.changed[1].position->latitude, -23.2);
    }
};

QTEST_GUILESS_MAIN(TestIsoPositionBatches)
#include "test_iso_position_batches.moc"
