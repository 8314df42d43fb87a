#include "models/FleetContext.h"

#include "models/AlarmModel.h"
#include "models/FleetBridge.h"
#include "models/FleetModel.h"
#include "models/FleetSelection.h"
#include "models/HeadlessMonitor.h"
#include "models/StopController.h"

namespace ocu {

FleetContext::FleetContext(QObject* parent)
    : QObject(parent), m_fleet(new FleetModel(this)), m_selection(new FleetSelection(m_fleet, this)),
      m_alarms(new AlarmModel(this)), m_stop(new StopController(m_alarms, this)) {
    m_alarms->watchFleet(m_fleet);
}

void FleetContext::addBridge(FleetBridge* bridge) {
    if (!bridge)
        return;
    for (const auto& b : m_bridges)
        if (b == bridge)
            return;
    m_bridges.push_back(bridge);
    m_fleet->addBridge(bridge);
    m_alarms->addBridge(bridge);
    m_stop->addBridge(bridge);
    if (m_monitor)
        m_monitor->addBridge(bridge);
}

QVector<FleetBridge*> FleetContext::bridges() const {
    QVector<FleetBridge*> out;
    for (const auto& b : m_bridges)
        if (b)
            out.push_back(b.data());
    return out;
}

HeadlessMonitor* FleetContext::createHeadlessMonitor(QIODevice* out) {
    if (!m_monitor) {
        m_monitor = new HeadlessMonitor(m_fleet, m_alarms, m_stop, this);
        for (FleetBridge* b : bridges())
            m_monitor->addBridge(b);
    }
    if (out)
        m_monitor->setOutput(out);
    return m_monitor;
}

} // namespace ocu
