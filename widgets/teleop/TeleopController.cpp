#include "widgets/teleop/TeleopController.h"

#include <QTimer>

#include <algorithm>

namespace ocu {

TeleopController::TeleopController(QObject* parent)
    : QObject(parent), m_timer(new QTimer(this)), m_deadManKey(Qt::Key_Shift) {
    m_timer->setTimerType(Qt::PreciseTimer);
    connect(m_timer, &QTimer::timeout, this, &TeleopController::tick);
    setRateHz(m_rateHz);
}

void TeleopController::setRateHz(double hz) {
    m_rateHz = std::clamp(hz, 1.0, 100.0);
    m_timer->start(static_cast<int>(1000.0 / m_rateHz));
}

void TeleopController::setSpeedLimit(double fraction) {
    m_limit = std::clamp(fraction, 0.0, 1.0);
}

void TeleopController::setEnabled(bool enabled) {
    if (m_enabled == enabled)
        return;
    m_enabled = enabled;
    if (!enabled)
        releaseAll(tr("control lost or disabled"));
}

void TeleopController::setDevice(InputDevice* device) {
    if (m_device)
        disconnect(m_device, nullptr, this, nullptr);
    m_device = device;
    if (!device)
        return;
    connect(device, &InputDevice::axesChanged, this, [this] { sendNow(tr("joystick released")); });
    connect(device, &InputDevice::connectedChanged, this, [this](bool connected) {
        if (!connected)
            sendNow(tr("joystick unplugged"));
    });
}

DriveAxes TeleopController::keyboardAxes() const {
    if (!m_keys.contains(m_deadManKey))
        return {};
    DriveAxes a;
    if (m_keys.contains(Qt::Key_W) || m_keys.contains(Qt::Key_Up))
        a.forward += 1;
    if (m_keys.contains(Qt::Key_S) || m_keys.contains(Qt::Key_Down))
        a.forward -= 1;
    if (m_keys.contains(Qt::Key_D) || m_keys.contains(Qt::Key_Right))
        a.turn += 1;
    if (m_keys.contains(Qt::Key_A) || m_keys.contains(Qt::Key_Left))
        a.turn -= 1;
    return a;
}

DriveAxes TeleopController::demand() const {
    if (!m_enabled)
        return {};
    DriveAxes raw;
    switch (activeSource()) {
    case Source::Device:
        raw = m_device->axes();
        break;
    case Source::Stick:
        raw = m_stick;
        break;
    case Source::Keyboard:
        raw = keyboardAxes();
        break;
    case Source::None:
        return {};
    }
    return {std::clamp(raw.forward, -1.0, 1.0) * m_limit, std::clamp(raw.turn, -1.0, 1.0) * m_limit};
}

TeleopController::Source TeleopController::activeSource() const {
    // A deflected physical device wins, then the on-screen stick, then the keyboard.
    if (m_device && m_device->isConnected() && !m_device->axes().isZero())
        return Source::Device;
    if (!m_stick.isZero())
        return Source::Stick;
    if (!keyboardAxes().isZero())
        return Source::Keyboard;
    return Source::None;
}

bool TeleopController::handleKey(int key, bool pressed, bool autoRepeat) {
    static const QSet<int> driving{Qt::Key_W,  Qt::Key_A,    Qt::Key_S,    Qt::Key_D,
                                   Qt::Key_Up, Qt::Key_Down, Qt::Key_Left, Qt::Key_Right};
    if (key != m_deadManKey && !driving.contains(key))
        return false;
    if (autoRepeat)
        return true;
    if (pressed)
        m_keys.insert(key);
    else
        m_keys.remove(key);
    sendNow(key == m_deadManKey ? tr("dead-man key released") : tr("keys released"));
    return true;
}

void TeleopController::setStick(DriveAxes axes) {
    m_stick = axes;
    sendNow(tr("stick released"));
}

void TeleopController::releaseAll(const QString& reason) {
    m_keys.clear();
    m_stick = {};
    if (!m_lastSent.isZero() || m_zeroRemaining > 0) {
        m_lastSent = {};
        m_zeroRemaining = kZeroRepeats;
        emit command({});
        emit stopped(reason);
    }
}

void TeleopController::sendNow(const QString& reasonIfZero) {
    const Source s = activeSource();
    if (s != m_source) {
        m_source = s;
        emit sourceChanged(s);
    }
    const DriveAxes d = demand();
    if (d == m_lastSent)
        return;
    const bool wasDriving = !m_lastSent.isZero();
    m_lastSent = d;
    m_zeroRemaining = kZeroRepeats;
    emit command(d); // changes go out at once, not at the next tick
    if (d.isZero() && wasDriving)
        emit stopped(reasonIfZero);
}

void TeleopController::tick() {
    const DriveAxes d = demand();
    if (!d.isZero() || !(d == m_lastSent)) {
        const bool wasDriving = !m_lastSent.isZero();
        m_lastSent = d;
        m_zeroRemaining = kZeroRepeats;
        emit command(d);
        if (d.isZero() && wasDriving)
            emit stopped(tr("input released"));
        return;
    }
    if (m_zeroRemaining > 0) {
        --m_zeroRemaining;
        emit command({});
    }
}

} // namespace ocu
