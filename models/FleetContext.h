#pragma once
// Convenience owner of the fleet picture's shared objects, so the app (GUI or headless) wires a bridge
// with one call: FleetModel, the one FleetSelection, AlarmModel (watching the fleet) and CommandGate
// (auditing into the alarm model). addBridge() connects a bridge to all of them and announces it
// (bridgeAdded) to front ends such as the headless monitor.
#include <QObject>
#include <QPointer>
#include <QVector>

namespace ocu {

class AlarmModel;
class FleetBridge;
class FleetModel;
class FleetSelection;
class CommandGate;

class FleetContext : public QObject {
    Q_OBJECT
public:
    explicit FleetContext(QObject* parent = nullptr);

    FleetModel* fleet() const { return m_fleet; }
    FleetSelection* selection() const { return m_selection; }
    AlarmModel* alarms() const { return m_alarms; }
    CommandGate* gate() const { return m_gate; }

    // Connects the bridge to the fleet model, the alarm model and the command gate, then emits
    // bridgeAdded. The bridge is not owned.
    void addBridge(FleetBridge* bridge);
    QVector<FleetBridge*> bridges() const;

signals:
    void bridgeAdded(ocu::FleetBridge* bridge);

private:
    FleetModel* m_fleet;
    FleetSelection* m_selection;
    AlarmModel* m_alarms;
    CommandGate* m_gate;
    QVector<QPointer<FleetBridge>> m_bridges;
};

} // namespace ocu
