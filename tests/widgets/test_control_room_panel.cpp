// The control-room panel: one row per console with operator, role, since and state (signed in, locked, not
// seen since); this console in bold; long names elide in a narrow dock instead of scrolling sideways; the
// notice while the history is out of reach.
#include "models/ControlRoomModel.h"
#include "widgets/ControlRoomPanel.h"

#include <QHeaderView>
#include <QLabel>
#include <QTableView>
#include <QtTest>

using namespace ocu;

class TestControlRoomPanel : public QObject {
    Q_OBJECT
private slots:
    void showsTheRoomWithinItsWidth() {
        ControlRoomModel room;
        room.setThisConsole(QStringLiteral("dispatch-desk"));
        const qint64 now = QDateTime::currentMSecsSinceEpoch();
        ConsolePresence a{QStringLiteral("dispatch-desk"),
                          QStringLiteral("bob"),
                          QStringLiteral("dispatcher"),
                          now,
                          false,
                          {QStringLiteral("jaus:7.1.1")},
                          now,
                          false};
        ConsolePresence b{QStringLiteral("ugv-desk-with-a-very-long-console-name-for-the-north-pit"),
                          QStringLiteral("alexandra-the-night-shift-supervisor"),
                          QStringLiteral("ugv_operator"),
                          now,
                          true,
                          {},
                          now,
                          false};
        ConsolePresence c{QStringLiteral("site-office"),
                          QStringLiteral("carol"),
                          QStringLiteral("site_manager"),
                          now,
                          false,
                          {},
                          QDateTime(QDate::currentDate(), QTime(9, 5)).toMSecsSinceEpoch(),
                          true};
        room.setRoom({a, b, c});

        ControlRoomPanel panel(&room);
        panel.resize(340, 240);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        panel.setConnected(true);
        QVERIFY(!panel.notice()->isVisible());
        QTableView* t = panel.table();
        QCOMPARE(t->model()->rowCount(), 3);
        const auto text = [t](int row, int col) { return t->model()->index(row, col).data().toString(); };
        QCOMPARE(text(0, ControlRoomModel::Console), QStringLiteral("dispatch-desk"));
        QCOMPARE(t->model()->index(0, ControlRoomModel::Console).data(Qt::ToolTipRole).toString(),
                 QStringLiteral("dispatch-desk (this console)"));
        QVERIFY(t->model()->index(0, ControlRoomModel::Console).data(Qt::FontRole).value<QFont>().bold());
        QCOMPARE(text(0, ControlRoomModel::Operator), QStringLiteral("bob"));
        QCOMPARE(text(0, ControlRoomModel::Role), QStringLiteral("dispatcher"));
        QCOMPARE(text(0, ControlRoomModel::Since), QDateTime::fromMSecsSinceEpoch(now).toString("HH:mm"));
        QCOMPARE(text(0, ControlRoomModel::State), QStringLiteral("signed in"));
        QCOMPARE(text(1, ControlRoomModel::Role), QStringLiteral("UGV operator"));
        QCOMPARE(text(1, ControlRoomModel::State), QStringLiteral("locked"));
        QCOMPARE(text(2, ControlRoomModel::State), QStringLiteral("not seen since 09:05"));
        // The long names give up width (elided, whole in the tooltip): no sideways scrolling.
        QTRY_VERIFY(t->horizontalHeader()->length() <= t->viewport()->width());
        QCOMPARE(t->model()->index(1, ControlRoomModel::Operator).data(Qt::ToolTipRole).toString(),
                 QStringLiteral("alexandra-the-night-shift-supervisor"));

        panel.setConnected(false, QStringLiteral("connection refused"));
        QVERIFY(panel.notice()->isVisible());
        QVERIFY(panel.notice()->text().contains(QStringLiteral("as last seen")));
    }
};

QTEST_MAIN(TestControlRoomPanel)
#include "test_control_room_panel.moc"
