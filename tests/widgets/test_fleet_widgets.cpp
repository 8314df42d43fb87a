// Fleet list, hold-to-confirm, event log and pass-count panel, offscreen.
#include "models/AlarmModel.h"
#include "models/CommandGate.h"
#include "models/FleetFilterProxy.h"
#include "models/FleetModel.h"
#include "models/FleetSelection.h"
#include "models/testing/FakeFleetBridge.h"
#include "widgets/ColumnFit.h"
#include "widgets/EventLogWidget.h"
#include "widgets/FleetListWidget.h"
#include "widgets/HoldToConfirmButton.h"
#include "widgets/PassCountPanel.h"

#include <QComboBox>
#include <QDateTime>
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

        // In a narrow dock (a quarter of a 1366-px screen) the filter field goes above the
        // combos instead of holding the list ~480 px wide; back beside them when there is room.
        QVERIFY(!list.filterRowWrapped());
        QVERIFY2(list.minimumWidth() > 0 && list.minimumWidth() <= 340,
                 qPrintable(QString::number(list.minimumWidth())));
        list.resize(330, 400);
        QTRY_VERIFY(list.filterRowWrapped());
        auto* combo = list.findChild<QComboBox*>();
        QVERIFY(combo);
        QTRY_VERIFY2(
            list.filterEdit()->geometry().bottom() < combo->geometry().top(),
            qPrintable(QStringLiteral("filter %1, combo %2").arg(list.filterEdit()->y()).arg(combo->y())));
        QVERIFY(combo->geometry().right() < 330);
        list.resize(900, 400);
        QTRY_VERIFY(!list.filterRowWrapped());
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

        // The histogram has a scale (area ticks 0 / half / top), the area on each bar and
        // titles.
        const PassCountPanel::HistogramAxis a = panel.histogramAxis();
        QCOMPARE(a.values.size(), 9);
        QCOMPARE(a.values[1], 50.0); // 50 cells of 1 m² with 2 passes
        QCOMPARE(a.values[3], 50.0);
        QCOMPARE(a.values[0], 0.0);
        QCOMPARE(a.top, 50.0);
        QCOMPARE(a.ticks,
                 (QStringList{QStringLiteral("0 m²"), QStringLiteral("25 m²"), QStringLiteral("50 m²")}));
        QCOMPARE(a.barLabels[1], QStringLiteral("50 m²"));
        QVERIFY(a.barLabels[0].isEmpty());
        QCOMPARE(a.xTitle, QStringLiteral("Passes"));
        QVERIFY(!a.yTitle.isEmpty());
    }

    // In a fixed-size window no header and no cell in view is elided ("Link / a",
    // "2026-11-23 …"): every column is at least as wide as what its header and visible cells need.
    void columnsFitTheirContent() {
        Rig rig;
        for (int i = 0; i < 30; ++i) {
            MachineState m = machine(QStringLiteral("iso23725:HT%1").arg(100 + i));
            m.type = QStringLiteral("HaulTruck");
            m.hasPosition = true;
            m.e = -1234.56 + i;
            m.n = 2345.67;
            m.lastDataMs = QDateTime::currentMSecsSinceEpoch();
            rig.iso.setMachine(m);
        }
        for (int i = 0; i < 20; ++i)
            rig.alarms.add(makeEvent(EventSeverity::Warning, EventKind::LinkLoss, QStringLiteral("jaus:101"),
                                     QStringLiteral("link lost %1").arg(i), QStringLiteral("jaus")));
        QCoreApplication::processEvents();
        QWidget window;
        window.setFixedSize(1366, 768);
        auto* list = new FleetListWidget(&rig.fleet, &rig.selection, &window);
        auto* log = new EventLogWidget(&rig.alarms, &window);
        list->setGeometry(0, 0, 683, 500);
        log->setGeometry(0, 500, 1366, 268);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        for (QTableView* view : {list->findChild<QTableView*>(), log->tableView()}) {
            QVERIFY(view != nullptr);
            QHeaderView* h = view->horizontalHeader();
            const int columns = view->model()->columnCount();
            auto fits = [&] {
                for (int c = 0; c < columns; ++c) {
                    if (h->isSectionHidden(c) || h->sectionResizeMode(c) == QHeaderView::Stretch ||
                        (h->stretchLastSection() && c == columns - 1))
                        continue;
                    if (headerTextWidth(h, c) > h->sectionSize(c))
                        return false;
                    for (int r = 0; r < qMin(20, view->model()->rowCount()); ++r)
                        if (static_cast<QAbstractItemView*>(view)
                                ->sizeHintForIndex(view->model()->index(r, c))
                                .width() > h->sectionSize(c))
                            return false;
                }
                return true;
            };
            QTRY_VERIFY_WITH_TIMEOUT(fits(), 10000);
        }
    }
};

QTEST_MAIN(TestFleetWidgets)
#include "test_fleet_widgets.moc"
