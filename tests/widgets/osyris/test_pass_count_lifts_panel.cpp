// The pass-count panel's lifts and filters and the crew messages panel:
// - filters edited in the panel reach the source (after the editing pause), the lift picker lists the
//   source's lifts and sets the lift the layer shows, the summary follows the lift shown, given-up gaps are
//   stated;
// - the crew panel sends through the command gate on Enter to the picked machine and shows what went on the
//   wire and the simulated driver's answer (loopback multicast).
#include "models/CommandGate.h"
#include "models/bridges/OsyrisBridge.h"
#include "models/bridges/OsyrisPassCountLayer.h"
#include "protocols/osyris/PassCountGrid.h"
#include "sim/osyris/OsyrisDemo.h"
#include "widgets/PassCountPanel.h"
#include "widgets/osyris/CrewMessagesPanel.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QtTest>

using namespace ocu;

namespace {
constexpr std::uint32_t kGood = osyris::kPosValid | osyris::kPosAccuracyHigh | osyris::kPosVibrating;

void drive(osyris::PassCountGrid& g, std::uint8_t m, double x0, double x1, double z, std::uint32_t slot0) {
    const double dir = x1 > x0 ? 1 : -1;
    const int n = int(std::lround(std::abs(x1 - x0) / 0.5));
    for (int i = 0; i <= n; ++i) {
        osyris::CmPos p;
        p.x = float(x0 + dir * i * 0.5);
        p.z = float(z);
        p.dx = 2.0f;
        p.flags = kGood | (dir > 0 ? osyris::kPosForward : osyris::kPosBackward);
        p.slot = slot0 + std::uint32_t(i);
        g.addPosition(m, p);
    }
}

// A source with two lifts: lift 0 rolled twice over 20 m, lift 1 once over the first 10 m.
struct FakeSource : PassCountControls {
    OsyrisPassCountLayer layer{0.34, QPointF(0, 0)};
    PassCountFilter applied;
    int applyCalls = 0;
    FakeSource() {
        osyris::PassCountSettings s;
        s.liftThickness = 0.1;
        osyris::PassCountGrid g(s);
        drive(g, 1, 0, 20, 0.05, 0);
        drive(g, 1, 20, 0, 0.05, 100);
        drive(g, 1, 0, 10, 0.15, 200);
        g.giveUp(1, 41, 99);
        layer.setSnapshot(g.snapshot());
        applied.liftThickness = 0.1;
    }
    PassCountFilter passCountFilter() const override { return applied; }
    void setPassCountFilter(const PassCountFilter& f) override {
        applied = f;
        ++applyCalls;
    }
    QVector<PassCountLiftInfo> passCountLifts() const override {
        QVector<PassCountLiftInfo> out;
        for (int i = 0; i < layer.snapshot()->liftCount(); ++i)
            out.push_back({layer.snapshot()->liftBottom(i), layer.snapshot()->liftTop(i)});
        return out;
    }
    int viewLift() const override { return layer.viewLift(); }
    void setViewLift(int l) override { layer.setViewLift(l); }
    QStringList passCountGaps() const override { return {QStringLiteral("Roller 1: 59 positions given up")}; }
};
} // namespace

class TestPassCountLiftsPanel : public QObject {
    Q_OBJECT
private slots:
    void liftsAndFilters() {
        FakeSource src;
        PassCountPanel panel;
        panel.setLayer(&src.layer);
        panel.setControls(&src);
        QCOMPARE(src.applyCalls, 0); // showing the source's filter applies nothing
        QComboBox* lift = panel.liftPicker();
        QCOMPARE(lift->count(), 3); // top-most + two lifts
        QVERIFY2(lift->itemText(2).contains(QStringLiteral("0.10")) && lift->itemText(2).contains(QStringLiteral("0.20")),
                 qPrintable(lift->itemText(2)));
        const double topArea = panel.summary().coveredArea;
        // Lift 1 (the first 10 m only): the layer shows it and the summary follows.
        lift->setCurrentIndex(2);
        emit lift->activated(2);
        QCOMPARE(src.layer.viewLift(), 1);
        QVERIFY(panel.summary().coveredArea < topArea * 0.7);
        QCOMPARE(panel.summary().histogram[1] > 0, true);
        lift->setCurrentIndex(1);
        emit lift->activated(1);
        QCOMPARE(src.layer.viewLift(), 0);
        QCOMPARE(panel.summary().histogram[2] > 0, true); // lift 0 was rolled twice
        QVERIFY(panel.findChild<QLabel*>() != nullptr);
        bool gapShown = false;
        for (QLabel* l : panel.findChildren<QLabel*>())
            gapShown = gapShown || l->text().contains(QStringLiteral("given up"));
        QVERIFY(gapShown);

        // Filters: applied once after the editing pause.
        auto boxes = panel.findChildren<QComboBox*>();
        QComboBox* vibration = nullptr;
        for (QComboBox* b : boxes)
            if (b->findText(QStringLiteral("Static only")) >= 0)
                vibration = b;
        QVERIFY(vibration);
        vibration->setCurrentIndex(vibration->findData(int(PassCountFilter::Vibration::Off)));
        PassCountFilter f = panel.filter();
        f.speedMax = 5 / 3.6;
        panel.setFilter(f);
        QTRY_COMPARE(src.applyCalls, 1);
        QCOMPARE(src.applied.vibration, PassCountFilter::Vibration::Off);
        QVERIFY(std::abs(src.applied.speedMax - 5 / 3.6) < 0.01);
        QCOMPARE(src.applied.liftThickness, 0.1);
    }

    void crewPanelSendsOnEnterAndShowsTheAnswer() {
        sim::osyris::OsyrisDemoOptions opts;
        opts.rollers = 1;
        opts.paver = false;
        opts.relay = false;
        opts.crewMessageEveryS = 0;
        sim::osyris::OsyrisDemo demo(opts);
        std::string err;
        QVERIFY2(demo.start(&err), err.c_str());
        OsyrisBridge bridge(demo.ocuConfig(), GeoFrame(GeoPoint{48.1, 11.5, 500}));
        CommandGate gate;
        gate.addBridge(&bridge);
        QVERIFY(bridge.start().isEmpty());
        CrewMessagesPanel panel;
        panel.setCommandGate(&gate);
        panel.setBridge(&bridge, &bridge);
        QCOMPARE(panel.recipientPicker()->count(), 2); // all + Roller 1
        panel.recipientPicker()->setCurrentIndex(1);
        panel.entry()->setText(QStringLiteral("lift 2 done?"));
        // Sent only once a station is heard (the bridge refuses before): retry Enter until it goes out.
        QTRY_VERIFY_WITH_TIMEOUT(
            [&] {
                if (!panel.history().isEmpty() && panel.history().last().contains(QStringLiteral("NOT sent"))) {
                    panel.entry()->setText(QStringLiteral("lift 2 done?"));
                }
                if (!panel.entry()->text().isEmpty())
                    QTest::keyClick(panel.entry(), Qt::Key_Return);
                return panel.history().join(QLatin1Char('\n')).contains(QStringLiteral("Roller 1: lift 2 done? (sent)"));
            }(),
            30000);
        QTRY_VERIFY_WITH_TIMEOUT(
            panel.history().join(QLatin1Char('\n')).contains(QStringLiteral("Roller 1: OK, lift 2 done?")), 30000);
        QCOMPARE(demo.crewMessagesReceived(0), 1);
        // The answer arrived while the panel was not in front of anyone: unread until it is shown.
        QSignalSpy unread(&panel, &CrewMessagesPanel::unreadChanged);
        QVERIFY(panel.unreadCount() >= 1);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        QTRY_COMPARE(panel.unreadCount(), 0);
        QVERIFY(!unread.isEmpty());
        QCOMPARE(unread.last().at(0).toInt(), 0);
        bridge.stop();
        demo.stop();
    }
};

QTEST_MAIN(TestPassCountLiftsPanel)
#include "test_pass_count_lifts_panel.moc"
