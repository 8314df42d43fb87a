#pragma once
// One row per machine across all protocols. Fed by FleetBridge::machinesUpdated /
// machinesRemoved; ages, staleness and removal are evaluated by refresh() (a timer, default 500 ms).
#include "models/MachineState.h"
#include "models/ModelClock.h"

#include <QAbstractTableModel>
#include <QHash>
#include <QPointer>
#include <QTimer>
#include <QVector>

#include <memory>

namespace ocu {

class FleetBridge;

class FleetModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column {
        ColName,
        ColType,
        ColProtocol,
        ColLink, // link state and data age
        ColEast,
        ColNorth,
        ColLatitude,
        ColLongitude,
        ColHeading,
        ColSpeed,
        ColMode,
        ColStop,
        ColController,
        ColHealth,
        ColLastMessage,
        ColumnCount
    };
    enum Role {
        IdRole = Qt::UserRole + 1, // QString machine id
        RawRole,                   // raw value of the cell for sorting/filtering (numbers stay numbers)
        StateRole,                 // QVariant<MachineState>
        StatusRole,                // int(StatusCategory)
        StatusColorRole,           // QColor of the status
        StaleRole,                 // bool
        AgeMsRole,                 // qint64 data age (ms)
        ProtocolRole,              // int(Protocol)
    };

    explicit FleetModel(QObject* parent = nullptr);

    // Connects the bridge's machine signals to this model.
    void addBridge(FleetBridge* bridge);

    // QAbstractItemModel
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

    // Direct updates (what the bridges' signals call).
    void upsert(const QVector<MachineState>& machines);
    void remove(const QStringList& ids);

    int rowOf(const QString& id) const { return m_index.value(id, -1); }
    const MachineState* machine(const QString& id) const;
    const MachineState& machineAt(int row) const { return m_rows[row].state; }
    bool isStaleAt(int row) const { return m_rows[row].stale; }
    bool isStale(const QString& id) const;
    qint64 ageMsAt(int row) const;
    StatusCategory statusAt(int row) const { return statusOf(m_rows[row].state, m_rows[row].stale); }
    QStringList ids() const;
    const QVector<MachineState>& machinesSnapshot() const; // all machines in row order (cached)

    // Data older than this is stale (grey); default 5 s. Removal after removeAfterMs without data
    // (0 = never); default 60 s.
    void setStaleAfterMs(qint64 ms) { m_staleAfterMs = ms; }
    qint64 staleAfterMs() const { return m_staleAfterMs; }
    // Protocol-specific staleness (anchors-features.md §8.1: each protocol has its own rate); overrides the
    // default for that protocol. A negative value removes the override.
    void setStaleAfterMs(Protocol protocol, qint64 ms);
    qint64 staleAfterMs(Protocol protocol) const {
        return m_staleByProtocol.value(int(protocol), m_staleAfterMs);
    }
    void setRemoveAfterMs(qint64 ms) { m_removeAfterMs = ms; }
    qint64 removeAfterMs() const { return m_removeAfterMs; }
    void setRefreshIntervalMs(int ms); // 0 stops the timer (tests call refresh() themselves)
    // The clock ages and staleness are measured on (null: the system clock); tests give a manual one.
    void setClock(std::shared_ptr<const ModelClock> clock) { m_clock = clockOrSystem(std::move(clock)); }
    qint64 nowMs() const { return m_clock->nowMs(); }

    static QString columnName(int column);

public slots:
    // Updates ages, flips staleness, removes expired machines.
    void refresh();

signals:
    void machineAdded(const QString& id);
    void machineRemoved(const QString& id);
    // One signal per delivered batch (added and updated ids), for the map and the headless monitor.
    void machinesChanged(const QStringList& ids);
    void machineStaleChanged(const QString& id, bool stale);

private:
    struct Row {
        MachineState state;
        bool stale = false;
    };
    QVariant display(const Row& r, int column) const;
    QVariant raw(const Row& r, int column) const;
    void rebuildIndex();

    QVector<Row> m_rows;
    QHash<QString, int> m_index;
    mutable QVector<MachineState> m_snapshot;
    mutable bool m_snapshotValid = false;
    qint64 m_staleAfterMs = 5000;
    QHash<int, qint64> m_staleByProtocol;
    qint64 m_removeAfterMs = 60000;
    std::shared_ptr<const ModelClock> m_clock = systemModelClock();
    QTimer m_timer;
};

} // namespace ocu
