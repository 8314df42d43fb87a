// The JAUS access-control and teleop panels against two simulated UGVs on loopback.
#include "models/AlarmModel.h"
#include "models/FleetContext.h"
#include "models/FleetModel.h"
#include "models/FleetSelection.h"
#include "models/bridges/JausBridge.h"
#include "models/jaus/JausSubsystemModel.h"
#include "models/testing/CommandWait.h"
#include "sim/jaus/JausDemo.h"
#include "widgets/HoldToConfirmButton.h"
#include "widgets/jaus/JausControlPanel.h"
#include "widgets/jaus/TeleopPanel.h"
#include "widgets/jaus/TeleopVideoPane.h"
#include "widgets/jaus/VehicleDetailsWidget.h"
#include "widgets/teleop/JoystickMappingDialog.h"
#include "widgets/teleop/TeleopController.h"

#include "protocols/jaus/JausStack.h"

#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTableView>
#include <QTreeWidget>
#include <QVBoxLayout>
#include <QtTest>

#include <cmath>

using namespace ocu;
using namespace ocu::jaus;

namespace {

struct Site {
    explicit Site(Role role = Role::PrimaryOperator, double linkLostS = 5) : demo(options()) {
        JausConfig c;
        c.linkLostS = linkLostS;
        c.subsystemId = 200;
        c.callSign = "OCU-TEST";
        c.role = role;
        c.authority = role == Role::Monitor ? 0 : 205;
        demo.configure(c);
        bridge = std::make_unique<JausBridge>(c, GeoFrame(options().origin));
        ctx.addBridge(bridge.get());
        QString e = bridge->start();
        if (!e.isEmpty())
            qFatal("%s", qPrintable(e));
    }
    static sim::JausDemoOptions options() {
        sim::JausDemoOptions o;
        o.count = 2;
        o.alternateKinematics = false;
        return o;
    }
    sim::SimulatedUgv& ugv(std::uint16_t id) { return *demo.find(id); }
    // Displacement of the UGV along its own heading since `from` (x north, y east, yaw clockwise).
    double forwardSince(const sim::UgvState& from, std::uint16_t id) {
        const auto s = ugv(id).state();
        return (s.x - from.x) * std::cos(from.yaw) + (s.y - from.y) * std::sin(from.yaw);
    }

    sim::JausDemo demo;
    FleetContext ctx;
    std::unique_ptr<JausBridge> bridge;
};

// A window with the two panels side by side and a line edit to move the focus to.
struct Window {
    explicit Window(Site& s)
        : control(new JausControlPanel(s.bridge.get(), s.ctx.gate(), s.ctx.selection())),
          teleop(new TeleopPanel(s.bridge.get(), s.ctx.gate(), s.ctx.selection(), nullptr)),
          other(new QLineEdit) {
        auto* l = new QVBoxLayout(&w);
        l->addWidget(control);
        l->addWidget(teleop);
        l->addWidget(other);
        w.resize(900, 900);
        w.show();
    }
    QWidget w;
    JausControlPanel* control;
    TeleopPanel* teleop;
    QLineEdit* other;
};

JausSubsystemModel::RowColour colourOf(JausControlPanel* p, std::uint16_t id) {
    const int row = p->model()->rowOf(id);
    if (row < 0)
        return JausSubsystemModel::RowColour::None;
    return static_cast<JausSubsystemModel::RowColour>(
        p->model()->index(row, 0).data(JausSubsystemModel::RowColourRole).toInt());
}

QString accessOf(JausControlPanel* p, std::uint16_t id) {
    const int row = p->model()->rowOf(id);
    return row < 0 ? QString() : p->model()->index(row, JausSubsystemModel::Access).data().toString();
}

void takeControl(Window& win, std::uint16_t id) {
    QTRY_VERIFY_WITH_TIMEOUT(win.control->controlButton(id) && win.control->controlButton(id)->isEnabled(),
                             10000);
    QTest::mouseClick(win.control->controlButton(id), Qt::LeftButton);
    QTRY_COMPARE_WITH_TIMEOUT(accessOf(win.control, id), QString("CONTROL_ACCEPTED"), 10000);
}

} // namespace

class TestJausPanels : public QObject {
    Q_OBJECT
    // The vehicle under this console's control in the teleop panel, driven ahead with Shift+key held.
    void driveAheadByKeys(Site& s, Window& win, std::uint16_t id, Qt::Key key) {
        QTRY_COMPARE_WITH_TIMEOUT(win.control->model()->rowCount(), 2, 10000);
        takeControl(win, id);
        win.teleop->setVehicle(id);
        QTRY_VERIFY_WITH_TIMEOUT(win.teleop->controller()->isEnabled(), 10000);
        QVERIFY(QTest::qWaitForWindowExposed(&win.w));
        win.teleop->setFocus();
        QTest::keyPress(win.teleop, Qt::Key_Shift);
        QTest::keyPress(win.teleop, key, Qt::ShiftModifier);
        QTRY_VERIFY_WITH_TIMEOUT(s.ugv(id).state().v > 0.3, 10000);
    }

private slots:
    void discoveredRowsWithDetails() {
        Site s;
        Window win(s);
        QTRY_COMPARE_WITH_TIMEOUT(win.control->model()->rowCount(), 2, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(win.control->model()->index(0, 0).data().toString().contains("UGV-126"),
                                 10000);
        // A new row shows MONITORING until the vehicle's ReportControl arrives: nobody controls it, so the
        // access column settles on NOT_CONTROLLED (from the vehicle's report, never assumed).
        QTRY_COMPARE_WITH_TIMEOUT(accessOf(win.control, 126), QString("NOT_CONTROLLED"), 10000);
        QCOMPARE(colourOf(win.control, 126), JausSubsystemModel::RowColour::None);
        // The details tree shows subsystem -> node -> component [s.n.c] -> service URI and version.
        win.control->table()->setCurrentIndex(win.control->model()->index(0, 0));
        QCOMPARE(s.ctx.selection()->currentId(), QString("jaus:126"));
        auto hasService = [&] {
            for (auto* item : win.control->details()->tree()->findItems("urn:jaus:jss:core:AccessControl",
                                                                        Qt::MatchRecursive))
                if (item->parent() && item->parent()->text(0).startsWith("[126.") &&
                    item->text(1).startsWith("v"))
                    return true;
            return false;
        };
        QTRY_VERIFY_WITH_TIMEOUT(hasService(), 10000);
    }

    // A pose report changes no cell of the table, so it must not make the table re-measure its
    // rows (ResizeToContents): the model signals only cells that show something new.
    void poseReportsChangeNoCell() {
        Site s;
        Window win(s);
        QTRY_COMPARE_WITH_TIMEOUT(accessOf(win.control, 126), QString("NOT_CONTROLLED"), 10000);
        QTRY_VERIFY_WITH_TIMEOUT(
            win.control->controlButton(126) && win.control->controlButton(126)->isEnabled(), 10000);
        QSignalSpy updates(s.bridge.get(), &JausVehicleBridge::subsystemUpdated);
        QSignalSpy changed(win.control->model(), &QAbstractItemModel::dataChanged);
        const QString before = win.control->model()->index(0, JausSubsystemModel::Access).data().toString();
        QTRY_VERIFY_WITH_TIMEOUT(updates.count() >= 20, 20000);
        int rowChanges = 0;
        for (const auto& args : changed) // the 1 s data-age refresh (Link column only) is not a row change
            if (args.at(0).value<QModelIndex>().column() != JausSubsystemModel::Link ||
                args.at(1).value<QModelIndex>().column() != JausSubsystemModel::Link)
                ++rowChanges;
        QVERIFY2(
            rowChanges * 4 < updates.count(),
            qPrintable(QStringLiteral("%1 row changes for %2 reports").arg(rowChanges).arg(updates.count())));
        QCOMPARE(win.control->model()->index(0, JausSubsystemModel::Access).data().toString(), before);
    }

    // The details pane says what to do when nothing is selected and shows the selected machine
    // of any protocol (JAUS: the vehicle details; others: the fleet picture's details).
    void detailsPaneHintAndAnyProtocol() {
        Site s;
        Window w(s);
        QVERIFY(w.control->detailsText().contains("No machine selected"));
        QVERIFY(w.control->detailsText().contains("Select one in the fleet list"));
        MachineState truck;
        truck.id = QStringLiteral("iso23725:HT101");
        truck.protocol = Protocol::Iso23725;
        truck.name = QStringLiteral("HT101");
        truck.type = QStringLiteral("HaulTruck");
        truck.hasPosition = true;
        truck.e = 12.5;
        s.ctx.fleet()->upsert({truck});
        s.ctx.selection()->setCurrent(truck.id);
        QVERIFY2(w.control->detailsText().contains("Name: HT101"), qPrintable(w.control->detailsText()));
        QVERIFY(w.control->detailsText().contains("Protocol: iso23725"));
        QTRY_VERIFY_WITH_TIMEOUT(w.control->model()->rowOf(126) >= 0, 20000);
        s.ctx.selection()->setCurrent(QStringLiteral("jaus:126"));
        QCOMPARE(w.control->detailsText(), QStringLiteral("jaus:126"));
        s.ctx.selection()->clear();
        QVERIFY(w.control->detailsText().contains("No machine selected"));
    }
    // Keyboard only (docs/keyboard.md): from the vehicle table Tab reaches the row's Control
    // button and Space presses it (control is taken, as with the mouse).
    void keyboardReachesTheRowButtons() {
        Site s;
        Window win(s);
        QVERIFY(QTest::qWaitForWindowExposed(&win.w));
        win.w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&win.w));
        QTRY_COMPARE_WITH_TIMEOUT(win.control->model()->rowCount(), 2, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(
            win.control->controlButton(126) && win.control->controlButton(126)->isEnabled(), 10000);
        win.control->table()->setFocus(Qt::ShortcutFocusReason);
        QTRY_VERIFY(win.control->table()->hasFocus());
        QTest::keyClick(win.control->table(), Qt::Key_Down); // arrows select a row
        QStringList path;
        for (int i = 0; i < 30 && QApplication::focusWidget() != win.control->controlButton(126); ++i) {
            QWidget* f = QApplication::focusWidget();
            path << (f ? f->metaObject()->className() + QStringLiteral(":") + f->objectName() : QString("-"));
            QTest::keyClick(f ? f : &win.w, Qt::Key_Tab);
        }
        QVERIFY2(QApplication::focusWidget() == win.control->controlButton(126),
                 qPrintable(path.join(QStringLiteral(" > "))));
        // Straight from the table to the first row's buttons: table > Monitor > Control.
        QVERIFY2(path.size() <= 2, qPrintable(path.join(QStringLiteral(" > "))));
        QTest::keyClick(win.control->controlButton(126), Qt::Key_Space);
        QTRY_COMPARE_WITH_TIMEOUT(accessOf(win.control, 126), QString("CONTROL_ACCEPTED"), 10000);
    }

    void takeControlTurnsRowGreen() {
        Site s;
        Window win(s);
        QTRY_COMPARE_WITH_TIMEOUT(win.control->model()->rowCount(), 2, 10000);
        QCOMPARE(colourOf(win.control, 126), JausSubsystemModel::RowColour::None);
        takeControl(win, 126);
        QTRY_COMPARE_WITH_TIMEOUT(colourOf(win.control, 126), JausSubsystemModel::RowColour::OursOk, 10000);
        QVERIFY(win.control->releaseButton(126)->isEnabled());
        QVERIFY(!win.control->controlButton(126)->isEnabled());
        QTest::mouseClick(win.control->releaseButton(126), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(accessOf(win.control, 126) != "CONTROL_ACCEPTED", 10000);
        QTRY_COMPARE_WITH_TIMEOUT(colourOf(win.control, 126), JausSubsystemModel::RowColour::None, 10000);
        QTRY_COMPARE_WITH_TIMEOUT(s.ugv(126).state().controller.subsystem, std::uint16_t(0), 10000);
    }

    void driveWithKeysAndReleaseSendsZeros() {
        Site s;
        Window win(s);
        QTRY_COMPARE_WITH_TIMEOUT(win.control->model()->rowCount(), 2, 10000);
        takeControl(win, 126);
        win.teleop->setVehicle(126);
        QTRY_VERIFY_WITH_TIMEOUT(win.teleop->controller()->isEnabled(), 10000);
        win.teleop->setFocus();
        QVERIFY(QTest::qWaitForWindowExposed(&win.w));
        QSignalSpy commands(win.teleop->controller(), &TeleopController::command);
        const sim::UgvState start = s.ugv(126).state();
        QTest::keyPress(win.teleop, Qt::Key_Shift);
        QTest::keyPress(win.teleop, Qt::Key_W, Qt::ShiftModifier);
        // +X is forward: the vehicle moves along its heading.
        QTRY_VERIFY_WITH_TIMEOUT(s.forwardSince(start, 126) > 0.5, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(s.ugv(126).state().v > 0.3, 10000);
        // Positive rotation is a right turn (yaw clockwise from north).
        QTest::keyPress(win.teleop, Qt::Key_D, Qt::ShiftModifier);
        QTRY_VERIFY_WITH_TIMEOUT(s.ugv(126).state().w > 0.1, 10000);
        QTest::keyRelease(win.teleop, Qt::Key_D, Qt::ShiftModifier);
        QTest::keyRelease(win.teleop, Qt::Key_W, Qt::ShiftModifier);
        // Releasing the keys sends zeros at once: the vehicle stops on them, never by its 1 s drive timeout
        // (counted by the UGV even after it recovers).
        QVERIFY(commands.last().at(0).value<DriveAxes>().isZero());
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(s.ugv(126).state().v) < 1e-3, 10000);
        QVERIFY(!s.ugv(126).state().driveTimedOut);
        QCOMPARE(s.ugv(126).counters().get("drive.timeouts"), std::uint64_t(0));
        QTest::keyRelease(win.teleop, Qt::Key_Shift);
    }

    // The teleop drive session goes through the command gate - one audited drive_start and one
    // drive_stop (with why it ended) per session, not one line per 20 Hz message; a session the vehicle's
    // link ends is shown in the panel, in red, and audited.
    void driveSessionGoesThroughTheGate() {
        Site s(Role::PrimaryOperator, 1.0);
        Window win(s);
        QTRY_COMPARE_WITH_TIMEOUT(win.control->model()->rowCount(), 2, 10000);
        takeControl(win, 126);
        win.teleop->setVehicle(126);
        QTRY_VERIFY_WITH_TIMEOUT(win.teleop->controller()->isEnabled(), 10000);
        win.teleop->setFocus();
        QVERIFY(QTest::qWaitForWindowExposed(&win.w));
        auto audits = [&](const char* pattern) {
            QStringList out;
            for (int i = 0; i < s.ctx.alarms()->rowCount(); ++i)
                if (s.ctx.alarms()->eventAt(i).kind == ocu::EventKind::Audit &&
                    s.ctx.alarms()->eventAt(i).text.contains(
                        QRegularExpression(QString::fromLatin1(pattern))))
                    out << s.ctx.alarms()->eventAt(i).text;
            return out;
        };
        const sim::UgvState start = s.ugv(126).state();
        QTest::keyPress(win.teleop, Qt::Key_Shift);
        QTest::keyPress(win.teleop, Qt::Key_W, Qt::ShiftModifier);
        QTRY_VERIFY_WITH_TIMEOUT(win.teleop->sessionOpen(), 10000);
        QTRY_VERIFY_WITH_TIMEOUT(s.forwardSince(start, 126) > 0.5, 10000); // ~20 demands a second meanwhile
        QCOMPARE(audits("^drive_start by teleop: sent to jaus:126").size(), 1);
        QVERIFY(audits("^drive_stop").isEmpty());
        QTest::keyRelease(win.teleop, Qt::Key_W, Qt::ShiftModifier);
        QTRY_COMPARE_WITH_TIMEOUT(
            audits("^drive_stop by teleop: sent to jaus:126 \\(session ended: keys released\\)").size(), 1,
            10000);
        QVERIFY(!win.teleop->sessionOpen());
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(s.ugv(126).state().v) < 1e-3, 10000);
        QVERIFY(win.teleop->driveProblem().isEmpty());

        // A second session; then the vehicle falls silent: its link goes down, the session ends, the panel
        // says why in red and the audit line too.
        QTest::keyPress(win.teleop, Qt::Key_W, Qt::ShiftModifier);
        QTRY_COMPARE_WITH_TIMEOUT(audits("^drive_start by teleop: sent to jaus:126").size(), 2, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(win.teleop->sessionOpen(), 10000);
        s.ugv(126).setPacketLoss(1.0);
        QTRY_VERIFY_WITH_TIMEOUT(!win.teleop->sessionOpen(), 20000);
        QTRY_VERIFY_WITH_TIMEOUT(win.teleop->driveProblem().contains(QLatin1String("link")), 10000);
        QVERIFY(win.teleop->findChild<QLabel*>(QStringLiteral("label-drive-problem"))->isVisible());
        QTRY_COMPARE_WITH_TIMEOUT(audits("^drive_stop by teleop: .*jaus:126.*link").size(), 1, 10000);
        if (const QString shots = qEnvironmentVariable("OCU_SCREENSHOT_DIR"); !shots.isEmpty())
            win.w.grab().save(shots + QStringLiteral("/teleop-drive-problem.png"));
        // Keys still held: no new session (and audit line) per demand.
        QTest::qWait(500);
        QCOMPARE(audits("^drive_start").size(), 2);
        QTest::keyRelease(win.teleop, Qt::Key_W, Qt::ShiftModifier);
        QTest::keyRelease(win.teleop, Qt::Key_Shift);
    }

    // The mapping dialog: nothing drives while it is open (the operator moves the stick to detect axes); OK
    // applies the detected mapping, saves it for the device, and the vehicle drives with it afterwards.
    void joystickMappingDialogDetectsAndNeverDrives() {
        QStandardPaths::setTestModeEnabled(true);
        FakeInputDevice pad(QStringLiteral("Test pad/2"));
        { // no mapping saved for this device from an earlier run
            QSettings settings;
            settings.remove(QStringLiteral("teleop"));
        }
        Site s;
        QWidget w;
        auto* controlPanel = new JausControlPanel(s.bridge.get(), s.ctx.gate(), s.ctx.selection());
        auto* teleopPanel = new TeleopPanel(s.bridge.get(), s.ctx.gate(), s.ctx.selection(), &pad);
        auto* l = new QVBoxLayout(&w);
        l->addWidget(controlPanel);
        l->addWidget(teleopPanel);
        w.show();
        JausControlPanel& control = *controlPanel;
        TeleopPanel& teleop = *teleopPanel;
        QTRY_COMPARE_WITH_TIMEOUT(control.model()->rowCount(), 2, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(control.controlButton(126) && control.controlButton(126)->isEnabled(),
                                 10000);
        QTest::mouseClick(control.controlButton(126), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(accessOf(&control, 126), QString("CONTROL_ACCEPTED"), 10000);
        teleop.setVehicle(126);
        QTRY_VERIFY_WITH_TIMEOUT(teleop.controller()->isEnabled(), 10000);
        QVERIFY(teleop.joystickMappingButton()->isEnabled());
        pad.setRaw({0, 0, 0, 0});

        QSignalSpy commands(teleop.controller(), &TeleopController::command);
        QTest::mouseClick(teleop.joystickMappingButton(), Qt::LeftButton);
        auto* dlg = teleop.findChild<JoystickMappingDialog*>();
        QVERIFY(dlg);
        QTRY_VERIFY(dlg->isVisible());
        // Detect forward: this pad reads +1 on axis 3 when pushed forward.
        QTest::mouseClick(dlg->findChild<QPushButton*>(QStringLiteral("button-detect-forward")),
                          Qt::LeftButton);
        pad.setRaw({0, 0, 0, 1.0});
        QCOMPARE(dlg->findChild<QComboBox*>(QStringLiteral("combo-forward-axis"))->currentIndex(), 3);
        QVERIFY(!dlg->findChild<QCheckBox*>(QStringLiteral("check-invert-forward"))->isChecked());
        pad.setRaw({0, 0, 0, 0});
        // Detect turn: axis 2 reads -1 when pushed right, so it is inverted.
        QTest::mouseClick(dlg->findChild<QPushButton*>(QStringLiteral("button-detect-turn")), Qt::LeftButton);
        pad.setRaw({0, 0, -1.0, 0});
        QCOMPARE(dlg->findChild<QComboBox*>(QStringLiteral("combo-turn-axis"))->currentIndex(), 2);
        QVERIFY(dlg->findChild<QCheckBox*>(QStringLiteral("check-invert-turn"))->isChecked());
        pad.setRaw({0, 0, 0, 0});
        QTest::qWait(300); // the controller's stream ticks meanwhile
        for (const auto& c : commands)
            QVERIFY2(c.at(0).value<DriveAxes>().isZero(), "the vehicle was driven while mapping");
        dlg->accept();

        const AxisMapping m = pad.mapping();
        QCOMPARE(m.forwardAxis, 3);
        QCOMPARE(m.turnAxis, 2);
        QVERIFY(!m.invertForward);
        QVERIFY(m.invertTurn);
        const auto saved = loadSavedJoystickMapping(QStringLiteral("Test pad/2"));
        QVERIFY(saved);
        QCOMPARE(*saved, m);
        // Now the stick drives with the new mapping: axis 3 forward moves the vehicle ahead.
        const sim::UgvState start = s.ugv(126).state();
        pad.setRaw({0, 0, 0, 1.0});
        QTRY_VERIFY_WITH_TIMEOUT(s.forwardSince(start, 126) > 0.3, 10000);
        pad.setRaw({0, 0, 0, 0});
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(s.ugv(126).state().v) < 1e-3, 10000);
        QSettings().remove(QStringLiteral("teleop"));
    }

    void focusLossSendsZeros() {
        Site s;
        Window win(s);
        driveAheadByKeys(s, win, 127, Qt::Key_Up);
        if (QTest::currentTestFailed())
            return;
        // The operator clicks elsewhere with the keys still held: the teleop panel loses focus.
        QFocusEvent out(QEvent::FocusOut, Qt::MouseFocusReason);
        QApplication::sendEvent(win.teleop, &out);
        win.other->setFocus();
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(s.ugv(127).state().v) < 1e-3, 10000);
        QVERIFY(!s.ugv(127).state().driveTimedOut); // stopped by the zeros, not by its drive timeout
        QCOMPARE(s.ugv(127).counters().get("drive.timeouts"), std::uint64_t(0));
        QVERIFY(!win.teleop->controller()->isDriving());
    }

    // The panel leaving the operator's sight (hidden, or a dock tab behind another: OnScreenWatcher) sends
    // the zeros, like a focus loss.
    void hidingThePanelSendsZeros() {
        Site s;
        Window win(s);
        driveAheadByKeys(s, win, 127, Qt::Key_Up);
        if (QTest::currentTestFailed())
            return;
        win.teleop->hide();
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(s.ugv(127).state().v) < 1e-3, 10000);
        QVERIFY(!s.ugv(127).state().driveTimedOut); // stopped by the zeros, not by its drive timeout
        QVERIFY(!win.teleop->controller()->isDriving());
    }

    // The video in a panel of its own (the UGV workspace's main area): its leaving the operator's sight
    // sends the zeros as well, and says why: driving needs the controls and the picture in front.
    void hidingTheDetachedVideoSendsZeros() {
        Site s;
        Window win(s);
        TeleopVideoPane* video = win.teleop->detachVideo();
        QCOMPARE(win.teleop->detachVideo(), video); // once
        QVERIFY(!win.teleop->isAncestorOf(video));
        win.w.layout()->addWidget(video); // after the teleop panel: it goes first
        driveAheadByKeys(s, win, 127, Qt::Key_Up);
        if (QTest::currentTestFailed())
            return;
        QSignalSpy stopped(win.teleop->controller(), &TeleopController::stopped);
        video->hide();
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(s.ugv(127).state().v) < 1e-3, 10000);
        QVERIFY(!s.ugv(127).state().driveTimedOut); // stopped by the zeros, not by its drive timeout
        QVERIFY(!win.teleop->controller()->isDriving());
        QVERIFY(!stopped.isEmpty());
        QCOMPARE(stopped.first().at(0).toString(), QStringLiteral("teleop video hidden"));
        // Out of sight, the keys start no new session.
        QTest::keyRelease(win.teleop, Qt::Key_Up, Qt::ShiftModifier);
        QTest::keyPress(win.teleop, Qt::Key_Up, Qt::ShiftModifier);
        QTest::qWait(300);
        QVERIFY(!win.teleop->sessionOpen());
        QTest::keyRelease(win.teleop, Qt::Key_Up, Qt::ShiftModifier);
        QTest::keyRelease(win.teleop, Qt::Key_Shift);
    }

    void spaceStopsTheVehicle() {
        Site s;
        Window win(s);
        driveAheadByKeys(s, win, 126, Qt::Key_W);
        if (QTest::currentTestFailed())
            return;
        QTest::keyClick(win.teleop, Qt::Key_Space, Qt::ShiftModifier);
        QTRY_COMPARE_WITH_TIMEOUT(s.ugv(126).state().management, ManagementState::Emergency, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(s.ugv(126).state().v) < 1e-3, 10000);
        // The panel shows the emergency; driving is disabled until the emergency is cleared.
        QTRY_VERIFY_WITH_TIMEOUT(!win.teleop->controller()->isEnabled(), 10000);
        QTRY_VERIFY_WITH_TIMEOUT(win.teleop->clearEmergencyButton()->isEnabled(), 10000);
        QTRY_COMPARE_WITH_TIMEOUT(colourOf(win.control, 126), JausSubsystemModel::RowColour::OursWarning,
                                  10000);
        // The hold clears through the command gate, with its token, and both are audited.
        win.teleop->clearEmergencyButton()->setHoldDurationMs(100);
        QSignalSpy confirmed(win.teleop->clearEmergencyButton(), &HoldToConfirmButton::confirmed);
        QTest::mousePress(win.teleop->clearEmergencyButton(), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(confirmed.count(), 1, 10000);
        QTest::mouseRelease(win.teleop->clearEmergencyButton(), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(s.ugv(126).state().management != ManagementState::Emergency, 10000);
        // The audit line is written when the gate's result is final (the stack's outcome reaches the GUI
        // thread), which may come after the vehicle already reports the change: wait for it.
        auto audits = [&] {
            QStringList out;
            for (int i = 0; i < s.ctx.alarms()->rowCount(); ++i)
                if (s.ctx.alarms()->eventAt(i).kind == ocu::EventKind::Audit)
                    out << s.ctx.alarms()->eventAt(i).text;
            return out;
        };
        auto count = [&](const char* pattern) {
            return audits().filter(QRegularExpression(QString::fromLatin1(pattern))).size();
        };
        QTRY_VERIFY2_WITH_TIMEOUT(count("^clear_stop by teleop: sent to jaus:126") == 1,
                                  qPrintable(audits().join(QLatin1Char('\n'))), 10000);
        QTRY_VERIFY2_WITH_TIMEOUT(count("^stop by teleop: sent to jaus:126") == 1,
                                  qPrintable(audits().join(QLatin1Char('\n'))), 10000);
        // Control requests from the JAUS panel are audited too.
        QTRY_VERIFY2_WITH_TIMEOUT(count("^request_control by gui: sent to jaus:126") >= 1,
                                  qPrintable(audits().join(QLatin1Char('\n'))), 10000);
    }

    void preemptedByHigherAuthorityTurnsGrey() {
        Site s;
        Window win(s);
        QTRY_COMPARE_WITH_TIMEOUT(win.control->model()->rowCount(), 2, 10000);
        takeControl(win, 126);
        // A second console with a higher authority in the same band.
        struct Quiet : JausListener {
            void onSubsystemChanged(const SubsystemSnapshot&) override {}
            void onEvent(const JausEvent&) override {}
        } quiet;
        JausConfig c2;
        c2.subsystemId = 201;
        c2.callSign = "OCU-2";
        c2.authority = 230;
        s.demo.configure(c2);
        JausStack second(c2, quiet);
        second.start();
        QTRY_VERIFY_WITH_TIMEOUT(
            second.snapshot(126).has_value() && second.snapshot(126)->mobilityComponent.subsystem, 10000);
        second.requestControl(126, {});
        QTRY_COMPARE_WITH_TIMEOUT(accessOf(win.control, 126), QString("PREEMPTED"), 10000);
        QTRY_COMPARE_WITH_TIMEOUT(colourOf(win.control, 126), JausSubsystemModel::RowColour::Other, 10000);
        const int row = win.control->model()->rowOf(126);
        QVERIFY(win.control->model()
                    ->index(row, JausSubsystemModel::Controller)
                    .data()
                    .toString()
                    .startsWith("201."));
        second.stop();
    }

    void monitorRoleCommandsNothing() {
        Site s(Role::Monitor);
        Window win(s);
        QTRY_COMPARE_WITH_TIMEOUT(win.control->model()->rowCount(), 2, 10000);
        QVERIFY(win.control->controlButton(126));
        QVERIFY(!win.control->controlButton(126)->isEnabled());
        const auto r = ocu::testing::bridgeResult(
            [&](auto d) { s.bridge->command(RequestControl{QStringLiteral("jaus:126")}, d); });
        QVERIFY(!r.ok);
        QVERIFY(r.message.contains("MONITOR"));
        QTest::qWait(500);
        QCOMPARE(s.ugv(126).state().controller.subsystem, std::uint16_t(0));
        // The monitor role may stop (SetEmergency on the wire) but not clear.
        win.teleop->setVehicle(126);
        QTRY_VERIFY_WITH_TIMEOUT(win.teleop->emergencyButton()->isEnabled(), 10000);
        QTest::mouseClick(win.teleop->emergencyButton(), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(s.ugv(126).state().management, ManagementState::Emergency, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(s.bridge->subsystem(126)->emergency, 10000);
        QVERIFY(!win.teleop->clearEmergencyButton()->isEnabled());
        const CommandResult clear = ocu::testing::gateResult([&](auto h) {
            s.ctx.gate()->clearStop(QStringLiteral("jaus:126"),
                                    s.ctx.gate()->requestClearToken(QStringLiteral("jaus:126")),
                                    QStringLiteral("test"), h);
        });
        QVERIFY(!clear.ok);
        QVERIFY2(clear.message.contains(QStringLiteral("no command rights")), qPrintable(clear.message));
        QTest::qWait(500);
        QCOMPARE(s.ugv(126).state().management, ManagementState::Emergency);
    }
};

QTEST_MAIN(TestJausPanels)
#include "test_jaus_panels.moc"
