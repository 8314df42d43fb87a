#include "models/FleetContext.h"

#include "models/AlarmModel.h"
#include "models/CommandGate.h"
#include "models/FleetBridge.h"
#include "models/FleetModel.h"
#include "models/FleetSelection.h"

namespace ocu {

FleetContext::FleetContext(QObject* parent)
    : QObject(parent), m_fleet(new FleetModel(this)), m_selection(new FleetSelection(m_fleet, this)),
      m_alarms(new AlarmModel(this)), m_gate(new CommandGate(m_alarms, this)) {
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
    m_gate->addBridge(bridge);
    emit bridgeAdded(bridge);
}

QVector<FleetBridge*> FleetContext::bridges() const {
    QVector<FleetBridge*> out;
    for (const auto& b : m_bridges)
        if (b)
            out.push_back(b.data());
    return out;
}

} // namespace ocu
