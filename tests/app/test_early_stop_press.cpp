// A real mouse press on the window's STOP ALL button (XTest, through the X server, under Xvfb): the stops
// leave while the GUI thread is busy, one STOP ALL is recorded per press however the press is seen, and a
// press elsewhere or on a window covering the button stops nothing.
#include "app/EarlyStopPress.h"
#include "app/MainWindow.h"
#include "models/AlarmModel.h"
#include "models/CommandGate.h"
#include "models/testing/FakeFleetBridge.h"
#include "tests/support/XTestClicker.h"

#include <QSignalSpy>
#include <QtTest>

#include <chrono>
#include <thread>

using namespace ocu;

namespace {

int stopAllCalls(const FakeFleetBridge& b) {
    int n = 0;
    for (const auto& c : b.calls())
        n += c.name == QLatin1String("stop_all");
    return n;
}

// A person's presses are tens of milliseconds apart; the watcher and the button recognise one press by its X
// server time (milliseconds), so two injected presses must not share a millisecond.
void apart() {
    static QElapsedTimer last;
    while (last.isValid() && last.elapsed() < 3)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    last.start();
}

template <class Pred> bool waitWithoutEvents(Pred pred) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (!pred() && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    return pred();
}

// A window that counts the presses it receives.
class PressCounter : public QWidget {
public:
    int presses = 0;

protected:
    void mousePressEvent(QMouseEvent*) override { ++presses; }
};

} // namespace

class TestEarlyStopPress : public QObject {
    Q_OBJECT
    AlarmModel* m_alarms = nullptr;
    CommandGate* m_gate = nullptr;
    FakeFleetBridge* m_bridge = nullptr;
    MainWindow* m_window = nullptr;
    EarlyStopPress* m_early = nullptr;
    test::XTestClicker m_clicker;

    QPoint buttonCentre() const {
        QWidget* b = m_window->stopAllButton();
        return b->mapToGlobal(b->rect().center()) * b->devicePixelRatioF();
    }

private slots:
    void init() {
        m_alarms = new AlarmModel;
        m_gate = new CommandGate(m_alarms);
        m_bridge = new FakeFleetBridge(Protocol::Jaus);
        m_bridge->fromCallersThread = true;
        MachineState m;
        m.id = QStringLiteral("jaus:1");
        m_bridge->setMachine(m);
        m_gate->addBridge(m_bridge);
        m_window = new MainWindow;
        connect(m_window, &MainWindow::stopAllRequested, m_gate,
                [this] { m_gate->stopAll(QStringLiteral("gui")); });
        m_early = new EarlyStopPress(*m_window, m_gate);
        m_window->resize(1024, 700);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window));
        QVERIFY2(m_early->active(), "the press watcher did not start (xcb platform and XInput 2 needed)");
        std::string error;
        QVERIFY2(m_clicker.open(error), error.c_str());
    }
    void cleanup() {
        m_clicker.release();
        delete m_window; // and the press watcher with it
        delete m_gate;
        delete m_bridge;
        delete m_alarms;
    }

    // The GUI thread sleeps through the press: the stop is on its way all the same, from another thread;
    // once the GUI thread runs, one STOP ALL is recorded and the button's own press event does not stop
    // again.
    void pressStopsWhileTheGuiThreadIsBusy() {
        QSignalSpy finished(m_gate, &CommandGate::commandFinished);
        const QPoint at = buttonCentre();
        m_clicker.moveTo(at.x(), at.y());
        m_clicker.press();
        QVERIFY(waitWithoutEvents([this] { return stopAllCalls(*m_bridge) == 1; }));
        QVERIFY(m_bridge->stopAllThread() != std::this_thread::get_id());
        QCOMPARE(m_early->pressesActed(), 1);
        QCOMPARE(finished.count(), 0);
        QTRY_VERIFY(m_window->stopAllButton()->isDown()); // the press event reached the button
        QTRY_COMPARE(finished.count(), 1);
        QCOMPARE(finished.at(0).at(1).toString(), QStringLiteral("gui"));
        m_clicker.release();
        QTRY_VERIFY(!m_window->stopAllButton()->isDown());
        QCOMPARE(finished.count(), 1);
        QCOMPARE(stopAllCalls(*m_bridge), 1);
    }

    // With the GUI thread idle, whichever of the two sees the press first stops; still one STOP ALL per
    // press.
    void onePressOneStopWhenIdle() {
        QSignalSpy finished(m_gate, &CommandGate::commandFinished);
        const QPoint at = buttonCentre();
        m_clicker.moveTo(at.x(), at.y());
        for (int i = 1; i <= 3; ++i) {
            apart();
            m_clicker.press();
            QTRY_VERIFY(m_window->stopAllButton()->isDown());
            QTRY_COMPARE(finished.count(), i);
            m_clicker.release();
            QTRY_VERIFY(!m_window->stopAllButton()->isDown());
            QCOMPARE(stopAllCalls(*m_bridge), i);
        }
        QCOMPARE(finished.count(), 3);
    }

    // F12 while the GUI thread sleeps: the stop leaves from the watcher; held, it does not repeat; the
    // shortcut, when the GUI thread runs, does not stop again. Then F12 and Ctrl+Shift+Space with the GUI
    // idle: one STOP ALL each.
    void stopKeysWhileTheGuiThreadIsBusy() {
        QSignalSpy finished(m_gate, &CommandGate::commandFinished);
        m_window->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(m_window));
        m_clicker.key("F12", true);
        QVERIFY(waitWithoutEvents([this] { return stopAllCalls(*m_bridge) == 1; }));
        QVERIFY(m_bridge->stopAllThread() != std::this_thread::get_id());
        QCOMPARE(m_early->keysActed(), 1);
        QTRY_COMPARE(finished.count(), 1);
        m_clicker.key("F12", false);
        QTRY_COMPARE(m_early->keysSeen(), 1);

        apart();
        m_clicker.key("F12", true);
        m_clicker.key("F12", false);
        QTRY_COMPARE(finished.count(), 2);
        QTRY_COMPARE(m_early->keysSeen(), 2);
        apart();
        m_clicker.key("Control_L", true);
        m_clicker.key("Shift_L", true);
        m_clicker.key("space", true);
        m_clicker.key("space", false);
        m_clicker.key("Shift_L", false);
        m_clicker.key("Control_L", false);
        QTRY_COMPARE(finished.count(), 3);
        QTRY_COMPARE(m_early->keysSeen(), 3);
        QCOMPARE(stopAllCalls(*m_bridge), 3);
        QCOMPARE(finished.count(), 3);
    }

    // F12 with the focus in another window: the watcher leaves it alone (another program may own that
    // window); this one is ours, so the application-wide shortcut stops, once, on the GUI thread.
    void stopKeyWithTheFocusElsewhere() {
        QSignalSpy finished(m_gate, &CommandGate::commandFinished);
        PressCounter other;
        other.setGeometry(900, 600, 200, 100);
        other.show();
        other.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&other));
        m_clicker.key("F12", true);
        m_clicker.key("F12", false);
        QTRY_COMPARE(m_early->keysSeen(), 1);
        QCOMPARE(m_early->keysActed(), 0);
        QTRY_COMPARE(finished.count(), 1);
        QCOMPARE(stopAllCalls(*m_bridge), 1);
    }

    // A press beside the button, or on a window that covers it, stops nothing.
    void otherPressesStopNothing() {
        QWidget* b = m_window->stopAllButton();
        const QPoint beside =
            b->mapToGlobal(QPoint(b->width() + 40, b->height() / 2)) * b->devicePixelRatioF();
        m_clicker.moveTo(beside.x(), beside.y());
        m_clicker.press();
        m_clicker.release();
        QTRY_COMPARE(m_early->pressesSeen(), 1);
        QCOMPARE(m_early->pressesActed(), 0);

        PressCounter cover; // another top-level window over the button
        cover.setWindowFlags(Qt::Tool | Qt::FramelessWindowHint | Qt::WindowStaysOnTopHint);
        cover.setGeometry(QRect(b->mapToGlobal(QPoint(-20, -20)), b->size() + QSize(40, 40)));
        cover.show();
        QVERIFY(QTest::qWaitForWindowExposed(&cover));
        const QPoint at = buttonCentre();
        m_clicker.moveTo(at.x(), at.y());
        m_clicker.press();
        m_clicker.release();
        QTRY_COMPARE(m_early->pressesSeen(), 2);
        QTRY_COMPARE(cover.presses, 1); // the press went to the covering window
        QCOMPARE(m_early->pressesActed(), 0);
        QCOMPARE(stopAllCalls(*m_bridge), 0);
    }
};

QTEST_MAIN(TestEarlyStopPress)
#include "test_early_stop_press.moc"
