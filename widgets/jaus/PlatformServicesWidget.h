#pragma once
// The selected vehicle's platform services in the JAUS control panel (AEP-4818 §6.2.5, §6.2.6, §5.7,
// §8.8): its platform mode and state as it reports them, with the commands it allows (a mode it supports,
// the emergency state at once, every other state after the operator confirms), its odometer and trip with
// "Reset trip", and whether it offers a comms-lost policy service (and which version; setting a policy
// waits for a published message layout). Commands go through the command gate (audited, per target).
#include "models/commands/OperatorCommand.h"
#include "models/jaus/JausVehicle.h"

#include <QPointer>
#include <QWidget>

#include <functional>

class QComboBox;
class QLabel;
class QPushButton;

namespace ocu {

class JausVehicleBridge;
class CommandGate;

class PlatformServicesWidget : public QWidget {
    Q_OBJECT
public:
    PlatformServicesWidget(JausVehicleBridge* bridge, CommandGate* gate, QWidget* parent = nullptr);

    void setVehicle(quint16 subsystem); // 0: nothing shown
    quint16 vehicle() const { return m_subsystem; }
    // Asks the operator before a dangerous command; the default is a modal question (tests replace it).
    using Confirm = std::function<bool(const QString& question)>;
    void setConfirm(Confirm confirm) { m_confirm = std::move(confirm); }

    QLabel* modeLabel() const { return m_mode; }
    QLabel* stateLabel() const { return m_state; }
    QLabel* odometerLabel() const { return m_odometer; }
    QLabel* commsLostLabel() const { return m_commsLost; }
    QComboBox* modeChoice() const { return m_modeChoice; }
    QComboBox* stateChoice() const { return m_stateChoice; }
    QPushButton* setModeButton() const { return m_setMode; }
    QPushButton* setStateButton() const { return m_setState; }
    QPushButton* emergencyButton() const { return m_emergency; }
    QPushButton* resetTripButton() const { return m_resetTrip; }

private:
    void refresh();
    void send(const OperatorCommand& command);
    void commandState(int state);
    JausVehicleBridge* m_bridge;
    QPointer<CommandGate> m_gate;
    Confirm m_confirm;
    quint16 m_subsystem = 0;
    QLabel* m_mode;
    QLabel* m_state;
    QLabel* m_odometer;
    QLabel* m_commsLost;
    QComboBox* m_modeChoice;
    QComboBox* m_stateChoice;
    QPushButton* m_setMode;
    QPushButton* m_setState;
    QPushButton* m_emergency;
    QPushButton* m_resetTrip;
};

} // namespace ocu
