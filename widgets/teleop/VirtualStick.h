#pragma once
// On-screen stick for mouse and touch: drag the knob; releasing it springs back to the centre and
// drives zero.
#include "widgets/teleop/InputDevice.h"

#include <QWidget>

namespace ocu {

class VirtualStick : public QWidget {
    Q_OBJECT
public:
    explicit VirtualStick(QWidget* parent = nullptr);
    DriveAxes axes() const { return m_axes; }
    // Beside the drive settings in a laptop's side column; it grows where there is room.
    QSize sizeHint() const override { return {160, 160}; }
    QSize minimumSizeHint() const override { return {120, 120}; }
    // Pixel position of a demand (for tests and for drawing).
    QPointF pointFor(DriveAxes a) const;

signals:
    void axesChanged(ocu::DriveAxes axes);

protected:
    void paintEvent(QPaintEvent*) override;
    void mousePressEvent(QMouseEvent*) override;
    void mouseMoveEvent(QMouseEvent*) override;
    void mouseReleaseEvent(QMouseEvent*) override;
    bool event(QEvent*) override;
    void hideEvent(QHideEvent*) override;

private:
    void moveTo(QPointF p);
    void release();
    double radius() const;
    DriveAxes m_axes;
    bool m_dragging = false;
};

// Live display of a device's raw axes (bars), for checking the mapping and the dead zone.
class AxisDisplay : public QWidget {
    Q_OBJECT
public:
    explicit AxisDisplay(QWidget* parent = nullptr);
    void setAxes(const QVector<double>& raw);
    void setMapped(DriveAxes a);
    // A bar a row: the demand's two, then the device's axes (thinner); no room taken for a device not there.
    QSize sizeHint() const override { return {220, 2 * 18 + int(m_raw.size()) * 10}; }

protected:
    void paintEvent(QPaintEvent*) override;

private:
    QVector<double> m_raw;
    DriveAxes m_mapped;
};

} // namespace ocu
