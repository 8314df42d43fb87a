#pragma once
// The window's side of who is at the console (models/OperatorSession.h): File › Switch operator… and
// File › Lock (Ctrl+Alt+L), the operator and role in the status bar, the lock screen, the sign-in dialogs and
// the confirmation before control is released; keyboard and mouse activity restart the idle lock.
#include <QObject>
#include <QPointer>

namespace ocu {

class LockScreen;
class MainWindow;
class OperatorSession;
class SignInDialog;

class OperatorUi : public QObject {
    Q_OBJECT
public:
    OperatorUi(MainWindow& window, OperatorSession* session);

    LockScreen* lockScreen() const { return m_lock; }
    // The dialogs (not shown): tests drive them, the actions exec() them.
    SignInDialog* makeSwitchDialog();
    SignInDialog* makeUnlockDialog();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void showOperator();
    void onLocked(bool locked);
    MainWindow& m_window;
    QPointer<OperatorSession> m_session;
    LockScreen* m_lock = nullptr;
    QObject* m_label = nullptr;
    qint64 m_lastActivityMs = 0;
};

} // namespace ocu
