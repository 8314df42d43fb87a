#pragma once
// Input devices for teleoperation behind one abstraction, so the teleop logic is tested with a fake
// device and the application uses SDL2 game controllers and joysticks.
#include <QObject>
#include <QPoint>
#include <QString>
#include <QVector>

#include <algorithm>
#include <optional>

namespace ocu {

// Normalised driving demand. forward: +1 full ahead, -1 full astern. turn: +1 full right, -1 full left
// (AS6009/JAUS convention: +X forward, positive rotation about the down axis = right turn).
struct DriveAxes {
    double forward = 0;
    double turn = 0;
    bool isZero() const { return forward == 0 && turn == 0; }
    bool operator==(const DriveAxes&) const = default;
};

// Which raw axis drives what, and the dead zone (site configuration `teleop.joystick`, or the operator's
// mapping dialog).
struct AxisMapping {
    int forwardAxis = 1;       // SDL axis index (game controller: left stick Y)
    int turnAxis = 0;          // left stick X
    bool invertForward = true; // stick pushed away reads negative in SDL
    bool invertTurn = false;
    double deadZone = 0.12;
    bool operator==(const AxisMapping&) const = default;
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

// Raw axes (-1..1) through a mapping; an axis the device does not have reads 0.
inline DriveAxes mapAxes(const QVector<double>& raw, const AxisMapping& m) {
    auto axis = [&](int idx, bool invert) {
        if (idx < 0 || idx >= raw.size())
            return 0.0;
        const double v = std::clamp(raw[idx], -1.0, 1.0);
        return applyDeadZone(invert ? -v : v, m.deadZone);
    };
    return {axis(m.forwardAxis, m.invertForward), axis(m.turnAxis, m.invertTurn)};
}

// "Move the stick now" detection: the axis that travelled furthest from its rest value, at least minTravel;
// negative says the movement read negative (so that direction needs inverting).
struct DetectedAxis {
    int index = -1;
    bool negative = false;
};
inline std::optional<DetectedAxis> detectAxis(const QVector<double>& rest, const QVector<double>& now,
                                              double minTravel = 0.5) {
    std::optional<DetectedAxis> best;
    double bestTravel = minTravel;
    for (int i = 0; i < now.size(); ++i) {
        const double travel = now[i] - (i < rest.size() ? rest[i] : 0.0);
        const double a = travel < 0 ? -travel : travel;
        if (a >= bestTravel) {
            bestTravel = a;
            best = DetectedAxis{i, travel < 0};
        }
    }
    return best;
}

class InputDevice : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;
    virtual QString name() const = 0;
    virtual bool isConnected() const = 0;
    virtual DriveAxes axes() const = 0;
    // Devices with raw axes can be re-mapped by the operator; the others return nothing and ignore it.
    virtual QVector<double> rawAxes() const { return {}; }
    virtual bool supportsMapping() const { return false; }
    virtual AxisMapping mapping() const { return {}; }
    virtual void setMapping(const AxisMapping& m) { (void)m; }
    // The first hat (POV switch) as x -1 left .. +1 right, y -1 down .. +1 up; (0,0) centred or none. It
    // drives the camera's pan-tilt.
    virtual QPoint hat() const { return {}; }

signals:
    void axesChanged(ocu::DriveAxes axes);
    void rawAxesChanged(const QVector<double>& raw);
    // false = unplugged or lost: the teleop controller stops the vehicle at once.
    void connectedChanged(bool connected);
    void hatChanged(QPoint hat);
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
    // Raw stick values, mapped like a real joystick.
    void setRaw(const QVector<double>& raw) {
        m_raw = raw;
        emit rawAxesChanged(raw);
        setAxes(mapAxes(raw, m_mapping));
    }
    QVector<double> rawAxes() const override { return m_raw; }
    bool supportsMapping() const override { return true; }
    AxisMapping mapping() const override { return m_mapping; }
    void setMapping(const AxisMapping& m) override { m_mapping = m; }
    QPoint hat() const override { return m_hat; }
    void setHat(QPoint h) {
        m_hat = h;
        emit hatChanged(h);
    }
    void plug() {
        m_connected = true;
        emit connectedChanged(true);
    }
    void unplug() {
        m_connected = false;
        m_axes = {};
        m_hat = {};
        emit connectedChanged(false);
    }

private:
    QString m_name;
    bool m_connected = true;
    DriveAxes m_axes;
    QVector<double> m_raw;
    AxisMapping m_mapping;
    QPoint m_hat;
};

} // namespace ocu

Q_DECLARE_METATYPE(ocu::DriveAxes)
