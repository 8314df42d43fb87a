#include "widgets/HoldToConfirmButton.h"

#include <QPainter>
#include <QStyleOptionButton>

namespace ocu {

HoldToConfirmButton::HoldToConfirmButton(const QString& text, QWidget* parent) : QPushButton(text, parent) {
    setToolTip(tr("Press and hold to confirm"));
    m_tick.setInterval(30);
    connect(&m_tick, &QTimer::timeout, this, &HoldToConfirmButton::onTick);
    // pressed/released cover the mouse and the keyboard (Space) alike.
    connect(this, &QAbstractButton::pressed, this, &HoldToConfirmButton::onPressed);
    connect(this, &QAbstractButton::released, this, &HoldToConfirmButton::onReleased);
}

double HoldToConfirmButton::progress() const {
    if (!m_holding)
        return m_done ? 1.0 : 0.0;
    return std::min(1.0, double(m_held.elapsed()) / m_holdMs);
}

void HoldToConfirmButton::onPressed() {
    m_holding = true;
    m_done = false;
    m_held.start();
    m_tick.start();
    update();
}

void HoldToConfirmButton::onTick() {
    if (!m_holding)
        return;
    if (m_held.elapsed() >= m_holdMs && !m_done) {
        m_done = true;
        m_holding = false;
        m_tick.stop();
        update();
        emit confirmed();
        return;
    }
    update();
}

void HoldToConfirmButton::onReleased() {
    if (!m_holding)
        return;
    // A release right at the deadline still counts (the timer may not have ticked yet).
    const bool reached = m_held.elapsed() >= m_holdMs;
    m_holding = false;
    m_tick.stop();
    if (reached && !m_done) {
        m_done = true;
        update();
        emit confirmed();
        return;
    }
    update();
    emit cancelled();
}

void HoldToConfirmButton::paintEvent(QPaintEvent* e) {
    QPushButton::paintEvent(e);
    const double p = progress();
    if (p <= 0 || !m_holding)
        return;
    QPainter painter(this);
    QRect r = rect().adjusted(3, height() - 7, -3, -3);
    painter.fillRect(r, QColor(0xdd, 0xdd, 0xdd));
    r.setWidth(int(r.width() * p));
    painter.fillRect(r, QColor(0x2e, 0xb8, 0x2e));
}

} // namespace ocu
