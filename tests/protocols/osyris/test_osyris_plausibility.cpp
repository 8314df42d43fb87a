// Plausibility gate and bounded sweep: one hostile CmPos (a drum of 10^6 m, x = 10^30 m,
// NaN) used to hang the io thread in PassCountGrid::sweep or be drawn on another continent.
#include "protocols/common/Clock.h"
#include "protocols/osyris/OsyrisCodec.h"
#include "protocols/osyris/PassCountGrid.h"
#include "protocols/osyris/Plausibility.h"
#include "protocols/osyris/RibbonStore.h"
#include "protocols/osyris/StationCore.h"

#include <QtTest>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>

using namespace ocu;
using namespace ocu::osyris;
using namespace std::chrono;

namespace {

constexpr std::uint32_t kGood = kPosValid | kPosAccuracyHigh | kPosVibrating | kPosForward;

CmPos pos(std::uint32_t slot, float x, float y, float width = 2.1f) {
    CmPos p;
    p.slot = slot;
    p.x = x;
    p.y = y;
    p.dx = width;
    p.speed = 1.0;
    p.flags = kGood;
    return p;
}

struct Recorder : OsyrisListener {
    std::vector<MachineSnapshot> positions;
    std::vector<std::string> warnings;
    void onMachinePosition(const MachineSnapshot& s) override { positions.push_back(s); }
    void onEvent(Severity s, const std::string& text) override {
        if (s == Severity::Warning)
            warnings.push_back(text);
    }
};

} // namespace

class TestOsyrisPlausibility : public QObject {
    Q_OBJECT
private slots:
    void rulesNameTheFault() {
        const PlausibilityLimits l;
        QCOMPARE(checkPosition(pos(1, 10, 10), l), PositionFault::None);
        QCOMPARE(checkPosition(pos(1, 10, 10, 0.0f), l), PositionFault::None); // no extent carried
        QCOMPARE(checkPosition(pos(1, 10, 10, 1e6f), l), PositionFault::DrumWidth);
        QCOMPARE(checkPosition(pos(1, 10, 10, 0.1f), l), PositionFault::DrumWidth);
        QCOMPARE(checkPosition(pos(1, 10, 10, -3.0f), l), PositionFault::DrumWidth);
        QCOMPARE(checkPosition(pos(1, 1e30f, 10), l), PositionFault::OutsideExtent);
        QCOMPARE(checkPosition(pos(1, 10, -50001), l), PositionFault::OutsideExtent);
        QCOMPARE(checkPosition(pos(1, std::numeric_limits<float>::quiet_NaN(), 10), l),
                 PositionFault::NonFinite);
        QCOMPARE(checkPosition(pos(1, 10, std::numeric_limits<float>::infinity()), l),
                 PositionFault::NonFinite);
        CmPos fast = pos(1, 10, 10);
        fast.speed = 31;
        QCOMPARE(checkPosition(fast, l), PositionFault::Speed);
        QCOMPARE(QString(nameFor(PositionFault::DrumWidth)), QString("drum_width"));
    }

    void gridIgnoresImplausiblePositionsAndKeepsCounting() {
        PassCountGrid grid;
        // A real roller's run, a hostile 10^6 m drum in the middle (the old code swept ~10^13 cells here),
        // then the run goes on: counted as two traversals split at the bad position, nothing else changes.
        for (std::uint32_t s = 0; s < 10; ++s)
            grid.addPosition(1, pos(s, float(s), 0));
        const auto before = grid.summary().coveredCells;
        QVERIFY(before > 0);
        grid.addPosition(1, pos(10, 10, 0, 1e6f));
        grid.addPosition(1, pos(11, 1e30f, 0));
        QCOMPARE(grid.summary().coveredCells, before);
        QCOMPARE(grid.implausiblePositions(), std::uint64_t(2));
        for (std::uint32_t s = 12; s < 20; ++s)
            grid.addPosition(1, pos(s, float(s), 0));
        QVERIFY(grid.summary().coveredCells > before);
        QCOMPARE(grid.countAt(5, 0), 1);
        QCOMPARE(grid.countAt(1e30, 1e30), 0); // readers far away: no overflow
    }

    void oversizedSweepsAreBounded() {
        PassCountSettings s;
        s.cellSize = 0.02; // odd settings: a 10 m step with a 6 m drum would be 300 x 500 cells
        s.maxJump = 10;
        PassCountGrid grid(s);
        grid.addPosition(1, pos(0, 0, 0, 6.0f));
        grid.addPosition(1, pos(1, 9.9f, 0, 6.0f));
        QCOMPARE(grid.oversizedSweeps(), std::uint64_t(1));
        QCOMPARE(grid.summary().coveredCells, std::uint64_t(0));
    }

    void stationKeepsTheSlotWarnsOnceAndModelsNeverSeeIt() {
        FakeClock clock;
        auto store = RibbonStore::inMemory();
        OsyrisConfig cfg;
        cfg.stationIndex = 200;
        PassCountGrid grid(cfg.passCount);
        Recorder rec;
        StationCore core(cfg, clock, *store, &grid, &rec, [](const Bytes&) {});
        core.start();
        auto receive = [&](const CmPos& p) {
            Bytes b;
            encodePos(b, 7, 7, p);
            core.receive(b);
        };
        receive(pos(0, 1, 1));
        receive(pos(1, 2, 1));
        receive(pos(2, 3, 1, 1e6f)); // the drum of 10^6 m from the report
        receive(pos(3, std::numeric_limits<float>::quiet_NaN(), 1));
        receive(pos(4, 4, 1, 1e5f)); // same cause again within 30 s: counted, no second warning
        receive(pos(5, 5, 1));
        core.tick();

        QVERIFY(store->held(7).contains(2)); // the ribbon stays complete for everyone's repair
        QVERIFY(store->held(7).contains(4));
        QCOMPARE(core.counters().get("rx.implausible.drum_width"), std::uint64_t(2));
        QCOMPARE(core.counters().get("rx.implausible.non_finite"), std::uint64_t(1));
        QCOMPARE(int(rec.warnings.size()), 2); // one per machine and cause
        QVERIFY2(rec.warnings[0].find("drum width") != std::string::npos, rec.warnings[0].c_str());
        QVERIFY(rec.warnings[0].find("slot 2") != std::string::npos);

        QCOMPARE(int(rec.positions.size()), 6);
        for (int i : {2, 3, 4}) {
            QVERIFY(!rec.positions[i].implausible.empty());
            QCOMPARE(rec.positions[i].x, 0.0); // no coordinate of a refused position reaches a model
            QCOMPARE(rec.positions[i].width, 0.0);
        }
        QVERIFY(rec.positions[5].implausible.empty());
        QCOMPARE(rec.positions[5].x, 5.0);

        clock.advance(seconds(31)); // the rate limit is per 30 s: a new warning after that
        receive(pos(6, 6, 1, 1e6f));
        QCOMPARE(int(rec.warnings.size()), 3);
    }

    void phantomRangesNeitherWinNorStarveTheRealRibbons() {
        // One ALIVE announcing slots 0..0xFFFFFFFE made the console NAK that phantom gap for
        // ever and, after ~12 s, no real roller's gap was asked for again. Two real rollers with a gap each,
        // a phantom station with an absurd range and another with a wide but believable one.
        FakeClock clock;
        auto store = RibbonStore::inMemory();
        OsyrisConfig cfg;
        cfg.stationIndex = 200;
        cfg.beatMs = 100;
        cfg.maxNaksPerBeat = 1; // the scarcest budget: fairness must still reach every ribbon
        std::map<std::uint8_t, int> naks;
        StationCore core(cfg, clock, *store, nullptr, nullptr, [&](const Bytes& d) {
            for (const auto& m : decodeDatagram(d).messages)
                if (auto* r = std::get_if<CmRequest>(&m.body); r && r->type == RequestType::Nak)
                    ++naks[m.header.whose];
        });
        core.start();
        auto receive = [&](std::uint8_t who, std::uint8_t whose, const CmPos* p, const CmRequest* r) {
            Bytes b;
            if (p)
                encodePos(b, who, whose, *p);
            if (r)
                encodeRequest(b, who, whose, *r);
            core.receive(b);
        };
        for (std::uint8_t owner : {1, 2})
            for (std::uint32_t s : {0u, 1u, 2u, 40u, 41u}) { // slots 3..39 missing
                const CmPos p = pos(s, float(s), float(owner));
                receive(owner, owner, &p, nullptr);
            }
        const CmRequest absurd{RequestType::Alive, 0, 0xFFFFFFFEu, 0, 0};
        receive(9, 9, nullptr, &absurd);
        QCOMPARE(core.counters().get("rx.rejected.alive_range_too_wide"), std::uint64_t(1));
        const CmRequest wide{RequestType::Alive, 0, (1u << 22) - 2, 0, 0};
        receive(8, 8, nullptr, &wide);
        const CmRequest ahead{RequestType::Alive, 0, 3'000'000u, 0, 0}; // a third station about roller 1
        receive(8, 1, nullptr, &ahead);
        QCOMPARE(core.counters().get("rx.rejected.alive_range_ahead"), std::uint64_t(1));
        for (int beat = 0; beat < 40; ++beat) {
            clock.advance(milliseconds(100));
            core.tick();
        }
        // Unanswered, a gap is asked for again after ttlBeats (20): twice in 40 Beats is every chance it had;
        // sorted newest first across ribbons (the old order) the wide phantom took all 40 and the rollers
        // none.
        QVERIFY2(naks[1] >= 2 && naks[2] >= 2,
                 qPrintable(QString("roller 1: %1, roller 2: %2, wide phantom: %3")
                                .arg(naks[1])
                                .arg(naks[2])
                                .arg(naks[8])));
        QCOMPARE(naks.count(9), std::size_t(0)); // the absurd range is never asked for
    }

    void oneDatagramCostsABoundedAnswer() {
        // One 1,250-byte datagram of 50 ALL requests made the console send 206 messages.
        FakeClock clock;
        auto store = RibbonStore::inMemory();
        OsyrisConfig cfg;
        cfg.stationIndex = 200;
        StationCore core(cfg, clock, *store, nullptr, nullptr, [](const Bytes&) {});
        core.start();
        for (std::uint8_t owner : {1, 2}) {
            Bytes b;
            encodePos(b, owner, owner, pos(0, 1, float(owner)));
            core.receive(b);
        }
        const auto newest0 = core.counters().get("tx.retx.newest");
        const auto pong0 = core.counters().get("tx.pong");
        Bytes flood;
        for (int i = 0; i < 25; ++i) { // 50 requests, about 1,250 bytes
            encodeRequest(flood, 9, kIdxAll, {RequestType::All, 0, kSlotLast, 0, 0});
            encodeRequest(flood, 9, kIdxAll, {RequestType::Ping, 0, 0, 1, 1});
        }
        QVERIFY(flood.size() <= 1400);
        core.receive(flood);
        QCOMPARE(core.counters().get("tx.retx.newest") - newest0, std::uint64_t(2)); // one per ribbon held
        QCOMPARE(core.counters().get("tx.pong") - pong0, std::uint64_t(1));
        QCOMPARE(core.counters().get("rx.limited.all"), std::uint64_t(24));
        QCOMPARE(core.counters().get("rx.limited.ping"), std::uint64_t(24));
        // A Beat later the same requester is answered again (a late joiner whose first ALL was lost).
        clock.advance(milliseconds(cfg.beatMs));
        core.tick();
        Bytes again;
        encodeRequest(again, 9, kIdxAll, {RequestType::All, 0, kSlotLast, 0, 0});
        core.receive(again);
        QCOMPARE(core.counters().get("tx.retx.newest") - newest0, std::uint64_t(4));
    }

    void rejectedInputIsAWarningOncePerMinute() {
        // Rejected OSYRIS datagrams went to stderr only.
        FakeClock clock;
        auto store = RibbonStore::inMemory();
        OsyrisConfig cfg;
        Recorder rec;
        StationCore core(cfg, clock, *store, nullptr, &rec, [](const Bytes&) {});
        core.start();
        const CmRequest absurd{RequestType::Alive, 0, 0xFFFFFFFEu, 0, 0};
        for (int i = 0; i < 3; ++i) {
            Bytes b;
            encodeRequest(b, 9, 9, absurd);
            core.receive(b);
        }
        auto warnings = [&] {
            return std::count_if(rec.warnings.begin(), rec.warnings.end(), [](const std::string& w) {
                return w.find("rejected (alive_range_too_wide)") != std::string::npos;
            });
        };
        QCOMPARE(core.counters().get("rx.rejected.alive_range_too_wide"), std::uint64_t(3));
        QCOMPARE(warnings(), 1);
        clock.advance(seconds(61));
        Bytes b;
        encodeRequest(b, 9, 9, absurd);
        core.receive(b);
        QCOMPARE(warnings(), 2);
        QVERIFY(rec.warnings.back().find("4 so far") != std::string::npos);
    }

    void unknownStationsAreCapped() {
        // Every station index a datagram names used to get ribbons, timers and rate-limit
        // entries.
        FakeClock clock;
        auto store = RibbonStore::inMemory();
        OsyrisConfig cfg;
        cfg.stationIndex = 200;
        cfg.machineNames[120] = "R-120"; // configured: admitted whatever the unknown ones did before
        StationCore core(cfg, clock, *store, nullptr, nullptr, [](const Bytes&) {});
        core.start();
        auto send = [&](std::uint8_t who, std::uint8_t whose) {
            Bytes b;
            encodePos(b, who, whose, pos(0, 1, 1));
            core.receive(b);
        };
        const int cap = StationCore::kMaxUnknownStations;
        for (int i = 0; i < cap; ++i)
            send(std::uint8_t(10 + i), std::uint8_t(10 + i));
        QCOMPARE(core.counters().get("rx.rejected.station_cap"), std::uint64_t(0));
        QCOMPARE(int(store->machines().size()), cap);
        // Beyond the cap: the datagram is counted and nothing is allocated for its sender or its ribbon.
        for (int i = 0; i < 50; ++i)
            send(std::uint8_t(60 + i), std::uint8_t(60 + i));
        QCOMPARE(core.counters().get("rx.rejected.station_cap"), std::uint64_t(50));
        QCOMPARE(int(store->machines().size()), cap);
        QCOMPARE(int(core.heardStations().size()), cap);
        QVERIFY(!core.knownMax(60));
        // An admitted station relaying (or inventing) the ribbon of a new one: that message is ignored too.
        send(10, 99);
        Bytes alive;
        encodeRequest(alive, 10, 98, {RequestType::Alive, 0, 10, 0, 0});
        core.receive(alive);
        QCOMPARE(core.counters().get("rx.rejected.station_cap"), std::uint64_t(52));
        QVERIFY(!core.knownMax(99) && !core.knownMax(98));
        // A configured station and the known ones keep working.
        send(120, 120);
        send(10, 10);
        QCOMPARE(int(store->machines().size()), cap + 1);
        QCOMPARE(store->count(10), std::uint64_t(1)); // the same slot again: a duplicate
        // A message claiming another sender inside a datagram is not believed (§6: one IdxWho per datagram).
        Bytes mixed;
        encodePos(mixed, 10, 10, pos(1, 1, 1));
        encodePos(mixed, 11, 11, pos(1, 1, 1));
        core.receive(mixed);
        QCOMPARE(core.counters().get("rx.rejected.mixed_sender"), std::uint64_t(1));
        QCOMPARE(store->count(11), std::uint64_t(1));
        QCOMPARE(store->count(10), std::uint64_t(2));
    }

    void ribbonStoreIsBounded() {
        // The ribbon of an admitted station grew without a bound (one station could fill the
        // memory with positions). Beyond the bound a position is refused, counted and warned about; what is
        // held stays (it is in the pass counts) and the ribbon's gaps are no longer NAKed (they would be
        // refused). The store-wide bound likewise; other ribbons keep working below it.
        FakeClock clock;
        auto store = RibbonStore::inMemory();
        OsyrisConfig cfg;
        cfg.stationIndex = 200;
        cfg.maxRibbonSlots = 100;
        cfg.maxStoreSlots = 250;
        Recorder rec;
        std::map<std::uint8_t, int> naks;
        StationCore core(cfg, clock, *store, nullptr, &rec, [&](const Bytes& d) {
            for (const auto& m : decodeDatagram(d).messages)
                if (auto* r = std::get_if<CmRequest>(&m.body); r && r->type == RequestType::Nak)
                    ++naks[m.header.whose];
        });
        core.start();
        auto send = [&](std::uint8_t owner, std::uint32_t slot) {
            Bytes b;
            encodePos(b, owner, owner, pos(slot, float(slot % 50), float(owner)));
            core.receive(b);
        };
        for (std::uint32_t s = 0; s < 150; s += 1)
            send(10, s * 2); // every other slot: gaps all along the ribbon
        QCOMPARE(store->count(10), std::uint64_t(100));
        QCOMPARE(core.counters().get("rx.rejected.ribbon_full"), std::uint64_t(50));
        QVERIFY(store->has(10, 0) && store->has(10, 198) && !store->has(10, 200));
        send(10, 198); // a held slot again is a duplicate, not a refusal
        QCOMPARE(core.counters().get("rx.rejected.ribbon_full"), std::uint64_t(50));
        const auto warned = std::count_if(rec.warnings.begin(), rec.warnings.end(), [](const std::string& w) {
            return w.find("rejected (ribbon_full)") != std::string::npos;
        });
        QCOMPARE(warned, 1); // one warning a minute, however many refused
        // Another station's ribbon is still taken, up to the store's bound (250 in all).
        for (std::uint32_t s = 0; s < 200; ++s)
            send(11, s);
        QCOMPARE(store->count(11), std::uint64_t(100)); // its own ribbon bound first
        for (std::uint32_t s = 0; s < 80; ++s)
            send(12, s);
        QCOMPARE(store->totalCount(), std::uint64_t(250));
        QCOMPARE(store->count(12), std::uint64_t(50));
        QCOMPARE(core.counters().get("rx.rejected.store_full"), std::uint64_t(30));
        // The full ribbons' gaps are not asked for: nothing would be kept.
        for (int beat = 0; beat < 100; ++beat) {
            clock.advance(milliseconds(cfg.beatMs));
            core.tick();
        }
        QCOMPARE(naks[10], 0);
        QCOMPARE(store->count(10), std::uint64_t(100)); // nothing held was dropped
    }

    void oneDatagramCausesAtMostKDatagramsSent_data() {
        QTest::addColumn<bool>(
            "owner"); // the station under test has its own ribbon (a machine) or not (the OCU)
        QTest::addColumn<QString>("flood");
        for (bool owner : {false, true})
            for (const char* f : {"all", "ping", "nak", "nak-repeated", "mixed"})
                QTest::newRow(qPrintable(QString(owner ? "machine, " : "console, ") + f))
                    << owner << QString(f);
    }
    void oneDatagramCausesAtMostKDatagramsSent() {
        // "one received datagram causes at most a documented constant number of datagrams sent".
        // The worst datagrams a hostile station can send (MaxLen full of ALL, PING or NAK for everything) fed
        // to a StationCore holding three ribbons whose positions carry enough properties that no two answers
        // fit one datagram; the datagrams sent afterwards are compared with the same run without that
        // datagram.
        QFETCH(bool, owner);
        QFETCH(QString, flood);
        const std::uint8_t self = owner ? 1 : 200;
        const std::uint8_t hostile = 9;
        std::vector<PosProp> props(78); // 73 + 8 + 78 x 8 = 705 bytes: more than MaxLen / 2
        for (std::size_t i = 0; i < props.size(); ++i)
            props[i] = PosProp{std::uint32_t(i), std::uint32_t(i)};
        auto run = [&](bool probe, std::uint64_t* answered) {
            FakeClock clock;
            auto store = RibbonStore::inMemory();
            OsyrisConfig cfg;
            cfg.stationIndex = self;
            cfg.beatMs = 100;
            cfg.ttlBeats = 10;
            int sent = 0;
            StationCore core(cfg, clock, *store, nullptr, nullptr, [&](const Bytes&) { ++sent; });
            core.start();
            for (std::uint32_t s = 0; s < 400; ++s) {
                if (owner)
                    core.publishOwnPosition(pos(0, float(s) * 0.3f, 0), props);
                for (std::uint8_t other : {2, 3}) {
                    if (other == self)
                        continue;
                    Bytes b;
                    encodePos(b, other, other, pos(s, float(s) * 0.3f, float(other)));
                    encodePosProps(b, other, other, props);
                    core.receive(b);
                }
            }
            for (int beat = 0; beat < 30; ++beat) { // settle: late-join ALL and the first ALIVEs are out
                clock.advance(milliseconds(100));
                core.tick();
            }
            auto request = [&](RequestType t, std::uint8_t whose) {
                Bytes b;
                const std::uint32_t to = t == RequestType::Nak ? kSlotLast - 1 : 0;
                while (b.size() + kRequestSize <= 1400)
                    encodeRequest(b, hostile, whose, {t, 0, to, 1, 1});
                return b;
            };
            std::vector<Bytes> before, probes;
            const std::uint8_t ribbon = owner ? self : 2;
            if (flood == "all") {
                probes.push_back(request(RequestType::All, kIdxAll));
            } else if (flood == "ping") {
                probes.push_back(request(RequestType::Ping, kIdxAll));
            } else if (flood == "nak") {
                probes.push_back(request(RequestType::Nak, ribbon));
            } else if (flood == "nak-repeated") {
                // A relay that hears the owner answers only the second repetition of a NAK (§5 soft relay).
                before.push_back(request(RequestType::Nak, 3));
                before.push_back(request(RequestType::Nak, 3));
                probes.push_back(request(RequestType::Nak, 3));
            } else {
                Bytes b;
                for (int i = 0; b.size() + 3 * kRequestSize <= 1400; ++i) {
                    encodeRequest(b, hostile, kIdxAll, {RequestType::All, 0, 0, 0, 0});
                    encodeRequest(b, hostile, self, {RequestType::Ping, 0, 0, 1, 1});
                    encodeRequest(b, hostile, std::uint8_t(i % 2 ? 3 : ribbon),
                                  {RequestType::Nak, std::uint32_t(i), kSlotLast, 0, 0});
                }
                probes.push_back(b);
            }
            for (const auto& b : before) {
                if (b.size() > 1400)
                    qFatal("a probe larger than MaxLen");
                core.receive(b);
                for (int beat = 0; beat < 8; ++beat) {
                    clock.advance(milliseconds(100));
                    core.tick();
                }
            }
            for (int beat = 0; beat < 8; ++beat) {
                clock.advance(milliseconds(100));
                core.tick();
            }
            const int sent0 = sent;
            const auto retx0 = core.counters().get("tx.retx") + core.counters().get("tx.pong");
            if (probe)
                for (const auto& b : probes) {
                    if (b.size() > 1400)
                        qFatal("a probe larger than MaxLen");
                    core.receive(b);
                }
            for (int beat = 0; beat < 60; ++beat) {
                clock.advance(milliseconds(100));
                core.tick();
            }
            *answered = core.counters().get("tx.retx") + core.counters().get("tx.pong") - retx0;
            return sent - sent0;
        };
        std::uint64_t answeredWith = 0, answeredWithout = 0;
        const int with = run(true, &answeredWith);
        const int without = run(false, &answeredWithout);
        qInfo("%s: %d datagrams sent in 6 s after the datagram, %d without it (answers %llu vs %llu); K = %d",
              qPrintable(flood), with, without, qulonglong(answeredWith), qulonglong(answeredWithout),
              StationCore::kMaxDatagramsPerReceived);
        if (!owner && flood == "nak")
            QCOMPARE(answeredWith, std::uint64_t(0)); // a relay answers only a repeated NAK (§5 soft relay)
        else
            QVERIFY(answeredWith > answeredWithout); // the datagram was answered: the bound is not silence
        QVERIFY2(with - without <= StationCore::kMaxDatagramsPerReceived,
                 qPrintable(QString("%1 datagrams caused by one").arg(with - without)));
    }

    void limitsComeFromTheConfiguration() {
        OsyrisConfig cfg;
        cfg.passCount.plausibility.maxWidthM = 13; // a wide paver screed
        QCOMPARE(checkPosition(pos(1, 0, 0, 12.5f), cfg.passCount.plausibility), PositionFault::None);
        PassCountGrid grid(cfg.passCount);
        grid.addPosition(1, pos(0, 0, 0, 12.5f));
        grid.addPosition(1, pos(1, 1, 0, 12.5f));
        QCOMPARE(grid.implausiblePositions(), std::uint64_t(0));
        QVERIFY(grid.summary().coveredCells > 0);
    }
};

QTEST_APPLESS_MAIN(TestOsyrisPlausibility)
#include "test_osyris_plausibility.moc"
