// Pass-count layer, TRex palettes and the below/within/above summary.
#include "models/PassCountLayer.h"
#include "models/SiteMapData.h"

#include <QTest>

using namespace ocu;

class TestPassCount : public QObject {
    Q_OBJECT
private slots:
    void gridAddressingAndCounts() {
        GridPassCountLayer g({100.0, 200.0}, 0.5, 10, 4);
        QCOMPARE(g.count(0, 0), 0);
        const quint64 rev = g.revision();
        g.addPass(100.1, 200.1); // cell (0,0)
        g.addPass(104.9, 201.9); // cell (9,3)
        g.addPass(99.9, 200.1);  // outside
        QVERIFY(g.revision() > rev);
        QCOMPARE(g.count(0, 0), 1);
        QCOMPARE(g.count(9, 3), 1);
        QCOMPARE(g.count(-1, 0), 0);
        std::vector<std::uint16_t> out;
        const QRect got = g.countsIn(QRect(8, 2, 5, 5), out);
        QCOMPARE(got, QRect(8, 2, 2, 2));
        QCOMPARE(out, (std::vector<std::uint16_t>{0, 0, 0, 1}));
    }

    void changedCellsAreTracked() {
        GridPassCountLayer g({0, 0}, 1.0, 100, 100);
        const quint64 r0 = g.revision();
        QVERIFY(g.changedCellsSince(r0).isEmpty());
        g.setCount(5, 6, 2);
        const quint64 r1 = g.revision();
        g.fillRect(QRect(10, 10, 5, 5), 3);
        QCOMPARE(g.changedCellsSince(r1), QRect(10, 10, 5, 5));
        QCOMPARE(g.changedCellsSince(r0), QRect(5, 6, 10, 9));
        // Older than the kept history: everything.
        for (int i = 0; i < 600; ++i)
            g.addPass(50.5, 50.5);
        QCOMPARE(g.changedCellsSince(r0), QRect(0, 0, 100, 100));
        QCOMPARE(g.changedCellsSince(g.revision() - 1), QRect(50, 50, 1, 1));
    }

    void palettes() {
        // The per-count palette is an ordered scale: every further pass is lighter (relative luminance), by a
        // visible step, and opaque; 9 and more share the last colour; no pass is transparent.
        auto luminance = [](QColor c) {
            return 0.2126 * c.redF() + 0.7152 * c.greenF() + 0.0722 * c.blueF();
        };
        for (int c = 2; c <= 9; ++c) {
            const QColor a = passCountDiscreteColor(c - 1), b = passCountDiscreteColor(c);
            QVERIFY2(luminance(b) > luminance(a) + 0.03, qPrintable(QString::number(c)));
            QCOMPARE(b.alpha(), 255);
        }
        QCOMPARE(passCountDiscreteColor(1), QColor(0x44, 0x01, 0x54));
        QCOMPARE(passCountDiscreteColor(12), passCountDiscreteColor(9));
        QCOMPARE(passCountDiscreteColor(0).alpha(), 0);
        const PassTarget t{3, 5};
        QCOMPARE(passCountSummaryColor(2, t), QColor(0x1E, 0x90, 0xFF));
        QCOMPARE(passCountSummaryColor(3, t), QColor(0x9A, 0xCD, 0x32));
        QCOMPARE(passCountSummaryColor(5, t), QColor(0x9A, 0xCD, 0x32));
        QCOMPARE(passCountSummaryColor(6, t), QColor(0xFF, 0x00, 0x00));
    }

    void summaryBelowWithinAbove() {
        GridPassCountLayer g({0, 0}, 2.0, 10, 10);
        g.fillRect(QRect(0, 0, 10, 1), 1); // 10 cells below
        g.fillRect(QRect(0, 1, 10, 2), 4); // 20 cells within
        g.fillRect(QRect(0, 3, 5, 2), 12); // 10 cells above
        const PassCountSummary s = summarize(g, {3, 5});
        QCOMPARE(s.coveredCells, qint64(40));
        QCOMPARE(s.coveredArea, 160.0);
        QCOMPARE(s.belowPct, 25.0);
        QCOMPARE(s.withinPct, 50.0);
        QCOMPARE(s.abovePct, 25.0);
        QCOMPARE(s.histogram[1], qint64(10));
        QCOMPARE(s.histogram[4], qint64(20));
        QCOMPARE(s.histogram[9], qint64(10));
    }

    void siteMapBoundsAndTaskColours() {
        SiteMapData d;
        QVERIFY(d.bounds().isNull());
        d.features.push_back({QStringLiteral("r1"),
                              QStringLiteral("Ramp"),
                              MapFeatureKind::Road,
                              QStringLiteral("haul"),
                              true,
                              {{-10, 5}, {30, 40}},
                              8});
        d.features.push_back({QStringLiteral("a1"),
                              QStringLiteral("Pit"),
                              MapFeatureKind::Area,
                              QStringLiteral("load"),
                              true,
                              {{0, -20}, {10, -20}, {5, 0}},
                              0});
        QCOMPARE(d.bounds(), QRectF(QPointF(-10, -20), QPointF(30, 40)));
        QVERIFY(taskColor(QStringLiteral("haul")) != taskColor(QStringLiteral("load")));
        QCOMPARE(taskColor(QStringLiteral("Custom")), taskColor(QStringLiteral("custom")));
    }
};

QTEST_GUILESS_MAIN(TestPassCount)
#include "test_pass_count.moc"
