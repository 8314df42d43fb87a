#include "widgets/teleop/VirtualStick.h"

#include <QMouseEvent>
#include <QPainter>
#include <QTouchEvent>

#include <algorithm>
#include <cmath>

namespace ocu {

VirtualStick::VirtualStick(QWidget* parent) : QWidget(parent) {
    setAttribute(Qt::WA_AcceptTouchEvents);
    setObjectName(QStringLiteral("virtual-stick"));
    setToolTip(tr("Drag to drive: up = forward, right = turn right. Release to stop."));
}

double VirtualStick::radius() const {
    return std::min(width(), height()) / 2.0 - 14.0;
}

QPointF VirtualStick::pointFor(DriveAxes a) const {
    const QPointF c = rect().center();
    return {c.x() + a.turn * radius(), c.y() - a.forward * radius()};
}

void VirtualStick::moveTo(QPointF p) {
    const QPointF c = rect().center();
    const double r = std::max(1.0, radius());
    double x = (p.x() - c.x()) / r, y = (c.y() - p.y()) / r;
    const double len = std::hypot(x, y);
    if (len > 1.0) {
        x /= len;
        y /= len;
    }
    DriveAxes a{applyDeadZone(y, 0.05), applyDeadZone(x, 0.05)};
    if (!(a == m_axes)) {
        m_axes = a;
        emit axesChanged(a);
    }
    update();
}

void VirtualStick::release() {
    m_dragging = false;
    if (!m_axes.isZero()) {
        m_axes = {};
        emit axesChanged(m_axes);
    }
    update();
}

void VirtualStick::mousePressEvent(QMouseEvent* e) {
    if (e->button() != Qt::LeftButton)
        return;
    m_dragging = true;
    moveTo(e->position());
}

void VirtualStick::mouseMoveEvent(QMouseEvent* e) {
    if (m_dragging)
        moveTo(e->position());
}

void VirtualStick::mouseReleaseEvent(QMouseEvent*) {
    release();
}

void VirtualStick::hideEvent(QHideEvent* e) {
    release();
    QWidget::hideEvent(e);
}

bool VirtualStick::event(QEvent* e) {
    switch (e->type()) {
    case QEvent::TouchBegin:
    case QEvent::TouchUpdate: {
        auto* t = static_cast<QTouchEvent*>(e);
        if (!t->points().isEmpty()) {
            m_dragging = true;
            moveTo(t->points().first().position());
        }
        return true;
    }
    case QEvent::TouchEnd:
    case QEvent::TouchCancel:
        release();
        return true;
    default:
        return QWidget::event(e);
    }
}

void VirtualStick::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QPointF c = rect().center();
    const double r = radius();
    p.setPen(QPen(palette().color(QPalette::Mid), 2));
    p.setBrush(palette().color(QPalette::Base));
    p.drawEllipse(c, r, r);
    p.setPen(QPen(palette().color(QPalette::Mid), 1, Qt::DashLine));
    p.drawLine(QPointF(c.x() - r, c.y()), QPointF(c.x() + r, c.y()));
    p.drawLine(QPointF(c.x(), c.y() - r), QPointF(c.x(), c.y() + r));
    p.setPen(palette().color(QPalette::WindowText));
    p.drawText(QRectF(c.x() - 30, c.y() - r + 2, 60, 16), Qt::AlignCenter, tr("fwd"));
    const QPointF k = pointFor(m_axes);
    p.setPen(QPen(QColor(20, 20, 20), 2));
    p.setBrush(m_axes.isZero() ? QColor(150, 150, 150) : QColor(40, 120, 220));
    p.drawEllipse(k, 13, 13);
}

AxisDisplay::AxisDisplay(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("axis-display"));
}

void AxisDisplay::setAxes(const QVector<double>& raw) {
    const bool rows = raw.size() != m_raw.size();
    m_raw = raw;
    if (rows)
        updateGeometry();
    update();
}

void AxisDisplay::setMapped(DriveAxes a) {
    m_mapped = a;
    update();
}

void AxisDisplay::paintEvent(QPaintEvent*) {
    QPainter p(this);
    const int rows = static_cast<int>(m_raw.size()) + 2;
    const double h = std::max(8.0, height() / double(std::max(rows, 1)) - 2);
    auto bar = [&](int row, const QString& label, double v, const QColor& colour) {
        const double y = row * (h + 2);
        const QRectF box(70, y, width() - 74, h);
        p.setPen(palette().color(QPalette::WindowText));
        p.drawText(QRectF(0, y, 66, h), Qt::AlignVCenter | Qt::AlignRight, label);
        p.setPen(palette().color(QPalette::Mid));
        p.setBrush(palette().color(QPalette::Base));
        p.drawRect(box);
        const double mid = box.center().x();
        const double x = mid + std::clamp(v, -1.0, 1.0) * box.width() / 2;
        p.fillRect(QRectF(std::min(mid, x), y + 1, std::abs(x - mid), h - 2), colour);
    };
    bar(0, tr("forward"), m_mapped.forward, QColor(40, 120, 220));
    bar(1, tr("turn"), m_mapped.turn, QColor(40, 120, 220));
    for (int i = 0; i < m_raw.size(); ++i)
        bar(i + 2, tr("axis %1").arg(i), m_raw[i], QColor(130, 130, 130));
}

} // namespace ocu
