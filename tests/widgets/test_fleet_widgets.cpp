// Fleet list, stop controls, hold-to-confirm, event log and pass-count panel, offscreen.
#include "models/AlarmModel.h"
#include "models/CommandGate.h"
#include "models/FleetFilterProxy.h"
#include "models/FleetModel.h"
#include "models/FleetSelection.h"
#include "models/testing/FakeFleetBridge.h"
#include "widgets/EventLogWidget.h"
#include "widgets/FleetListWidget.h"
#include "widgets/HoldToConfirmButton.h"
#include "widgets/PassCountPanel.h"
#include "widgets/StopControls.h"

#include <QFile>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QSignalSpy>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>

using namespace ocu;

namespace {
MachineState machine(const QString& id) {
    MachineState m;
    m.id = id;
    m.protocol = protocolOfId(id);
    m.name = QStringLiteral("N-") + id.section(QLatin1Char(':'), 1);
    m.link = LinkState::Up;
    m.stop = StopState::None;
    m.health = HealthLevel::Ok;
    return m;
}

struct Rig {
    FleetModel fleet;
    FleetSelection selection{&fleet};
    AlarmModel alarms;
    CommandGate stop{&alarms};
    FakeFleetBridge jaus{Protocol::Jaus}, iso{Protocol::Iso23725}, osy{Protocol::Osyris};
    Rig() {
        fleet.setRefreshIntervalMs(0);
        for (FakeFleetBridge* b : {&jaus, &iso, &osy}) {
            fleet.addBridge(b);
            stop.addBridge(b);
            alarms.addBridge(b);
            b->setMachine(machine(protocolPrefix(b->protocol()) + QStringLiteral("1")));
        }
        QCoreApplication::processEvents();
    }
};
} // namespace

class TestFleetWidgets : public QObject {
    Q_OBJECT
private slots:
    void stopAllButtonAndShortcutReachEveryStackWithoutAsking() {
        Rig rig;
        QWidget window;
        auto* button = new StopAllButton(&rig.stop, &window);
        QAction* action = createStopAllAction(&rig.stop, &window);
        window.addAction(action);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QTest::mouseClick(button, Qt::LeftButton);
        for (FakeFleetBridge* b : {&rig.jaus, &rig.iso, &rig.osy}) {
            QCOMPARE(b->calls().size(), 1);
            QCOMPARE(b->calls()[0].name, QStringLiteral("stop_all"));
        }
        // No modal dialog was opened (stopping never asks).
        QVERIFY(QApplication::activeModalWidget() == nullptr);
        // The shown state is what the machines report (the fake ones report their stop).
        QCoreApplication::processEvents();
        QCOMPARE(rig.fleet.machine(QStringLiteral("iso23725:1"))->stop, StopState::Stopped);
        // The shortcut action does the same.
        QVERIFY(action->shortcuts().contains(QKeySequence(Qt::Key_F12)));
        action->trigger();
        QCOMPARE(rig.osy.calls().size(), 2);
        // Audited twice.
        int audits = 0;
        for (int i = 0; i < rig.alarms.rowCount(); ++i)
            audits += rig.alarms.eventAt(i).kind == EventKind::Audit ? 1 : 0;
        QCOMPARE(audits, 2);
    }

    void releaseNeedsAHoldStopDoesNot() {
        Rig rig;
        MachineStopControls controls(&rig.fleet, &rig.selection, &rig.stop);
        controls.releaseButton()->setHoldDurationMs(1000);
        controls.show();
        QVERIFY(QTest::qWaitForWindowExposed(&controls));
        rig.selection.setCurrent(QStringLiteral("jaus:1"));
        QVERIFY(controls.stopButton()->isEnabled());

        // One click stops.
        QTest::mouseClick(controls.stopButton(), Qt::LeftButton);
        QCOMPARE(rig.jaus.calls().size(), 1);
        QCOMPARE(rig.jaus.calls()[0].name, QStringLiteral("stop"));
        QCoreApplication::processEvents();
        QVERIFY(controls.stateLabel()->text().contains(QStringLiteral("STOPPED")));

        // A click (or a short press) on release does nothing but cancel.
        QSignalSpy cancelled(controls.releaseButton(), &HoldToConfirmButton::cancelled);
        QTest::mouseClick(controls.releaseButton(), Qt::LeftButton);
        QCOMPARE(cancelled.count(), 1);
        QTest::mousePress(controls.releaseButton(), Qt::LeftButton);
        QTest::qWait(100);
        QTest::mouseRelease(controls.releaseButton(), Qt::LeftButton);
        QCOMPARE(cancelled.count(), 2);
        QCOMPARE(rig.jaus.calls().size(), 1);

        // Holding for the full duration releases.
        QSignalSpy confirmed(controls.releaseButton(), &HoldToConfirmButton::confirmed);
        QTest::mousePress(controls.releaseButton(), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(confirmed.count(), 1, 5000);
        QTest::mouseRelease(controls.releaseButton(), Qt::LeftButton);
        QCOMPARE(rig.jaus.calls().size(), 2);
        QCOMPARE(rig.jaus.calls()[1].name, QStringLiteral("clear_stop"));
        QCOMPARE(cancelled.count(), 2); // the release after confirmation is not a cancel
        QCoreApplication::processEvents();
        QVERIFY(controls.stateLabel()->text().contains(QStringLiteral("running")));
    }

    void fleetListDensityFilterAndColours() {
        Rig rig;
        MachineState stopped = machine(QStringLiteral("osyris:7"));
        stopped.stop = StopState::Stopped;
        rig.osy.setMachine(stopped);
        QCoreApplication::processEvents();
        FleetListWidget list(&rig.fleet, &rig.selection);
        list.resize(900, 400);
        list.show();
        QVERIFY(QTest::qWaitForWindowExposed(&list));
        QCOMPARE(list.proxy()->rowCount(), 4);
        const int dense = list.tableView()->verticalHeader()->defaultSectionSize();
        list.setDensity(FleetListWidget::Density::Large);
        QVERIFY(list.tableView()->verticalHeader()->defaultSectionSize() > dense);
        QVERIFY(list.tableView()->font().pointSize() > QFontInfo(list.font()).pointSize());

        QTest::keyClicks(list.filterEdit(), QStringLiteral("osyris"));
        QCOMPARE(list.proxy()->rowCount(), 2);

        // The stop column of a stopped machine is painted red.
        const QModelIndex stopCell =
            list.proxy()->mapFromSource(rig.fleet.index(rig.fleet.rowOf(stopped.id), FleetModel::ColStop));
        list.tableView()->scrollTo(stopCell);
        const QRect r = list.tableView()->visualRect(stopCell);
        const QImage img = list.tableView()->viewport()->grab().toImage();
        const QColor px = img.pixelColor(r.right() - 2, r.center().y());
        QVERIFY2(px == statusColor(StatusCategory::FaultOrStopped), qPrintable(px.name()));
        QCOMPARE(stopCell.data(FleetModel::StatusColorRole).value<QColor>(),
                 statusColor(StatusCategory::FaultOrStopped));
        QVERIFY(FleetListWidget::describeMachine(stopped).contains(QStringLiteral("stopped")));
    }

    void eventLogAlarmStaysUntilAcknowledged() {
        AlarmModel alarms;
        EventLogWidget log(&alarms);
        log.show();
        QVERIFY(QTest::qWaitForWindowExposed(&log));
        alarms.add(makeEvent(EventSeverity::Info, EventKind::Info, {}, QStringLiteral("started")));
        alarms.add(makeEvent(EventSeverity::Alarm, EventKind::ControlLost, QStringLiteral("jaus:101"),
                             QStringLiteral("control lost")));
        QVERIFY(log.unackLabel()->text().contains(QStringLiteral("1 unacknowledged")));
        QTest::qWait(50);
        QCOMPARE(alarms.unacknowledgedCount(), 1);

        QTest::keyClicks(log.searchEdit(), QStringLiteral("control"));
        QCOMPARE(log.proxy()->rowCount(), 1);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("e.csv"));
        QVERIFY(log.exportShown(path));
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = f.readAll().trimmed().split('\n');
        QCOMPARE(lines.size(), 2);
        QVERIFY(lines[1].contains("control_lost,jaus:101"));

        log.tableView()->selectRow(0);
        QTest::mouseClick(log.ackButton(), Qt::LeftButton);
        QCOMPARE(alarms.unacknowledgedCount(), 0);
        QVERIFY(!log.unackLabel()->text().contains(QStringLiteral("unacknowledged")));
    }

    void passCountPanelSummarises() {
        GridPassCountLayer g({0, 0}, 1.0, 10, 10);
        g.fillRect(QRect(0, 0, 10, 5), 2);
        g.fillRect(QRect(0, 5, 10, 5), 4);
        PassCountPanel panel;
        QSignalSpy target(&panel, &PassCountPanel::targetChanged);
        panel.setLayer(&g);
        QCOMPARE(panel.summary().belowPct, 50.0);
        QCOMPARE(panel.summary().withinPct, 50.0);
        QVERIFY(panel.summaryLabel()->text().contains(QStringLiteral("100 m²")));
        panel.setTarget({1, 2});
        QCOMPARE(target.count(), 1);
        QCOMPARE(panel.summary().withinPct, 50.0);
        QCOMPARE(panel.summary().abovePct, 50.0);
        QSignalSpy palette(&panel, &PassCountPanel::paletteChanged);
        panel.setPalette(PassPalette::Summary);
        QCOMPARE(palette.count(), 1);
        QCOMPARE(panel.palette(), PassPalette::Summary);
    }
};

QTEST_MAIN(TestFleetWidgets)
#include "test_fleet_widgets.moc"
