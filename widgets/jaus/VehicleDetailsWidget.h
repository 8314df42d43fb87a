#pragma once
// Vehicle details: platform specifications, mode and state, platform services (mode, state, lights,
// odometer, comms-lost service), health, the services tree
// subsystem → node → component [s.n.c] → service URI and version, and the vehicle's last messages.
#include "models/jaus/JausVehicle.h"

#include <QWidget>

class QTreeWidget;
class QListWidget;
class QTreeWidgetItem;

namespace ocu {

class JausVehicleBridge;

class VehicleDetailsWidget : public QWidget {
    Q_OBJECT
public:
    explicit VehicleDetailsWidget(JausVehicleBridge* bridge, QWidget* parent = nullptr);
    void showSubsystem(std::uint16_t subsystem);
    std::uint16_t subsystem() const { return m_subsystem; }
    QTreeWidget* tree() const { return m_tree; }
    QListWidget* messages() const { return m_messages; }

private:
    void rebuild(const JausVehicle& s);
    static void addPlatformServices(QTreeWidgetItem* parent, const JausPlatformServices& p);
    JausVehicleBridge* m_bridge;
    std::uint16_t m_subsystem = 0;
    QTreeWidget* m_tree;
    QListWidget* m_messages;
};

} // namespace ocu
