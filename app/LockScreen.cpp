#include "app/LockScreen.h"

#include <QApplication>
#include <QEvent>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QPainter>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>

namespace ocu {

LockScreen::LockScreen(QWidget* window, QWidget* keepVisible)
    : QWidget(window), m_window(window), m_keep(keepVisible) {
    setObjectName(QStringLiteral("lock-screen"));
    setAttribute(Qt::WA_NoSystemBackground);
    auto* card = new QWidget(this);
    card->setObjectName(QStringLiteral("lock-card"));
    card->setAttribute(Qt::WA_StyledBackground);
    card->setStyleSheet(QStringLiteral("#lock-card { background:rgba(20,24,30,225); border:2px solid #ffd400;"
                                       " border-radius:8px; } QLabel { color:white; }"));
    auto* box = new QVBoxLayout(card);
    box->setContentsMargins(24, 18, 24, 18);
    auto* title = new QLabel(tr("Console locked"), card);
    title->setStyleSheet(QStringLiteral("font-size:20px; font-weight:bold;"));
    m_who = new QLabel(card);
    m_who->setObjectName(QStringLiteral("lock-who"));
    auto* hint = new QLabel(tr("The picture is read-only. STOP ALL stays active (F12)."), card);
    auto* buttons = new QHBoxLayout;
    m_unlock = new QPushButton(tr("&Unlock…"), card);
    m_unlock->setObjectName(QStringLiteral("lock-unlock"));
    m_switch = new QPushButton(tr("S&witch operator…"), card);
    m_switch->setObjectName(QStringLiteral("lock-switch"));
    buttons->addWidget(m_unlock);
    buttons->addWidget(m_switch);
    for (QWidget* w :
         {static_cast<QWidget*>(title), static_cast<QWidget*>(m_who), static_cast<QWidget*>(hint)})
        box->addWidget(w, 0, Qt::AlignHCenter);
    box->addLayout(buttons);
    auto* outer = new QVBoxLayout(this);
    outer->addStretch();
    outer->addWidget(card, 0, Qt::AlignHCenter);
    outer->addStretch();
    connect(m_unlock, &QPushButton::clicked, this, &LockScreen::unlockRequested);
    connect(m_switch, &QPushButton::clicked, this, &LockScreen::switchRequested);
    window->installEventFilter(this);
    hide();
}

void LockScreen::setWho(const QString& text) {
    m_who->setText(text);
}

void LockScreen::place() {
    const int top = m_keep ? m_keep->mapTo(m_window, QPoint(0, m_keep->height())).y() : 0;
    setGeometry(0, top, m_window->width(), m_window->height() - top);
    raise();
}

QList<QWidget*> LockScreen::tabCycle() const {
    QList<QWidget*> above, veil;
    for (QWidget* w : m_window->findChildren<QWidget*>()) {
        if (!w->isVisible() || !w->isEnabled() || !(w->focusPolicy() & Qt::TabFocus) ||
            w->window() != m_window)
            continue;
        if (isAncestorOf(w))
            veil << w;
        else if (w->mapTo(m_window, QPoint(0, w->height())).y() <= geometry().top())
            above << w;
    }
    const auto leftToRight = [this](QWidget* a, QWidget* b) {
        return a->mapTo(m_window, QPoint()).x() < b->mapTo(m_window, QPoint()).x();
    };
    std::sort(above.begin(), above.end(), leftToRight);
    std::sort(veil.begin(), veil.end(), leftToRight);
    return above + veil;
}

bool LockScreen::eventFilter(QObject* watched, QEvent* event) {
    // Tab and Shift+Tab go round what the locked console offers (the row above the veil with STOP ALL, then
    // the veil's buttons) instead of the window's focus chain, which runs through the panels under it.
    if (event->type() == QEvent::KeyPress && isVisible()) {
        const auto* key = static_cast<QKeyEvent*>(event);
        QWidget* focus = QApplication::focusWidget();
        if ((key->key() == Qt::Key_Tab || key->key() == Qt::Key_Backtab) && focus &&
            focus->window() == m_window && !(key->modifiers() & (Qt::ControlModifier | Qt::AltModifier))) {
            const QList<QWidget*> cycle = tabCycle();
            if (!cycle.isEmpty()) {
                const int at = int(cycle.indexOf(focus));
                const int step = key->key() == Qt::Key_Backtab ? -1 : 1;
                const int next = at < 0 ? 0 : (at + step + int(cycle.size())) % int(cycle.size());
                cycle.at(next)->setFocus(step > 0 ? Qt::TabFocusReason : Qt::BacktabFocusReason);
                return true;
            }
        }
    }
    if (watched == m_window && (event->type() == QEvent::Resize || event->type() == QEvent::LayoutRequest) &&
        isVisible())
        place();
    return QWidget::eventFilter(watched, event);
}

void LockScreen::showEvent(QShowEvent* event) {
    place();
    QWidget::showEvent(event);
    m_focusWatch = connect(qApp, &QApplication::focusChanged, this,
                           [this](QWidget*, QWidget* now) { keepFocusOff(now); });
    qApp->installEventFilter(this);
    keepFocusOff(QApplication::focusWidget());
}

void LockScreen::hideEvent(QHideEvent* event) {
    disconnect(m_focusWatch);
    qApp->removeEventFilter(this);
    QWidget::hideEvent(event);
}

void LockScreen::keepFocusOff(QWidget* now) {
    if (!now || now == this || isAncestorOf(now) || !m_window->isAncestorOf(now))
        return; // ours, or another window (a dialog, a floating panel: the gate refuses its commands)
    if (m_keep && (now == m_keep || m_keep->isAncestorOf(now)))
        return; // STOP ALL and the safety toolbar stay reachable
    if (now->mapTo(m_window, QPoint(0, now->height())).y() <= geometry().top())
        return; // above the veil, beside STOP ALL (the workspace bar): only changes what the picture shows
    m_unlock->setFocus(Qt::OtherFocusReason);
}

void LockScreen::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.fillRect(rect(), QColor(10, 12, 16, 110)); // the picture shows through
}

} // namespace ocu
