#pragma once
// The shared control-room history on PostgreSQL. Every console writes its events, alarms,
// acknowledgements, shelvings and command audit to one database; acknowledgements and shelvings made at
// another console reach this console's AlarmModel within a second (LISTEN/NOTIFY). All database work runs on
// a worker thread of its own, never on the GUI thread. Every record goes first into a local SQLite outbox
// (one file per console) and leaves it only once PostgreSQL has it, so a console that loses the database
// keeps working and back-fills when it returns: each record carries an idempotent key (console, outbox
// origin, sequence) and is inserted with ON CONFLICT DO NOTHING, so nothing is lost and nothing doubled.
// Each console also publishes who is at it (operator, role, since, locked, the addresses its stacks control
// machines with) with a heartbeat, and reads the room: who is where (models/history/PgPresence.h).
// Schema and operation: docs/recording.md ("Shared control-room history on PostgreSQL").
#include "models/ControlRoomModel.h"

#include <QObject>
#include <QPointer>
#include <QString>

#include <atomic>
#include <memory>
#include <optional>

class QThread;

namespace ocu {

class AlarmModel;
class CommandGate;
class OperatorSession;
struct FleetEvent;

struct PgHistoryConfig {
    QString conninfo;       // libpq connection string, e.g. "host=db.site dbname=ocu user=ocu"
    QString console;        // this console's name in the shared history ("dispatcher", "site-manager")
    QString outboxPath;     // the local SQLite outbox
    int reconnectMs = 1000; // retry period while the database is away
    // Presence: this console's heartbeat, and how long another console's row may go without one before it
    // reads as stale ("not seen since ..."): three heartbeats missed.
    int heartbeatMs = 10000;
    int staleAfterMs = 30000;
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
    // Publishes who is at this console and keeps it current: on every sign-in, switch, lock and unlock;
    // stop() (a clean exit) ends it. `controllerAddresses`: what this console's stacks control machines with
    // ("jaus:3.1.1"), so that the other consoles can name it as a machine's controller.
    void attachSession(OperatorSession* session, const QStringList& controllerAddresses);
    // Publishes (or replaces) this console's presence.
    void publishPresence(const ConsolePresence& presence);
    // Every console's presence as last read (this one's too); empty until connected.
    const QVector<ConsolePresence>& room() const { return m_room; }

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
    // The room was read again and differs from before.
    void roomChanged(const QVector<ocu::ConsolePresence>& room);

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
    QVector<ConsolePresence> m_room;
    std::optional<ConsolePresence> m_presence; // this console's, published again by start()
    bool m_applyingRemote = false;
    bool m_gateAttached = false;
    qint64 m_recorded = 0;
    std::atomic<bool> m_connected{false};
    std::atomic<qint64> m_pending{0}; // in the outbox (worker)
    std::atomic<qint64> m_queued{0};  // posted to the worker, not yet in the outbox
};

} // namespace ocu
