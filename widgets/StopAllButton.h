#pragma once
// The STOP ALL button: it acts on the press (mouse button down, a touch landing, Space or Enter going
// down), never on the release, so the stop is on its way while the operator's hand is still moving.
// Holding it or letting go changes nothing; auto-repeat of a held key does not stop twice. The stop itself
// is the default action's (its shortcuts fire on key-down too).
#include "widgets/StopPressClaims.h"

#include <QToolButton>

#include <functional>

namespace ocu {

class StopAllButton : public QToolButton {
    Q_OBJECT
public:
    explicit StopAllButton(QWidget* parent = nullptr);

    // A mouse press, or Ctrl+Shift+Space on the focused button, acts only when `claim(what, its time)` is
    // true: the same press may have been acted on already, off the GUI thread (X11StopPressWatcher,
    // StopPressClaims). None set: every press acts.
    void setPressClaim(std::function<bool(StopInput, unsigned long serverTimeMs)> claim) {
        m_claim = std::move(claim);
    }

protected:
    bool event(QEvent* e) override;
    void mousePressEvent(QMouseEvent* e) override;
    void mouseReleaseEvent(QMouseEvent* e) override;
    void mouseMoveEvent(QMouseEvent* e) override;
    void keyPressEvent(QKeyEvent* e) override;
    void keyReleaseEvent(QKeyEvent* e) override;

private:
    void fire();
    static bool isActivationKey(int key);
    std::function<bool(StopInput, unsigned long)> m_claim;
};

} // namespace ocu
