#pragma once
// Input devices for teleoperation behind one abstraction, so the teleop logic is tested with a fake
// device and the application uses SDL2 game controllers and joysticks.
#include <QObject>
#include <QString>

namespace ocu {

// Normalised driving demand. forward: +1 full ahead, -1 full astern. turn: +1 full right, -1 full left
// (AS6009/JAUS convention: +X forward, positive rotation about the down axis = right turn).
struct DriveAxes {
    double forward = 0;
    double turn = 0;
    bool isZero() const { return forward == 0 && turn == 0; }
    bool operator==(const DriveAxes&) const = default;
};

class InputDevice : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;
    virtual QString name() const = 0;
    virtual bool isConnected() const = 0;
    virtual DriveAxes axes() const = 0;

signals:
    void axesChanged(ocu::DriveAxes axes);
    // false = unplugged or lost: the teleop controller stops the vehicle at once.
    void connectedChanged(bool connected);
};

// A device driven by tests (and by scripted demos): set axes, plug, unplug.
class FakeInputDevice : public InputDevice {
    Q_OBJECT
public:
    explicit FakeInputDevice(QString name = QStringLiteral("Fake joystick"), QObject* parent = nullptr)
        : InputDevice(parent), m_name(std::move(name)) {}
    QString name() const override { return m_name; }
    bool isConnected() const override { return m_connected; }
    DriveAxes axes() const override { return m_axes; }

    void setAxes(DriveAxes a) {
        m_axes = a;
        emit axesChanged(a);
    }
    void plug() {
        m_connected = true;
        emit connectedChanged(true);
    }
    void unplug() {
        m_connected = false;
        m_axes = {};
        emit connectedChanged(false);
    }

private:
    QString m_name;
    bool m_connected = true;
    DriveAxes m_axes;
};

// Applies a dead zone and rescales the rest of the travel to 0..1, so small stick drift sends nothing
// and full deflection still reaches 1.
inline double applyDeadZone(double v, double deadZone) {
    if (deadZone <= 0)
        return v;
    const double a = v < 0 ? -v : v;
    if (a <= deadZone)
        return 0;
    const double s = (a - deadZone) / (1.0 - deadZone);
    return v < 0 ? -s : s;
}

} // namespace ocu

Q_DECLARE_METATYPE(ocu::DriveAxes)
