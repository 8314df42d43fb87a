// STOP ALL from a gamepad or USB button: read on its own thread, the stop sent from there while the GUI
// thread is busy, audited once per press; the device's coming and going shown. Devices are SDL virtual
// joysticks, so no hardware is needed.
#include "app/HardwareStopButton.h"
#include "models/AlarmModel.h"
#include "models/CommandGate.h"
#include "models/testing/FakeFleetBridge.h"
#include "widgets/teleop/JoystickStopButton.h"

#include <QSignalSpy>
#include <QtTest>

#include <SDL.h>

#include <atomic>
#include <chrono>
#include <thread>

using namespace ocu;

namespace {

// One SDL virtual joystick (named "Virtual Controller" by SDL) with `buttons` buttons, held open by the test.
class VirtualPad {
public:
    explicit VirtualPad(int buttons) {
        m_index = SDL_JoystickAttachVirtual(SDL_JOYSTICK_TYPE_GAMECONTROLLER, 2, buttons, 0);
        if (m_index >= 0)
            m_js = SDL_JoystickOpen(m_index);
    }
    ~VirtualPad() { detach(); }
    bool ok() const { return m_js != nullptr; }
    void set(int button, bool down) { SDL_JoystickSetVirtualButton(m_js, button, down ? 1 : 0); }
    void detach() {
        if (!m_js)
            return;
        const SDL_JoystickID id = SDL_JoystickInstanceID(m_js);
        SDL_JoystickClose(m_js);
        m_js = nullptr;
        for (int i = 0; i < SDL_NumJoysticks(); ++i)
            if (SDL_JoystickGetDeviceInstanceID(i) == id)
                SDL_JoystickDetachVirtual(i);
    }

private:
    int m_index = -1;
    SDL_Joystick* m_js = nullptr;
};

// Waits (without the Qt event loop) until the watcher has read the devices `n` more times.
bool waitPolls(const JoystickStopButton& w, std::uint64_t n) {
    const auto until = w.polls() + n;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (w.polls() < until && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    return w.polls() >= until;
}

template <class Pred> bool waitWithoutEvents(Pred pred) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (!pred() && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    return pred();
}

} // namespace

class TestHardwareStopButton : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
        SDL_SetMainReady();
        QCOMPARE(SDL_InitSubSystem(SDL_INIT_JOYSTICK), 0); // keeps SDL up between the test functions
    }
    void cleanupTestCase() { SDL_QuitSubSystem(SDL_INIT_JOYSTICK); }

    // One call per press: holding does not repeat, a release and a new press does.
    void onePressOneStop() {
        VirtualPad pad(8);
        QVERIFY(pad.ok());
        std::atomic<int> presses{0};
        std::atomic<int> connects{0};
        JoystickStopButton w({"Virtual", 3, 2},
                             {[&](const std::string&) { ++presses; },
                              [&](bool up, const std::string&) { connects += up ? 1 : 0; }});
        QVERIFY(w.available());
        QVERIFY(waitWithoutEvents([&] { return connects.load() == 1; }));
        QVERIFY(QString::fromStdString(w.device()).contains(QLatin1String("Virtual")));
        pad.set(3, true);
        QVERIFY(waitWithoutEvents([&] { return presses.load() == 1; }));
        QVERIFY(waitPolls(w, 20)); // held for 20 reads
        QCOMPARE(presses.load(), 1);
        pad.set(5, true); // another button: nothing
        QVERIFY(waitPolls(w, 5));
        QCOMPARE(presses.load(), 1);
        pad.set(3, false);
        QVERIFY(waitPolls(w, 5));
        pad.set(3, true);
        QVERIFY(waitWithoutEvents([&] { return presses.load() == 2; }));
    }

    // A button already held when the device appears (a latched mushroom button) is a press.
    void heldAtAppearanceIsAPress() {
        VirtualPad pad(4);
        QVERIFY(pad.ok());
        pad.set(0, true);
        SDL_JoystickUpdate(); // the virtual device takes the state
        std::atomic<int> presses{0};
        JoystickStopButton w({"", 0, 2}, {[&](const std::string&) { ++presses; }, {}});
        QVERIFY(waitWithoutEvents([&] { return presses.load() == 1; }));
        QVERIFY(waitPolls(w, 10));
        QCOMPARE(presses.load(), 1);
    }

    // A device of another name, or one without the button, is not watched.
    void otherDevicesAreIgnored() {
        VirtualPad pad(2);
        QVERIFY(pad.ok());
        std::atomic<int> connects{0};
        JoystickStopButton byName({"Big Red", 0, 2}, {{}, [&](bool, const std::string&) { ++connects; }});
        JoystickStopButton byButton({"", 5, 2}, {{}, [&](bool, const std::string&) { ++connects; }});
        QVERIFY(waitPolls(byName, 10));
        QVERIFY(waitPolls(byButton, 10));
        QCOMPARE(connects.load(), 0);
        QCOMPARE(byName.device(), std::string());
        QCOMPARE(byButton.device(), std::string());
    }

    // The stop leaves from the button's thread while the GUI thread is blocked; once the GUI thread runs,
    // the gate records one STOP ALL of origin stop_button with the bridge's outcome.
    void stopLeavesWhileTheGuiThreadIsBusy() {
        AlarmModel alarms;
        CommandGate gate(&alarms);
        FakeFleetBridge bridge(Protocol::Jaus);
        bridge.fromCallersThread = true;
        MachineState m;
        m.id = QStringLiteral("jaus:1");
        bridge.setMachine(m);
        gate.addBridge(&bridge);
        QSignalSpy finished(&gate, &CommandGate::commandFinished);
        VirtualPad pad(8);
        QVERIFY(pad.ok());
        HardwareStopButton button("Virtual", 2, &gate, &alarms);
        QTRY_VERIFY(button.connected());
        QVERIFY(button.deviceName().contains(QLatin1String("Virtual")));

        pad.set(2, true);
        // No event loop from here: the GUI thread is "painting".
        const bool sent = waitWithoutEvents([&] {
            for (const auto& c : bridge.calls())
                if (c.name == QLatin1String("stop_all"))
                    return true;
            return false;
        });
        QVERIFY(sent);
        QVERIFY(bridge.stopAllThread() != std::this_thread::get_id());
        QCOMPARE(finished.count(), 0); // not yet audited: that is the gate thread's part

        QTRY_COMPARE(finished.count(), 1);
        const auto r = finished.at(0).at(0).value<CommandResult>();
        QCOMPARE(finished.at(0).at(1).toString(), QStringLiteral("stop_button"));
        QCOMPARE(r.action, QStringLiteral("stop_all"));
        QVERIFY(r.ok);
        int stops = 0;
        for (const auto& c : bridge.calls())
            stops += c.name == QLatin1String("stop_all");
        QCOMPARE(stops, 1); // sent once: the gate's part used what the button's thread sent
    }

    // The device going away is a warning in the event log; its return is information.
    void deviceLossIsShown() {
        AlarmModel alarms;
        CommandGate gate(&alarms);
        auto pad = std::make_unique<VirtualPad>(4);
        QVERIFY(pad->ok());
        HardwareStopButton button("Virtual", 1, &gate, &alarms);
        QSignalSpy changes(&button, &HardwareStopButton::connectionChanged);
        QTRY_VERIFY(button.connected());
        pad->detach();
        QTRY_VERIFY(!button.connected());
        QCOMPARE(changes.last().at(0).toBool(), false);
        bool warned = false;
        for (int i = 0; i < alarms.rowCount(); ++i) {
            const FleetEvent& e = alarms.eventAt(i);
            if (e.text.contains(QLatin1String("STOP button disconnected")))
                warned = e.severity == EventSeverity::Warning;
        }
        QVERIFY(warned);
    }
};

QTEST_MAIN(TestHardwareStopButton)
#include "test_hardware_stop_button.moc"
