#include "widgets/OnScreenWatcher.h"

#include <QDockWidget>
#include <QEvent>
#include <QTimer>
#include <QWidget>

namespace ocu {

OnScreenWatcher::OnScreenWatcher(QWidget* widget)
    : QObject(widget), m_widget(widget), m_poll(new QTimer(this)) {
    widget->installEventFilter(this);
    // Going behind another dock tab comes with no event the widget sees, and visibilityChanged comes before
    // the region is gone: while on screen, look again four times a second (one region test).
    m_poll->setInterval(250);
    connect(m_poll, &QTimer::timeout, this, &OnScreenWatcher::evaluate);
    attachDock();
    evaluate();
}

bool OnScreenWatcher::eventFilter(QObject* watched, QEvent* event) {
    if (watched == m_widget) {
        switch (event->type()) {
        case QEvent::Hide:
            evaluate(); // hidden is hidden at once
            break;
        case QEvent::Show:
            evaluate();
            evaluateSoon(); // again once the layout has given it its region
            break;
        case QEvent::Paint: // painted: in front after all (a raised dock tab's region may come late)
        case QEvent::Resize:
            if (!m_onScreen)
                evaluateSoon();
            break;
        case QEvent::ParentChange:
            attachDock();
            evaluateSoon();
            break;
        default:
            break;
        }
    }
    return QObject::eventFilter(watched, event);
}

void OnScreenWatcher::attachDock() {
    QDockWidget* dock = nullptr;
    for (QWidget* w = m_widget->parentWidget(); w && !dock; w = w->parentWidget())
        dock = qobject_cast<QDockWidget*>(w);
    if (dock == m_dock)
        return;
    if (m_dock)
        disconnect(m_dock, nullptr, this, nullptr);
    m_dock = dock;
    if (m_dock)
        connect(m_dock, &QDockWidget::visibilityChanged, this, &OnScreenWatcher::evaluateSoon);
}

// After the event: a tab switch reports the new dock before the layout has given it its region.
void OnScreenWatcher::evaluateSoon() {
    if (m_pending)
        return;
    m_pending = true;
    QTimer::singleShot(0, this, [this] {
        m_pending = false;
        evaluate();
    });
}

void OnScreenWatcher::evaluate() {
    const bool on = m_widget->isVisible() && !m_widget->visibleRegion().isEmpty();
    if (on == m_onScreen)
        return;
    m_onScreen = on;
    if (on)
        m_poll->start();
    else
        m_poll->stop();
    emit changed(on);
}

} // namespace ocu
