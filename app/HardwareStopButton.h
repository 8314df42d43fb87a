#pragma once
// STOP ALL from a gamepad or USB button (site configuration `stop_button`): the press sends the stops from
// the button's own thread through CommandGate::stopAllEarly, then the gate's thread records it as one STOP
// ALL of origin "stop_button". Its device coming and going is an operator-visible event and a status-bar
// lamp.

#include <QObject>
#include <QString>

#include <memory>
#include <string>

namespace ocu {

class AlarmModel;
class CommandGate;
class JoystickStopButton;

class HardwareStopButton : public QObject {
    Q_OBJECT
public:
    // `gate` and `alarms` must outlive this object; the bridges must stay up until it is destroyed.
    HardwareStopButton(const std::string& device, int button, CommandGate* gate, AlarmModel* alarms,
                       QObject* parent = nullptr);
    ~HardwareStopButton() override; // joins the button's thread

    bool connected() const { return m_connected; }
    QString deviceName() const { return m_device; }
    // What the button is, for the status bar: "button 3 of any device", "button 0 of \"Big red\"".
    QString description() const;

signals:
    void connectionChanged(bool connected, const QString& device);

private:
    void onConnection(bool connected, const QString& device);

    CommandGate* m_gate;
    AlarmModel* m_alarms;
    std::string m_wanted;
    int m_button;
    bool m_connected = false;
    QString m_device;
    std::unique_ptr<JoystickStopButton> m_watcher;
};

} // namespace ocu
