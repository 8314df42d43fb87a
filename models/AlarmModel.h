#pragma once
// Alarms and event log (issue 6 §7): link loss, timeouts, health faults, diagnostics, discrepancies,
// control lost, text messages, audit entries. Alarms (requiresAck) stay unacknowledged until an operator
// acknowledges them; the unacknowledged count feeds the status bar.
#include "models/FleetEvent.h"

#include <QAbstractTableModel>
#include <QHash>
#include <QSortFilterProxyModel>
#include <QVector>

class QIODevice;

namespace ocu {

class FleetBridge;
class FleetModel;
struct LinkStatus;

class AlarmModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { ColTime, ColSeverity, ColKind, ColMachine, ColText, ColAck, ColumnCount };
    enum Role {
        SeverityRole = Qt::UserRole + 1,
        KindRole,
        AckedRole,
        RequiresAckRole,
        TimeRole,
        MachineRole
    };

    explicit AlarmModel(QObject* parent = nullptr);

    // Bridge events become entries; a link going Down raises a LinkLoss alarm, coming back an info entry.
    void addBridge(FleetBridge* bridge);
    // Machines going stale raise Timeout alarms; a machine turning to health Fault raises a HealthFault
    // alarm.
    void watchFleet(FleetModel* fleet);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

    const FleetEvent& eventAt(int row) const { return m_rows[row].event; }
    bool isAcknowledged(int row) const { return m_rows[row].acked; }
    int unacknowledgedCount() const { return m_unacked; }

    // Entries are kept up to this many; the oldest acknowledged ones go first, unacknowledged alarms are
    // never dropped.
    void setMaxEntries(int n) { m_maxEntries = n; }

    // CSV (RFC 4180 quoting): time (ISO 8601 UTC), severity, kind, machine, source, text, acknowledged.
    bool exportCsv(QIODevice* out, const QVector<int>& rows = {}) const;
    bool exportCsv(const QString& path) const;

public slots:
    void add(const ocu::FleetEvent& event);
    void acknowledge(int row);
    void acknowledgeAll();

signals:
    void unacknowledgedCountChanged(int count);
    void eventAdded(const ocu::FleetEvent& event);
    void alarmAcknowledged(const QString& key, const QString& by, qint64 atMs);

private:
    struct Row {
        FleetEvent event;
        bool acked = false;
        qint64 ackedMs = 0;
    };
    void onLink(const LinkStatus& status);
    void trim();

    QVector<Row> m_rows;
    int m_unacked = 0;
    int m_maxEntries = 20000;
    QHash<QString, int> m_linkDown; // link name -> 1 while down (dedupe)
    QHash<QString, int> m_health;   // machine id -> last health level
};

// Filter of the event log: free text, minimum severity, unacknowledged only.
class AlarmFilterProxy : public QSortFilterProxyModel {
    Q_OBJECT
public:
    explicit AlarmFilterProxy(QObject* parent = nullptr);
    void setText(const QString& text);
    void setMinimumSeverity(EventSeverity s);
    void setUnacknowledgedOnly(bool on);

protected:
    bool filterAcceptsRow(int sourceRow, const QModelIndex& sourceParent) const override;

private:
    QString m_text;
    EventSeverity m_minSeverity = EventSeverity::Info;
    bool m_unackedOnly = false;
};

} // namespace ocu
