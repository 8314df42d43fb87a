#pragma once
// The presence table of the shared control-room history (ocu_presence): one row per console saying who is
// signed in there, with which role, since when, whether it is locked, the addresses its stacks control
// machines with, and a heartbeat. PgHistory's worker runs these on its own connection (worker thread only,
// never the GUI thread). A clean exit deletes the console's row; a crashed console's row stays and its
// heartbeat ages: older than the stale timeout, it reads as stale. docs/recording.md ("Who is where").
#include "models/ControlRoomModel.h"

#include <optional>

struct pg_conn;

namespace ocu {

class PgPresence {
public:
    PgPresence(QString console, int staleAfterMs) : m_console(std::move(console)), m_staleMs(staleAfterMs) {}

    // The table, its index and its NOTIFY trigger; run inside the history's schema transaction.
    static const char* schemaSql();
    // The channel its trigger notifies when a console's presence changes (not on a heartbeat alone).
    static const char* channel() { return "ocu_presence"; }

    // What this console publishes from now on (also after every reconnection).
    void set(const ConsolePresence& mine) { m_mine = mine; }
    bool hasPresence() const { return m_mine.has_value(); }
    // Writes this console's row (insert or replace); false when the connection failed.
    bool publish(pg_conn* c);
    // Refreshes the heartbeat (re-publishes a row someone deleted); false when the connection failed.
    bool heartbeat(pg_conn* c);
    // Deletes this console's row at a clean exit, waiting at most timeoutMs for the server; true when the
    // server deleted it in time (false also when nothing was published).
    bool end(pg_conn* c, int timeoutMs);
    // Every console's row, stale ones marked by the database's clock; nullopt when the query failed.
    std::optional<QVector<ConsolePresence>> readRoom(pg_conn* c) const;

private:
    QString m_console;
    int m_staleMs;
    std::optional<ConsolePresence> m_mine;
};

} // namespace ocu
