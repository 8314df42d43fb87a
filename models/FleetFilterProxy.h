#pragma once
// Sort and filter of the fleet model: free text (name, id, type, mode), protocol set, status set.
// Sorting uses FleetModel::RawRole so numbers sort as numbers.
#include "models/MachineState.h"

#include <QSet>
#include <QSortFilterProxyModel>
#include <QTimer>

namespace ocu {

class FleetFilterProxy : public QSortFilterProxyModel {
    Q_OBJECT
public:
    explicit FleetFilterProxy(QObject* parent = nullptr);

    void setText(const QString& text);
    QString text() const { return m_text; }
    // Empty set = all protocols / all states.
    void setProtocols(const QSet<Protocol>& protocols);
    void setStatuses(const QSet<StatusCategory>& statuses);

    // The source's data changes (1,000 machines at 10 Hz) reach the sort/filter and the view at
    // most every `ms` (0 = at once, the default), merged into one dataChanged of the changed cells' bounds.
    // Rows, resets and layout changes pass at once. Call before or after setSourceModel.
    void setChangeIntervalMs(int ms);
    int changeIntervalMs() const { return m_changeIntervalMs; }
    void setSourceModel(QAbstractItemModel* source) override;
    // Merged changes handed to the sort/filter so far (tests, benchmarks); flushChanges() hands over now.
    int changeBatches() const { return m_changeBatches; }
    void flushChanges();

protected:
    bool filterAcceptsRow(int sourceRow, const QModelIndex& sourceParent) const override;

private:
    QString m_text;
    QSet<Protocol> m_protocols;
    QSet<StatusCategory> m_statuses;

    void reroute();
    void onSourceDataChanged(const QModelIndex& topLeft, const QModelIndex& bottomRight,
                             const QList<int>& roles);
    int m_changeIntervalMs = 0;
    bool m_rerouted = false;
    QTimer m_changeTimer;
    int m_top = -1, m_bottom = -1, m_left = -1, m_right = -1; // pending source cells (bounds)
    QList<int> m_roles;
    bool m_allRoles = false;
    int m_changeBatches = 0;
    QList<QMetaObject::Connection> m_throttleConnections;
};

} // namespace ocu
