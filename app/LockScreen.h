#pragma once
// The locked console: a veil over the window below the safety toolbar. The picture stays visible under it
// and keeps moving, but takes no input (read-only); STOP ALL stays visible above it and reachable by its
// keys (F12, Ctrl+Shift+Space) and by Tab. Keyboard focus stays on the veil and the row above it (STOP ALL,
// the workspaces): Tab or a click cannot reach a widget under it. The veil says who locked it and offers
// Unlock and Switch operator.
#include <QWidget>

class QLabel;
class QPushButton;

namespace ocu {

class LockScreen : public QWidget {
    Q_OBJECT
public:
    // `window` is covered from the bottom of `keepVisible` (the safety toolbar) down.
    LockScreen(QWidget* window, QWidget* keepVisible);

    void setWho(const QString& text);
    QPushButton* unlockButton() const { return m_unlock; }
    QPushButton* switchButton() const { return m_switch; }

signals:
    void unlockRequested();
    void switchRequested();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
    void paintEvent(QPaintEvent* event) override;
    void showEvent(QShowEvent* event) override;
    void hideEvent(QHideEvent* event) override;

private:
    void place();
    // Focus that lands on a widget under the veil goes to Unlock instead.
    void keepFocusOff(QWidget* now);
    // The widgets Tab visits while locked: the row above the veil, then the veil's buttons.
    QList<QWidget*> tabCycle() const;
    QWidget* m_window;
    QWidget* m_keep;
    QLabel* m_who = nullptr;
    QPushButton* m_unlock = nullptr;
    QPushButton* m_switch = nullptr;
    QMetaObject::Connection m_focusWatch;
};

} // namespace ocu
