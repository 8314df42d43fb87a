#pragma once
// Access-control panel: one row per discovered subsystem with monitor / control / release,
// who controls it, the access state in words and the row colours of the FKIE IOP panels; below it the
// details of the selected vehicle.
#include "models/commands/OperatorCommand.h"

#include <QJsonObject>
#include <QPointer>
#include <QWidget>

class QTableView;
class QPushButton;
class QLabel;
class QStackedWidget;
class QTimer;

namespace ocu {

class JausVehicleBridge;
class CommandGate;
class JausSubsystemModel;
class VehicleDetailsWidget;
class PlatformServicesWidget;
class FleetSelection;
class HandoffBanner;

class JausControlPanel : public QWidget {
    Q_OBJECT
public:
    // Control request/release go through the command gate (audited).
    JausControlPanel(JausVehicleBridge* bridge, CommandGate* gate, FleetSelection* selection,
                     QWidget* parent = nullptr);

    JausSubsystemModel* model() const { return m_model; }
    QTableView* table() const { return m_table; }
    VehicleDetailsWidget* details() const { return m_details; }
    // The selected vehicle's platform mode and state, odometer and comms-lost service, with their commands.
    PlatformServicesWidget* platformServices() const { return m_platform; }
    // Hand-off between consoles: requests to answer, our own request, asking for a held vehicle.
    HandoffBanner* handoff() const { return m_handoff; }
    // The action buttons of a row (for keyboard users and tests).
    QPushButton* controlButton(std::uint16_t subsystem) const;
    QPushButton* releaseButton(std::uint16_t subsystem) const;
    QPushButton* monitorButton(std::uint16_t subsystem) const;
    // What the details pane shows: the hint when nothing is selected, "jaus:<id>" for a JAUS vehicle (the
    // details widget), the machine's details text for a machine of any other protocol.
    QString detailsText() const;

private:
    void fitColumnsWithinWidth();
    void installRowButtons(int first, int last);
    void refreshButtons();
    void selectSubsystem(std::uint16_t subsystem);
    void showMachineDetails(const QString& id);

    void send(const OperatorCommand& command);
    JausVehicleBridge* m_bridge;
    QPointer<CommandGate> m_gate;
    FleetSelection* m_selection;
    JausSubsystemModel* m_model;
    QTableView* m_table;
    VehicleDetailsWidget* m_details;
    PlatformServicesWidget* m_platform = nullptr;
    HandoffBanner* m_handoff;
    QLabel* m_roleLabel;
    QPushButton* m_releaseAll;
    QStackedWidget* m_detailsStack;
    QLabel* m_hint;
    QLabel* m_generic;
    QTimer* m_detailsRefresh;
    QString m_detailsId;
    int m_actionsWidth = 0; // the row buttons' width
};

} // namespace ocu
