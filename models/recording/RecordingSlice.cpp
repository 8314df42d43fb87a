// A slice of a recording: a new recording file holding one time window - a keyframe at its start, the
// machine changes re-encoded as the recorder writes them, and the other tables' rows of the window.
#include "models/recording/Recording.h"

#include "models/recording/RecordSchema.h"
#include "models/recording/Recorder.h"
#include "models/recording/RecordingQuery.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>

#include <sqlite3.h>

#include <algorithm>
#include <utility>

namespace ocu::recording {

namespace {

bool exec(sqlite3* db, const char* sql) {
    return sqlite3_exec(db, sql, nullptr, nullptr, nullptr) == SQLITE_OK;
}

// The new file's schema, the source attached as "src", its meta data and machines, and the meta data of the
// window; all in the transaction begun here.
bool beginSlice(sqlite3* dst, const QString& srcPath, qint64 from, qint64 to) {
    // 1-KiB pages as the recorder writes schema 4 (less of each chunk's last overflow page lost).
    bool ok = exec(dst, "PRAGMA page_size=1024") && exec(dst, "PRAGMA journal_mode=WAL") &&
              exec(dst, kSchemaSql) && exec(dst, "BEGIN");
    {
        Query attach(dst, "ATTACH DATABASE ? AS src");
        attach.bind(1, srcPath);
        ok = ok && attach.run();
    }
    ok = ok && exec(dst, "INSERT INTO meta SELECT * FROM src.meta") &&
         exec(dst, "INSERT INTO machines SELECT * FROM src.machines");
    Query q(dst, "INSERT OR REPLACE INTO meta(key, value) VALUES(?, ?)");
    for (const auto& [k, v] : {std::pair{QStringLiteral("start_ms"), QString::number(from)},
                               std::pair{QStringLiteral("end_ms"), QString::number(to)},
                               std::pair{QStringLiteral("slice_of"), QFileInfo(srcPath).fileName()},
                               std::pair{QStringLiteral("schema"), QString::number(kSchemaVersion)},
                               std::pair{QStringLiteral("states_codec"), QStringLiteral("zstd")}}) {
        q.bind(1, k).bind(2, v);
        ok = ok && q.run();
    }
    return ok;
}

// Everything else of the window; the site map and the links as they were at its start, the pass counts and
// the protocols' own records up to its end, the inbound messages overlapping it.
void copyWindowRows(sqlite3* dst, sqlite3* src, qint64 from, qint64 to, bool& ok) {
    for (const char* sql :
         {"INSERT INTO events(t, time_ms, severity, kind, machine, source, text, requires_ack, key) SELECT "
          "t, "
          "time_ms, severity, kind, machine, source, text, requires_ack, key FROM src.events WHERE t >= ?1 "
          "AND t <= ?2",
          "INSERT INTO acks(t, key, by, at_ms) SELECT t, key, by, at_ms FROM src.acks WHERE t >= ?1 AND t <= "
          "?2",
          "INSERT INTO commands(t, origin, action, target, ok, audit) SELECT t, origin, action, target, ok, "
          "audit "
          "FROM src.commands WHERE t >= ?1 AND t <= ?2",
          "INSERT INTO links(t, protocol, link, state, age_ms, detail) SELECT t, protocol, link, state, "
          "age_ms, detail "
          "FROM src.links WHERE t <= ?2",
          "INSERT INTO sitemaps(t, data) SELECT t, data FROM src.sitemaps WHERE t <= ?2"}) {
        Query q(dst, sql);
        q.bind(1, from).bind(2, to);
        ok = ok && q.run();
    }
    // Pass counts up to the end (the counts at `from` are the changes before it applied).
    if (Query has(src, "SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = 'passcounts'");
        has.next()) {
        Query q(
            dst,
            "INSERT INTO passcounts(t, data) SELECT t, data FROM src.passcounts WHERE t <= ?2 ORDER BY id");
        q.bind(2, to);
        ok = ok && q.run();
    }
    // The protocols' own records up to the end: like the links, the picture at `from` is built from those
    // before it (a mission's driven path grows record by record).
    if (Query has(src, "SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = 'details'"); has.next()) {
        Query q(dst, "INSERT INTO details(t, machine, kind, data) SELECT t, machine, kind, data FROM "
                     "src.details WHERE t <= ?2 ORDER BY id");
        q.bind(2, to);
        ok = ok && q.run();
    }
    // Inbound messages (schema 2): the chunks overlapping the window (a chunk spans at most ~1 s).
    if (Query has(src, "SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = 'messages'"); has.next())
        for (const char* sql :
             {"INSERT INTO msg_channels SELECT * FROM src.msg_channels",
              "INSERT INTO messages(t0, t1, n, data) SELECT t0, t1, n, data FROM src.messages "
              "WHERE t1 >= ?1 AND t0 <= ?2 ORDER BY id"}) {
            Query q(dst, sql);
            q.bind(1, from).bind(2, to);
            ok = ok && q.run();
        }
}

} // namespace

// The picture at `from` as a keyframe, then the machine changes re-encoded (as the recorder does): schema 4,
// Moves' lat/lon derived through the same site frame, a chunk per second, a keyframe per keyframe interval.
void Recording::writeSliceStates(sqlite3* dst, qint64 from, qint64 to, bool& ok) const {
    QHash<std::uint32_t, MachineState> last = statesAtIdx(from);
    QHash<QString, std::uint32_t> idxOf;
    for (auto it = m_ids.cbegin(); it != m_ids.cend(); ++it)
        idxOf.insert(it.value(), it.key());
    auto keyframe = [&](qint64 t) {
        ChunkEncoder k(nullptr);
        k.begin(t);
        for (auto it = last.cbegin(); it != last.cend(); ++it)
            k.full(it.key(), t, *it);
        return compressBlob(k.data(), BlobCodec::Zstd, RecorderOptions().zstdLevel);
    };
    Query insKf(dst, "INSERT OR REPLACE INTO keyframes(t, chunk, n, data) VALUES(?,?,?,?)");
    insKf.bind(1, from).bind(2, 0).bind(3, last.size()).bind(4, keyframe(from));
    ok = ok && insKf.run();
    Query insState(dst, "INSERT INTO states(t0, t1, n, data) VALUES(?,?,?,?)");
    ChunkEncoder chunk(&m_frame);
    qint64 t1 = 0, lastKeyframe = from, chunkId = 0;
    int n = 0;
    const qint64 kfInterval =
        std::max<qint64>(100, meta(QStringLiteral("keyframe_interval_ms")).toLongLong());
    auto flushChunk = [&] {
        if (n == 0)
            return;
        insState.bind(1, chunk.t0())
            .bind(2, t1)
            .bind(3, n)
            .bind(4, compressBlob(chunk.data(), BlobCodec::Zstd, RecorderOptions().zstdLevel));
        ok = ok && insState.run();
        chunkId = sqlite3_last_insert_rowid(dst);
        n = 0;
        if (t1 - lastKeyframe >= kfInterval) {
            insKf.bind(1, t1).bind(2, chunkId).bind(3, last.size()).bind(4, keyframe(t1));
            ok = ok && insKf.run();
            lastKeyframe = t1;
        }
    };
    changes(from, to, [&](const StateChange& c) {
        if (n > 0 && c.t - chunk.t0() > 1000)
            flushChunk();
        if (n == 0)
            chunk.begin(c.t);
        t1 = c.t;
        ++n;
        const std::uint32_t idx = idxOf.value(c.state.id);
        if (c.removed) {
            chunk.removed(idx, c.t);
            last.remove(idx);
            return ok;
        }
        auto p = last.find(idx);
        if (p == last.end() || !sameStatus(*p, c.state) || !chunk.move(idx, c.t, *p, c.state)) {
            chunk.full(idx, c.t, c.state);
            last.insert(idx, c.state);
        }
        return ok;
    });
    flushChunk();
}

bool Recording::exportSlice(const QString& path, qint64 from, qint64 to, QString* error) const {
    auto fail = [&](const QString& why) {
        if (error)
            *error = why;
        return false;
    };
    if (QFileInfo::exists(path))
        return fail(QCoreApplication::translate("Recording", "%1 exists already").arg(path));
    if (to < from)
        return fail(QCoreApplication::translate("Recording", "the window ends before it starts"));
    sqlite3* dst = nullptr;
    if (sqlite3_open_v2(path.toUtf8().constData(), &dst, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE,
                        nullptr) != SQLITE_OK) {
        const QString why = dst ? QString::fromUtf8(sqlite3_errmsg(dst)) : QString();
        sqlite3_close(dst);
        return fail(QCoreApplication::translate("Recording", "cannot create %1: %2").arg(path, why));
    }
    bool ok = beginSlice(dst, m_path, from, to);
    writeSliceStates(dst, from, to, ok);
    copyWindowRows(dst, m_db, from, to, ok);
    ok = ok && exec(dst, "COMMIT") && exec(dst, "DETACH DATABASE src") &&
         exec(dst, "PRAGMA wal_checkpoint(TRUNCATE)");
    const QString why = QString::fromUtf8(sqlite3_errmsg(dst));
    sqlite3_close(dst);
    if (!ok) {
        for (const QString& suffix : {QString(), QStringLiteral("-wal"), QStringLiteral("-shm")})
            QFile::remove(path + suffix);
        return fail(QCoreApplication::translate("Recording", "slice to %1 failed: %2").arg(path, why));
    }
    return true;
}

} // namespace ocu::recording
