#pragma once
// Whether a widget is really in front of the operator: visible, and not inside a dock that is a tab behind
// another. Such a dock keeps isVisible() true and its widgets get no hide event (Qt 6.4); only
// QDockWidget::visibilityChanged and the empty visible region tell. Panels that cost something while shown
// (video decoding, teleop input) follow this instead of their show/hide events.
#include <QObject>
#include <QPointer>

class QDockWidget;
class QTimer;
class QWidget;

namespace ocu {

class OnScreenWatcher : public QObject {
    Q_OBJECT
public:
    explicit OnScreenWatcher(QWidget* widget);
    bool onScreen() const { return m_onScreen; }

signals:
    void changed(bool onScreen);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void attachDock();
    void evaluateSoon();
    void evaluate();

    QWidget* m_widget;
    QPointer<QDockWidget> m_dock;
    QTimer* m_poll;
    bool m_onScreen = false;
    bool m_pending = false;
};

} // namespace ocu
