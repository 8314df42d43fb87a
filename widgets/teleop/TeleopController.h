#pragma once
// Turns keyboard, on-screen stick and joystick input into a stream of drive demands at a fixed rate.
// Safety rules (DEVELOPERS.md, AEP-4818 drive timeout): a demand is repeated every period while it lasts
// (the vehicle stops by itself when the stream stops); on release, focus loss or device loss a zero is
// sent at once and then repeated several periods, never relying on a single message.
#include "widgets/teleop/InputDevice.h"

#include <QObject>
#include <QPointer>
#include <QSet>

class QTimer;

namespace ocu {

class TeleopController : public QObject {
    Q_OBJECT
public:
    enum class Source { None, Keyboard, Stick, Device };
    Q_ENUM(Source)
    static constexpr int kZeroRepeats = 5;

    explicit TeleopController(QObject* parent = nullptr);

    void setRateHz(double hz);
    double rateHz() const { return m_rateHz; }
    // Fraction of full demand (0..1) the operator allows, within the platform's limits.
    void setSpeedLimit(double fraction);
    double speedLimit() const { return m_limit; }
    // Driving is possible only while enabled (this console controls the vehicle, no emergency).
    // Disabling stops at once.
    void setEnabled(bool enabled);
    bool isEnabled() const { return m_enabled; }

    void setDevice(InputDevice* device);
    InputDevice* device() const { return m_device; }
    void setDeadManKey(int key) { m_deadManKey = key; }
    int deadManKey() const { return m_deadManKey; }

    // Keyboard: returns true when the key belongs to driving (W/A/S/D, arrows, dead-man).
    bool handleKey(int key, bool pressed, bool autoRepeat = false);
    void setStick(DriveAxes axes);
    // Focus loss, panel hidden, vehicle changed: forget every held input and stop.
    void releaseAll(const QString& reason);

    DriveAxes demand() const;
    Source activeSource() const;
    bool isDriving() const { return !m_lastSent.isZero(); }

signals:
    // Emitted every period while driving and kZeroRepeats times after a stop; axes scaled by the limit.
    void command(ocu::DriveAxes axes);
    void stopped(const QString& reason);
    void sourceChanged(ocu::TeleopController::Source source);

private:
    void tick();
    void sendNow(const QString& reasonIfZero);
    DriveAxes keyboardAxes() const;

    QTimer* m_timer;
    double m_rateHz = 20;
    double m_limit = 0.5;
    bool m_enabled = false;
    QPointer<InputDevice> m_device;
    int m_deadManKey;
    QSet<int> m_keys;
    DriveAxes m_stick;
    DriveAxes m_lastSent;
    int m_zeroRemaining = 0;
    Source m_source = Source::None;
};

} // namespace ocu
