#include "widgets/StopAllButton.h"

#include <QAction>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QTouchEvent>

namespace ocu {

StopAllButton::StopAllButton(QWidget* parent) : QToolButton(parent) {
    // Touches come as touch events, not as mice synthesised after the touch ends.
    setAttribute(Qt::WA_AcceptTouchEvents);
    setFocusPolicy(Qt::StrongFocus);
}

void StopAllButton::fire() {
    if (!isEnabled())
        return;
    setDown(true);
    if (QAction* a = defaultAction())
        a->trigger();
    else
        emit clicked();
}

bool StopAllButton::isActivationKey(int key) {
    return key == Qt::Key_Space || key == Qt::Key_Select || key == Qt::Key_Return || key == Qt::Key_Enter;
}

bool StopAllButton::event(QEvent* e) {
    switch (e->type()) {
    case QEvent::TouchBegin:
        fire();
        e->accept();
        return true;
    case QEvent::TouchUpdate:
        e->accept();
        return true;
    case QEvent::TouchEnd:
    case QEvent::TouchCancel:
        setDown(false);
        e->accept();
        return true;
    default:
        return QToolButton::event(e);
    }
}

void StopAllButton::mousePressEvent(QMouseEvent* e) {
    if (e->button() != Qt::LeftButton) {
        e->ignore();
        return;
    }
    e->accept();
    if (m_claim && !m_claim(StopInput::MouseButton, static_cast<unsigned long>(e->timestamp()))) {
        setDown(true); // stopped already, off the GUI thread: only the button goes down
        return;
    }
    fire();
}

void StopAllButton::mouseReleaseEvent(QMouseEvent* e) {
    // The stop went out on the press: a release (inside or outside) only lets the button up.
    e->accept();
    setDown(false);
}

void StopAllButton::mouseMoveEvent(QMouseEvent* e) {
    e->accept(); // no "dragged off cancels" as for ordinary buttons: nothing is pending
}

void StopAllButton::keyPressEvent(QKeyEvent* e) {
    if (!isActivationKey(e->key())) {
        QToolButton::keyPressEvent(e);
        return;
    }
    e->accept();
    if (e->isAutoRepeat())
        return;
    const auto mods =
        e->modifiers() & (Qt::ControlModifier | Qt::ShiftModifier | Qt::AltModifier | Qt::MetaModifier);
    if (m_claim && e->key() == Qt::Key_Space && mods == (Qt::ControlModifier | Qt::ShiftModifier) &&
        !m_claim(StopInput::CtrlShiftSpace, static_cast<unsigned long>(e->timestamp()))) {
        setDown(true); // Ctrl+Shift+Space, stopped already off the GUI thread
        return;
    }
    fire();
}

void StopAllButton::keyReleaseEvent(QKeyEvent* e) {
    if (!isActivationKey(e->key())) {
        QToolButton::keyReleaseEvent(e);
        return;
    }
    e->accept();
    if (!e->isAutoRepeat())
        setDown(false);
}

} // namespace ocu
