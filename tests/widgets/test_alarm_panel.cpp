// The alarm panel's alarm management (issue 19 §5): a grouped alarm shows its count and, selected, its items
// in the details pane; shelving the selected alarm hides it (until shown on purpose) and takes it out of the
// unacknowledged count; the alarm-rate label counts new alarms per 10 minutes and says FLOOD above 10.
#include "models/AlarmModel.h"
#include "widgets/EventLogWidget.h"

#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QTableView>
#include <QtTest>

using namespace ocu;

class TestAlarmPanel : public QObject {
    Q_OBJECT
private slots:
    void groupedAlarmShelvingAndRate() {
        qint64 now = 1'800'000'000'000;
        AlarmModel alarms;
        alarms.setClock([&] { return now; });
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

        log.tableView()->selectRow(0);
        QVERIFY(log.detailsPane()->toPlainText().contains(QStringLiteral("machine T2")));
        QVERIFY(log.detailsPane()->toPlainText().contains(QStringLiteral("fleet.not_in_fms|ahs|iso23725")));

        log.shelveSelected(); // default 15 min
        QCOMPARE(alarms.unacknowledgedCount(), 0);
        QCOMPARE(log.proxy()->rowCount(), 0);
        QVERIFY(alarms.isKeyShelved(QStringLiteral("fleet.not_in_fms|ahs|iso23725")));
        QCOMPARE(alarms.shelf(QStringLiteral("fleet.not_in_fms|ahs|iso23725")).untilMs, now + 15 * 60 * 1000);

        for (int i = 0; i < 11; ++i)
            alarms.add(makeEvent(EventSeverity::Alarm, EventKind::LinkLoss, {}, QStringLiteral("lost"),
                                 QStringLiteral("link%1").arg(i)));
        QVERIFY(log.rateLabel()->text().contains(QStringLiteral("FLOOD")));
        QVERIFY(log.rateLabel()->text().contains(QStringLiteral("12 alarms / 10 min")));
    }
};

QTEST_MAIN(TestAlarmPanel)
#include "test_alarm_panel.moc"
