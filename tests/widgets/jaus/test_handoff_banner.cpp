// Hand-off between two consoles through their JAUS panels (two FleetContexts, each with its JausBridge and
// command gate: subsystems 200 and 201) and the simulated UGV's Enhanced Access Control over loopback.
// Console B sees the vehicle held by A and asks with a reason (keyboard: type it, Enter); A's banner shows
// who asks and why with a countdown, and A's operator accepts, denies or asks to wait from the keyboard; the
// outcome shows on both consoles; each step is a gate command with its per-target result. With
// the consoles in one control room (the shared history's presence) the prompt and the ask name the operator
// at the other console beside its JAUS ID. With OCU_SCREENSHOT_DIR set, A's panel with the prompt is saved at
// 1366x768.
#include "models/CommandGate.h"
#include "models/ControlRoomModel.h"
#include "models/FleetContext.h"
#include "models/FleetSelection.h"
#include "models/bridges/JausBridge.h"
#include "sim/jaus/JausDemo.h"
#include "widgets/jaus/HandoffBanner.h"
#include "widgets/jaus/JausControlPanel.h"

#include <QApplication>
#include <QDir>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QVBoxLayout>
#include <QtTest>

using namespace ocu;
using namespace ocu::jaus;

namespace {

struct Console {
    Console(sim::JausDemo& demo, std::uint16_t ss) {
        JausConfig c;
        c.subsystemId = ss;
        c.callSign = "OCU-" + std::to_string(ss);
        c.authority = 205;
        demo.configure(c);
        bridge = std::make_unique<JausBridge>(c, GeoFrame(sim::JausDemoOptions{}.origin));
        ctx.addBridge(bridge.get());
        const QString e = bridge->start();
        if (!e.isEmpty())
            qFatal("%s", qPrintable(e));
        panel = new JausControlPanel(bridge.get(), ctx.gate(), ctx.selection());
        auto* l = new QVBoxLayout(&window);
        l->addWidget(panel);
        window.resize(1366, 768);
        window.show();
        QObject::connect(ctx.gate(), &CommandGate::commandFinished,
                         [this](const CommandResult& r, const QString&) { results << r; });
    }
    HandoffBanner* banner() const { return panel->handoff(); }
    std::optional<JausVehicle> ugv() const { return bridge->subsystem(126); }
    // The last final result of `action` through the gate.
    std::optional<CommandResult> result(const QString& action) const {
        for (auto it = results.rbegin(); it != results.rend(); ++it)
            if (it->action == action)
                return *it;
        return std::nullopt;
    }
    FleetContext ctx;
    std::unique_ptr<JausBridge> bridge;
    QWidget window;
    JausControlPanel* panel;
    QList<CommandResult> results;
};

sim::JausDemoOptions demoOptions() {
    sim::JausDemoOptions o;
    o.count = 1;
    return o;
}

} // namespace

class TestHandoffBanner : public QObject {
    Q_OBJECT

    // A holds the UGV; B, with it selected, asks for it from the keyboard. Returns with A's prompt shown.
    void askFromB(Console& a, Console& b, const QString& holder = QStringLiteral("200.1.1"),
                  const QString& asker = QStringLiteral("Console 201.1.1")) {
        QTRY_VERIFY_WITH_TIMEOUT(a.ugv() && a.ugv()->handoff.offered && b.ugv() && b.ugv()->handoff.offered,
                                 15000);
        a.ctx.gate()->command(RequestControl{QStringLiteral("jaus:126")}, QStringLiteral("gui"));
        QTRY_VERIFY_WITH_TIMEOUT(a.ugv()->controlledByUs, 15000);
        QVERIFY(!a.banner()->isVisible()); // nothing to ask or answer on A
        b.ctx.selection()->setCurrent(QStringLiteral("jaus:126"));
        QTRY_VERIFY_WITH_TIMEOUT(b.banner()->askButton()->isVisible(), 15000);
        const QString askText = b.banner()->findChild<QLabel*>(QStringLiteral("handoff-ask-text"))->text();
        QVERIFY2(askText.contains(holder), qPrintable(askText));
        b.banner()->reasonEdit()->setFocus();
        QTest::keyClicks(b.banner()->reasonEdit(), QStringLiteral("shift change"));
        QTest::keyClick(b.banner()->reasonEdit(), Qt::Key_Return);
        QTRY_VERIFY_WITH_TIMEOUT(b.result(QStringLiteral("handoff_request")).has_value(), 15000);
        QVERIFY2(b.result(QStringLiteral("handoff_request"))->ok,
                 qPrintable(b.result(QStringLiteral("handoff_request"))->message));
        QTRY_VERIFY_WITH_TIMEOUT(a.banner()->promptShown(), 15000);
        const QString prompt = a.banner()->promptText();
        QVERIFY2(prompt.contains(asker + QStringLiteral(" asks for control of UGV-126 (authority 205)")),
                 qPrintable(prompt));
        QVERIFY2(prompt.contains("Reason: OCU-201: shift change"), qPrintable(prompt));
        QVERIFY2(prompt.contains("Answer within"), qPrintable(prompt));
        QTRY_VERIFY_WITH_TIMEOUT(b.banner()->statusText().contains("Waiting for the holder's answer"), 15000);
        QVERIFY(b.banner()->withdrawButton()->isVisible());
    }

private slots:
    void acceptedFromTheKeyboard() {
        sim::JausDemo demo(demoOptions());
        Console a(demo, 200), b(demo, 201);
        askFromB(a, b);
        if (const QByteArray dir = qgetenv("OCU_SCREENSHOT_DIR"); !dir.isEmpty())
            a.window.grab().save(QDir(QString::fromLocal8Bit(dir)).filePath("handoff-prompt-1366x768.png"));
        // Keyboard path: from "Release all", Tab reaches Accept.
        a.window.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&a.window));
        auto* releaseAll = a.panel->findChild<QPushButton*>(QStringLiteral("button-release-all"));
        releaseAll->setFocus();
        QTest::keyClick(releaseAll, Qt::Key_Tab);
        QCOMPARE(QApplication::focusWidget(), a.banner()->acceptButton());
        QTest::keyClick(a.banner()->acceptButton(), Qt::Key_Space);
        QTRY_VERIFY_WITH_TIMEOUT(a.result(QStringLiteral("handoff_answer")).has_value(), 15000);
        QVERIFY(a.result(QStringLiteral("handoff_answer"))->ok);
        QTRY_VERIFY_WITH_TIMEOUT(b.ugv()->controlledByUs, 15000);
        QTRY_VERIFY_WITH_TIMEOUT(!a.ugv()->controlledByUs, 15000);
        QTRY_VERIFY_WITH_TIMEOUT(b.banner()->statusText().contains("Control handed over"), 15000);
        QVERIFY(!a.banner()->promptShown());
        // The outcome put away with OK; A now sees B holding it and could ask back.
        b.banner()->dismissButton()->click();
        QVERIFY(b.banner()->statusText().isEmpty());
        a.ctx.selection()->setCurrent(QStringLiteral("jaus:126"));
        QTRY_VERIFY_WITH_TIMEOUT(a.banner()->askButton()->isVisible(), 15000);
    }

    void denied() {
        sim::JausDemo demo(demoOptions());
        Console a(demo, 200), b(demo, 201);
        askFromB(a, b);
        a.banner()->denyButton()->setFocus();
        QTest::keyClick(a.banner()->denyButton(), Qt::Key_Space);
        QTRY_VERIFY_WITH_TIMEOUT(b.banner()->statusText().contains("Denied"), 15000);
        QVERIFY(b.banner()->statusText().contains("denied by 200.1.1"));
        QVERIFY(!a.banner()->promptShown());
        QVERIFY(a.ugv()->controlledByUs);
        QVERIFY(!b.ugv()->controlledByUs);
    }

    // A answers "wait": B shows it and keeps the request up (re-asserted past the vehicle's 5 s request
    // timeout), A's prompt stays with the decision time started again; A then accepts.
    void namedByTheControlRoom() {
        sim::JausDemo demo(demoOptions());
        Console a(demo, 200), b(demo, 201);
        // The room as both consoles read it from the shared history: who sits where, and the JAUS
        // addresses their stacks control with.
        ControlRoomModel room;
        ConsolePresence alice;
        alice.console = QStringLiteral("dispatch-desk");
        alice.operatorName = QStringLiteral("alice");
        alice.controllerAddresses = {QStringLiteral("jaus:200.1.1")};
        ConsolePresence bob;
        bob.console = QStringLiteral("ugv-desk");
        bob.operatorName = QStringLiteral("bob");
        bob.controllerAddresses = {QStringLiteral("jaus:201.1.1")};
        room.setRoom({alice, bob});
        a.banner()->setControlRoom(&room);
        b.banner()->setControlRoom(&room);
        askFromB(a, b, QStringLiteral("held by alice at dispatch-desk (console 200.1.1, authority 205)"),
                 QStringLiteral("bob at ugv-desk (console 201.1.1)"));
        // bob leaves the room (his console's presence gone): the prompt falls back to the JAUS ID.
        room.setRoom({alice});
        QVERIFY2(a.banner()->promptText().contains("Console 201.1.1 asks"),
                 qPrintable(a.banner()->promptText()));
        a.banner()->denyButton()->click();
        QTRY_VERIFY_WITH_TIMEOUT(b.banner()->statusText().contains("Denied"), 15000);
    }

    void waitThenAccepted() {
        sim::JausDemo demo(demoOptions());
        Console a(demo, 200), b(demo, 201);
        askFromB(a, b);
        a.banner()->waitButton()->setFocus();
        QTest::keyClick(a.banner()->waitButton(), Qt::Key_Space);
        QTRY_VERIFY_WITH_TIMEOUT(a.result(QStringLiteral("handoff_answer")).has_value(), 15000);
        QVERIFY(a.result(QStringLiteral("handoff_answer"))->ok);
        QTRY_VERIFY_WITH_TIMEOUT(b.banner()->statusText().contains("The holder asks you to wait"), 15000);
        QCOMPARE(b.ugv()->handoff.state, HandoffState::Waiting);
        QVERIFY(b.banner()->withdrawButton()->isVisible());
        QTRY_VERIFY_WITH_TIMEOUT(a.banner()->promptText().contains("You asked it to wait"), 15000);
        QTest::qWait(6000);
        QCOMPARE(b.ugv()->handoff.state, HandoffState::Waiting);
        QVERIFY(a.banner()->promptShown());
        a.banner()->acceptButton()->click();
        QTRY_VERIFY_WITH_TIMEOUT(b.ugv()->controlledByUs, 15000);
        QTRY_VERIFY_WITH_TIMEOUT(b.banner()->statusText().contains("Control handed over"), 15000);
    }
};

QTEST_MAIN(TestHandoffBanner)
#include "test_handoff_banner.moc"
