// Pass-count snapshots for other threads: copy-on-write tiles (an unchanged tile is shared by consecutive
// snapshots, a changed one is copied and the old snapshot keeps its values), the readers of a snapshot, a
// snapshot that stays unchanged while another thread keeps counting into the grid, and the core offering
// snapshots at a bounded rate with back-pressure (fake clock).
#include "protocols/osyris/PassCountGrid.h"
#include "protocols/osyris/RibbonStore.h"
#include "protocols/osyris/StationCore.h"

#include <QtTest>

#include <atomic>
#include <cmath>
#include <mutex>
#include <thread>

using namespace ocu;
using namespace ocu::osyris;

namespace {
constexpr std::uint32_t kGood = kPosValid | kPosAccuracyHigh | kPosVibrating;

std::vector<CmPos> run(double x0, double x1, double y, double step, std::uint32_t firstSlot = 0) {
    std::vector<CmPos> out;
    int n = static_cast<int>(std::lround(std::abs(x1 - x0) / step));
    double dir = x1 > x0 ? 1 : -1;
    for (int i = 0; i <= n; ++i) {
        CmPos p;
        p.x = static_cast<float>(x0 + dir * i * step);
        p.y = static_cast<float>(y);
        p.dx = 2.1f;
        p.flags = kGood | (dir > 0 ? kPosForward : kPosBackward);
        p.slot = firstSlot + static_cast<std::uint32_t>(i);
        out.push_back(p);
    }
    return out;
}

void feed(PassCountGrid& g, std::uint8_t m, const std::vector<CmPos>& ps) {
    for (auto& p : ps)
        g.addPosition(m, p);
}

std::int32_t tileOf(const PassCountGrid& g, double v) {
    return g.cellIndex(v) >> kTileBits;
}

std::uint64_t checksum(const PassCountSnapshot& s) {
    std::uint64_t h = 1469598103934665603ull;
    for (const auto& e : s.tiles())
        for (auto c : e.tile->counts)
            h = (h ^ c) * 1099511628211ull;
    return h;
}

struct Recorder : OsyrisListener {
    bool ready = true;
    std::vector<std::shared_ptr<const PassCountSnapshot>> snaps;
    bool readyForPassCounts() override { return ready; }
    void onPassCounts(std::shared_ptr<const PassCountSnapshot> s) override { snaps.push_back(std::move(s)); }
};
} // namespace

class TestOsyrisSnapshot : public QObject {
    Q_OBJECT
private slots:
    void unchangedTilesAreSharedChangedOnesCopied() {
        PassCountGrid g;
        feed(g, 1, run(-5, 5, -3, 0.3));     // patch A, around the origin (negative cells too)
        feed(g, 2, run(100, 110, 100, 0.3)); // patch B, far away
        auto s1 = g.snapshot();
        const auto before = s1->tileValues();
        QCOMPARE(before, g.snapshotTiles());
        QVERIFY(!s1->empty());

        feed(g, 2, run(110, 100, 100, 0.3, 1000)); // a second pass over B only (backward: a new traversal)
        auto s2 = g.snapshot();
        QVERIFY(s2->sequence() > s1->sequence());
        QCOMPARE(s1->tileValues(), before); // the published snapshot did not change
        QCOMPARE(s2->tileValues(), g.snapshotTiles());

        const std::int32_t aty = tileOf(g, -3), bty = tileOf(g, 100);
        int shared = 0, copied = 0;
        for (const auto& e : s2->tiles()) {
            const PassCountTile* old = s1->tile(e.tx, e.ty);
            QVERIFY(old);
            if (e.ty == aty) { // A was not touched: the very same tile object
                QCOMPARE(e.tile.get(), old);
                QVERIFY(e.tile->generation <= s1->sequence());
                ++shared;
            } else if (e.ty == bty) { // B was written: a copy, the old one keeps its counts
                QVERIFY(e.tile.get() != old);
                QVERIFY(e.tile->generation > s1->sequence());
                QVERIFY(e.tile->counts != old->counts);
                ++copied;
            }
        }
        QVERIFY(shared >= 2 && copied >= 1);
        QCOMPARE(s1->countAtCell(g.cellIndex(105), g.cellIndex(100)), 1);
        QCOMPARE(s2->countAtCell(g.cellIndex(105), g.cellIndex(100)), 2);
        QCOMPARE(s2->countAtCell(g.cellIndex(0), g.cellIndex(-3)), 1);

        // What changed between them: B's tiles only.
        auto changed = s2->changedSince(s1->sequence());
        QVERIFY(changed);
        QVERIFY(changed->cy0 >= bty * kTileSize && changed->cx0 >= tileOf(g, 100) * kTileSize);
        QVERIFY(changed->cx1 < (tileOf(g, 110) + 1) * kTileSize);

        // No change: a new snapshot shares every tile and reports nothing changed.
        auto s3 = g.snapshot();
        QCOMPARE(s3->tiles().size(), s2->tiles().size());
        for (std::size_t i = 0; i < s3->tiles().size(); ++i)
            QCOMPARE(s3->tiles()[i].tile.get(), s2->tiles()[i].tile.get());
        QVERIFY(!s3->changedSince(s2->sequence()));

        // Clearing (new settings) empties the next snapshot and says so.
        g.reset();
        auto s4 = g.snapshot();
        QVERIFY(s4->empty());
        QCOMPARE(s4->clearedAt(), s4->sequence());
        QVERIFY(s3->clearedAt() < s4->clearedAt());
        QCOMPARE(s3->tileValues(), s2->tileValues()); // still intact
    }

    void snapshotReadersMatchTheGrid() {
        PassCountGrid g;
        feed(g, 1, run(-12, 12, -1, 0.3));
        feed(g, 1, run(12, -12, 0.5, 0.3, 500));
        feed(g, 2, run(-3, 20, 4, 0.3));
        auto s = g.snapshot();
        QCOMPARE(s->cellSize(), g.settings().cellSize);
        const CellBox e = s->extent();
        QCOMPARE(e.cx0 % kTileSize, 0);
        QCOMPARE((e.cx1 + 1) % kTileSize, 0);
        // A rectangle crossing tile borders and the origin, reaching past the covered extent.
        const std::int32_t cx0 = g.cellIndex(-14), cy0 = g.cellIndex(-6);
        const int cols = 130, rows = 45;
        std::vector<PassCount> a(std::size_t(cols) * rows, 7), b(std::size_t(cols) * rows, 9);
        g.countsInRect(cx0, cy0, cols, rows, a.data());
        s->countsInRect(cx0, cy0, cols, rows, b.data());
        QCOMPARE(a, b);
        QVERIFY(std::count(b.begin(), b.end(), 2) > 0);
        for (int r = 0; r < rows; r += 4)
            for (int c = 0; c < cols; c += 3)
                QCOMPARE(s->countAtCell(cx0 + c, cy0 + r), g.countAtCell(cx0 + c, cy0 + r));
        QCOMPARE(s->summary().histogram, g.summary().histogram);
        QCOMPARE(s->summary().coveredCells, g.summary().coveredCells);
        QCOMPARE(s->summary().percentWithin, g.summary().percentWithin);
    }

    void snapshotStaysUnchangedWhileAnotherThreadCounts() {
        // The writer owns the grid (as the io thread does) and keeps rolling over the same strip, so the same
        // tiles change all the time; every 40 positions it hands a snapshot over. The reader (as the GUI
        // thread) reads each snapshot again and again, with no lock shared with the writer while it reads.
        PassCountGrid g;
        feed(g, 9, run(-40, -30, 30, 0.3)); // a patch the writer never touches again
        std::mutex mailbox;                 // the hand-over only (a queued signal in the app)
        std::shared_ptr<const PassCountSnapshot> latest = g.snapshot();
        std::atomic<bool> stop{false};
        std::atomic<std::uint64_t> written{0};
        const std::int32_t untouchedTx = tileOf(g, -35), untouchedTy = tileOf(g, 30);
        std::thread writer([&] {
            std::uint32_t slot = 0;
            for (int pass = 0; !stop; ++pass) {
                for (auto& p : run(pass % 2 ? 20 : -20, pass % 2 ? -20 : 20, 0, 0.3, slot)) {
                    g.addPosition(1, p);
                    if (++written % 40 == 0) {
                        auto s = g.snapshot();
                        std::lock_guard l(mailbox);
                        latest = std::move(s);
                    }
                }
                slot += 200;
            }
        });
        auto take = [&] {
            std::lock_guard l(mailbox);
            return latest;
        };
        int concurrentReads = 0, sharedSeen = 0, rounds = 0;
        std::shared_ptr<const PassCountSnapshot> previous;
        QElapsedTimer t;
        t.start();
        while ((concurrentReads < 20 || sharedSeen < 5) && t.elapsed() < 60000) {
            auto s = take();
            ++rounds;
            const std::uint64_t sum = checksum(*s);
            const auto values = s->tileValues();
            const std::uint64_t w0 = written;
            for (int i = 0; i < 20; ++i)
                QCOMPARE(checksum(*s), sum);
            if (written != w0)
                ++concurrentReads; // the writer counted on while this snapshot was being read
            QCOMPARE(s->tileValues(), values);
            if (previous && previous->sequence() < s->sequence()) {
                // The untouched patch is the same tile object in both snapshots.
                const PassCountTile* untouched = s->tile(untouchedTx, untouchedTy);
                QVERIFY(untouched && untouched == previous->tile(untouchedTx, untouchedTy));
                ++sharedSeen;
            }
            previous = s;
            std::this_thread::yield();
        }
        stop = true;
        writer.join();
        QVERIFY2(
            concurrentReads >= 20,
            qPrintable(QString("%1 of %2 reads overlapped the writer").arg(concurrentReads).arg(rounds)));
        QVERIFY(sharedSeen >= 5);
        // The last snapshot handed over still holds what the grid held when it was taken.
        auto last = take();
        QVERIFY(last->summary().coveredCells > 0);
    }

    void coreOffersSnapshotsAtABoundedRateWithBackPressure() {
        FakeClock clock;
        auto store = RibbonStore::inMemory();
        OsyrisConfig cfg;
        cfg.stationIndex = 3;
        cfg.beatMs = 100;
        cfg.passCountPublishMs = 300;
        PassCountGrid grid(cfg.passCount);
        Recorder rec;
        StationCore core(cfg, clock, *store, &grid, &rec, [](const Bytes&) {});
        core.start();
        double x = 0;
        auto beat = [&](bool move) {
            if (move) {
                CmPos p;
                p.x = static_cast<float>(x += 0.5);
                p.dx = 2.1f;
                p.flags = kGood | kPosForward;
                core.publishOwnPosition(p);
            }
            clock.advance(milliseconds(100));
            core.tick();
        };
        for (int i = 0; i < 20; ++i) // 2 s of counting, a change on every Beat
            beat(true);
        QVERIFY2(rec.snaps.size() >= 5 && rec.snaps.size() <= 7,
                 qPrintable(QString::number(rec.snaps.size())));
        for (std::size_t i = 1; i < rec.snaps.size(); ++i) {
            QVERIFY(rec.snaps[i]->sequence() > rec.snaps[i - 1]->sequence());
            QVERIFY(rec.snaps[i]->summary().coveredCells >= rec.snaps[i - 1]->summary().coveredCells);
        }
        // The GUI has not taken the last one: nothing more is built, the change stays pending.
        rec.ready = false;
        const auto n = rec.snaps.size();
        for (int i = 0; i < 10; ++i)
            beat(true);
        QCOMPARE(rec.snaps.size(), n);
        rec.ready = true;
        beat(false);
        QCOMPARE(rec.snaps.size(), n + 1);
        QCOMPARE(rec.snaps.back()->tileValues(), grid.snapshotTiles());
        // Nothing changed: nothing is published.
        for (int i = 0; i < 10; ++i)
            beat(false);
        QCOMPARE(rec.snaps.size(), n + 1);
    }
};

QTEST_GUILESS_MAIN(TestOsyrisSnapshot)
#include "test_osyris_snapshot.moc"
