// The map's trail store: the newest points per machine kept in order across the moves inside a machine's
// slot, points closer than the minimum distance dropped, removed machines' slots reused, a new capacity
// keeping the newest points.
#include "widgets/MapTrails.h"

#include <QTest>

using namespace ocu;

namespace {
QVector<QPointF> trailOf(const MapTrails& trails, double firstX) {
    // The trail whose oldest point has x == firstX (storage order is not the machines' order).
    QVector<QPointF> found;
    trails.forEach([&](const MapTrails::Span& t) {
        if (t.xy[0] == float(firstX))
            for (int k = 0; k < t.n; ++k)
                found.push_back(QPointF(t.xy[2 * k], t.xy[2 * k + 1]));
    });
    return found;
}
QVector<QPointF> line(int from, int to, double y) {
    QVector<QPointF> pts;
    for (int i = from; i <= to; ++i)
        pts.push_back(QPointF(i, y));
    return pts;
}
} // namespace

class TestMapTrails : public QObject {
    Q_OBJECT
private slots:
    void keepsTheNewestPointsInOrder() {
        MapTrails trails;
        trails.setCapacity(5);
        // 23 appends: the slot (room for 10) is compacted twice along the way.
        for (int i = 0; i < 23; ++i)
            trails.appendIfMoved(QStringLiteral("a"), QPointF(i, 1), 1.0);
        QCOMPARE(trails.size(), 1);
        QCOMPARE(trailOf(trails, 18), line(18, 22, 1));
    }

    void dropsPointsCloserThanTheMinimum() {
        MapTrails trails;
        trails.setCapacity(10);
        trails.appendIfMoved(QStringLiteral("a"), QPointF(0, 0), 1.0);
        trails.appendIfMoved(QStringLiteral("a"), QPointF(0.5, 0), 1.0); // 0.5 m: dropped
        trails.appendIfMoved(QStringLiteral("a"), QPointF(1, 0), 1.0);
        QCOMPARE(trailOf(trails, 0), QVector<QPointF>({{0, 0}, {1, 0}}));
    }

    void machinesApartAndSlotsReused() {
        MapTrails trails;
        trails.setCapacity(4);
        for (int i = 0; i < 6; ++i) {
            trails.appendIfMoved(QStringLiteral("a"), QPointF(100 + i, 0), 1.0);
            trails.appendIfMoved(QStringLiteral("b"), QPointF(200 + i, 0), 1.0);
        }
        QCOMPARE(trailOf(trails, 102), line(102, 105, 0));
        QCOMPARE(trailOf(trails, 202), line(202, 205, 0));
        trails.remove(QStringLiteral("a"));
        QCOMPARE(trails.size(), 1);
        QVERIFY(trailOf(trails, 102).isEmpty());
        // A new machine takes the freed slot and starts empty.
        trails.appendIfMoved(QStringLiteral("c"), QPointF(300, 0), 1.0);
        QCOMPARE(trails.size(), 2);
        QCOMPARE(trailOf(trails, 300), QVector<QPointF>({{300, 0}}));
        QCOMPARE(trailOf(trails, 202), line(202, 205, 0));
    }

    void newCapacityKeepsTheNewest() {
        MapTrails trails;
        trails.setCapacity(8);
        for (int i = 0; i < 8; ++i)
            trails.appendIfMoved(QStringLiteral("a"), QPointF(i, 0), 1.0);
        trails.setCapacity(3);
        QCOMPARE(trailOf(trails, 5), line(5, 7, 0));
        trails.appendIfMoved(QStringLiteral("a"), QPointF(8, 0), 1.0);
        QCOMPARE(trailOf(trails, 6), line(6, 8, 0));
        trails.setCapacity(0); // no trails
        trails.appendIfMoved(QStringLiteral("a"), QPointF(9, 0), 1.0);
        QVERIFY(trails.isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestMapTrails)
#include "test_map_trails.moc"
