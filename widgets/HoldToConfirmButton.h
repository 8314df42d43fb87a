#pragma once
// A button that confirms only after being held down (mouse or Space) for a deliberate time; releasing
// early cancels. Used for releasing stops (anchors-features.md §8.3: apply is fast, clear is
// deliberate). Stopping itself uses plain buttons that never ask.
#include <QElapsedTimer>
#include <QPushButton>
#include <QTimer>

namespace ocu {

class HoldToConfirmButton : public QPushButton {
    Q_OBJECT
public:
    explicit HoldToConfirmButton(const QString& text, QWidget* parent = nullptr);

    void setHoldDurationMs(int ms) { m_holdMs = std::max(50, ms); }
    int holdDurationMs() const { return m_holdMs; }
    double progress() const; // 0..1 while held

signals:
    void confirmed();
    void cancelled();

protected:
    void paintEvent(QPaintEvent* e) override;

private:
    void onPressed();
    void onReleased();
    void onTick();

    int m_holdMs = 1500;
    QElapsedTimer m_held;
    QTimer m_tick;
    bool m_holding = false;
    bool m_done = false;
};

} // namespace ocu
