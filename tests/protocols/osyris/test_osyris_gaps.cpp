// Late join and gaps at the station, with a fake clock: a machine whose early slots are never
// answered is counted after the gap once this station asked for them gapGiveUpNaks times (or waited
// gapGiveUpMs), the cells are marked incomplete, an operator event names the slots, and a late arrival is
// recounted. A gap that is being repaired is not given up. At the grid: whatever gaps were given up and in
// whatever order their slots came late, the recount ends with exactly the counts (every lift) of a straight
// count, and nothing incomplete.
#include "protocols/osyris/PassCountGrid.h"
#include "protocols/osyris/RibbonStore.h"
#include "protocols/osyris/StationCore.h"

#include <QtTest>

#include <cmath>
#include <random>

using namespace ocu;
using namespace ocu::osyris;
using namespace std::chrono;

namespace {
constexpr std::uint32_t kGood = kPosValid | kPosAccuracyHigh | kPosVibrating | kPosForward;

CmPos pos(std::uint32_t slot) { // x = slot / 2 m along y = 0
    CmPos p;
    p.x = static_cast<float>(slot * 0.5);
    p.dx = 2.1f;
    p.speed = 2;
    p.flags = kGood;
    p.slot = slot;
    return p;
}

// Slots [from, to] of machine 1 as datagrams of at most 10 positions (MaxLen).
std::vector<Bytes> datagrams(std::uint32_t from, std::uint32_t to) {
    std::vector<Bytes> out;
    for (auto s = from; s <= to; ++s) {
        if ((s - from) % 10 == 0)
            out.emplace_back();
        encodePos(out.back(), 1, 1, pos(s));
    }
    return out;
}

struct Recorder : OsyrisListener {
    std::vector<std::pair<Severity, std::string>> events;
    void onEvent(Severity s, const std::string& t) override { events.emplace_back(s, t); }
    bool has(const std::string& part) const {
        for (auto& e : events)
            if (e.second.find(part) != std::string::npos)
                return true;
        return false;
    }
};

struct Station {
    FakeClock clock;
    std::unique_ptr<RibbonStore> store = RibbonStore::inMemory();
    PassCountGrid grid;
    Recorder rec;
    std::uint64_t naksFor0 = 0; // NAKs sent for machine 1 that cover slot 0
    std::unique_ptr<StationCore> core;
    explicit Station(OsyrisConfig cfg) {
        cfg.stationIndex = 200;
        cfg.machineNames[1] = "Roller 1";
        core = std::make_unique<StationCore>(cfg, clock, *store, &grid, &rec, [this](const Bytes& b) {
            auto d = decodeDatagram(b);
            for (auto& m : d.messages)
                if (auto* r = std::get_if<CmRequest>(&m.body);
                    r && r->type == RequestType::Nak && m.header.whose == 1 && r->from == 0)
                    ++naksFor0;
        });
        core->start();
    }
    void receive(std::uint32_t from, std::uint32_t to) {
        for (auto& d : datagrams(from, to))
            core->receive(d);
    }
    void alive(std::uint32_t from, std::uint32_t to) {
        Bytes b;
        encodeRequest(b, 1, 1, {RequestType::Alive, from, to, 0, 0});
        core->receive(b);
    }
    void run(milliseconds d) {
        for (auto t = milliseconds(0); t < d; t += milliseconds(100)) {
            clock.advance(milliseconds(100));
            core->tick();
        }
    }
    int countAt(double x) const { return grid.countAtCell(grid.cellIndex(x), grid.cellIndex(0.1)); }
};
} // namespace

class TestOsyrisGaps : public QObject {
    Q_OBJECT
private slots:
    void unansweredEarlySlotsAreGivenUpAfterNNaks() {
        OsyrisConfig cfg;
        cfg.gapGiveUpNaks = 3;
        cfg.gapGiveUpMs = 0; // only the NAK rule
        Station st(cfg);
        st.receive(20, 60); // joined late: slots 0..19 are never answered by anybody
        st.alive(0, 60);    // the owner shows its ribbon starts at 0
        st.run(milliseconds(1000));
        QCOMPARE(st.countAt(20), 0); // waits at the gap
        QVERIFY(!st.rec.has("unobtainable"));
        // Up to the third NAK and for its TTL (20 Beats) nothing is given up; then it is.
        for (int i = 0; i < 600 && st.naksFor0 < 3; ++i)
            st.run(milliseconds(100));
        QCOMPARE(st.naksFor0, std::uint64_t(3));
        st.run(milliseconds(1800));
        QVERIFY(!st.rec.has("unobtainable"));
        QCOMPARE(st.countAt(20), 0);
        st.run(milliseconds(300));
        QVERIFY(st.rec.has("positions 0-19 of Roller 1 are unobtainable (asked for 3 times"));
        QCOMPARE(st.countAt(20), 1);
        QVERIFY(st.grid.incompleteAtCell(st.grid.cellIndex(10), 0));
        QCOMPARE(st.core->counters().get("grid.gap.given_up.slots"), std::uint64_t(20));
        QCOMPARE(st.grid.givenUp().at(1).ranges(), (std::vector<SlotRange>{{0, 19}}));

        // They come after all: recounted (at most every 5 s), incomplete no more.
        st.receive(0, 19);
        st.run(milliseconds(6000));
        QCOMPARE(st.countAt(5), 1);
        QVERIFY(!st.grid.incompleteAtCell(st.grid.cellIndex(10), 0));
        QVERIFY(st.rec.has("recounted"));
    }

    void lateSlotsRecountToAStraightCount() {
        // Two machines drive lanes back and forth over three lifts (z rises each 4 lanes), 3 of 4 positions
        // vibrating. Per seed: random gaps are withheld, given up the way StationCore does (the first missing
        // slot up to the next held one), counted on after them, then delivered late in random batches with a
        // recount after each batch; the grid must end equal, tile for tile and lift for lift, to a grid that
        // was fed the whole ribbons straight.
        PassCountSettings settings;
        settings.liftThickness = 0.05;
        auto track = [](std::uint8_t machine, std::uint32_t slot) {
            const std::uint32_t lane = slot / 60, k = slot % 60;
            const bool forward = lane % 2 == 0;
            CmPos p;
            p.x = static_cast<float>((forward ? k : 59 - k) * 0.3);
            p.y = static_cast<float>(machine * 1.2 + (lane % 3) * 0.4);
            p.z = static_cast<float>(0.01 + (lane / 4) * 0.05);
            p.dx = 2.0f;
            p.speed = 1.5;
            p.flags = kPosValid | kPosAccuracyHigh | (slot % 4 != 3 ? kPosVibrating : 0) |
                      (forward ? kPosForward : kPosBackward);
            p.slot = slot;
            return p;
        };
        constexpr std::uint32_t kSlots = 720;
        auto straightStore = RibbonStore::inMemory();
        for (std::uint8_t m : {1, 2})
            for (std::uint32_t s = 0; s < kSlots; ++s)
                straightStore->put(m, {track(m, s), {}});
        PassCountGrid straight(settings);
        straight.advanceAll(*straightStore);
        const auto want = straight.snapshot();
        QCOMPARE(want->liftCount(), 3);

        for (std::uint32_t seed = 1; seed <= 40; ++seed) {
            std::mt19937 rng(seed);
            std::map<std::uint8_t, std::vector<std::uint32_t>> withheld;
            auto store = RibbonStore::inMemory();
            for (std::uint8_t m : {1, 2}) {
                std::vector<bool> missing(kSlots, false);
                const int gaps = 1 + int(rng() % 4);
                for (int g = 0; g < gaps; ++g) {
                    const std::uint32_t from = rng() % (kSlots - 1), len = 1 + rng() % 40;
                    for (std::uint32_t s = from; s < std::min(kSlots - 1, from + len); ++s)
                        missing[s] = true; // the last slot always arrives: every gap has a held slot after it
                }
                if (seed % 5 == 0)
                    for (std::uint32_t s = 0; s < 25; ++s)
                        missing[s] = true; // a late join
                for (std::uint32_t s = 0; s < kSlots; ++s)
                    if (missing[s])
                        withheld[m].push_back(s);
                    else
                        store->put(m, {track(m, s), {}});
            }
            PassCountGrid grid(settings);
            grid.advanceAll(*store);
            // Give up each gap where the grid waits, then count on, until every ribbon is through.
            for (std::uint8_t m : {1, 2})
                for (int guard = 0; guard < 1000 && grid.nextSlot(m) < kSlots; ++guard) {
                    const std::uint32_t next = grid.nextSlot(m);
                    std::uint32_t last = next;
                    for (const auto& r : store->held(m).ranges())
                        if (r.from > next) {
                            last = r.from - 1;
                            break;
                        }
                    grid.giveUp(m, next, last);
                    grid.advance(m, *store);
                }
            QCOMPARE(grid.nextSlot(1), kSlots);
            QCOMPARE(grid.nextSlot(2), kSlots);
            bool anyIncomplete = false;
            grid.snapshot()->forEachCell(
                -1, [&](std::int32_t, std::int32_t, int, bool inc) { anyIncomplete = anyIncomplete || inc; });
            QVERIFY(anyIncomplete);
            // The withheld slots arrive late, in random order and batches; a recount after each batch.
            std::vector<std::pair<std::uint8_t, std::uint32_t>> late;
            for (const auto& [m, gone] : withheld)
                for (auto s : gone)
                    late.emplace_back(m, s);
            std::shuffle(late.begin(), late.end(), rng);
            for (std::size_t i = 0; i < late.size();) {
                const std::size_t batch = 1 + rng() % 30;
                for (std::size_t j = 0; j < batch && i < late.size(); ++j, ++i)
                    store->put(late[i].first, {track(late[i].first, late[i].second), {}});
                QVERIFY(grid.givenUpArrived(1, *store) || grid.givenUpArrived(2, *store));
                grid.recount(*store);
            }
            QVERIFY(!grid.givenUpArrived(1, *store) && !grid.givenUpArrived(2, *store));
            QVERIFY(grid.givenUp().at(1).empty() && grid.givenUp().at(2).empty());
            const auto got = grid.snapshot();
            QVERIFY2(got->tileValues() == want->tileValues(), qPrintable(QString("seed %1").arg(seed)));
            QCOMPARE(got->liftCount(), want->liftCount());
            for (int l = 0; l < want->liftCount(); ++l)
                QVERIFY2(got->tileValues(l) == want->tileValues(l),
                         qPrintable(QString("seed %1 lift %2").arg(seed).arg(l)));
            got->forEachCell(-1, [&](std::int32_t, std::int32_t, int, bool inc) { QVERIFY(!inc); });
        }
    }

    void timeoutRule() {
        OsyrisConfig cfg;
        cfg.gapGiveUpNaks = 0;
        cfg.gapGiveUpMs = 20000;
        Station st(cfg);
        st.receive(20, 60);
        st.run(milliseconds(19000));
        QCOMPARE(st.countAt(20), 0);
        st.run(milliseconds(1500));
        QCOMPARE(st.countAt(20), 1);
        QVERIFY(st.rec.has("not obtained in 2"));
    }

    void aGapBeingRepairedIsNotGivenUp() {
        OsyrisConfig cfg;
        cfg.gapGiveUpNaks = 2;
        cfg.gapGiveUpMs = 0;
        Station st(cfg);
        st.receive(0, 0);
        st.receive(200, 210);
        st.alive(0, 210);
        // Every NAK round gets part of the gap answered (the newest slots first), so the waiting gap is
        // answered for: it must not be given up while the repair progresses.
        std::uint32_t top = 199;
        for (int round = 0; round < 12; ++round) {
            const std::uint64_t before = st.naksFor0 + st.core->counters().get("tx.nak");
            for (int i = 0; i < 600 && st.naksFor0 + st.core->counters().get("tx.nak") == before; ++i)
                st.run(milliseconds(100));
            st.receive(top - 9, top);
            top -= 10;
        }
        QVERIFY(!st.rec.has("unobtainable"));
        QCOMPARE(st.countAt(0.5), 0); // still waiting for slot 1
    }
};

QTEST_GUILESS_MAIN(TestOsyrisGaps)
#include "test_osyris_gaps.moc"
