#pragma once
// STOP ALL on the press of the window's STOP ALL button or of its keys (F12, Ctrl+Shift+Space), sent before
// the GUI thread sees the input: on the xcb platform an X11StopPressWatcher's thread recognises a press over
// the button, or a stop key with the focus in the window, and sends the stops
// through CommandGate::stopAllEarly; the gate's thread then records the one STOP ALL (origin "gui"), and the
// button or the shortcut, when its own event comes, knows it was handled (StopPressClaims). On other
// platforms (offscreen, Wayland) nothing changes: the button acts on its press event.

#include <QObject>
#include <QPointer>

#include <memory>

namespace ocu {

class CommandGate;
class MainWindow;
class StopAllButton;
class StopPressClaims;
class X11StopPressWatcher;

class EarlyStopPress : public QObject {
    Q_OBJECT
public:
    // A child of `window`; `gate` and its bridges must outlive it (delete it before stopping the stacks).
    EarlyStopPress(MainWindow& window, CommandGate* gate);
    ~EarlyStopPress() override; // joins the watcher's thread

    // True when the press is watched off the GUI thread.
    bool active() const { return m_watcher != nullptr; }
    // Presses of the left button the watcher has decided on, and those over the button it acted on.
    int pressesSeen() const;
    int pressesActed() const;
    // Stop keys the watcher has decided on, and those it acted on.
    int keysSeen() const;
    int keysActed() const;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void publishTarget();

    MainWindow& m_window;
    QPointer<StopAllButton> m_button; // may go before this object while the window is destroyed
    CommandGate* m_gate;
    std::shared_ptr<StopPressClaims> m_claims;
    std::unique_ptr<X11StopPressWatcher> m_watcher;
    unsigned long m_keyPassed = 0; // the stop key's time this filter claimed and let through
};

} // namespace ocu
