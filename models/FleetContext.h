#pragma once
// Convenience owner of the fleet picture's shared objects, so the app (GUI or headless) wires a bridge
// with one call: FleetModel, the one FleetSelection, AlarmModel (watching the fleet) and StopController
// (auditing into the alarm model). addBridge() connects a bridge to all of them (and to the headless
// monitor when one was created).
#include <QObject>
#include <QPointer>
#include <QVector>

class QIODevice;

namespace ocu {

class AlarmModel;
class FleetBridge;
class FleetModel;
class FleetSelection;
class HeadlessMonitor;
class StopController;

class FleetContext : public QObject {
    Q_OBJECT
public:
    explicit FleetContext(QObject* parent = nullptr);

    FleetModel* fleet() const { return m_fleet; }
    FleetSelection* selection() const { return m_selection; }
    AlarmModel* alarms() const { return m_alarms; }
    StopController* stop() const { return m_stop; }
    HeadlessMonitor* monitor() const { return m_monitor; }

    // Connects the bridge to the fleet model, the alarm model, the stop controller and the monitor.
    // The bridge is not owned.
    void addBridge(FleetBridge* bridge);
    QVector<FleetBridge*> bridges() const;

    // Creates the headless monitor (once); `out` = nullptr means stdout. Bridges added before and after
    // are connected to it.
    HeadlessMonitor* createHeadlessMonitor(QIODevice* out = nullptr);

private:
    FleetModel* m_fleet;
    FleetSelection* m_selection;
    AlarmModel* m_alarms;
    StopController* m_stop;
    HeadlessMonitor* m_monitor = nullptr;
    QVector<QPointer<FleetBridge>> m_bridges;
};

} // namespace ocu
