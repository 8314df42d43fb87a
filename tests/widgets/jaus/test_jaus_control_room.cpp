// The JAUS control table names another console of the control room by its person: a vehicle whose
// controller's JAUS address is published by a console in the room reads "<operator> at <console>" (the
// tooltip keeps the JAUS ID); an address no console publishes stays a JAUS ID; ours stays "this console".
#include "models/ControlRoomModel.h"
#include "models/FleetContext.h"
#include "models/jaus/JausSubsystemModel.h"
#include "tests/widgets/jaus/FakeJausBridge.h"
#include "widgets/jaus/JausControlPanel.h"

#include <QSignalSpy>
#include <QTableView>
#include <QtTest>

using namespace ocu;

namespace {

JausVehicle vehicle(quint16 id, JausAddress controller, bool ours) {
    JausVehicle v;
    v.subsystem = id;
    v.callSign = QStringLiteral("UGV-%1").arg(id);
    v.link = JausLink::Up;
    v.controller = controller;
    v.controllerAuthority = 210;
    v.controlledByUs = ours;
    v.access = ours ? JausAccess::ControlAccepted : JausAccess::Monitoring;
    return v;
}

ConsolePresence presence(const QString& console, const QString& user, const QStringList& addresses) {
    ConsolePresence p;
    p.console = console;
    p.operatorName = user;
    p.role = QStringLiteral("ugv_operator");
    p.sinceMs = QDateTime::currentMSecsSinceEpoch();
    p.controllerAddresses = addresses;
    return p;
}

} // namespace

class TestJausControlRoom : public QObject {
    Q_OBJECT
private slots:
    void controllerColumnNamesTheConsole() {
        testing::FakeJausBridge bridge;
        bridge.ident.ownId = {200, 1, 1};
        bridge.report(vehicle(5, {7, 1, 1}, false));  // another console of the room
        bridge.report(vehicle(6, {8, 1, 2}, false));  // a controller no console of the room publishes
        bridge.report(vehicle(4, {200, 1, 1}, true)); // ours
        bridge.report(vehicle(3, {0, 0, 0}, false));  // nobody
        FleetContext ctx;
        JausControlPanel panel(&bridge, ctx.gate(), ctx.selection());
        ControlRoomModel room;
        room.setThisConsole(QStringLiteral("ugv-desk"));
        panel.model()->setControlRoom(&room);
        JausSubsystemModel* model = panel.model();
        const auto cell = [model](quint16 id, int role = Qt::DisplayRole) {
            return model->data(model->index(model->rowOf(id), JausSubsystemModel::Controller), role)
                .toString();
        };
        // No room read yet: JAUS IDs, as without the shared history.
        QCOMPARE(cell(5), QStringLiteral("7.1.1 (210)"));
        QCOMPARE(cell(4), QStringLiteral("this console (210)"));

        QSignalSpy changed(model, &QAbstractItemModel::dataChanged);
        room.setRoom(
            {presence(QStringLiteral("dispatch-desk"), QStringLiteral("bob"), {QStringLiteral("jaus:7.1.1")}),
             presence(QStringLiteral("ugv-desk"), QStringLiteral("alice"),
                      {QStringLiteral("jaus:200.1.1")})});
        QVERIFY(!changed.isEmpty()); // the table is told, no report from the vehicle needed
        QCOMPARE(cell(5), QStringLiteral("bob at dispatch-desk (210)"));
        QCOMPARE(cell(5, Qt::ToolTipRole), QStringLiteral("bob at dispatch-desk (210), JAUS 7.1.1 (210)"));
        QCOMPARE(cell(6), QStringLiteral("8.1.2 (210)"));
        QCOMPARE(cell(4), QStringLiteral("this console (210)"));
        QCOMPARE(cell(3), QStringLiteral("nobody"));
        // What the table shows.
        QTableView* table = panel.table();
        QCOMPARE(table->model()->index(model->rowOf(5), JausSubsystemModel::Controller).data().toString(),
                 QStringLiteral("bob at dispatch-desk (210)"));

        // A switch of operator at that console: the new person.
        room.setRoom({presence(QStringLiteral("dispatch-desk"), QStringLiteral("carol"),
                               {QStringLiteral("jaus:7.1.1")})});
        QCOMPARE(cell(5), QStringLiteral("carol at dispatch-desk (210)"));
        // The console left the room: the JAUS ID again.
        room.setRoom({});
        QCOMPARE(cell(5), QStringLiteral("7.1.1 (210)"));
    }
};

QTEST_MAIN(TestJausControlRoom)
#include "test_jaus_control_room.moc"
