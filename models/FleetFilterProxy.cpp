#include "models/FleetFilterProxy.h"

#include "models/FleetModel.h"

#include <algorithm>
#include <climits>

namespace ocu {

FleetFilterProxy::FleetFilterProxy(QObject* parent) : QSortFilterProxyModel(parent) {
    setSortRole(FleetModel::RawRole);
    setDynamicSortFilter(true);
    m_changeTimer.setSingleShot(true);
    connect(&m_changeTimer, &QTimer::timeout, this, &FleetFilterProxy::flushChanges);
}

// ---- Throttled data changes ----

void FleetFilterProxy::setChangeIntervalMs(int ms) {
    m_changeIntervalMs = std::max(0, ms);
    if (m_changeIntervalMs == 0)
        flushChanges();
    reroute();
}

void FleetFilterProxy::setSourceModel(QAbstractItemModel* source) {
    if (source == sourceModel())
        return; // QSortFilterProxyModel keeps its connections too
    m_top = -1; // pending changes were of the old source
    m_changeTimer.stop();
    for (const auto& c : std::as_const(m_throttleConnections))
        disconnect(c);
    m_throttleConnections.clear();
    m_rerouted = false;
    QSortFilterProxyModel::setSourceModel(source);
    reroute();
}

void FleetFilterProxy::reroute() {
    QAbstractItemModel* src = sourceModel();
    if (!src || m_rerouted || m_changeIntervalMs == 0)
        return;
    // QSortFilterProxyModel (Qt 6.4) handles dataChanged in a private slot connected by name; it is taken off
    // the source's signal and fed the merged changes by flushChanges().
    if (!disconnect(src, SIGNAL(dataChanged(QModelIndex, QModelIndex, QList<int>)), this,
                    SLOT(_q_sourceDataChanged(QModelIndex, QModelIndex, QList<int>)))) {
        qWarning("FleetFilterProxy: cannot throttle data changes with this Qt; they pass at once");
        return;
    }
    m_rerouted = true;
    m_throttleConnections << connect(src, &QAbstractItemModel::dataChanged, this,
                                     &FleetFilterProxy::onSourceDataChanged);
    // Rows inserted or removed shift the pending rows: widen them to the end (clipped at the flush).
    auto widen = [this](const QModelIndex& parent, int first, int) {
        if (m_top >= 0 && !parent.isValid()) {
            m_top = std::min(m_top, first);
            m_bottom = INT_MAX;
        }
    };
    m_throttleConnections << connect(src, &QAbstractItemModel::rowsInserted, this, widen);
    m_throttleConnections << connect(src, &QAbstractItemModel::rowsRemoved, this, widen);
    m_throttleConnections << connect(src, &QAbstractItemModel::layoutChanged, this, [this] {
        if (m_top >= 0) {
            m_top = 0;
            m_bottom = INT_MAX;
        }
    });
    m_throttleConnections << connect(src, &QAbstractItemModel::modelReset, this, [this] { m_top = -1; });
}

void FleetFilterProxy::onSourceDataChanged(const QModelIndex& topLeft, const QModelIndex& bottomRight,
                                           const QList<int>& roles) {
    if (!topLeft.isValid() || !bottomRight.isValid() || topLeft.parent().isValid())
        return; // a flat table; nothing else is shown
    if (m_top < 0) {
        m_top = topLeft.row();
        m_bottom = bottomRight.row();
        m_left = topLeft.column();
        m_right = bottomRight.column();
        m_roles = roles;
        m_allRoles = roles.isEmpty();
    } else {
        m_top = std::min(m_top, topLeft.row());
        m_bottom = std::max(m_bottom, bottomRight.row());
        m_left = std::min(m_left, topLeft.column());
        m_right = std::max(m_right, bottomRight.column());
        if (roles.isEmpty())
            m_allRoles = true;
        else if (!m_allRoles)
            for (int r : roles)
                if (!m_roles.contains(r))
                    m_roles.push_back(r);
    }
    if (m_changeIntervalMs == 0)
        flushChanges(); // the interval was set back to 0 after the source was taken over
    else if (!m_changeTimer.isActive())
        m_changeTimer.start(m_changeIntervalMs);
}

void FleetFilterProxy::flushChanges() {
    m_changeTimer.stop();
    QAbstractItemModel* src = sourceModel();
    if (m_top < 0 || !src || !m_rerouted) {
        m_top = -1;
        return;
    }
    const int bottom = std::min(m_bottom, src->rowCount() - 1);
    const int right = std::min(m_right, src->columnCount() - 1);
    const int top = m_top;
    m_top = -1;
    if (top > bottom || m_left > right)
        return;
    const QList<int> roles = m_allRoles ? QList<int>{} : m_roles;
    ++m_changeBatches;
    QMetaObject::invokeMethod(this, "_q_sourceDataChanged", Qt::DirectConnection,
                              Q_ARG(QModelIndex, src->index(top, m_left)),
                              Q_ARG(QModelIndex, src->index(bottom, right)), Q_ARG(QList<int>, roles));
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
