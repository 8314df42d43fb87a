#include "app/EarlyStopPress.h"

#include "app/MainWindow.h"
#include "models/CommandGate.h"
#include "widgets/StopAllButton.h"
#include "widgets/StopPressClaims.h"
#include "widgets/X11StopPressWatcher.h"

#include <QApplication>
#include <QEvent>
#include <QKeyEvent>
#include <QLoggingCategory>
#include <QMetaObject>

#include <optional>

namespace ocu {

EarlyStopPress::EarlyStopPress(MainWindow& window, CommandGate* gate)
    : QObject(&window), m_window(window), m_gate(gate), m_claims(std::make_shared<StopPressClaims>()) {
    auto* button = qobject_cast<StopAllButton*>(window.stopAllButton());
    m_button = button;
    if (!button || QGuiApplication::platformName() != QLatin1String("xcb"))
        return;
    auto claims = m_claims;
    auto watcher = std::make_unique<X11StopPressWatcher>([claims, gate](StopInput input, unsigned long time) {
        if (!claims->claim(input, time))
            return; // the button's own press event came first and stopped
        auto early = gate->stopAllEarly();
        QMetaObject::invokeMethod(
            gate, [gate, early] { gate->stopAll(QStringLiteral("gui"), {}, early); }, Qt::QueuedConnection);
    });
    std::string error;
    if (!watcher->start(error)) {
        qWarning().noquote() << "STOP ALL press watched on the GUI thread only:"
                             << QString::fromStdString(error);
        return;
    }
    m_watcher = std::move(watcher);
    button->setPressClaim(
        [claims](StopInput input, unsigned long time) { return claims->claim(input, time); });
    button->installEventFilter(this);
    window.installEventFilter(this);
    qApp->installEventFilter(this); // the stop keys' shortcut events, whichever widget has the focus
    publishTarget();
}

EarlyStopPress::~EarlyStopPress() {
    m_watcher.reset(); // no press is claimed after this
    if (m_button)
        m_button->setPressClaim({});
}

int EarlyStopPress::pressesSeen() const {
    return m_watcher ? m_watcher->pressesSeen() : 0;
}

int EarlyStopPress::pressesActed() const {
    return m_watcher ? m_watcher->pressesActed() : 0;
}

int EarlyStopPress::keysSeen() const {
    return m_watcher ? m_watcher->keysSeen() : 0;
}

int EarlyStopPress::keysActed() const {
    return m_watcher ? m_watcher->keysActed() : 0;
}

namespace {
// The STOP ALL action's shortcuts (MainWindow): F12, Ctrl+Shift+Space; nothing for any other key.
std::optional<StopInput> stopKey(const QKeyEvent* k) {
    const auto mods =
        k->modifiers() & (Qt::ControlModifier | Qt::ShiftModifier | Qt::AltModifier | Qt::MetaModifier);
    if (k->key() == Qt::Key_F12 && mods == Qt::NoModifier)
        return StopInput::F12;
    if (k->key() == Qt::Key_Space && mods == (Qt::ControlModifier | Qt::ShiftModifier))
        return StopInput::CtrlShiftSpace;
    return std::nullopt;
}
} // namespace

bool EarlyStopPress::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::ShortcutOverride) {
        // Shortcuts are tried after this event: accepted, the key goes to the focus widget instead (which
        // ignores it). A key the watcher already acted on must not stop a second time.
        // The same event comes here once per widget it propagates through: claimed once, by its time.
        auto* k = static_cast<QKeyEvent*>(event);
        const std::optional<StopInput> input = stopKey(k);
        if (m_watcher && !k->isAutoRepeat() && input) {
            const auto time = static_cast<unsigned long>(k->timestamp());
            if (time != m_keyPassed && !m_claims->claim(*input, time)) {
                k->accept();
                return true;
            }
            m_keyPassed = time;
        }
        return QObject::eventFilter(watched, event);
    }
    if (watched != m_button && watched != &m_window)
        return QObject::eventFilter(watched, event);
    switch (event->type()) {
    case QEvent::Move:
    case QEvent::Resize:
    case QEvent::Show:
    case QEvent::Hide:
    case QEvent::EnabledChange:
    case QEvent::WindowStateChange:
    case QEvent::WinIdChange:
        publishTarget();
        break;
    default:
        break;
    }
    return QObject::eventFilter(watched, event);
}

// The button's rectangle in root-window pixels (X counts device pixels) and our top-level X window.
void EarlyStopPress::publishTarget() {
    StopAllButton* b = m_button;
    if (!m_watcher || !b)
        return;
    const qreal dpr = b->devicePixelRatioF();
    const QPoint tl = b->mapToGlobal(QPoint(0, 0));
    const bool armed = b->isVisible() && b->isEnabled() && !m_window.isMinimized();
    m_watcher->setTarget(static_cast<unsigned long>(m_window.winId()), int(tl.x() * dpr), int(tl.y() * dpr),
                         int(b->width() * dpr), int(b->height() * dpr), armed);
}

} // namespace ocu
