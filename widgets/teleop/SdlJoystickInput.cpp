#include "widgets/teleop/SdlJoystickInput.h"

#include "widgets/teleop/SdlJoysticks.h"

#include <QTimer>

#include <SDL.h>

namespace ocu {

SdlJoystickInput::SdlJoystickInput(QObject* parent) : InputDevice(parent) {
    std::string error;
    if (!startSdlJoysticks(error)) {
        m_error = QString::fromStdString(error);
        return;
    }
    m_available = true;
    openFirst();
    m_timer = new QTimer(this);
    m_timer->setTimerType(Qt::PreciseTimer);
    connect(m_timer, &QTimer::timeout, this, &SdlJoystickInput::poll);
    m_timer->start(10); // 100 Hz: axis latency well under the 50 ms command period
}

SdlJoystickInput::~SdlJoystickInput() {
    close();
    if (m_available)
        stopSdlJoysticks();
}

QString SdlJoystickInput::name() const {
    return m_joystick ? m_name : tr("No joystick");
}

QStringList SdlJoystickInput::deviceNames() const {
    QStringList out;
    if (!m_available)
        return out;
    for (int i = 0; i < SDL_NumJoysticks(); ++i)
        out << QString::fromUtf8(SDL_JoystickNameForIndex(i));
    return out;
}

void SdlJoystickInput::openFirst() {
    if (m_joystick || SDL_NumJoysticks() <= 0)
        return;
    SDL_Joystick* j = SDL_JoystickOpen(0);
    if (!j)
        return;
    m_joystick = j;
    m_instanceId = SDL_JoystickInstanceID(j);
    m_name = QString::fromUtf8(SDL_JoystickName(j));
    m_raw = QVector<double>(SDL_JoystickNumAxes(j), 0.0);
    emit connectedChanged(true);
}

void SdlJoystickInput::close() {
    if (!m_joystick)
        return;
    SDL_JoystickClose(static_cast<SDL_Joystick*>(m_joystick));
    m_joystick = nullptr;
    m_instanceId = -1;
    m_axes = {};
    m_raw.clear();
    if (!m_hat.isNull()) {
        m_hat = {};
        emit hatChanged(m_hat);
    }
}

void SdlJoystickInput::poll() {
    SDL_Event ev;
    while (SDL_PollEvent(&ev)) {
        if (ev.type == SDL_JOYDEVICEADDED) {
            openFirst();
        } else if (ev.type == SDL_JOYDEVICEREMOVED && ev.jdevice.which == m_instanceId) {
            close();
            emit axesChanged(m_axes); // zero
            emit connectedChanged(false);
            openFirst(); // another device may still be plugged in
        }
    }
    if (!m_joystick)
        return;
    auto* j = static_cast<SDL_Joystick*>(m_joystick);
    if (!SDL_JoystickGetAttached(j)) {
        close();
        emit axesChanged(m_axes);
        emit connectedChanged(false);
        return;
    }
    QVector<double> raw(SDL_JoystickNumAxes(j));
    for (int i = 0; i < raw.size(); ++i)
        raw[i] = SDL_JoystickGetAxis(j, i) / 32767.0;
    if (raw != m_raw) {
        m_raw = raw;
        emit rawAxesChanged(m_raw);
    }
    if (SDL_JoystickNumHats(j) > 0) {
        const Uint8 h = SDL_JoystickGetHat(j, 0);
        const QPoint hat((h & SDL_HAT_RIGHT ? 1 : 0) - (h & SDL_HAT_LEFT ? 1 : 0),
                         (h & SDL_HAT_UP ? 1 : 0) - (h & SDL_HAT_DOWN ? 1 : 0));
        if (hat != m_hat) {
            m_hat = hat;
            emit hatChanged(hat);
        }
    }
    const DriveAxes a = mapAxes(raw, m_mapping);
    if (!(a == m_axes)) {
        m_axes = a;
        emit axesChanged(a);
    }
}

} // namespace ocu
