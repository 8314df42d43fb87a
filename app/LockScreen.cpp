#include "app/LockScreen.h"

#include <QApplication>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QPushButton>
#include <QVBoxLayout>

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

bool LockScreen::eventFilter(QObject* watched, QEvent* event) {
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
    keepFocusOff(QApplication::focusWidget());
}

void LockScreen::hideEvent(QHideEvent* event) {
    disconnect(m_focusWatch);
    QWidget::hideEvent(event);
}

void LockScreen::keepFocusOff(QWidget* now) {
    if (!now || now == this || isAncestorOf(now) || !m_window->isAncestorOf(now))
        return; // ours, or another window (a dialog, a floating panel: the gate refuses its commands)
    if (m_keep && (now == m_keep || m_keep->isAncestorOf(now)))
        return; // STOP ALL and the safety toolbar stay reachable
    m_unlock->setFocus(Qt::OtherFocusReason);
}

void LockScreen::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.fillRect(rect(), QColor(10, 12, 16, 110)); // the picture shows through
}

} // namespace ocu
