#pragma once
// Sort and filter of the fleet model: free text (name, id, type, mode), protocol set, status set.
// Sorting uses FleetModel::RawRole so numbers sort as numbers.
#include "models/MachineState.h"

#include <QSet>
#include <QSortFilterProxyModel>

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

protected:
    bool filterAcceptsRow(int sourceRow, const QModelIndex& sourceParent) const override;

private:
    QString m_text;
    QSet<Protocol> m_protocols;
    QSet<StatusCategory> m_statuses;
};

} // namespace ocu
