// The OSYRIS pass-count layer the map, the 3D view and the summary panel read: it reads the immutable
// snapshot the bridge handed to the GUI thread (extent, counts, changed cells between revisions), and, end to
// end over loopback multicast, a snapshot the GUI holds stays unchanged while the io thread keeps counting;
// the layer changes only when the GUI thread takes the next snapshot from its event queue.
#include "models/bridges/OsyrisBridge.h"
#include "models/bridges/OsyrisPassCountLayer.h"

#include "protocols/osyris/PassCountGrid.h"
#include "sim/osyris/OsyrisDemo.h"

#include <QSignalSpy>
#include <QtTest>

#include <cmath>
#include <thread>

using namespace ocu;
using namespace ocu::osyris;

namespace {
void stripe(PassCountGrid& g, std::uint8_t m, double x0, double x1, double y, std::uint32_t slot0 = 0) {
    const int n = static_cast<int>(std::lround(std::abs(x1 - x0) / 0.3));
    const double dir = x1 > x0 ? 1 : -1;
    for (int i = 0; i <= n; ++i) {
        CmPos p;
        p.x = static_cast<float>(x0 + dir * i * 0.3);
        p.y = static_cast<float>(y);
        p.dx = 2.1f;
        p.flags = kPosValid | kPosAccuracyHigh | kPosVibrating | (dir > 0 ? kPosForward : kPosBackward);
        p.slot = slot0 + static_cast<std::uint32_t>(i);
        g.addPosition(m, p);
    }
}

std::vector<std::uint16_t> all(const PassCountLayer& l) {
    std::vector<std::uint16_t> out;
    l.countsIn(QRect(0, 0, l.columns(), l.rows()), out);
    return out;
}
} // namespace

class TestOsyrisPassCountLayer : public QObject {
    Q_OBJECT
private slots:
    void readsTheSnapshotItHolds() {
        PassCountGrid g;
        stripe(g, 1, -10, 10, -2); // A
        stripe(g, 2, 30, 40, 20);  // B, inside A-B's bounding box from the start
        OsyrisPassCountLayer layer(0.34, QPointF(100, 200));
        QCOMPARE(layer.columns(), 0);
        QCOMPARE(layer.revision(), quint64(1));
        QVERIFY(all(layer).empty());

        auto s1 = g.snapshot();
        layer.setSnapshot(s1);
        const CellBox e = s1->extent();
        QCOMPARE(layer.columns(), e.cx1 - e.cx0 + 1);
        QCOMPARE(layer.rows(), e.cy1 - e.cy0 + 1);
        QCOMPARE(layer.origin(), QPointF(100 + e.cx0 * 0.34, 200 + e.cy0 * 0.34));
        QCOMPARE(layer.revision(), quint64(1 + s1->sequence()));
        const auto counts = all(layer);
        QCOMPARE(counts.size(), std::size_t(layer.columns()) * std::size_t(layer.rows()));
        for (int r = 0; r < layer.rows(); r += 5)
            for (int c = 0; c < layer.columns(); c += 7) {
                QCOMPARE(layer.count(c, r), g.countAtCell(e.cx0 + c, e.cy0 + r));
                QCOMPARE(int(counts[std::size_t(r) * std::size_t(layer.columns()) + std::size_t(c)]),
                         layer.count(c, r));
            }
        const ocu::PassCountSummary sum = summarize(layer, {3, 5});
        QCOMPARE(std::uint64_t(sum.coveredCells), s1->summary().coveredCells);
        QVERIFY(sum.coveredCells > 100);

        // B passed again: only B's tiles are reported as changed; the extent stays.
        const quint64 r1 = layer.revision();
        stripe(g, 2, 40, 30, 20, 500);
        layer.setSnapshot(g.snapshot());
        QVERIFY(layer.revision() > r1);
        QCOMPARE(layer.columns(), e.cx1 - e.cx0 + 1);
        const QRect changed = layer.changedCellsSince(r1);
        const int bCol = g.cellIndex(35) - e.cx0, bRow = g.cellIndex(20) - e.cy0,
                  aRow = g.cellIndex(-2) - e.cy0;
        QVERIFY(changed.contains(bCol, bRow));
        QVERIFY(!changed.contains(g.cellIndex(0) - e.cx0, aRow));
        QVERIFY(layer.changedCellsSince(layer.revision()).isEmpty());
        QCOMPARE(layer.count(bCol, bRow), 2);

        // An older snapshot arriving late is ignored.
        const quint64 r2 = layer.revision();
        layer.setSnapshot(s1);
        QCOMPARE(layer.revision(), r2);
        QCOMPARE(layer.count(bCol, bRow), 2);

        // The extent grows: only the new stripe's tiles count as changed, in the new frame.
        stripe(g, 3, -200, -190, -2);
        layer.setSnapshot(g.snapshot());
        QVERIFY(layer.columns() > e.cx1 - e.cx0 + 1);
        const QRect grown = layer.changedCellsSince(r2);
        QVERIFY(!grown.isEmpty());
        QVERIFY(grown.width() < layer.columns());
        QCOMPARE(grown.left(), 0); // the stripe lies west of everything before

        // Cleared and refilled to the same extent: everything counts as changed too.
        const quint64 r3 = layer.revision();
        const int cols = layer.columns(), rows = layer.rows();
        g.reset();
        stripe(g, 1, -10, 10, -2);
        stripe(g, 2, 30, 40, 20);
        stripe(g, 3, -200, -190, -2);
        layer.setSnapshot(g.snapshot());
        QCOMPARE(layer.columns(), cols);
        QCOMPARE(layer.changedCellsSince(r3), QRect(0, 0, cols, rows));
    }

    void bridgeHandsImmutableSnapshotsToTheGuiThread() {
        sim::osyris::OsyrisDemoOptions o;
        o.speedUp = 20;
        o.relay = false;
        sim::osyris::OsyrisDemo demo(o);
        std::string err;
        QVERIFY2(demo.start(&err), err.c_str());
        OsyrisBridge bridge(demo.ocuConfig(), GeoFrame());
        QSignalSpy changed(&bridge, &FleetBridge::passCountChanged);
        QCOMPARE(bridge.start(), QString());
        const auto* layer = dynamic_cast<const OsyrisPassCountLayer*>(bridge.passCountLayer());
        QVERIFY(layer);
        QTRY_VERIFY_WITH_TIMEOUT(layer->snapshot() && layer->snapshot()->summary().coveredCells > 50, 30000);
        QVERIFY(changed.count() > 0);

        // The GUI holds a snapshot; the io thread goes on counting into the same tiles.
        const std::shared_ptr<const PassCountSnapshot> held = layer->snapshot();
        const auto values = held->tileValues();
        const auto heldCounts = all(*layer);
        const quint64 heldRevision = layer->revision();
        // Without the GUI's event loop nothing reaches the layer, however much the io thread counts
        // meanwhile.
        std::this_thread::sleep_for(std::chrono::milliseconds(1500));
        QCOMPARE(layer->revision(), heldRevision);
        QCOMPARE(all(*layer), heldCounts);
        QTRY_VERIFY_WITH_TIMEOUT(layer->snapshot()->sequence() > held->sequence() &&
                                     layer->snapshot()->tileValues() != values,
                                 30000);
        QCOMPARE(held->tileValues(), values); // unchanged while the io thread kept ingesting

        // Copy on write between what the GUI held and what it holds now: a tile is either the same object
        // with the same counts, or a copy written after the held snapshot was taken.
        const auto now = layer->snapshot();
        int same = 0, copied = 0;
        for (const auto& e : now->tiles()) {
            const PassCountTile* old = held->tile(e.tx, e.ty);
            if (!old)
                continue;
            if (e.tile.get() == old) {
                ++same;
            } else {
                QVERIFY(e.tile->generation > held->sequence());
                ++copied;
            }
        }
        QVERIFY(copied > 0);
        QVERIFY(same + copied > 0);
        QCOMPARE(bridge.passCountSummary().coveredCells, now->summary().coveredCells);
        bridge.stop();
        demo.stop();
    }
};

QTEST_GUILESS_MAIN(TestOsyrisPassCountLayer)
#include "test_osyris_pass_count_layer.moc"
