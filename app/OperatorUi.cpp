#include "app/OperatorUi.h"

#include "app/LockScreen.h"
#include "app/MainWindow.h"
#include "models/OperatorSession.h"
#include "widgets/SignInDialog.h"

#include <QAction>
#include <QApplication>
#include <QDateTime>
#include <QEvent>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QStatusBar>
#include <QToolBar>

namespace ocu {

OperatorUi::OperatorUi(MainWindow& window, OperatorSession* session)
    : QObject(&window), m_window(window), m_session(session) {
    auto* label = new QLabel(&window);
    label->setObjectName(QStringLiteral("status-operator"));
    window.statusBar()->addPermanentWidget(label);
    m_label = label;
    m_lock = new LockScreen(&window, window.findChild<QToolBar*>(QStringLiteral("toolbar-safety")));

    QMenu* file = window.fileMenu();
    QAction* before = file->actions().isEmpty() ? nullptr : file->actions().constLast();
    auto* switchAction = new QAction(tr("S&witch operator…"), &window);
    switchAction->setObjectName(QStringLiteral("action-switch-operator"));
    auto* lockAction = new QAction(tr("&Lock"), &window);
    lockAction->setObjectName(QStringLiteral("action-lock"));
    lockAction->setShortcut(QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_L));
    lockAction->setShortcutContext(Qt::ApplicationShortcut);
    file->insertAction(before, switchAction);
    file->insertAction(before, lockAction);
    file->insertSeparator(before);
    window.addAction(lockAction); // active even when the menu bar is hidden

    const auto runSwitch = [this] {
        SignInDialog* d = makeSwitchDialog();
        d->exec();
        d->deleteLater();
    };
    connect(switchAction, &QAction::triggered, this, runSwitch);
    connect(m_lock, &LockScreen::switchRequested, this, runSwitch);
    connect(lockAction, &QAction::triggered, this, [this] {
        if (m_session)
            m_session->lock();
    });
    connect(m_lock, &LockScreen::unlockRequested, this, [this] {
        SignInDialog* d = makeUnlockDialog();
        d->exec();
        d->deleteLater();
    });
    connect(session, &OperatorSession::operatorChanged, this, &OperatorUi::showOperator);
    connect(session, &OperatorSession::lockedChanged, this, &OperatorUi::onLocked);
    qApp->installEventFilter(this);
    showOperator();
    onLocked(session->isLocked());
}

void OperatorUi::showOperator() {
    if (!m_session)
        return;
    const OperatorIdentity who = m_session->current();
    auto* label = static_cast<QLabel*>(m_label);
    label->setText(tr("%1 · %2").arg(who.user, roleDisplayName(who.role)));
    label->setToolTip(tr("Operator %1, role %2, at console %3 (File › Switch operator…)")
                          .arg(who.user, roleDisplayName(who.role), who.console));
    m_lock->setWho(tr("Locked by %1 (%2)").arg(who.user, roleDisplayName(who.role)));
    // Their own arrangement of the workspaces, in their role's workspace the first time.
    m_window.setOperator(who.user, firstWorkspaceFor(who.role));
}

void OperatorUi::onLocked(bool locked) {
    m_lock->setVisible(locked);
    if (locked)
        m_lock->unlockButton()->setFocus();
}

SignInDialog* OperatorUi::makeSwitchDialog() {
    QPointer<OperatorSession> session = m_session;
    QWidget* parent = &m_window;
    return new SignInDialog(
        tr("Switch operator"),
        tr("The next operator signs in with their own password. The machines keep running."), QString(),
        [session, parent](const QString& user, const QString& password) -> QString {
            if (!session)
                return tr("no operator session");
            QString why;
            const auto confirm = [parent](const QStringList& machines) {
                return QMessageBox::question(
                           parent, tr("Release control"),
                           tr("The new operator's role may not control machines. Release control of %1?")
                               .arg(machines.join(QStringLiteral(", "))),
                           QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel) == QMessageBox::Yes;
            };
            return session->switchTo(user, password, confirm, &why) == OperatorSession::Switch::Switched
                       ? QString()
                       : why;
        },
        &m_window);
}

SignInDialog* OperatorUi::makeUnlockDialog() {
    QPointer<OperatorSession> session = m_session;
    return new SignInDialog(
        tr("Unlock"), tr("Enter your password to unlock the console."),
        session ? session->current().user : QString(),
        [session](const QString&, const QString& password) -> QString {
            QString why;
            return !session ? tr("no operator session") : session->unlock(password, &why) ? QString() : why;
        },
        &m_window);
}

bool OperatorUi::eventFilter(QObject* watched, QEvent* event) {
    switch (event->type()) {
    case QEvent::KeyPress:
    case QEvent::MouseButtonPress:
    case QEvent::MouseMove:
    case QEvent::Wheel: {
        // At most once a second: mouse moves come in hundreds.
        const qint64 now = QDateTime::currentMSecsSinceEpoch();
        if (m_session && now - m_lastActivityMs > 1000) {
            m_lastActivityMs = now;
            m_session->activity();
        }
        break;
    }
    default:
        break;
    }
    return QObject::eventFilter(watched, event);
}

} // namespace ocu
