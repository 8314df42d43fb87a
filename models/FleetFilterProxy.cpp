#include "models/FleetFilterProxy.h"

#include "models/FleetModel.h"

namespace ocu {

FleetFilterProxy::FleetFilterProxy(QObject* parent) : QSortFilterProxyModel(parent) {
    setSortRole(FleetModel::RawRole);
    setDynamicSortFilter(true);
}

void FleetFilterProxy::setText(const QString& text) {
    m_text = text.trimmed();
    invalidateFilter();
}

void FleetFilterProxy::setProtocols(const QSet<Protocol>& protocols) {
    m_protocols = protocols;
    invalidateFilter();
}

void FleetFilterProxy::setStatuses(const QSet<StatusCategory>& statuses) {
    m_statuses = statuses;
    invalidateFilter();
}

bool FleetFilterProxy::filterAcceptsRow(int sourceRow, const QModelIndex& sourceParent) const {
    auto* fleet = qobject_cast<FleetModel*>(sourceModel());
    if (!fleet || sourceParent.isValid())
        return true;
    const MachineState& m = fleet->machineAt(sourceRow);
    if (!m_protocols.isEmpty() && !m_protocols.contains(m.protocol))
        return false;
    if (!m_statuses.isEmpty() && !m_statuses.contains(fleet->statusAt(sourceRow)))
        return false;
    if (m_text.isEmpty())
        return true;
    const Qt::CaseSensitivity cs = Qt::CaseInsensitive;
    return m.id.contains(m_text, cs) || m.name.contains(m_text, cs) || m.type.contains(m_text, cs) ||
           m.modeText.contains(m_text, cs) || m.controller.contains(m_text, cs) ||
           m.healthText.contains(m_text, cs);
}

} // namespace ocu
