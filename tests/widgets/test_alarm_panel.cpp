// The alarm panel's alarm management: a grouped alarm shows its count and, selected, its items
// in the details pane; shelving the selected alarm hides it (until shown on purpose) and takes it out of the
// unacknowledged count; the alarm-rate label counts new alarms per 10 minutes and says FLOOD above 10.
#include "models/AlarmModel.h"
#include "widgets/EventLogWidget.h"

#include <QHeaderView>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QStyle>
#include <QTableView>
#include <QtTest>

using namespace ocu;

class TestAlarmPanel : public QObject {
    Q_OBJECT
private slots:
    void groupedAlarmShelvingAndRate() {
        auto clock = std::make_shared<ManualModelClock>(1'800'000'000'000);
        AlarmModel alarms;
        alarms.setClock(clock);
        EventLogWidget log(&alarms);
        log.resize(1200, 600);
        log.show();
        QVERIFY(QTest::qWaitForWindowExposed(&log));
        QVERIFY(!log.detailsPane()->placeholderText().isEmpty()); // says what to do with nothing selected

        FleetEvent g = makeEvent(EventSeverity::Warning, EventKind::Discrepancy, {},
                                 QStringLiteral("3 machines of the AHS are not in the FMS fleet on ahs"),
                                 QStringLiteral("iso23725"));
        g.cause = QStringLiteral("fleet.not_in_fms");
        g.group = QStringLiteral("ahs");
        g.itemCount = 3;
        g.details = {QStringLiteral("machine T1"), QStringLiteral("machine T2"),
                     QStringLiteral("machine T3")};
        alarms.add(g);
        QCOMPARE(log.proxy()->rowCount(), 1);
        QCOMPARE(log.proxy()->index(0, AlarmModel::ColCount).data().toString(), QStringLiteral("3"));
        QVERIFY(log.rateLabel()->text().contains(QStringLiteral("1 alarms / 10 min")));

        // The details pane is folded while nothing is selected (the table keeps the rows of a
        // short dock) and opens with the selection.
        QVERIFY(!log.detailsShown());
        log.tableView()->selectRow(0);
        QVERIFY(log.detailsShown());
        QVERIFY(log.detailsPane()->height() >= log.detailsPane()->fontMetrics().lineSpacing() * 3);
        QVERIFY(log.detailsPane()->toPlainText().contains(QStringLiteral("machine T2")));
        QVERIFY(log.detailsPane()->toPlainText().contains(QStringLiteral("fleet.not_in_fms|ahs|iso23725")));

        log.shelveSelected(); // default 15 min
        QCOMPARE(alarms.unacknowledgedCount(), 0);
        QCOMPARE(log.proxy()->rowCount(), 0);
        QTRY_VERIFY(!log.detailsShown()); // nothing selected any more
        QVERIFY(alarms.isKeyShelved(QStringLiteral("fleet.not_in_fms|ahs|iso23725")));
        QCOMPARE(alarms.shelf(QStringLiteral("fleet.not_in_fms|ahs|iso23725")).untilMs,
                 clock->nowMs() + 15 * 60 * 1000);

        for (int i = 0; i < 11; ++i)
            alarms.add(makeEvent(EventSeverity::Alarm, EventKind::LinkLoss, {}, QStringLiteral("lost"),
                                 QStringLiteral("link%1").arg(i)));
        QVERIFY(log.rateLabel()->text().contains(QStringLiteral("FLOOD")));
        QVERIFY(log.rateLabel()->text().contains(QStringLiteral("12 alarms / 10 min")));
    }

    // At 1366 x 768 (the event log dock is about 800 px wide): the message takes the width the
    // fitted columns leave; a long machine id is capped, its full text in the tooltip; nothing else is cut.
    void messageTakesTheRemainingWidth() {
        AlarmModel alarms;
        const QString longId = QStringLiteral("iso23725:9f4ef755-dc01-4363-9959-2205d5b7910b");
        const QString longText =
            QStringLiteral("1,000 machines of the AHS are not in the FMS fleet: see the list "
                           "in the details below");
        alarms.add(makeEvent(EventSeverity::Warning, EventKind::Discrepancy, longId, longText));
        alarms.add(
            makeEvent(EventSeverity::Info, EventKind::Info, {}, QStringLiteral("OSYRIS station 2 heard")));
        EventLogWidget log(&alarms);
        log.resize(800, 300);
        log.show();
        QVERIFY(QTest::qWaitForWindowExposed(&log));
        auto* view = log.findChild<QTableView*>();
        QVERIFY(view);
        // The button rows fit an 800-px dock (a wider minimum and the dock cuts off the last buttons).
        QVERIFY2(log.minimumSizeHint().width() <= 800,
                 qPrintable(QString::number(log.minimumSizeHint().width())));
        QHeaderView* h = view->horizontalHeader();
        QTRY_VERIFY(h->sectionSize(AlarmModel::ColMachine) > h->sectionSize(AlarmModel::ColAck) ||
                    h->sectionSize(AlarmModel::ColMachine) >= 160); // fitted once shown
        QVERIFY2(h->sectionSize(AlarmModel::ColMachine) <= 170,
                 qPrintable(QString::number(h->sectionSize(3))));
        const int message = h->sectionSize(AlarmModel::ColText);
        QVERIFY2(message >= 220,
                 qPrintable(QStringLiteral("message %1 of %2").arg(message).arg(view->viewport()->width())));
        // Every column fits inside the view: no horizontal scrolling needed at this width.
        int total = 0;
        for (int c = 0; c < AlarmModel::ColumnCount; ++c)
            total += h->sectionSize(c);
        QVERIFY2(total <= view->viewport()->width() + 1, qPrintable(QString::number(total)));
        // The short columns show their content unelided (title and cells).
        for (int c : {int(AlarmModel::ColTime), int(AlarmModel::ColSeverity), int(AlarmModel::ColPriority),
                      int(AlarmModel::ColCount)}) {
            const QString title = view->model()->headerData(c, Qt::Horizontal).toString();
            const int margin = h->style()->pixelMetric(QStyle::PM_HeaderMargin, nullptr, h);
            const int want = std::max(static_cast<QAbstractItemView*>(view)->sizeHintForColumn(c),
                                      h->fontMetrics().horizontalAdvance(title) + 2 * margin);
            QVERIFY2(
                h->sectionSize(c) >= want - 1,
                qPrintable(QStringLiteral("column %1: %2 < %3").arg(c).arg(h->sectionSize(c)).arg(want)));
        }
        // Capped and elided text: the tooltip has it whole.
        const QModelIndex machine = view->model()->index(0, AlarmModel::ColMachine);
        const QModelIndex text = view->model()->index(0, AlarmModel::ColText);
        QCOMPARE(machine.data(Qt::ToolTipRole).toString(), longId);
        QCOMPARE(text.data(Qt::ToolTipRole).toString(), longText);
    }
};

QTEST_MAIN(TestAlarmPanel)
#include "test_alarm_panel.moc"
