#pragma once
// The dispatch table: one row per haul truck with its custodian, autonomy mode, assignment and
// the answer to this console's last request, task, destination, ETA, production state, payload and time in
// state, as the trucks reported them (DispatchSource). Rows that need the dispatcher (the truck asks for
// work, or its custodian went from AHS to FMS) carry the "needs assignment" cue; a rejected request is marked
// too.
//
// ETA = the remaining route's length (DispatchSource::route: the roads still to enter, the rest of the
// current way not counted) over the truck's reported speed; below 1 m/s (loading, queued, just starting) the
// nominal haul speed (kNominalSpeedMs, 25 km/h) is used instead and the ETA is shown with a "~". Routes are
// cached per truck until its way, destination or assignment changes, and computed only for rows a view asks
// for.
//
// Updates are incremental: trucksChanged(ids) re-reads those trucks; the display texts of a row are formatted
// once per update (kept in the row, so painting allocates nothing for them) and compared with the previous
// ones, and dataChanged covers only the cells whose text (or the row's cue) really changed, one signal per
// run of consecutive rows with the same changed columns (a view repaints only those cells, and nothing for
// rows scrolled out of sight). Rows are kept in truck-name order; the "in state" and "ETA" columns (time and
// reported speed) are refreshed once a second.
#include "models/DispatchSource.h"
#include "models/ModelClock.h"

#include <QAbstractTableModel>
#include <QHash>
#include <QPointer>
#include <QTimer>

#include <array>
#include <functional>

namespace ocu {

class FleetModel;

class DispatchModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column {
        ColTruck,
        ColCustodian,
        ColMode,
        ColAssignment,
        ColTask,
        ColDestination,
        ColEta,
        ColProduction,
        ColPayload,
        ColInState,
        ColumnCount
    };
    enum Role { IdRole = Qt::UserRole + 1, NeedsAssignmentRole, EtaSecondsRole };
    static constexpr double kNominalSpeedMs = 25.0 / 3.6;

    explicit DispatchModel(QObject* parent = nullptr);

    // Not owned. `fleet` (optional) gives the speeds for the ETA.
    void setSource(DispatchSource* source);
    DispatchSource* source() const { return m_source; }
    void setFleet(FleetModel* fleet);
    // The clock times in production are counted on (null: the system clock).
    void setClock(std::shared_ptr<const ModelClock> clock) { m_clock = clockOrSystem(std::move(clock)); }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

    int rowOf(const QString& id) const;
    const DispatchTruck& truckAt(int row) const { return m_rows[row].truck; }
    const QVector<DispatchTruck> trucks() const;
    // Remaining route of a truck (cached, see above).
    const DispatchRoute& routeOf(int row) const;
    // Seconds to the destination, or a negative number when unknown; `nominal` tells whether the nominal
    // speed stood in for the reported one.
    double etaSeconds(int row, bool* nominal = nullptr) const;
    int needsAssignmentCount() const;

public slots:
    // Re-reads these trucks from the source (removed when the source no longer has them).
    void updateTrucks(const QStringList& ids);
    void reload();
    void refreshTimes(); // the "in state" column

signals:
    // After every update (ids changed/added/removed): the queue view and the overlays follow it.
    void trucksUpdated(const QStringList& ids);

private:
    struct Row {
        DispatchTruck truck;
        // Route cache key and value.
        mutable bool routeValid = false;
        mutable DispatchRoute route;
        // Display texts of the columns that depend only on the truck's report (not ETA, not in state).
        std::array<QString, ColumnCount> text;
    };
    QString assignmentText(const DispatchTruck& t) const;
    void formatRow(Row& r) const;
    void removeRowAt(int row);
    void insertSorted(DispatchTruck&& t); // in truck-name order
    QString etaText(int row) const;
    void reindex(int from);

    QPointer<DispatchSource> m_source;
    QPointer<FleetModel> m_fleet;
    QVector<Row> m_rows;
    QHash<QString, int> m_index;
    QTimer m_clockTimer;
    std::shared_ptr<const ModelClock> m_clock = systemModelClock();
};

// Per load area (shovel) and per dump area (dump, crusher): the trucks assigned to it (Pending/Active, still
// on the way) and the trucks at it (their reported way is the area: queued, spotting, loading or dumping).
class DispatchQueueModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { ColArea, ColKind, ColEnRoute, ColAtArea, ColTrucks, ColumnCount };
    explicit DispatchQueueModel(DispatchModel* trucks, QObject* parent = nullptr);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

    struct Queue {
        DispatchArea area;
        QStringList enRoute; // truck names
        QStringList atArea;
    };
    const QVector<Queue>& queues() const { return m_queues; }
    // The queue of one area (link + way id), or null.
    const Queue* queueOf(const QString& link, qint64 wayId) const;
    static bool isQueueArea(const DispatchArea& a); // Load or Offload (dump, crusher)
    // "at: A, B; coming: C, D" with at most `shown` names per list (then "+N more" as "+N").
    static QString trucksText(const Queue& q, int shown);
    static constexpr int kShownNames = 8;

public slots:
    void rebuild();

private:
    DispatchModel* m_trucks;
    QVector<Queue> m_queues;
};

} // namespace ocu
