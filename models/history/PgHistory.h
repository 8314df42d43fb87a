#pragma once
// The shared control-room history on PostgreSQL. Every console writes its events, alarms,
// acknowledgements, shelvings and command audit to one database; acknowledgements and shelvings made at
// another console reach this console's AlarmModel within a second (LISTEN/NOTIFY). All database work runs on
// a worker thread of its own, never on the GUI thread. Every record goes first into a local SQLite outbox
// (one file per console) and leaves it only once PostgreSQL has it, so a console that loses the database
// keeps working and back-fills when it returns: each record carries an idempotent key (console, outbox
// origin, sequence) and is inserted with ON CONFLICT DO NOTHING, so nothing is lost and nothing doubled.
// Schema and operation: docs/recording.md ("Shared control-room history on PostgreSQL").
#include <QObject>
#include <QPointer>
#include <QString>

#include <atomic>
#include <memory>

class QThread;

namespace ocu {

class AlarmModel;
class CommandGate;
struct FleetEvent;

struct PgHistoryConfig {
    QString conninfo;       // libpq connection string, e.g. "host=db.site dbname=ocu user=ocu"
    QString console;        // this console's name in the shared history ("dispatcher", "site-manager")
    QString outboxPath;     // the local SQLite outbox
    int reconnectMs = 1000; // retry period while the database is away
};

class PgHistoryWorker;

class PgHistory : public QObject {
    Q_OBJECT
public:
    explicit PgHistory(PgHistoryConfig config, QObject* parent = nullptr);
    ~PgHistory() override;

    // Opens the outbox (error text when it cannot) and starts the worker, which connects in the background.
    QString start();
    void stop();

    // Records what the model reports (events, alarms, acknowledgements, shelvings) and applies the
    // acknowledgements and shelvings of the other consoles to it.
    void attach(AlarmModel* alarms);
    // Records the gate's command audit (every command, its per-target outcome).
    void attachGate(CommandGate* gate);

    bool isConnected() const { return m_connected.load(); }
    // Records in the outbox not yet in PostgreSQL.
    qint64 pendingCount() const { return m_queued.load() + m_pending.load(); }
    // Records this console has handed to the history since start.
    qint64 recordedCount() const { return m_recorded; }
    const PgHistoryConfig& config() const { return m_config; }

signals:
    void connectionChanged(bool connected, const QString& detail);
    // Another console acknowledged / shelved / unshelved (already applied to the attached model).
    void remoteAcknowledged(const QString& key, const QString& by, qint64 atMs);

private:
    friend class PgHistoryWorker;
    struct Record;
    void post(Record r);
    void onEvent(const FleetEvent& e);
    void applyRemote(const QString& kind, const QString& key, const QString& by, qint64 atMs, qint64 untilMs);

    PgHistoryConfig m_config;
    QThread* m_thread = nullptr;
    PgHistoryWorker* m_worker = nullptr;
    QPointer<AlarmModel> m_alarms;
    bool m_applyingRemote = false;
    bool m_gateAttached = false;
    qint64 m_recorded = 0;
    std::atomic<bool> m_connected{false};
    std::atomic<qint64> m_pending{0}; // in the outbox (worker)
    std::atomic<qint64> m_queued{0};  // posted to the worker, not yet in the outbox
};

} // namespace ocu
