#pragma once
// Game controllers and joysticks through SDL2: hot-plug, axis mapping, dead zone. Polled on the GUI
// thread by a timer (SDL's joystick subsystem needs no window).
#include "widgets/teleop/InputDevice.h"

#include <QStringList>

class QTimer;

namespace ocu {

class SdlJoystickInput : public InputDevice {
    Q_OBJECT
public:
    explicit SdlJoystickInput(QObject* parent = nullptr);
    ~SdlJoystickInput() override;

    // False when SDL's joystick subsystem could not start; errorString() says why.
    bool available() const { return m_available; }
    QString errorString() const { return m_error; }

    QString name() const override;
    bool isConnected() const override { return m_joystick != nullptr; }
    DriveAxes axes() const override { return m_axes; }
    QStringList deviceNames() const;
    // Raw axis values (-1..1) of the open device, for the live axis display.
    QVector<double> rawAxes() const override { return m_raw; }
    bool supportsMapping() const override { return true; }
    AxisMapping mapping() const override { return m_mapping; }
    void setMapping(const AxisMapping& m) override { m_mapping = m; }
    QPoint hat() const override { return m_hat; }

private:
    void poll();
    void openFirst();
    void close();

    bool m_available = false;
    QString m_error;
    void* m_joystick = nullptr; // SDL_Joystick*
    int m_instanceId = -1;
    QString m_name;
    AxisMapping m_mapping;
    DriveAxes m_axes;
    QVector<double> m_raw;
    QPoint m_hat;
    QTimer* m_timer = nullptr;
};

} // namespace ocu
