#include "widgets/teleop/PanTiltController.h"

#include <QTimer>

#include <algorithm>

namespace ocu {

PanTiltController::PanTiltController(QObject* parent) : QObject(parent), m_timer(new QTimer(this)) {
    connect(m_timer, &QTimer::timeout, this, &PanTiltController::tick);
    setRateHz(10);
}

void PanTiltController::setRateHz(double hz) {
    m_timer->start(static_cast<int>(1000.0 / std::clamp(hz, 1.0, 50.0)));
}

void PanTiltController::setEnabled(bool enabled) {
    if (enabled == m_enabled)
        return;
    m_enabled = enabled;
    if (!enabled)
        releaseAll(tr("camera control disabled"));
}

void PanTiltController::setDevice(InputDevice* device) {
    if (m_device)
        disconnect(m_device, nullptr, this, nullptr);
    m_device = device;
    if (!device)
        return;
    connect(device, &InputDevice::hatChanged, this, [this] { sendNow(tr("hat released")); });
    connect(device, &InputDevice::connectedChanged, this, [this](bool connected) {
        if (!connected)
            sendNow(tr("joystick unplugged"));
    });
}

bool PanTiltController::handleKey(int key, bool pressed, bool autoRepeat) {
    if (key != Qt::Key_J && key != Qt::Key_L && key != Qt::Key_I && key != Qt::Key_K)
        return false;
    if (autoRepeat)
        return true;
    if (pressed)
        m_keys.insert(key);
    else
        m_keys.remove(key);
    sendNow(tr("keys released"));
    return true;
}

void PanTiltController::setStick(DriveAxes axes) {
    m_stick = axes;
    sendNow(tr("stick released"));
}

void PanTiltController::releaseAll(const QString& reason) {
    m_keys.clear();
    m_stick = {};
    if (!m_lastSent.isZero() || m_zeroRemaining > 0) {
        m_lastSent = {};
        m_zeroRemaining = kZeroRepeats;
        emit command(0, 0);
        emit stopped(reason);
    }
}

PanTiltRates PanTiltController::demand() const {
    if (!m_enabled)
        return {};
    PanTiltRates r;
    if (m_device && m_device->isConnected() && !m_device->hat().isNull()) {
        r.pan = m_device->hat().x() * m_keyRate;
        r.tilt = m_device->hat().y() * m_keyRate;
    } else if (!m_stick.isZero()) {
        r.pan = m_stick.turn;
        r.tilt = m_stick.forward;
    } else {
        r.pan = ((m_keys.contains(Qt::Key_L) ? 1 : 0) - (m_keys.contains(Qt::Key_J) ? 1 : 0)) * m_keyRate;
        r.tilt = ((m_keys.contains(Qt::Key_I) ? 1 : 0) - (m_keys.contains(Qt::Key_K) ? 1 : 0)) * m_keyRate;
    }
    r.pan = std::clamp(r.pan, -1.0, 1.0);
    r.tilt = std::clamp(r.tilt, -1.0, 1.0);
    return r;
}

void PanTiltController::sendNow(const QString& reasonIfZero) {
    const PanTiltRates d = demand();
    if (d == m_lastSent)
        return;
    const bool wasMoving = !m_lastSent.isZero();
    m_lastSent = d;
    m_zeroRemaining = kZeroRepeats;
    emit command(d.pan, d.tilt);
    if (d.isZero() && wasMoving)
        emit stopped(reasonIfZero);
}

void PanTiltController::tick() {
    const PanTiltRates d = demand();
    if (!d.isZero() || !(d == m_lastSent)) {
        const bool wasMoving = !m_lastSent.isZero();
        m_lastSent = d;
        m_zeroRemaining = kZeroRepeats;
        emit command(d.pan, d.tilt);
        if (d.isZero() && wasMoving)
            emit stopped(tr("input released"));
        return;
    }
    if (m_zeroRemaining > 0) {
        --m_zeroRemaining;
        emit command(0, 0);
    }
}

} // namespace ocu
