#include "models/history/PgHistory.h"

#include "models/AlarmModel.h"
#include "models/CommandGate.h"
#include "models/history/PgPresence.h"

#include <QDateTime>
#include <QJsonArray>
#include <QJsonDocument>
#include <QLoggingCategory>
#include <QSet>
#include <QSocketNotifier>
#include <QSysInfo>
#include <QThread>
#include <QTimer>
#include <QUuid>

#include <libpq-fe.h>
#include <sqlite3.h>

#include <vector>

Q_LOGGING_CATEGORY(lcPgHistory, "ocu.history.pg")

namespace ocu {

struct PgHistory::Record {
    QString kind; // event | alarm | ack | shelve | unshelve | audit
    qint64 atMs = 0;
    QString key, severity, priority, machine, source, text, by;
    qint64 untilMs = 0;
    QByteArray details; // valid JSON or empty
};

namespace {

// The schema, created by whichever console connects first (serialised by an advisory lock so two consoles
// starting together do not race on CREATE). docs/recording.md ("Shared control-room history on PostgreSQL")
// explains every column.
constexpr const char* kSchemaSql = R"sql(
BEGIN;
SET LOCAL client_min_messages = warning;
SELECT pg_advisory_xact_lock(1601604);
CREATE TABLE IF NOT EXISTS ocu_history (
    id        bigserial PRIMARY KEY,
    console   text        NOT NULL,
    origin    uuid        NOT NULL,
    seq       bigint      NOT NULL,
    kind      text        NOT NULL CHECK (kind IN ('event','alarm','ack','shelve','unshelve','audit')),
    at        timestamptz NOT NULL,
    alarm_key text,
    severity  text,
    priority  text,
    machine   text,
    source    text,
    text      text,
    by_whom   text,
    until     timestamptz,
    details   jsonb,
    stored_at timestamptz NOT NULL DEFAULT now(),
    UNIQUE (console, origin, seq)
);
CREATE INDEX IF NOT EXISTS ocu_history_at ON ocu_history (at);
CREATE INDEX IF NOT EXISTS ocu_history_key ON ocu_history (alarm_key, at);
CREATE OR REPLACE FUNCTION ocu_history_notify() RETURNS trigger LANGUAGE plpgsql AS $$
BEGIN
    PERFORM pg_notify('ocu_alarm_state', NEW.id::text);
    RETURN NULL;
END $$;
CREATE OR REPLACE TRIGGER ocu_history_notify AFTER INSERT ON ocu_history FOR EACH ROW
    WHEN (NEW.kind IN ('ack', 'shelve', 'unshelve')) EXECUTE FUNCTION ocu_history_notify();
)sql"; // + the presence table (PgPresence::schemaSql()), then COMMIT

constexpr const char* kInsertSql =
    "INSERT INTO ocu_history (console, origin, seq, kind, at, alarm_key, severity, priority, machine, "
    "source, "
    "text, by_whom, until, details) VALUES ($1, $2::uuid, $3::bigint, $4, to_timestamp($5::bigint / 1000.0), "
    "$6, $7, $8, $9, $10, $11, $12, CASE WHEN $13::bigint > 0 THEN to_timestamp($13::bigint / 1000.0) END, "
    "$14::jsonb) ON CONFLICT (console, origin, seq) DO NOTHING";

constexpr const char* kRemoteSql =
    "SELECT id, console, kind, alarm_key, coalesce(by_whom, ''), (extract(epoch FROM at) * 1000)::bigint, "
    "coalesce((extract(epoch FROM until) * 1000)::bigint, 0) FROM ocu_history WHERE console <> $1 AND kind "
    "IN "
    "('ack', 'shelve', 'unshelve') AND alarm_key IS NOT NULL AND ";

constexpr int kBatch = 500;

// PostgreSQL text cannot hold NUL; everything else goes as is.
QByteArray pgText(const QString& s) {
    QByteArray b = s.toUtf8();
    b.replace('\0', "");
    return b;
}

} // namespace

class PgHistoryWorker : public QObject {
    Q_OBJECT
public:
    PgHistoryWorker(PgHistory* owner, PgHistoryConfig config)
        : m_owner(owner), m_cfg(std::move(config)), m_presence(m_cfg.console, m_cfg.staleAfterMs) {}
    ~PgHistoryWorker() override { close(); }

    // Worker thread from here on.
    QString open() {
        if (sqlite3_open_v2(m_cfg.outboxPath.toUtf8().constData(), &m_db,
                            SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_FULLMUTEX,
                            nullptr) != SQLITE_OK) {
            const QString e =
                m_db ? QString::fromUtf8(sqlite3_errmsg(m_db)) : QStringLiteral("out of memory");
            close();
            return QStringLiteral("history outbox %1: %2").arg(m_cfg.outboxPath, e);
        }
        sqlite3_busy_timeout(m_db, 2000);
        const char* ddl =
            "PRAGMA journal_mode=WAL; PRAGMA synchronous=NORMAL;"
            "CREATE TABLE IF NOT EXISTS meta(k TEXT PRIMARY KEY, v TEXT NOT NULL);"
            "CREATE TABLE IF NOT EXISTS outbox(seq INTEGER PRIMARY KEY AUTOINCREMENT, kind TEXT "
            "NOT NULL, at_ms INTEGER NOT NULL, alarm_key TEXT, severity TEXT, priority TEXT, "
            "machine TEXT, source TEXT, text TEXT, by_whom TEXT, until_ms INTEGER, details TEXT);"
            "CREATE TABLE IF NOT EXISTS rejected(seq INTEGER PRIMARY KEY, kind TEXT, at_ms "
            "INTEGER, error TEXT);";
        char* err = nullptr;
        if (sqlite3_exec(m_db, ddl, nullptr, nullptr, &err) != SQLITE_OK) {
            const QString e = QString::fromUtf8(err ? err : "?");
            sqlite3_free(err);
            close();
            return QStringLiteral("history outbox %1: %2").arg(m_cfg.outboxPath, e);
        }
        // The outbox's origin: part of every record's key, so a new outbox file never collides with the
        // sequence numbers of an old one.
        m_origin = queryText("SELECT v FROM meta WHERE k = 'origin'");
        if (m_origin.isEmpty()) {
            m_origin = QUuid::createUuid().toString(QUuid::WithoutBraces);
            sqlite3_stmt* st = nullptr;
            sqlite3_prepare_v2(m_db, "INSERT INTO meta(k, v) VALUES ('origin', ?)", -1, &st, nullptr);
            const QByteArray o = m_origin.toUtf8();
            sqlite3_bind_text(st, 1, o.constData(), int(o.size()), SQLITE_TRANSIENT);
            sqlite3_step(st);
            sqlite3_finalize(st);
        }
        m_owner->m_pending = queryText("SELECT count(*) FROM outbox").toLongLong();
        m_retry = new QTimer(this);
        m_retry->setSingleShot(true);
        connect(m_retry, &QTimer::timeout, this, &PgHistoryWorker::tryConnect);
        m_heartbeat = new QTimer(this);
        connect(m_heartbeat, &QTimer::timeout, this, &PgHistoryWorker::beat);
        QTimer::singleShot(0, this, &PgHistoryWorker::tryConnect);
        return {};
    }

    void close() {
        delete m_retry; // on the worker's thread, where it runs
        m_retry = nullptr;
        delete m_heartbeat;
        m_heartbeat = nullptr;
        // A clean exit leaves the room (a crash leaves a row whose heartbeat ages into "not seen since"). The
        // server answered in time: what the outbox still holds (the sign-out) goes now, not at the next
        // start.
        if (m_pg && PQstatus(m_pg) == CONNECTION_OK && m_presence.end(m_pg, 2000) &&
            m_owner->m_pending <= kBatch) // a long back-fill waits for the next start
            sendOutbox();
        dropConnection(QString(), false);
        if (m_db) {
            sqlite3_close(m_db);
            m_db = nullptr;
        }
    }

    void record(const PgHistory::Record& r) {
        --m_owner->m_queued;
        if (!m_db)
            return;
        sqlite3_stmt* st = nullptr;
        sqlite3_prepare_v2(m_db,
                           "INSERT INTO outbox(kind, at_ms, alarm_key, severity, priority, machine, source, "
                           "text, by_whom, until_ms, details) VALUES (?,?,?,?,?,?,?,?,?,?,?)",
                           -1, &st, nullptr);
        std::vector<QByteArray> keep;
        auto bindText = [&](int i, const QString& s) {
            if (s.isEmpty()) {
                sqlite3_bind_null(st, i);
                return;
            }
            keep.push_back(s.toUtf8());
            sqlite3_bind_text(st, i, keep.back().constData(), int(keep.back().size()), SQLITE_STATIC);
        };
        bindText(1, r.kind);
        sqlite3_bind_int64(st, 2, r.atMs);
        bindText(3, r.key);
        bindText(4, r.severity);
        bindText(5, r.priority);
        bindText(6, r.machine);
        bindText(7, r.source);
        bindText(8, r.text);
        bindText(9, r.by);
        sqlite3_bind_int64(st, 10, r.untilMs);
        if (r.details.isEmpty())
            sqlite3_bind_null(st, 11);
        else
            sqlite3_bind_text(st, 11, r.details.constData(), int(r.details.size()), SQLITE_STATIC);
        const int rc = sqlite3_step(st);
        sqlite3_finalize(st);
        if (rc != SQLITE_DONE) {
            qCWarning(lcPgHistory) << "outbox write failed:" << sqlite3_errmsg(m_db);
            return;
        }
        ++m_owner->m_pending;
        // Batch what arrives together (an event burst) into one transaction.
        if (!m_flushQueued) {
            m_flushQueued = true;
            QMetaObject::invokeMethod(this, &PgHistoryWorker::flush, Qt::QueuedConnection);
        }
    }

    void setPresence(const ConsolePresence& mine) {
        m_presence.set(mine);
        if (m_pg && !(m_presence.publish(m_pg) && readRoom()))
            lost();
    }

signals:
    void connectionChanged(bool connected, const QString& detail);
    void room(const QVector<ocu::ConsolePresence>& room);
    void remote(const QString& kind, const QString& key, const QString& by, qint64 atMs, qint64 untilMs);

private:
    QString queryText(const char* sql) {
        sqlite3_stmt* st = nullptr;
        QString out;
        if (sqlite3_prepare_v2(m_db, sql, -1, &st, nullptr) == SQLITE_OK && sqlite3_step(st) == SQLITE_ROW)
            out = QString::fromUtf8(reinterpret_cast<const char*>(sqlite3_column_text(st, 0)));
        sqlite3_finalize(st);
        return out;
    }

    void tryConnect() {
        if (m_pg || !m_db)
            return;
        const QByteArray info = m_cfg.conninfo.toUtf8();
        // connect_timeout first: the operator's conninfo may override it.
        const char* keys[] = {"connect_timeout", "dbname", nullptr};
        const char* values[] = {"3", info.constData(), nullptr};
        PGconn* c = PQconnectdbParams(keys, values, 1);
        if (PQstatus(c) != CONNECTION_OK) {
            const QString e = QString::fromUtf8(PQerrorMessage(c)).trimmed();
            PQfinish(c);
            noteDown(e);
            return;
        }
        m_pg = c;
        // Server notices (e.g. "terminating connection") go to the log category, not to stderr.
        PQsetNoticeProcessor(
            m_pg,
            [](void*, const char* message) {
                qCDebug(lcPgHistory).noquote() << QString::fromUtf8(message).trimmed();
            },
            nullptr);
        const QByteArray schema = QByteArray(kSchemaSql) + PgPresence::schemaSql() + "COMMIT;\n";
        if (!exec(schema.constData()) || !exec("LISTEN ocu_alarm_state") || !exec("LISTEN ocu_presence") ||
            !m_presence.publish(m_pg) || !readRoom()) {
            dropConnection(QString::fromUtf8(PQerrorMessage(m_pg)).trimmed(), true);
            return;
        }
        PGresult* prep = PQprepare(m_pg, "ins", kInsertSql, 14, nullptr);
        const bool ok = PQresultStatus(prep) == PGRES_COMMAND_OK;
        PQclear(prep);
        if (!ok) {
            dropConnection(QString::fromUtf8(PQerrorMessage(m_pg)).trimmed(), true);
            return;
        }
        PQsetnonblocking(m_pg, 0);
        m_notifier = new QSocketNotifier(qintptr(PQsocket(m_pg)), QSocketNotifier::Read, this);
        connect(m_notifier, &QSocketNotifier::activated, this, &PgHistoryWorker::onReadable);
        m_owner->m_connected = true;
        m_downReported = false;
        qCInfo(lcPgHistory) << "connected to the control-room history as" << m_cfg.console;
        emit connectionChanged(true, QString());
        m_heartbeat->start(m_cfg.heartbeatMs);
        // What other consoles decided while this one was away, then what this one kept meanwhile.
        catchUp();
        flush();
    }

    bool exec(const char* sql) {
        PGresult* r = PQexec(m_pg, sql);
        const auto st = PQresultStatus(r);
        PQclear(r);
        return st == PGRES_COMMAND_OK || st == PGRES_TUPLES_OK;
    }

    void noteDown(const QString& why) {
        m_owner->m_connected = false;
        if (!m_downReported) {
            m_downReported = true;
            qCWarning(lcPgHistory).noquote()
                << "control-room history unavailable, keeping the local outbox:" << why;
            emit connectionChanged(false, why);
        }
        if (m_retry && !m_retry->isActive())
            m_retry->start(m_cfg.reconnectMs);
    }

    void dropConnection(const QString& why, bool retry) {
        if (m_heartbeat)
            m_heartbeat->stop();
        delete m_notifier;
        m_notifier = nullptr;
        if (m_pg) {
            PQfinish(m_pg);
            m_pg = nullptr;
        }
        if (retry)
            noteDown(why);
        else
            m_owner->m_connected = false;
    }

    bool lost() {
        if (m_pg && PQstatus(m_pg) != CONNECTION_OK) {
            dropConnection(QString::fromUtf8(PQerrorMessage(m_pg)).trimmed(), true);
            return true;
        }
        return false;
    }

    void onReadable() {
        if (!m_pg)
            return;
        if (!PQconsumeInput(m_pg) || PQstatus(m_pg) != CONNECTION_OK) {
            dropConnection(QString::fromUtf8(PQerrorMessage(m_pg)).trimmed(), true);
            return;
        }
        drainNotifies();
    }

    // Notifications libpq already read while running another command sit in its buffer and wake no socket
    // notifier: drain them after every command, and again after the query their ids lead to.
    void drainNotifies() {
        for (int round = 0; m_pg && round < 100; ++round) {
            QStringList ids;
            bool roomChanged = false; // someone signed in, switched, locked or left
            while (PGnotify* n = PQnotifies(m_pg)) {
                bool ok = false;
                const qint64 id = QByteArray(n->extra).toLongLong(&ok);
                if (qstrcmp(n->relname, PgPresence::channel()) == 0)
                    roomChanged = true;
                else if (ok && !m_applied.contains(id))
                    ids << QString::number(id);
                PQfreemem(n);
            }
            if (ids.isEmpty() && !roomChanged)
                return;
            if (!ids.isEmpty())
                fetchRemote("id = ANY($2::bigint[])", QStringLiteral("{%1}").arg(ids.join(QLatin1Char(','))));
            if (roomChanged && m_pg && !readRoom() && lost())
                return;
        }
    }

    // Every heartbeat: this console is alive, and the room is read again (stale rows age without a NOTIFY).
    void beat() {
        if (m_pg && !(m_presence.heartbeat(m_pg) && readRoom()))
            lost();
    }

    bool readRoom() {
        const auto r = m_presence.readRoom(m_pg);
        if (r)
            emit room(*r);
        return r.has_value();
    }

    void catchUp() {
        // Ids are taken at insert, rows become visible at commit: look back a little and skip what was seen.
        if (m_lastRemoteId > 0)
            fetchRemote("id > $2::bigint", QString::number(std::max<qint64>(0, m_lastRemoteId - 1000)));
        else
            fetchRemote("at > now() - ($2::bigint * interval '1 millisecond')", QStringLiteral("600000"));
    }

    void fetchRemote(const char* where, const QString& arg) {
        const QByteArray sql = QByteArray(kRemoteSql) + where + " ORDER BY id";
        const QByteArray me = pgText(m_cfg.console), a = arg.toUtf8();
        const char* params[] = {me.constData(), a.constData()};
        PGresult* r = PQexecParams(m_pg, sql.constData(), 2, nullptr, params, nullptr, nullptr, 0);
        if (PQresultStatus(r) != PGRES_TUPLES_OK) {
            PQclear(r);
            lost();
            return;
        }
        for (int i = 0; i < PQntuples(r); ++i) {
            const qint64 id = QByteArray(PQgetvalue(r, i, 0)).toLongLong();
            m_lastRemoteId = std::max(m_lastRemoteId, id);
            if (m_applied.contains(id))
                continue;
            m_applied.insert(id);
            const QString by = QStringLiteral("%1 (%2)").arg(QString::fromUtf8(PQgetvalue(r, i, 4)),
                                                             QString::fromUtf8(PQgetvalue(r, i, 1)));
            emit remote(QString::fromUtf8(PQgetvalue(r, i, 2)), QString::fromUtf8(PQgetvalue(r, i, 3)), by,
                        QByteArray(PQgetvalue(r, i, 5)).toLongLong(),
                        QByteArray(PQgetvalue(r, i, 6)).toLongLong());
        }
        PQclear(r);
        if (m_applied.size() > 100000) // bounded: keep the newest ids only
            m_applied.clear();
    }

    struct Row {
        qint64 seq = 0;
        QByteArray f[12]; // kind, at, key, severity, priority, machine, source, text, by, until, details
        bool null[12] = {};
    };

    std::vector<Row> readBatch() {
        std::vector<Row> rows;
        sqlite3_stmt* st = nullptr;
        sqlite3_prepare_v2(m_db,
                           "SELECT seq, kind, at_ms, alarm_key, severity, priority, machine, source, text, "
                           "by_whom, until_ms, details FROM outbox ORDER BY seq LIMIT ?",
                           -1, &st, nullptr);
        sqlite3_bind_int(st, 1, kBatch);
        while (sqlite3_step(st) == SQLITE_ROW) {
            Row row;
            row.seq = sqlite3_column_int64(st, 0);
            for (int c = 1; c <= 11; ++c) {
                if (sqlite3_column_type(st, c) == SQLITE_NULL) {
                    row.null[c] = true;
                    continue;
                }
                const auto* t = reinterpret_cast<const char*>(sqlite3_column_text(st, c));
                row.f[c] = QByteArray(t, sqlite3_column_bytes(st, c));
            }
            rows.push_back(std::move(row));
        }
        sqlite3_finalize(st);
        return rows;
    }

    bool insert(const Row& row) {
        const QByteArray console = pgText(m_cfg.console), origin = m_origin.toUtf8(),
                         seq = QByteArray::number(row.seq);
        const char* p[14] = {console.constData(), origin.constData(), seq.constData()};
        for (int c = 1; c <= 11; ++c)
            p[2 + c] = row.null[c] ? nullptr : row.f[c].constData();
        if (!p[12])
            p[12] = "0";
        PGresult* r = PQexecPrepared(m_pg, "ins", 14, p, nullptr, nullptr, 0);
        const bool ok = PQresultStatus(r) == PGRES_COMMAND_OK;
        if (!ok)
            m_lastError = QString::fromUtf8(PQresultErrorMessage(r)).trimmed();
        PQclear(r);
        return ok;
    }

    void removeUpTo(qint64 seq) {
        sqlite3_stmt* st = nullptr;
        sqlite3_prepare_v2(m_db, "DELETE FROM outbox WHERE seq <= ?", -1, &st, nullptr);
        sqlite3_bind_int64(st, 1, seq);
        sqlite3_step(st);
        sqlite3_finalize(st);
        m_owner->m_pending = queryText("SELECT count(*) FROM outbox").toLongLong();
    }

    void reject(const Row& row) {
        qCWarning(lcPgHistory).noquote()
            << "history record" << row.seq << "refused by PostgreSQL:" << m_lastError;
        sqlite3_stmt* st = nullptr;
        sqlite3_prepare_v2(m_db, "INSERT OR REPLACE INTO rejected(seq, kind, at_ms, error) VALUES (?,?,?,?)",
                           -1, &st, nullptr);
        const QByteArray e = m_lastError.toUtf8();
        sqlite3_bind_int64(st, 1, row.seq);
        sqlite3_bind_text(st, 2, row.f[1].constData(), int(row.f[1].size()), SQLITE_STATIC);
        sqlite3_bind_int64(st, 3, row.f[2].toLongLong());
        sqlite3_bind_text(st, 4, e.constData(), int(e.size()), SQLITE_STATIC);
        sqlite3_step(st);
        sqlite3_finalize(st);
    }

    void flush() {
        m_flushQueued = false;
        sendOutbox();
        drainNotifies();
    }

    void sendOutbox() {
        while (m_pg && m_db) {
            const std::vector<Row> rows = readBatch();
            if (rows.empty())
                return;
            // One transaction per batch; the outbox rows go only after COMMIT succeeded. A crash between the
            // two re-sends them, and ON CONFLICT DO NOTHING makes that harmless.
            bool ok = exec("BEGIN");
            for (std::size_t i = 0; ok && i < rows.size(); ++i)
                ok = insert(rows[i]);
            if (ok)
                ok = exec("COMMIT");
            if (ok) {
                removeUpTo(rows.back().seq);
                continue;
            }
            if (lost())
                return; // back-filled after the reconnection
            exec("ROLLBACK");
            // The database is there but refused a row (should not happen: the records are built valid).
            // Send one by one so one bad record cannot block the rest; the refused one is kept aside.
            for (const Row& row : rows) {
                if (!insert(row)) {
                    if (lost())
                        return;
                    reject(row);
                }
                removeUpTo(row.seq);
            }
        }
    }

    PgHistory* m_owner;
    PgHistoryConfig m_cfg;
    PgPresence m_presence;
    QTimer* m_heartbeat = nullptr;
    sqlite3* m_db = nullptr;
    PGconn* m_pg = nullptr;
    QSocketNotifier* m_notifier = nullptr;
    QTimer* m_retry = nullptr;
    QString m_origin;
    QString m_lastError;
    qint64 m_lastRemoteId = 0;
    QSet<qint64> m_applied;
    bool m_flushQueued = false;
    bool m_downReported = false;
};

PgHistory::PgHistory(PgHistoryConfig config, QObject* parent) : QObject(parent), m_config(std::move(config)) {
    qRegisterMetaType<QVector<ocu::ConsolePresence>>();
    if (m_config.console.isEmpty())
        m_config.console = QSysInfo::machineHostName();
}

PgHistory::~PgHistory() {
    stop();
}

QString PgHistory::start() {
    if (m_thread)
        return {};
    m_thread = new QThread;
    m_thread->setObjectName(QStringLiteral("ocu-history-pg"));
    m_worker = new PgHistoryWorker(this, m_config);
    m_worker->moveToThread(m_thread);
    connect(m_worker, &PgHistoryWorker::connectionChanged, this, &PgHistory::connectionChanged,
            Qt::QueuedConnection);
    connect(m_worker, &PgHistoryWorker::remote, this, &PgHistory::applyRemote, Qt::QueuedConnection);
    connect(
        m_worker, &PgHistoryWorker::room, this,
        [this](const QVector<ConsolePresence>& room) {
            if (room == m_room)
                return;
            m_room = room;
            emit roomChanged(room);
        },
        Qt::QueuedConnection);
    m_thread->start();
    QString error;
    QMetaObject::invokeMethod(
        m_worker, [&] { error = m_worker->open(); }, Qt::BlockingQueuedConnection);
    if (!error.isEmpty())
        stop();
    else if (m_presence)
        publishPresence(*m_presence);
    return error;
}

void PgHistory::stop() {
    if (!m_thread)
        return;
    // The worker closes its connections on its own thread; records still in the outbox stay there.
    QMetaObject::invokeMethod(
        m_worker, [w = m_worker] { w->close(); }, Qt::BlockingQueuedConnection);
    m_thread->quit();
    m_thread->wait();
    delete m_worker; // its thread has ended and it owns no timer or notifier any more
    delete m_thread;
    m_thread = nullptr;
    m_worker = nullptr;
    m_connected = false;
}

void PgHistory::post(Record r) {
    if (!m_worker)
        return;
    ++m_recorded;
    ++m_queued;
    QMetaObject::invokeMethod(
        m_worker, [w = m_worker, r = std::move(r)] { w->record(r); }, Qt::QueuedConnection);
}

void PgHistory::attach(AlarmModel* alarms) {
    m_alarms = alarms;
    connect(alarms, &AlarmModel::eventAdded, this, &PgHistory::onEvent);
    connect(alarms, &AlarmModel::alarmAcknowledged, this,
            [this](const QString& key, const QString& by, qint64 at) {
                if (!m_applyingRemote)
                    post(Record{QStringLiteral("ack"), at, key, {}, {}, {}, {}, {}, by, 0, {}});
            });
    connect(alarms, &AlarmModel::alarmShelved, this,
            [this](const QString& key, const QString& by, qint64 at, qint64 until) {
                if (!m_applyingRemote)
                    post(Record{QStringLiteral("shelve"), at, key, {}, {}, {}, {}, {}, by, until, {}});
            });
    connect(alarms, &AlarmModel::alarmUnshelved, this,
            [this](const QString& key, const QString& by, qint64 at) {
                if (!m_applyingRemote)
                    post(Record{QStringLiteral("unshelve"), at, key, {}, {}, {}, {}, {}, by, 0, {}});
            });
}

void PgHistory::publishPresence(const ConsolePresence& presence) {
    m_presence = presence;
    if (m_worker)
        QMetaObject::invokeMethod(
            m_worker, [w = m_worker, presence] { w->setPresence(presence); }, Qt::QueuedConnection);
}

void PgHistory::attachGate(CommandGate* gate) {
    m_gateAttached = true;
    connect(gate, &CommandGate::audited, this, [this](const QString& line) {
        QJsonParseError err{};
        const QJsonDocument doc = QJsonDocument::fromJson(line.toUtf8(), &err);
        Record r;
        r.kind = QStringLiteral("audit");
        const QJsonObject o = doc.object();
        const QDateTime t =
            QDateTime::fromString(o.value(QStringLiteral("time")).toString(), Qt::ISODateWithMs);
        r.atMs = t.isValid() ? t.toMSecsSinceEpoch() : QDateTime::currentMSecsSinceEpoch();
        r.by = o.value(QStringLiteral("origin")).toString();
        r.machine = o.value(QStringLiteral("target")).toString();
        r.text = o.value(QStringLiteral("action")).toString() + QStringLiteral(": ") +
                 o.value(QStringLiteral("message")).toString();
        r.severity =
            o.value(QStringLiteral("ok")).toBool() ? QStringLiteral("info") : QStringLiteral("alarm");
        r.details = err.error == QJsonParseError::NoError && doc.isObject()
                        ? doc.toJson(QJsonDocument::Compact)
                        : QJsonDocument(QJsonArray{line}).toJson(QJsonDocument::Compact);
        post(std::move(r));
    });
}

void PgHistory::onEvent(const FleetEvent& e) {
    // The gate's audit lines are recorded whole (attachGate); its info entries in the model are their echo.
    if (m_gateAttached && e.kind == EventKind::Audit && !e.requiresAck)
        return;
    Record r;
    r.kind = e.requiresAck ? QStringLiteral("alarm") : QStringLiteral("event");
    r.atMs = e.timeMs;
    r.key = alarmKey(e);
    r.severity = toText(e.severity);
    if (e.requiresAck)
        r.priority = toText(effectivePriority(e));
    r.machine = e.machineId;
    r.source = e.source;
    r.text = e.text;
    QJsonObject d;
    d[QStringLiteral("kind")] = toText(e.kind);
    if (e.itemCount > 1)
        d[QStringLiteral("count")] = e.itemCount;
    if (!e.details.isEmpty())
        d[QStringLiteral("items")] = QJsonArray::fromStringList(e.details);
    r.details = QJsonDocument(d).toJson(QJsonDocument::Compact);
    post(std::move(r));
}

void PgHistory::applyRemote(const QString& kind, const QString& key, const QString& by, qint64 atMs,
                            qint64 untilMs) {
    if (!m_alarms)
        return;
    m_applyingRemote = true;
    if (kind == QLatin1String("ack")) {
        if (m_alarms->acknowledgeKey(key, by, atMs))
            emit remoteAcknowledged(key, by, atMs);
    } else if (kind == QLatin1String("shelve")) {
        m_alarms->applyShelve(key, by, atMs, untilMs);
    } else if (kind == QLatin1String("unshelve")) {
        m_alarms->unshelve(key, by);
    }
    m_applyingRemote = false;
}

} // namespace ocu

#include "PgHistory.moc"
