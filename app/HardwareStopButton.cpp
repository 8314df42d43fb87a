#include "app/HardwareStopButton.h"

#include "models/AlarmModel.h"
#include "models/CommandGate.h"
#include "models/FleetEvent.h"
#include "widgets/teleop/JoystickStopButton.h"

#include <QMetaObject>
#include <QPointer>

namespace ocu {

HardwareStopButton::HardwareStopButton(const std::string& device, int button, CommandGate* gate,
                                       AlarmModel* alarms, QObject* parent)
    : QObject(parent), m_gate(gate), m_alarms(alarms), m_wanted(device), m_button(button) {
    JoystickStopButton::Callbacks cb;
    cb.pressed = [this](const std::string&) {
        // The stops leave from this thread now; the gate's thread then audits and reports them. The gate
        // outlives this object, whose destructor joins this thread first.
        CommandGate* gate = m_gate;
        auto early = gate->stopAllEarly();
        QMetaObject::invokeMethod(
            gate, [gate, early] { gate->stopAll(QStringLiteral("stop_button"), {}, early); },
            Qt::QueuedConnection);
    };
    cb.connection = [this](bool up, const std::string& name) {
        QPointer<HardwareStopButton> self(this);
        const QString n = QString::fromStdString(name);
        QMetaObject::invokeMethod(
            this,
            [self, up, n] {
                if (self)
                    self->onConnection(up, n);
            },
            Qt::QueuedConnection);
    };
    m_watcher = std::make_unique<JoystickStopButton>(JoystickStopButton::Options{device, button, 2}, cb);
    if (!m_watcher->available() && m_alarms)
        m_alarms->add(makeEvent(EventSeverity::Alarm, EventKind::Info, {},
                                tr("STOP button unavailable: the joystick subsystem did not start (%1)")
                                    .arg(QString::fromStdString(m_watcher->error())),
                                QStringLiteral("stop_button")));
}

HardwareStopButton::~HardwareStopButton() = default;

QString HardwareStopButton::description() const {
    return m_wanted.empty() ? tr("button %1 of any joystick").arg(m_button)
                            : tr("button %1 of \"%2\"").arg(m_button).arg(QString::fromStdString(m_wanted));
}

void HardwareStopButton::onConnection(bool connected, const QString& device) {
    m_connected = connected;
    m_device = connected ? device : QString();
    if (m_alarms) {
        // Losing the hardware stop is a condition to act on; its return is information.
        m_alarms->add(connected ? makeEvent(EventSeverity::Info, EventKind::Info, {},
                                            tr("STOP button connected: %1 (%2)").arg(device, description()),
                                            QStringLiteral("stop_button"))
                                : makeEvent(EventSeverity::Warning, EventKind::Info, {},
                                            tr("STOP button disconnected: %1; STOP ALL stays available "
                                               "on the console")
                                                .arg(device),
                                            QStringLiteral("stop_button")));
    }
    emit connectionChanged(connected, device);
}

} // namespace ocu
