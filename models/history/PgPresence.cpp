#include "models/history/PgPresence.h"

#include "models/OperatorSession.h"
#include "models/history/PgHistory.h"

#include <QDateTime>
#include <QJsonArray>
#include <QJsonDocument>

#include <libpq-fe.h>
#include <poll.h>

#include <QElapsedTimer>

namespace ocu {

namespace {

// Added to a database created before it like every table of the history: IF NOT EXISTS, under the schema
// transaction's advisory lock. The trigger tells the other consoles at once when someone signs in, switches,
// locks or leaves; a heartbeat alone notifies nobody (each console re-reads the room on its own heartbeat).
constexpr const char* kPresenceSchemaSql = R"sql(
CREATE TABLE IF NOT EXISTS ocu_presence (
    console              text        PRIMARY KEY,
    operator             text        NOT NULL,
    role                 text        NOT NULL,
    since                timestamptz NOT NULL,
    locked               boolean     NOT NULL DEFAULT false,
    controller_addresses text[]      NOT NULL DEFAULT '{}',
    heartbeat            timestamptz NOT NULL DEFAULT now()
);
CREATE OR REPLACE FUNCTION ocu_presence_notify() RETURNS trigger LANGUAGE plpgsql AS $$
BEGIN
    PERFORM pg_notify('ocu_presence', coalesce(NEW.console, OLD.console));
    RETURN NULL;
END $$;
CREATE OR REPLACE TRIGGER ocu_presence_changed AFTER INSERT OR DELETE ON ocu_presence FOR EACH ROW
    EXECUTE FUNCTION ocu_presence_notify();
CREATE OR REPLACE TRIGGER ocu_presence_updated AFTER UPDATE ON ocu_presence FOR EACH ROW
    WHEN ((OLD.operator, OLD.role, OLD.since, OLD.locked, OLD.controller_addresses) IS DISTINCT FROM
          (NEW.operator, NEW.role, NEW.since, NEW.locked, NEW.controller_addresses))
    EXECUTE FUNCTION ocu_presence_notify();
)sql";

constexpr const char* kPresenceUpsertSql =
    "INSERT INTO ocu_presence (console, operator, role, since, locked, controller_addresses, heartbeat) "
    "VALUES ($1, $2, $3, to_timestamp($4::bigint / 1000.0), $5::boolean, "
    "ARRAY(SELECT json_array_elements_text($6::json)), now()) ON CONFLICT (console) DO UPDATE SET "
    "operator = EXCLUDED.operator, role = EXCLUDED.role, since = EXCLUDED.since, locked = EXCLUDED.locked, "
    "controller_addresses = EXCLUDED.controller_addresses, heartbeat = now()";

constexpr const char* kPresenceRoomSql =
    "SELECT console, operator, role, (extract(epoch FROM since) * 1000)::bigint, locked, "
    "array_to_json(controller_addresses)::text, (extract(epoch FROM heartbeat) * 1000)::bigint, "
    "heartbeat < now() - ($1::bigint * interval '1 millisecond') FROM ocu_presence ORDER BY console";

QByteArray presenceText(const QString& s) {
    QByteArray b = s.toUtf8();
    b.replace('\0', "");
    return b;
}

bool presenceOk(PGresult* r) {
    const auto st = PQresultStatus(r);
    return st == PGRES_COMMAND_OK || st == PGRES_TUPLES_OK;
}

} // namespace

const char* PgPresence::schemaSql() {
    return kPresenceSchemaSql;
}

bool PgPresence::publish(pg_conn* c) {
    if (!m_mine)
        return true;
    const QByteArray console = presenceText(m_console), op = presenceText(m_mine->operatorName),
                     role = presenceText(m_mine->role), since = QByteArray::number(m_mine->sinceMs),
                     locked = m_mine->locked ? QByteArray("true") : QByteArray("false"),
                     addresses = QJsonDocument(QJsonArray::fromStringList(m_mine->controllerAddresses))
                                     .toJson(QJsonDocument::Compact);
    const char* p[] = {console.constData(), op.constData(),     role.constData(),
                       since.constData(),   locked.constData(), addresses.constData()};
    PGresult* r = PQexecParams(c, kPresenceUpsertSql, 6, nullptr, p, nullptr, nullptr, 0);
    const bool ok = presenceOk(r);
    PQclear(r);
    return ok;
}

bool PgPresence::heartbeat(pg_conn* c) {
    if (!m_mine)
        return true;
    const QByteArray console = presenceText(m_console);
    const char* p[] = {console.constData()};
    PGresult* r = PQexecParams(c, "UPDATE ocu_presence SET heartbeat = now() WHERE console = $1", 1, nullptr,
                               p, nullptr, nullptr, 0);
    const bool ok = presenceOk(r);
    const bool gone = ok && QByteArray(PQcmdTuples(r)) == "0";
    PQclear(r);
    return ok && (!gone || publish(c));
}

bool PgPresence::end(pg_conn* c, int timeoutMs) {
    if (!m_mine)
        return false;
    m_mine.reset();
    // Bounded: an exit must not hang on a server that stopped answering (the row then goes stale).
    const QByteArray console = presenceText(m_console);
    const char* p[] = {console.constData()};
    if (!PQsendQueryParams(c, "DELETE FROM ocu_presence WHERE console = $1", 1, nullptr, p, nullptr, nullptr,
                           0))
        return false;
    QElapsedTimer t;
    t.start();
    bool ok = false;
    while (true) {
        if (!PQconsumeInput(c))
            return false;
        if (!PQisBusy(c)) {
            while (PGresult* r = PQgetResult(c)) {
                ok = ok || presenceOk(r);
                PQclear(r);
            }
            return ok;
        }
        const qint64 left = timeoutMs - t.elapsed();
        if (left <= 0)
            return false;
        pollfd fd{PQsocket(c), POLLIN, 0};
        if (poll(&fd, 1, int(left)) < 0)
            return false;
    }
}

std::optional<QVector<ConsolePresence>> PgPresence::readRoom(pg_conn* c) const {
    const QByteArray stale = QByteArray::number(m_staleMs);
    const char* p[] = {stale.constData()};
    PGresult* r = PQexecParams(c, kPresenceRoomSql, 1, nullptr, p, nullptr, nullptr, 0);
    if (PQresultStatus(r) != PGRES_TUPLES_OK) {
        PQclear(r);
        return std::nullopt;
    }
    QVector<ConsolePresence> room;
    for (int i = 0; i < PQntuples(r); ++i) {
        ConsolePresence s;
        s.console = QString::fromUtf8(PQgetvalue(r, i, 0));
        s.operatorName = QString::fromUtf8(PQgetvalue(r, i, 1));
        s.role = QString::fromUtf8(PQgetvalue(r, i, 2));
        s.sinceMs = QByteArray(PQgetvalue(r, i, 3)).toLongLong();
        s.locked = QByteArray(PQgetvalue(r, i, 4)) == "t";
        for (const QJsonValue& a : QJsonDocument::fromJson(PQgetvalue(r, i, 5)).array())
            s.controllerAddresses << a.toString();
        s.heartbeatMs = QByteArray(PQgetvalue(r, i, 6)).toLongLong();
        s.stale = QByteArray(PQgetvalue(r, i, 7)) == "t";
        room << s;
    }
    PQclear(r);
    return room;
}

// PgHistory's side (GUI thread): the operator session's changes become this console's presence.
void PgHistory::attachSession(OperatorSession* session, const QStringList& controllerAddresses) {
    // Since: when this operator signed in (a lock keeps it, a switch starts it again).
    auto since = std::make_shared<qint64>(QDateTime::currentMSecsSinceEpoch());
    auto publish = [this, session, controllerAddresses, since] {
        const OperatorIdentity who = session->current();
        publishPresence(
            {m_config.console, who.user, who.roleText(), *since, session->isLocked(), controllerAddresses});
    };
    connect(session, &OperatorSession::operatorChanged, this, [since, publish] {
        *since = QDateTime::currentMSecsSinceEpoch();
        publish();
    });
    connect(session, &OperatorSession::lockedChanged, this, publish);
    publish();
}

} // namespace ocu
