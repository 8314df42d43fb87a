#pragma once
// The reader's and the exporters' SQLite statement (Recording.cpp, RecordingJsonExport.cpp,
// RecordingCsvExport.cpp, RecordingSlice.cpp), and the time format of the exports.
#include <QByteArray>
#include <QDateTime>
#include <QString>

#include <sqlite3.h>

namespace ocu::recording {

// A prepared statement (nullptr when SQLite refused it: every call is then a no-op that finds nothing),
// finalized on scope exit.
struct Query {
    sqlite3_stmt* s = nullptr;
    Query(sqlite3* db, const char* sql) {
        if (sqlite3_prepare_v2(db, sql, -1, &s, nullptr) != SQLITE_OK)
            s = nullptr;
    }
    ~Query() { sqlite3_finalize(s); }
    Query(const Query&) = delete;
    Query& operator=(const Query&) = delete;
    Query& bind(int i, qint64 v) {
        if (s)
            sqlite3_bind_int64(s, i, v);
        return *this;
    }
    Query& bind(int i, const QString& v) {
        if (s) {
            const QByteArray u = v.toUtf8();
            sqlite3_bind_text(s, i, u.constData(), int(u.size()), SQLITE_TRANSIENT);
        }
        return *this;
    }
    Query& bind(int i, const QByteArray& v) {
        if (s)
            sqlite3_bind_blob(s, i, v.constData(), int(v.size()), SQLITE_TRANSIENT);
        return *this;
    }
    bool next() { return s && sqlite3_step(s) == SQLITE_ROW; }
    bool run() {
        if (!s)
            return false;
        const int rc = sqlite3_step(s);
        sqlite3_reset(s);
        return rc == SQLITE_DONE || rc == SQLITE_ROW;
    }
    qint64 i64(int c) const { return sqlite3_column_int64(s, c); }
    QString text(int c) const {
        return QString::fromUtf8(reinterpret_cast<const char*>(sqlite3_column_text(s, c)),
                                 sqlite3_column_bytes(s, c));
    }
    QByteArray blob(int c) const {
        // A copy: the column's memory is valid only until the next step.
        return QByteArray(static_cast<const char*>(sqlite3_column_blob(s, c)), sqlite3_column_bytes(s, c));
    }
};

// ISO 8601 UTC with milliseconds, as the exports write times.
inline QString isoTime(qint64 ms) {
    return QDateTime::fromMSecsSinceEpoch(ms, Qt::UTC).toString(Qt::ISODateWithMs);
}

} // namespace ocu::recording
