#pragma once
// Pan-tilt of a vehicle's camera from the keyboard (J/L pan, I/K tilt), the on-screen stick in its camera
// mode and a joystick hat, as a stream of rate demands (-1..1 of the sensor's rates) like the
// drive stream: a change goes out at once, a demand is repeated every period while it lasts, and on
// release, focus loss or device loss a zero goes out at once and is repeated a few periods.
#include "widgets/teleop/InputDevice.h"

#include <QObject>
#include <QPoint>
#include <QPointer>
#include <QSet>

class QTimer;

namespace ocu {

struct PanTiltRates {
    double pan = 0;  // +1 full rate right
    double tilt = 0; // +1 full rate up
    bool isZero() const { return pan == 0 && tilt == 0; }
    bool operator==(const PanTiltRates&) const = default;
};

class PanTiltController : public QObject {
    Q_OBJECT
public:
    static constexpr int kZeroRepeats = 3;
    explicit PanTiltController(QObject* parent = nullptr);

    void setRateHz(double hz);
    // Off (no camera with pan-tilt, no control of the vehicle): stops at once.
    void setEnabled(bool enabled);
    bool isEnabled() const { return m_enabled; }
    // Fraction of the full rate the keyboard and hat give (the stick gives its deflection).
    void setKeyRate(double fraction) { m_keyRate = fraction; }

    void setDevice(InputDevice* device); // its hat
    bool handleKey(int key, bool pressed, bool autoRepeat = false);
    // The on-screen stick in camera mode: turn -> pan, forward -> tilt.
    void setStick(DriveAxes axes);
    void releaseAll(const QString& reason);

    PanTiltRates demand() const;

signals:
    void command(double pan, double tilt);
    void stopped(const QString& reason);

private:
    void sendNow(const QString& reasonIfZero);
    void tick();

    QTimer* m_timer;
    bool m_enabled = false;
    double m_keyRate = 0.5;
    QPointer<InputDevice> m_device;
    QSet<int> m_keys;
    DriveAxes m_stick;
    PanTiltRates m_lastSent;
    int m_zeroRemaining = 0;
};

} // namespace ocu
