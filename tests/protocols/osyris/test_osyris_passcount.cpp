// Pass counts on synthetic tracks with known answers; order independence.
#include "protocols/osyris/PassCountGrid.h"
#include "protocols/osyris/RibbonStore.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <random>

using namespace ocu;
using namespace ocu::osyris;

namespace {
constexpr std::uint32_t kGood = kPosValid | kPosAccuracyHigh | kPosVibrating;

std::vector<CmPos> run(double x0, double x1, double y, double step, std::uint32_t flags, double width = 2.1,
                       std::uint32_t firstSlot = 0) {
    std::vector<CmPos> out;
    int n = static_cast<int>(std::lround(std::abs(x1 - x0) / step));
    double dir = x1 > x0 ? 1 : -1;
    for (int i = 0; i <= n; ++i) {
        CmPos p;
        p.x = static_cast<float>(x0 + dir * i * step);
        p.y = static_cast<float>(y);
        p.dx = static_cast<float>(width);
        p.flags = flags | (dir > 0 ? kPosForward : kPosBackward);
        p.slot = firstSlot + static_cast<std::uint32_t>(i);
        out.push_back(p);
    }
    return out;
}

void feed(PassCountGrid& g, std::uint8_t m, const std::vector<CmPos>& ps) {
    for (auto& p : ps)
        g.addPosition(m, p);
}

// Checks every cell of the region against expected(cx, cy) and that nothing outside is counted.
bool matches(const PassCountGrid& g, double xmin, double xmax, double ymin, double ymax,
             const std::function<int(double, double)>& expected, QString* why) {
    double cs = g.settings().cellSize;
    std::uint64_t inside = 0;
    for (auto cx = g.cellIndex(xmin) - 3; cx <= g.cellIndex(xmax) + 3; ++cx)
        for (auto cy = g.cellIndex(ymin) - 3; cy <= g.cellIndex(ymax) + 3; ++cy) {
            double x = (cx + 0.5) * cs, y = (cy + 0.5) * cs;
            int want = expected(x, y), got = g.countAtCell(cx, cy);
            inside += got > 0;
            if (want != got) {
                *why = QString("cell (%1, %2) centre (%3, %4): got %5, want %6")
                           .arg(cx)
                           .arg(cy)
                           .arg(x)
                           .arg(y)
                           .arg(got)
                           .arg(want);
                return false;
            }
        }
    std::uint64_t total = g.summary().coveredCells;
    if (total != inside) {
        *why = QString("%1 counted cells outside the checked region").arg(total - inside);
        return false;
    }
    return true;
}
} // namespace

class TestOsyrisPassCount : public QObject {
    Q_OBJECT
private slots:
    void straightRunIsOne() {
        PassCountGrid g;
        feed(g, 1, run(0, 20, 0, 0.5, kGood));
        QString why;
        QVERIFY2(matches(
                     g, 0, 20, -1.05, 1.05,
                     [](double x, double y) { return (x >= 0 && x < 20 && y >= -1.05 && y < 1.05) ? 1 : 0; },
                     &why),
                 qPrintable(why));
        auto s = g.summary();
        QCOMPARE(s.coveredCells, std::uint64_t(59 * 6)); // 20/0.34 -> 59 columns, 2.1 m -> 6 rows
        QCOMPARE(s.percentBelow, 100.0);
        QCOMPARE(s.histogram[1], s.coveredCells);
        QVERIFY(std::abs(s.coveredAreaM2 - 354 * 0.34 * 0.34) < 1e-9);
    }
    void smallStepsStillOne() {
        PassCountGrid g; // 0.1 m steps: below the 0.25 m minimum movement, a cell is still counted once
        feed(g, 1, run(0, 10, 0, 0.1, kGood));
        QString why;
        QVERIFY2(matches(
                     g, 0, 10, -1.05, 1.05,
                     [](double x, double y) { return (x >= 0 && x < 10 && y >= -1.05 && y < 1.05) ? 1 : 0; },
                     &why),
                 qPrintable(why));
    }
    void forwardThenBackIsTwo() {
        PassCountGrid g;
        auto f = run(0, 20, 0, 0.5, kGood);
        auto b = run(20, 0, 0, 0.5, kGood, 2.1, 41);
        feed(g, 1, f);
        feed(g, 1, std::vector<CmPos>(b.begin() + 1, b.end())); // slot 41 = 20 m is the turning point
        QString why;
        QVERIFY2(matches(
                     g, 0, 20, -1.05, 1.05,
                     [](double x, double y) { return (x > 0 && x < 20 && y >= -1.05 && y < 1.05) ? 2 : 0; },
                     &why),
                 qPrintable(why));
        // Direction filter: forward only counts one of them.
        PassCountSettings s;
        s.direction = DirectionFilter::Forward;
        PassCountGrid gf(s);
        feed(gf, 1, f);
        feed(gf, 1, std::vector<CmPos>(b.begin() + 1, b.end()));
        QCOMPARE(gf.countAt(10, 0), 1);
    }
    void threeOverlappingStripes() {
        PassCountGrid g;
        const double lanes[] = {0, 1.5, 3.0};
        for (int i = 0; i < 3; ++i)
            feed(g, static_cast<std::uint8_t>(i), run(0, 15, lanes[i], 0.5, kGood));
        auto expected = [&](double x, double y) {
            if (x < 0 || x >= 15)
                return 0;
            int n = 0;
            for (double l : lanes)
                n += (y >= l - 1.05 && y < l + 1.05);
            return n;
        };
        QString why;
        QVERIFY2(matches(g, 0, 15, -1.05, 4.05, expected, &why), qPrintable(why));
        auto s = g.summary();
        QVERIFY(s.histogram[1] > 0 && s.histogram[2] > 0);
        QCOMPARE(s.histogram[3], std::uint64_t(0));
        // Machine filter: only lane 1.
        PassCountSettings only1;
        only1.machines = {1};
        PassCountGrid g1(only1);
        for (int i = 0; i < 3; ++i)
            feed(g1, static_cast<std::uint8_t>(i), run(0, 15, lanes[i], 0.5, kGood));
        QCOMPARE(g1.countAt(5, 1.5), 1);
        QCOMPARE(g1.countAt(5, -0.8), 0);
    }
    void vibrationOffNotCounted() {
        PassCountGrid g;
        feed(g, 1, run(0, 20, 0, 0.5, kPosValid | kPosAccuracyHigh));
        QCOMPARE(g.summary().coveredCells, std::uint64_t(0));
        PassCountSettings s;
        s.vibration = VibrationFilter::Any;
        PassCountGrid all(s);
        feed(all, 1, run(0, 20, 0, 0.5, kPosValid | kPosAccuracyHigh));
        QCOMPARE(all.countAt(10, 0), 1);
    }
    void badPositionsNotCounted() {
        PassCountGrid g;
        auto r = run(0, 20, 0, 0.5, kGood);
        for (auto& p : r)
            if (p.x > 8 && p.x < 12)
                p.flags = (p.flags & ~(kPosValid | kPosAccuracyHigh)) | kPosGpsShadow | kPosAccuracyLow;
        feed(g, 1, r);
        QCOMPARE(g.countAt(5, 0), 1);
        QCOMPARE(g.countAt(10, 0), 0); // nothing swept across the shadow
        QCOMPARE(g.countAt(15, 0), 1);
        PassCountGrid low;
        auto lr = run(0, 20, 0, 0.5, kPosValid | kPosVibrating | kPosAccuracyLow);
        feed(low, 1, lr);
        QCOMPARE(low.summary().coveredCells, std::uint64_t(0)); // low accuracy is below the medium minimum
    }
    void targetSummary() {
        PassCountGrid g; // 4 passes forward/back/forward/back: within 3..5
        std::uint32_t slot = 0;
        for (int k = 0; k < 4; ++k) {
            auto r = k % 2 ? run(20, 0, 0, 0.5, kGood, 2.1, slot) : run(0, 20, 0, 0.5, kGood, 2.1, slot);
            feed(g, 1, std::vector<CmPos>(r.begin() + (k ? 1 : 0), r.end()));
            slot += static_cast<std::uint32_t>(r.size());
        }
        QCOMPARE(g.countAt(10, 0), 4);
        auto s = g.summary();
        QVERIFY(s.percentWithin > 90);
        QCOMPARE(s.percentAbove, 0.0);
        QVERIFY(std::abs(s.percentBelow + s.percentWithin + s.percentAbove - 100.0) < 1e-9);
    }
    void shuffledOrderIdentical() {
        // Three rollers' ribbons with turns, direction changes and vibration changes.
        std::vector<std::vector<CmPos>> ribbons(3);
        for (int m = 0; m < 3; ++m) {
            std::uint32_t slot = 0;
            for (int k = 0; k < 6; ++k) {
                std::uint32_t f = kPosValid | kPosAccuracyHigh | (k % 3 == 2 ? 0 : kPosVibrating);
                auto r = k % 2 ? run(30, 0, m * 1.4, 0.45, f, 2.0, slot)
                               : run(0, 30, m * 1.4 + 0.2 * k, 0.45, f, 2.0, slot);
                for (auto& p : r) {
                    p.y += 0.3f * std::sin(p.x * 0.3f); // curved track
                    ribbons[m].push_back(p);
                }
                slot += static_cast<std::uint32_t>(r.size());
            }
        }
        auto inOrder = RibbonStore::inMemory();
        PassCountGrid a;
        for (int m = 0; m < 3; ++m)
            for (auto& p : ribbons[m]) {
                inOrder->put(static_cast<std::uint8_t>(m), {p, {}});
                a.advance(static_cast<std::uint8_t>(m), *inOrder);
            }
        std::vector<std::pair<int, CmPos>> all;
        for (int m = 0; m < 3; ++m)
            for (auto& p : ribbons[m])
                all.emplace_back(m, p);
        for (std::uint32_t seed : {1u, 2u, 3u}) {
            std::mt19937 rng(seed);
            std::shuffle(all.begin(), all.end(), rng);
            auto shuffled = RibbonStore::inMemory();
            PassCountGrid b;
            for (auto& [m, p] : all) {
                shuffled->put(static_cast<std::uint8_t>(m), {p, {}});
                b.advance(static_cast<std::uint8_t>(m), *shuffled);
                if (seed == 1 && p.slot % 7 == 0) // duplicates (retransmissions) change nothing
                    QVERIFY(!shuffled->put(static_cast<std::uint8_t>(m), {p, {}}));
            }
            QVERIFY(a.summary().coveredCells > 1000);
            QVERIFY(a.snapshotTiles() == b.snapshotTiles());
            QCOMPARE(b.summary().histogram, a.summary().histogram);
        }
    }
    void readersAndDirty() {
        PassCountGrid g;
        feed(g, 1, run(-5, 5, -3, 0.5, kGood));
        auto d = g.takeDirty();
        QVERIFY(d);
        QVERIFY(d->xMin <= -5 + 0.34 && d->xMax >= 5 - 0.34);
        QVERIFY(!g.takeDirty());
        std::vector<std::uint16_t> buf(20 * 20);
        g.countsInRect(g.cellIndex(-1), g.cellIndex(-4), 20, 20, buf.data());
        QCOMPARE(int(buf[static_cast<std::size_t>(3 * 20 + 1)]),
                 g.countAtCell(g.cellIndex(-1) + 1, g.cellIndex(-4) + 3));
        QVERIFY(std::count(buf.begin(), buf.end(), 1) > 0);
    }
};

QTEST_GUILESS_MAIN(TestOsyrisPassCount)
#include "test_osyris_passcount.moc"
