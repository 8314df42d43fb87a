#pragma once
// Alarms and event log: link loss, timeouts, health faults, diagnostics, discrepancies,
// control lost, text messages, audit entries. Alarms (requiresAck) stay unacknowledged until an operator
// acknowledges them; the unacknowledged count feeds the status bar.
// Alarm management (EEMUA 191 / ISA-18.2): every alarm has a stable key (alarmKey: cause,
// machine or group, source) shared by the consoles of a control room; a repeat of an active (unacknowledged)
// alarm updates it (occurrence count, latest text and details) instead of adding a row; alarms have a
// priority; an alarm can be shelved for a time (suppressed, returns by itself on expiry); the alarm rate (new
// alarms in the last 10 min) and a flood flag (> 10 per 10 min, EEMUA 191 table 30) are kept.
#include "models/FleetEvent.h"
#include "models/ModelClock.h"

#include <QAbstractTableModel>
#include <QHash>
#include <QSortFilterProxyModel>
#include <QVector>

#include <deque>
#include <functional>

class QIODevice;
class QTimer;

namespace ocu {

class FleetBridge;
class FleetModel;
struct LinkStatus;

class AlarmModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column {
        ColTime,
        ColSeverity,
        ColKind,
        ColMachine,
        ColText,
        ColAck,
        ColPriority,
        ColCount,
        ColumnCount
    };
    enum Role {
        SeverityRole = Qt::UserRole + 1,
        KindRole,
        AckedRole,
        RequiresAckRole,
        TimeRole,
        MachineRole,
        KeyRole,         // alarmKey
        PriorityRole,    // int(AlarmPriority), resolved
        OccurrencesRole, // how often the alarm was raised while active
        ShelvedRole,     // bool
        DetailsRole      // QStringList
    };
    static constexpr qint64 kRateWindowMs = 10 * 60 * 1000; // EEMUA 191: alarms per 10 minutes
    static constexpr int kFloodThreshold = 10;              // more than this per 10 min = flood
    static constexpr int kDefaultMaxEntries = 20000;        // setMaxEntries
    // Consoles of one control room run NTP-synchronised clocks; an acknowledgement made elsewhere covers the
    // alarm occurrences raised up to this much after its stamp (acknowledgeKey).
    static constexpr qint64 kAckSkewMs = 5000;

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
    // Unacknowledged alarms that are not shelved.
    int unacknowledgedCount() const { return m_unacked; }
    QString keyAt(int row) const { return m_rows[row].key; }
    int occurrencesAt(int row) const { return m_rows[row].occurrences; }
    QString acknowledgedByAt(int row) const { return m_rows[row].ackedBy; }
    qint64 acknowledgedAtMs(int row) const { return m_rows[row].ackedMs; }
    bool isShelved(int row) const { return m_shelves.contains(m_rows[row].key); }
    // The newest row of an alarm key, or -1.
    int rowOfKey(const QString& key) const;

    // The clock of stamps, shelving expiry and the rate (null: the system clock); tests give a manual one.
    void setClock(std::shared_ptr<const ModelClock> clock) { m_clock = clockOrSystem(std::move(clock)); }
    qint64 nowMs() const { return m_clock->nowMs(); }
    // Who acknowledges and shelves at this console ("dispatcher", an operator's name).
    void setOperatorName(const QString& name) { m_operator = name; }
    QString operatorName() const { return m_operator; }

    struct Shelf {
        QString by;
        qint64 atMs = 0;
        qint64 untilMs = 0;
    };
    bool isKeyShelved(const QString& key) const { return m_shelves.contains(key); }
    Shelf shelf(const QString& key) const { return m_shelves.value(key); }
    QStringList shelvedKeys() const { return m_shelves.keys(); }

    // New alarms (not repeats, not shelved) in the last 10 minutes, and whether that is a flood.
    int alarmRate() const;
    bool isFlood() const { return alarmRate() > kFloodThreshold; }

    // Entries are kept up to this many; the oldest acknowledged ones go first, unacknowledged alarms are
    // never dropped.
    void setMaxEntries(int n) { m_maxEntries = n; }
    int maxEntries() const { return m_maxEntries; }

    // One row as a replay restores it (the list at a replay time, built without adding every event since the
    // start): the event as the row shows it (the latest occurrence's time and text, the highest severity),
    // how often it was raised, when it was first raised, and its acknowledgement.
    struct RestoredRow {
        FleetEvent event;
        bool acked = false;
        qint64 ackedMs = 0;
        QString ackedBy;
        int occurrences = 1;
        qint64 firstMs = 0;
    };
    // Replaces every row (a model reset; shelvings and the alarm rate are kept).
    void restore(const QVector<RestoredRow>& rows);

    // CSV (RFC 4180 quoting): time (ISO 8601 UTC), severity, kind, machine, source, text, acknowledged.
    bool exportCsv(QIODevice* out, const QVector<int>& rows = {}) const;
    bool exportCsv(const QString& path) const;

public slots:
    void add(const ocu::FleetEvent& event);
    void acknowledge(int row);
    void acknowledgeAll();
    // Acknowledges the active alarm of a key raised no later than atMs (+ clock skew between consoles), as
    // done by `by` (this console's operator or another console's). Returns whether an alarm was acknowledged.
    bool acknowledgeKey(const QString& key, const QString& by, qint64 atMs);
    // Shelves an alarm key for durationMs (ISA-18.2 §11.4): its rows leave the unacknowledged count and the
    // default view, new occurrences are not annunciated; it returns by itself at expiry.
    void shelve(const QString& key, qint64 durationMs, const QString& reason = {});
    // Applies a shelving decided elsewhere (another console): ignored when already expired.
    bool applyShelve(const QString& key, const QString& by, qint64 atMs, qint64 untilMs);
    bool unshelve(const QString& key, const QString& by = {});
    // Ends the shelvings whose time is up (also called every second by a timer while any exists).
    void expireShelving();

signals:
    void unacknowledgedCountChanged(int count);
    void eventAdded(const ocu::FleetEvent& event);
    // Every acknowledgement, shelving and unshelving, with the alarm's key (shared by the consoles), who
    // (operator or console; "expiry" for a shelving that ran out) and when (ms since the epoch).
    void alarmAcknowledged(const QString& key, const QString& by, qint64 atMs);
    void alarmShelved(const QString& key, const QString& by, qint64 atMs, qint64 untilMs);
    void alarmUnshelved(const QString& key, const QString& by, qint64 atMs);
    void alarmRateChanged(int alarmsPer10Min, bool flood);

private:
    struct Row {
        FleetEvent event;
        bool acked = false;
        qint64 ackedMs = 0;
        QString key;
        QString ackedBy;
        int occurrences = 1;
        qint64 firstMs = 0;
    };
    void onLink(const LinkStatus& status);
    void trim();
    void recount();
    void rebuildActive();
    void ackRow(int row, const QString& by, qint64 atMs, bool notify = true);
    void updateTimer();
    void pruneRate(bool notify);

    QVector<Row> m_rows;
    QHash<QString, int> m_active; // key -> row of the unacknowledged alarm with that key
    QHash<QString, Shelf> m_shelves;
    std::deque<qint64> m_annunciations; // times of new alarms, for the rate
    int m_lastRate = 0;
    std::shared_ptr<const ModelClock> m_clock = systemModelClock();
    QString m_operator;
    QTimer* m_timer = nullptr;
    int m_unacked = 0;
    int m_maxEntries = kDefaultMaxEntries;
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
    // Shelved alarms are hidden unless shown on purpose (ISA-18.2: shelved = out of the operator's list).
    void setShowShelved(bool on);

protected:
    bool filterAcceptsRow(int sourceRow, const QModelIndex& sourceParent) const override;

private:
    QString m_text;
    EventSeverity m_minSeverity = EventSeverity::Info;
    bool m_unackedOnly = false;
    bool m_showShelved = false;
};

} // namespace ocu
