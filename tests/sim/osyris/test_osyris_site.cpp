// OSYRIS stations on the in-memory radio with a fake clock (accelerated time): recovery under loss,
// late join, static and dynamic relay, restart on the same SQLite file, PING/PONG, text, range.
#include "sim/osyris/OsyrisDemo.h"
#include "sim/osyris/SimSite.h"

#include <QTemporaryDir>
#include <QtTest>

#include <random>
#include <set>

using namespace ocu;
using namespace ocu::osyris;
using namespace ocu::sim::osyris;

namespace {

OsyrisConfig cfg(std::uint8_t idx, int active = 7) {
    OsyrisConfig c;
    c.stationIndex = idx;
    c.active = active;
    c.beatMs = 100;
    c.sendPeriodMs = 2000;
    c.ttlBeats = 10;
    return c;
}

SimStationOptions machineStation(std::uint8_t idx, MachineSpec m) {
    SimStationOptions o;
    o.config = cfg(idx);
    o.machine = std::move(m);
    return o;
}

// Every station holds every slot of every ribbon its owner holds.
bool complete(SimSite& site, const std::vector<int>& stations, const std::vector<int>& owners,
              QString* why = nullptr) {
    for (int o : owners) {
        if (!site.running(o))
            continue;
        auto idx = site.core(o).idx();
        auto want = site.store(o).held(idx);
        for (int s : stations) {
            if (!site.running(s) || s == o)
                continue;
            auto have = site.store(s).held(idx);
            if (want.empty() || !have.containsAll(0, want.max())) {
                if (why) {
                    std::uint64_t got = 0;
                    if (!want.empty())
                        for (auto& r : have.intersect(0, want.max()))
                            got += r.size();
                    *why = QString("station %1 misses %2 slots of ribbon %3 (owner has %4)")
                               .arg(site.core(s).idx())
                               .arg(qulonglong(want.empty() ? 0 : want.max() + 1 - got))
                               .arg(idx)
                               .arg(qulonglong(want.count()));
                }
                return false;
            }
        }
    }
    return true;
}

struct Recorder : OsyrisListener {
    std::vector<std::pair<int, std::string>> texts;
    std::vector<std::pair<int, double>> pongs;
    std::set<int> alive;
    int positions = 0;
    int passChanges = 0;
    void onMachinePosition(const MachineSnapshot&) override { ++positions; }
    void onText(std::uint8_t idx, const std::string& t) override { texts.emplace_back(idx, t); }
    void onPong(std::uint8_t idx, double rtt, float, float) override { pongs.emplace_back(idx, rtt); }
    void onStationAlive(std::uint8_t idx, std::optional<SlotRange>) override { alive.insert(idx); }
    void onPassCountChanged(const GridRect&) override { ++passChanges; }
};

} // namespace

class TestOsyrisSite : public QObject {
    Q_OBJECT
private slots:
    // ocu-sim --interface ADDR serves consoles on other hosts: the stations' multicast must leave the host
    // there (TTL 1, one LAN segment), and never on loopback.
    void multicastTtlFollowsTheInterface() {
        QCOMPARE(OsyrisDemo().ocuConfig().multicastTtl, 0);
        OsyrisDemoOptions lan;
        lan.interfaceAddress = "192.168.10.5";
        QCOMPARE(OsyrisDemo(lan).ocuConfig().multicastTtl, 1);
    }

    void machineModels() {
        SimulatedMachine paver(paverSpec());
        auto p0 = paver.poseAt(0), p60 = paver.poseAt(60);
        QCOMPARE(p60.x - p0.x, 2.0f); // ~2 m/min
        QVERIFY((p0.flags & kPosValid) && (p0.flags & kPosForward) && !(p0.flags & kPosVibrating));
        QCOMPARE(p0.dx, 4.5f);
        auto spec = rollerSpec("R", 1.0, 1.7, 0, 3);
        spec.shadowFromX = 20;
        spec.shadowToX = 22;
        SimulatedMachine roller(spec);
        int fwd = 0, back = 0, vib = 0, still = 0, shadow = 0, medium = 0;
        for (int i = 0; i < 4000; ++i) {
            auto p = roller.poseAt(i * 0.1);
            QCOMPARE(p.y, 1.0f);
            QCOMPARE(p.dx, 1.7f);
            fwd += (p.flags & kPosForward) != 0;
            back += (p.flags & kPosBackward) != 0;
            vib += (p.flags & kPosVibrating) != 0;
            still += (p.flags & kPosVibrating) == 0;
            medium += (p.flags & kPosAccuracyMed) != 0;
            if (p.flags & kPosGpsShadow) {
                ++shadow;
                QVERIFY(!(p.flags & kPosValid));
                QVERIFY(p.x >= 20 && p.x <= 22);
            }
            // The roller works behind the paver.
            QVERIFY(p.x < paver.poseAt(i * 0.1).x - 4.9f);
        }
        QVERIFY(fwd > 1500 && back > 1500);
        QVERIFY(vib > 2500 && still > 500); // every 4th pass static
        QVERIFY(shadow > 0 && medium > 0);
        SimulatedMachine relay(relaySpec("C", 50, 0, 550, 0, 10));
        QCOMPARE(relay.poseAt(25).x, 300.0f);
        QCOMPARE(relay.poseAt(75).x, 300.0f); // on the way back
        QVERIFY(relay.poseAt(75).flags & kPosBackward);
    }

    void fiveStationsThirtyPercentLoss_data() {
        QTest::addColumn<int>("seed");
        QTest::addColumn<double>("loss");
        QTest::newRow("30% seed 7") << 7 << 0.30;
        QTest::newRow("30% seed 8") << 8 << 0.30;
        QTest::newRow("30% seed 9") << 9 << 0.30;
        QTest::newRow("30% seed 10") << 10 << 0.30;
        QTest::newRow("30% seed 11") << 11 << 0.30;
        if (qEnvironmentVariableIsSet("OSYRIS_MORE_SEEDS"))
            for (int seed = 12; seed < 30; ++seed)
                QTest::newRow(qPrintable(QString("30% seed %1").arg(seed))) << seed << 0.30;
        QTest::newRow("10% seed 7") << 7 << 0.10;
    }
    void fiveStationsThirtyPercentLoss() {
        QFETCH(int, seed);
        QFETCH(double, loss);
        SimSite site(static_cast<std::uint32_t>(seed));
        LinkProfile lossy;
        lossy.loss = loss;
        lossy.duplicate = 0.10;
        lossy.reorder = 0.20;
        site.network().setDefaultLink(lossy);
        // Paper-and-pencil bookkeeping of what the radio destroyed: originals lost per receiver, and every
        // position sent again later.
        std::set<std::pair<int, std::uint32_t>> sentOnce;
        std::uint64_t lostPositions = 0, retransmitted = 0, needless = 0, needlessByRelay = 0,
                      nakDatagrams = 0;
        site.network().setTap([&](int from, const Bytes& d, const std::vector<int>& lostAt) {
            bool nak = false;
            for (auto& m : decodeDatagram(d).messages) {
                if (auto* p = std::get_if<CmPos>(&m.body)) {
                    if (sentOnce.insert({m.header.whose, p->slot}).second) {
                        lostPositions += lostAt.size();
                    } else {
                        ++retransmitted;
                        // Needless: every other station already held the slot when it was sent again.
                        bool missing = false;
                        for (int i = 0; i < int(site.size()); ++i)
                            missing = missing || (i != from && !site.store(i).has(m.header.whose, p->slot));
                        needless += !missing;
                        needlessByRelay += !missing && site.core(from).idx() != m.header.whose;
                    }
                } else if (auto* r = std::get_if<CmRequest>(&m.body); r && r->type == RequestType::Nak) {
                    nak = true;
                }
            }
            nakDatagrams += nak;
        });
        site.add(machineStation(0, paverSpec()));
        site.add(machineStation(1, rollerSpec("R1", -1.0, 2.1, 0, 11)));
        site.add(machineStation(2, rollerSpec("R2", 1.0, 1.7, 10, 12)));
        site.add(machineStation(3, rollerSpec("R3", 0.0, 2.0, 20, 13)));
        SimStationOptions ocuStation;
        ocuStation.config = cfg(200, 15);
        site.add(ocuStation);
        std::vector<int> all{0, 1, 2, 3, 4};
        const double lossSeconds = qEnvironmentVariableIntValue("OSYRIS_LOSS_SECONDS") > 0
                                       ? qEnvironmentVariableIntValue("OSYRIS_LOSS_SECONDS")
                                       : 60;
        site.run(lossSeconds);
        QVERIFY(site.core(4).missingCount() > 0 || lostPositions > 0);
        site.network().setDefaultLink(LinkProfile{}); // the loss stops
        for (int i = 0; i < 4; ++i)
            site.setMachine(i, std::nullopt); // and the machines park, so "every slot" is a fixed target
        QString why;
        bool done = site.runUntil([&] { return complete(site, all, {0, 1, 2, 3}, &why); }, 60);
        QVERIFY2(done, qPrintable(why));
        site.run(0.3); // one more Beat: every grid has advanced over the last repairs
        std::uint64_t naks = 0, ncfs = 0, relay = 0, newest = 0, boosted = 0;
        for (int i : all) {
            naks += site.core(i).counters().get("tx.nak");
            ncfs += site.core(i).counters().get("tx.ncf");
            relay += site.core(i).counters().get("tx.retx.relay");
            newest += site.core(i).counters().get("tx.retx.newest");
            boosted += site.core(i).counters().get("tx.retx.boosted");
        }
        qInfo("retransmissions by non-owners %llu, late-join newest %llu, boosted %llu, needless %llu (by "
              "non-owners %llu); NAK "
              "datagrams %llu (%.3f per loss)",
              qulonglong(relay), qulonglong(newest), qulonglong(boosted), qulonglong(needless),
              qulonglong(needlessByRelay), qulonglong(nakDatagrams),
              double(nakDatagrams) / double(lostPositions));
        double perLoss = double(retransmitted) / double(lostPositions);
        qInfo(
            "%.0f%% loss, 5 stations: %llu lost (position, receiver) pairs, %llu retransmitted positions -> "
            "%.3f "
            "retransmissions per lost position; %llu NAKs (%.3f per loss), %llu NCFs; recovered %.1f s "
            "after the "
            "loss stopped",
            loss * 100, qulonglong(lostPositions), qulonglong(retransmitted), perLoss, qulonglong(naks),
            double(naks) / double(lostPositions), qulonglong(ncfs), site.simTime() - lossSeconds);
        QVERIFY(lostPositions > (loss > 0.2 ? 300u : 80u));
        // Deterministic run (fixed seed, fake clock). NORM's pure ARQ needs 1.03 here and the per-message ARQ
        // floor is 1.02 (research/norm-anchor.md); more than ~1.2 would mean duplicate answers leak.
        QVERIFY(perLoss > 0.5 && perLoss < 1.2);
        // NAK rounds: a NAK datagram carries the gaps of a round together, as NORM's NACK does.
        if (loss > 0.2)
            QVERIFY2(double(nakDatagrams) / double(lostPositions) <= 0.2, "NAK datagrams per lost position");
        // Same ribbons -> same pass counts at every station (live or recovered).
        for (int i = 1; i < 5; ++i)
            QVERIFY(site.grid(i).snapshotTiles() == site.grid(0).snapshotTiles());
        QVERIFY(site.grid(4).summary().coveredCells > 100);
    }

    void lateJoinAfterTenMinutes() {
        SimSite site(3);
        site.add(machineStation(0, paverSpec()));
        site.add(machineStation(1, rollerSpec("R1", -1.0, 2.1, 0, 11)));
        site.add(machineStation(2, rollerSpec("R2", 1.0, 1.7, 10, 12)));
        site.run(600); // ten minutes of simulated work
        std::map<std::uint8_t, std::uint32_t> newestAtJoin;
        for (int i = 0; i < 3; ++i)
            newestAtJoin[site.core(i).idx()] = site.store(i).newest(site.core(i).idx())->pos.slot;
        Recorder rec;
        SimStationOptions o;
        o.config = cfg(200, 15);
        o.listener = &rec;
        int late = site.add(o);
        bool newest = site.runUntil(
            [&] {
                for (auto [owner, slot] : newestAtJoin) {
                    auto n = site.store(late).newest(owner);
                    if (!n || n->pos.slot < slot)
                        return false;
                }
                return true;
            },
            0.2, 1); // 2 beats
        QVERIFY2(newest, "newest position of every machine within 2 beats");
        QVERIFY(site.store(late).count(0) < 100); // newest first, the history comes afterwards
        for (int i = 0; i < 3; ++i)
            site.setMachine(i, std::nullopt);
        QString why;
        QVERIFY2(site.runUntil(
                     [&] {
                         return complete(site, {late}, {0, 1, 2}, &why);
                     },
                     120),
                 qPrintable(why));
        qInfo("late joiner complete after %.1f s: %llu positions", site.simTime() - 600,
              qulonglong(site.store(late).totalCount()));
        site.run(0.3); // one more Beat: the grid advances over the last repairs (as in the five-station case)
        QVERIFY(site.grid(late).snapshotTiles() == site.grid(1).snapshotTiles()); // late join = live
        QVERIFY(rec.passChanges > 0);
        QVERIFY(rec.alive.count(0) && rec.alive.count(1));
    }

    void staticRelay() {
        SimSite site(5);
        site.network().setRange(250);
        int a = site.add(machineStation(1, relaySpec("A", 0, 0, 0, 0, 0)));
        int b = site.add(machineStation(2, relaySpec("B", 400, 0, 400, 0, 0)));
        SimStationOptions c;
        c.config = cfg(3);
        c.fixedPosition = std::make_pair(200.0, 0.0);
        int ci = site.add(c);
        QVERIFY(!site.network().inRange(a, b));
        QVERIFY(site.network().inRange(a, ci) && site.network().inRange(b, ci));
        site.run(60);
        site.setMachine(b, std::nullopt);
        site.setMachine(a, std::nullopt);
        QString why;
        QVERIFY2(site.runUntil([&] { return complete(site, {a, b}, {a, b}, &why); }, 60), qPrintable(why));
        QVERIFY(site.core(ci).counters().get("tx.retx") > 0); // C relayed
        QCOMPARE(site.store(a).held(2).ranges(), site.store(b).held(2).ranges());
    }

    void dynamicRelay() {
        SimSite site(9);
        site.network().setRange(250);
        int a = site.add(machineStation(1, relaySpec("A", 0, 0, 0, 0, 0)));
        int b = site.add(machineStation(2, relaySpec("B", 600, 0, 600, 0, 0)));
        // C shuttles between them and is never in range of both at once.
        int c = site.add(machineStation(3, relaySpec("C", 50, 0, 550, 0, 10)));
        QVERIFY(!site.network().inRange(a, b));
        site.run(200);
        site.setMachine(b, std::nullopt);
        QString why;
        QVERIFY2(site.runUntil([&] { return complete(site, {a}, {b}, &why); }, 300), qPrintable(why));
        QVERIFY(site.core(c).counters().get("tx.retx") > 0);
        QCOMPARE(site.store(a).held(2).ranges(), site.store(b).held(2).ranges());
    }

    void restartOnSameSqliteFile() {
        QTemporaryDir dir;
        SimSite site(4);
        site.add(machineStation(0, paverSpec()));
        site.add(machineStation(1, rollerSpec("R1", -1.0, 2.1, 0, 11)));
        SimStationOptions o;
        o.config = cfg(200, 15);
        o.config.sqlitePath = dir.filePath("site.sqlite").toStdString();
        int ocu = site.add(o);
        site.run(60);
        std::uint64_t before = site.store(ocu).totalCount();
        QVERIFY(before > 200);
        site.stop(ocu); // killed mid-run
        site.run(60);
        site.start(ocu);
        QCOMPARE(site.store(ocu).totalCount(), before); // keeps what it had
        std::uint64_t gap = 0;
        for (int i = 0; i < 2; ++i) {
            auto idx = site.core(i).idx();
            gap += site.store(i).held(idx).count() - site.store(ocu).held(idx).count();
        }
        std::uint64_t retxBefore =
            site.core(0).counters().get("tx.retx") + site.core(1).counters().get("tx.retx");
        for (int i = 0; i < 2; ++i)
            site.setMachine(i, std::nullopt);
        QString why;
        QVERIFY2(site.runUntil([&] { return complete(site, {ocu}, {0, 1}, &why); }, 60), qPrintable(why));
        std::uint64_t retx =
            site.core(0).counters().get("tx.retx") + site.core(1).counters().get("tx.retx") - retxBefore;
        std::uint64_t asked = site.core(ocu).counters().get("tx.nak.slots");
        qInfo("restart: gap %llu positions, %llu requested, %llu retransmitted", qulonglong(gap),
              qulonglong(asked), qulonglong(retx));
        QVERIFY(gap > 100);
        QVERIFY(asked <= gap + 10); // only the gap is fetched
        QVERIFY(retx <= gap + 10);
        QCOMPARE(site.core(ocu).counters().get("tx.all"), std::uint64_t(0));
    }

    void pingTextAndRejections() {
        SimSite site(2);
        Recorder r0, r1;
        auto o0 = machineStation(0, rollerSpec("R1", 0, 2.1, 0, 1));
        o0.listener = &r0;
        o0.config.active = 15;
        auto o1 = machineStation(1, rollerSpec("R2", 3, 2.1, 0, 2));
        o1.listener = &r1; // active 7: does not display messages
        site.add(o0);
        site.add(o1);
        site.run(1);
        site.core(0).ping(1);
        site.core(1).sendText("vibration off on bridge");
        site.core(0).sendText("hello");
        site.run(1);
        QCOMPARE(r0.pongs.size(), std::size_t(1));
        QCOMPARE(r0.pongs[0].first, 1);
        QVERIFY(r0.pongs[0].second >= 0 && r0.pongs[0].second < 300);
        QCOMPARE(r0.texts.size(), std::size_t(1));
        QCOMPARE(QString::fromStdString(r0.texts[0].second), QString("vibration off on bridge"));
        QVERIFY(r1.texts.empty()); // Active without 8
        QVERIFY(r0.positions > 0);
        // Garbage is rejected with a reason and counted; good data still flows.
        auto& c = site.core(0);
        Bytes junk{1, 2, 3};
        c.receive(junk);
        Bytes badLen{0, 0, 200, 0, 1, 0, 1, 1};
        c.receive(badLen);
        QCOMPARE(c.counters().get("rx.rejected.truncated"), std::uint64_t(2));
        Bytes big(3000, 0);
        c.receive(big);
        QCOMPARE(c.counters().get("rx.rejected.oversized"), std::uint64_t(1));
        std::mt19937 rng(3);
        for (int i = 0; i < 2000; ++i) {
            Bytes r(1 + rng() % 200);
            for (auto& x : r)
                x = static_cast<std::uint8_t>(rng());
            c.receive(r);
        }
        QVERIFY(c.counters().sumPrefix("rx.rejected.") > 1900);
        auto before = site.store(0).count(1);
        site.run(2);
        QVERIFY(site.store(0).count(1) > before);
    }

    void checksumAndRange() {
        SimSite site(2);
        auto a = machineStation(0, relaySpec("A", 0, 0, 0, 0, 0));
        a.config.checksum = Checksum::Crc16;
        auto b = machineStation(1, relaySpec("B", 50, 0, 50, 0, 0));
        site.add(a);
        site.add(b);
        site.run(3);
        QVERIFY(site.core(0).counters().get("rx.rejected.bad_checksum") > 0);
        QCOMPARE(site.store(0).count(1), std::uint64_t(0));

        SimSite far(3);
        auto c = machineStation(0, relaySpec("C", 0, 0, 0, 0, 0));
        c.config.maxRange = 100;
        auto d = machineStation(1, relaySpec("D", 500, 0, 500, 0, 0));
        d.config.maxRange = 100;
        auto e = machineStation(2, relaySpec("E", 60, 0, 60, 0, 0));
        e.config.maxRange = 100;
        far.add(c);
        far.add(d);
        far.add(e);
        far.run(5);
        QVERIFY(far.core(0).counters().get("rx.dropped.range") > 0);           // §7 MaxRange
        QCOMPARE(far.store(0).held(1).intersect(0, 5).size(), std::size_t(0)); // D never heard directly...
        QVERIFY(far.store(0).count(2) > 0);                                    // ...E (60 m) is
    }
};

QTEST_GUILESS_MAIN(TestOsyrisSite)
#include "test_osyris_site.moc"
