// The recorder's writer thread: creating the file, encoding what was queued into state chunks, keyframes,
// message chunks and rows, committing them, trimming a file over its limit and applying the run's retention.
#include "models/recording/RecorderWriter.h"

#include "models/FleetEvent.h"
#include "models/recording/BlobCodec.h"
#include "models/recording/MessageLog.h"
#include "models/recording/RecordSchema.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ctime>

namespace ocu::recording {

namespace {

qint64 threadCpuNs() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return qint64(ts.tv_sec) * 1000000000 + ts.tv_nsec;
}

} // namespace

// A recording is created whole or not at all: its schema and meta data are committed in one transaction
// under a temporary name that neither a reader nor retention takes for a recording, and the file gets its
// name only then (rename(2) is atomic). A console killed while creating it leaves a stray "<name>.part" of a
// few kilobytes (retention removes it), never a file named like a recording that does not open. The file is
// closed before the rename: SQLite names its journals after the path it was opened with.
QString createRecordingFile(const RecorderOptions& options, qint64 startMs, int keyframeIntervalMs) {
    const QString part = options.path + QStringLiteral(".part");
    for (const QString& suffix :
         {QString(), QStringLiteral("-journal"), QStringLiteral("-wal"), QStringLiteral("-shm")})
        QFile::remove(part + suffix);
    sqlite3* db = nullptr;
    auto fail = [&](const QString& what) {
        const QString e = Recorder::tr("cannot create %1: %2")
                              .arg(options.path, db ? QString::fromUtf8(sqlite3_errmsg(db)) : what);
        sqlite3_close(db);
        QFile::remove(part);
        return e;
    };
    if (sqlite3_open_v2(part.toUtf8().constData(), &db,
                        SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_NOMUTEX,
                        nullptr) != SQLITE_OK)
        return fail(QStringLiteral("out of memory"));
    auto exec = [&](const char* sql) {
        return sqlite3_exec(db, sql, nullptr, nullptr, nullptr) == SQLITE_OK;
    };
    // page_size and auto_vacuum are fixed when the first table is created, journal_mode=WAL is kept by the
    // file. Schema 4: 1-KiB pages. A chunk's blob (a few KB) fills overflow pages, and half a page per chunk
    // is lost on average: 4-KiB pages made that a fifth of the file.
    if (!exec(options.legacySchema3 ? "PRAGMA page_size=4096" : "PRAGMA page_size=1024") ||
        !exec("PRAGMA auto_vacuum=INCREMENTAL") || !exec("BEGIN") || !exec(kSchemaSql))
        return fail({});
    {
        Stmt meta(db, "INSERT OR REPLACE INTO meta(key, value) VALUES(?, ?)");
        const QList<QPair<QString, QString>> kv{
            {QStringLiteral("schema"),
             QString::number(options.legacySchema3 ? kLegacySchemaVersion : kSchemaVersion)},
            {QStringLiteral("states_codec"),
             QString::fromLatin1(blobCodecName(options.legacySchema3 ? BlobCodec::Zlib : BlobCodec::Zstd))},
            {QStringLiteral("messages"), options.messages ? QStringLiteral("1") : QStringLiteral("0")},
            {QStringLiteral("messages_codec"),
             QString::fromLatin1(blobCodecName(options.legacySchema3 ? BlobCodec::Zlib : BlobCodec::Zstd))},
            {QStringLiteral("start_ms"), QString::number(startMs)},
            {QStringLiteral("site_name"), options.siteName},
            {QStringLiteral("origin_lat"), QString::number(options.originLat, 'g', 17)},
            {QStringLiteral("origin_lon"), QString::number(options.originLon, 'g', 17)},
            {QStringLiteral("origin_alt"), QString::number(options.originAlt, 'g', 17)},
            {QStringLiteral("raw"), options.raw ? QStringLiteral("1") : QStringLiteral("0")},
            {QStringLiteral("keyframe_interval_ms"), QString::number(keyframeIntervalMs)},
        };
        for (const auto& [k, v] : kv) {
            meta.text(1, k);
            meta.text(2, v);
            if (!meta.run())
                return fail({});
        }
    }
    if (!exec("COMMIT") || !exec("PRAGMA journal_mode=WAL"))
        return fail({});
    sqlite3_close(db);
    db = nullptr;
    if (::rename(QFile::encodeName(part).constData(), QFile::encodeName(options.path).constData()) != 0)
        return fail(QString::fromLocal8Bit(std::strerror(errno)));
    return {};
}

Recorder::Writer::~Writer() {
    insState.reset();
    updState.reset();
    insMachine.reset();
    insKeyframe.reset();
    insEvent.reset();
    insAck.reset();
    insCommand.reset();
    insLink.reset();
    insMap.reset();
    insChannel.reset();
    insMessages.reset();
    insPass.reset();
    insDetail.reset();
    if (db)
        sqlite3_close(db);
}

void Recorder::Writer::addMessage(qint64 t, const QByteArray& packed) {
    UnpackedTapped u;
    if (!unpackTapped(packed, u))
        return;
    auto it = channelOf.find(u.key);
    if (it == channelOf.end()) {
        it = channelOf.insert(u.key, nextChannel++);
        insChannel->i64(1, *it);
        insChannel->text(2, u.channel.protocol);
        insChannel->text(3, u.channel.link);
        insChannel->text(4, u.channel.peer);
        insChannel->text(5, u.channel.type);
        insChannel->run();
    }
    if (!msgChunk.isEmpty() && t - msgT0 > 1000)
        writeMessages();
    if (msgChunk.isEmpty())
        msgT0 = t;
    appendMessage(msgChunk, *it, std::uint32_t(t - msgT0), u.raw, u.data, u.size);
    msgT1 = t;
    ++msgN;
}

void Recorder::Writer::writeMessages() {
    if (msgChunk.isEmpty())
        return;
    insMessages->i64(1, msgT0);
    insMessages->i64(2, msgT1);
    insMessages->i64(3, msgN);
    // Schema 3: zlib at its fastest. Schema 4: zstd (messages_codec), smaller for the same CPU.
    const QByteArray packed = pack(msgChunk);
    insMessages->blob(4, packed);
    insMessages->run();
    messages += quint64(msgN);
    messageBytes += quint64(packed.size());
    msgChunk.clear();
    msgN = 0;
}

std::uint32_t Recorder::Writer::indexOf(const QString& id) {
    auto it = idxOf.find(id);
    if (it != idxOf.end())
        return *it;
    const std::uint32_t idx = nextIdx++;
    idxOf.insert(id, idx);
    insMachine->i64(1, idx);
    insMachine->text(2, id);
    insMachine->run();
    return idx;
}

QByteArray Recorder::Writer::pack(const QByteArray& data) const {
    // Schema 3: zlib at its fastest. Schema 4: zstd, which shrinks the varint records further for less
    // CPU (bench_recording compares both).
    return legacy ? qCompress(data, 1) : compressBlob(data, BlobCodec::Zstd, zstdLevel);
}

// A state record at t: cuts the chunk after 1 s so that a seek decodes little past its target.
void Recorder::Writer::startRecord(qint64 t) {
    if (chunkN > 0 && t - chunkT0 > 1000) {
        writeChunk();
        closeChunk();
    }
    if (chunkN == 0) {
        chunkT0 = t;
        legacyChunk.clear();
        if (enc)
            enc->begin(t);
    }
    chunkT1 = t;
    ++chunkN;
}

void Recorder::Writer::addState(qint64 t, const MachineState& state) {
    const std::uint32_t idx = indexOf(state.id);
    startRecord(t);
    const auto dt = std::int32_t(t - chunkT0);
    auto prev = last.find(idx);
    const bool same = prev != last.end() && sameStatus(*prev, state);
    if (!legacy) {
        if (!same || !enc->move(idx, t, *prev, state)) {
            enc->full(idx, t, state);
            last.insert(idx, state);
        }
        return;
    }
    if (same && positionEncodable(state)) {
        if (positionEncodable(*prev))
            appendDelta(legacyChunk, idx, dt, t, *prev, state);
        else
            appendPosition(legacyChunk, idx, dt, t, state);
        // What a replay will see: the quantised position (keyframes carry the same).
        applyPosition(*prev, state, t);
    } else {
        appendFull(legacyChunk, idx, dt, state);
        last.insert(idx, state);
    }
}

void Recorder::Writer::addRemoval(qint64 t, const QString& id) {
    const std::uint32_t idx = indexOf(id);
    startRecord(t);
    if (enc)
        enc->removed(idx, t);
    else
        appendRemoved(legacyChunk, idx, std::int32_t(t - chunkT0));
    last.remove(idx);
}

// Writes the chunk being filled: a new row, or (schema 4) the open row again with what came since. Schema
// 4 keeps a chunk open over the commits of up to 1 s: every commit still holds everything recorded so
// far, and a chunk of 1 s instead of one commit's 200 ms compresses better and loses a fifth as many half
// pages.
void Recorder::Writer::writeChunk() {
    if (chunkN == 0)
        return;
    const QByteArray chunk = enc ? enc->data() : legacyChunk;
    const QByteArray packed = pack(chunk);
    if (openChunkId != 0) {
        updState->i64(1, chunkT1);
        updState->i64(2, chunkN);
        updState->blob(3, packed);
        updState->i64(4, openChunkId);
        updState->run();
        stateBytes -= openChunkBytes;
        stateRawBytes -= openChunkRawBytes;
    } else {
        insState->i64(1, chunkT0);
        insState->i64(2, chunkT1);
        insState->i64(3, chunkN);
        insState->blob(4, packed);
        insState->run();
        openChunkId = sqlite3_last_insert_rowid(db);
    }
    lastChunkId = openChunkId;
    lastChunkT1 = chunkT1;
    openChunkBytes = quint64(packed.size());
    openChunkRawBytes = quint64(chunk.size());
    stateBytes += openChunkBytes;
    stateRawBytes += openChunkRawBytes;
    if (legacy)
        closeChunk(); // schema 3: one chunk per commit, as that writer did
}
// The next record starts a new chunk (a keyframe refers to the chunks before it, never to one still
// open).
void Recorder::Writer::closeChunk() {
    openChunkId = 0;
    openChunkBytes = openChunkRawBytes = 0;
    chunkN = 0;
}

void Recorder::Writer::writeKeyframe(qint64 t) {
    QByteArray data;
    if (legacy) {
        for (auto it = last.cbegin(); it != last.cend(); ++it)
            appendFull(data, it.key(), 0, it.value());
    } else {
        ChunkEncoder kf(nullptr);
        kf.begin(t);
        for (auto it = last.cbegin(); it != last.cend(); ++it)
            kf.full(it.key(), t, it.value());
        data = kf.data();
    }
    const QByteArray packed = pack(data);
    insKeyframe->i64(1, t);
    insKeyframe->i64(2, lastChunkId);
    insKeyframe->i64(3, last.size());
    insKeyframe->blob(4, packed);
    insKeyframe->run();
    keyframeBytes += quint64(packed.size());
    lastKeyframeT = t;
}

// The file over its limit: the machine data before the keyframe a quarter into the file goes (that
// keyframe keeps the picture from there on); events, commands and links stay (they are small).
void Recorder::Writer::trimIfNeeded(qint64 t) {
    if (maxFileBytes <= 0 || t - lastTrimCheckT < 10000)
        return;
    lastTrimCheckT = t;
    Stmt size(db, "SELECT page_count * page_size FROM pragma_page_count(), pragma_page_size()");
    if (sqlite3_step(size.s) != SQLITE_ROW || sqlite3_column_int64(size.s, 0) <= maxFileBytes)
        return;
    Stmt kf(db,
            "SELECT t, chunk FROM keyframes ORDER BY t LIMIT 1 OFFSET (SELECT COUNT(*) / 4 FROM keyframes)");
    if (sqlite3_step(kf.s) != SQLITE_ROW)
        return;
    const qint64 kt = sqlite3_column_int64(kf.s, 0), chunk = sqlite3_column_int64(kf.s, 1);
    Stmt delS(db, "DELETE FROM states WHERE id <= ?");
    delS.i64(1, chunk);
    delS.run();
    Stmt delM(db, "DELETE FROM messages WHERE t1 < ?");
    delM.i64(1, kt);
    delM.run();
    Stmt delK(db, "DELETE FROM keyframes WHERE t < ?");
    delK.i64(1, kt);
    delK.run();
    Stmt meta(db, "INSERT OR REPLACE INTO meta(key, value) VALUES('trimmed_before_ms', ?)");
    meta.text(1, QString::number(kt));
    meta.run();
}
QString Recorder::Writer::open(const RecorderOptions& options) {
    if (sqlite3_open_v2(options.path.toUtf8().constData(), &db, SQLITE_OPEN_READWRITE | SQLITE_OPEN_NOMUTEX,
                        nullptr) != SQLITE_OK) {
        const QString err = db ? QString::fromUtf8(sqlite3_errmsg(db)) : Recorder::tr("out of memory");
        return Recorder::tr("cannot create %1: %2").arg(options.path, err);
    }
    sqlite3_busy_timeout(db, 2000);
    // Schema 4: 1-KiB pages. A chunk's blob (a few KB) fills overflow pages, and half a page per chunk is
    // lost on average: 4-KiB pages made that a fifth of the file.
    if (!exec(options.legacySchema3 ? "PRAGMA page_size=4096" : "PRAGMA page_size=1024") ||
        !exec("PRAGMA auto_vacuum=INCREMENTAL") || !exec("PRAGMA journal_mode=WAL") ||
        !exec("PRAGMA synchronous=NORMAL") || !exec(kSchemaSql))
        return Recorder::tr("cannot create the recording schema in %1: %2")
            .arg(options.path, QString::fromUtf8(sqlite3_errmsg(db)));
    insState = std::make_unique<Stmt>(db, "INSERT INTO states(t0, t1, n, data) VALUES(?,?,?,?)");
    updState = std::make_unique<Stmt>(db, "UPDATE states SET t1 = ?, n = ?, data = ? WHERE id = ?");
    insMachine = std::make_unique<Stmt>(db, "INSERT OR REPLACE INTO machines(idx, id) VALUES(?,?)");
    insKeyframe =
        std::make_unique<Stmt>(db, "INSERT OR REPLACE INTO keyframes(t, chunk, n, data) VALUES(?,?,?,?)");
    insEvent = std::make_unique<Stmt>(db, "INSERT INTO events(t, time_ms, severity, kind, machine, source, "
                                          "text, requires_ack, key) VALUES(?,?,?,?,?,?,?,?,?)");
    insAck = std::make_unique<Stmt>(db, "INSERT INTO acks(t, key, by, at_ms) VALUES(?,?,?,?)");
    insCommand = std::make_unique<Stmt>(db, "INSERT INTO commands(t, origin, action, target, ok, audit) "
                                            "VALUES(?,?,?,?,?,?)");
    insLink = std::make_unique<Stmt>(db, "INSERT INTO links(t, protocol, link, state, age_ms, detail) "
                                         "VALUES(?,?,?,?,?,?)");
    insMap = std::make_unique<Stmt>(db, "INSERT INTO sitemaps(t, data) VALUES(?,?)");
    insChannel = std::make_unique<Stmt>(
        db, "INSERT OR REPLACE INTO msg_channels(idx, protocol, link, peer, type) VALUES(?,?,?,?,?)");
    insMessages = std::make_unique<Stmt>(db, "INSERT INTO messages(t0, t1, n, data) VALUES(?,?,?,?)");
    insPass = std::make_unique<Stmt>(db, "INSERT INTO passcounts(t, data) VALUES(?,?)");
    insDetail = std::make_unique<Stmt>(db, "INSERT INTO details(t, machine, kind, data) VALUES(?,?,?,?)");
    legacy = options.legacySchema3;
    zstdLevel = options.zstdLevel;
    if (!legacy) {
        // The frame the bridges put the fleet's e/n/u in: a Move's lat/lon are derived from them through it.
        frame = std::make_unique<GeoFrame>(GeoPoint{options.originLat, options.originLon, options.originAlt});
        enc = std::make_unique<ChunkEncoder>(frame.get());
    }
    maxFileBytes = options.maxFileBytes;
    return {};
}

void Recorder::Writer::write(const Item& it) {
    switch (it.kind) {
    case Item::State:
        addState(it.t, it.state);
        break;
    case Item::Removed:
        addRemoval(it.t, it.a);
        break;
    case Item::Event: {
        Stmt& s = *insEvent;
        s.i64(1, it.t);
        s.i64(2, it.event.timeMs);
        s.i64(3, int(it.event.severity));
        s.i64(4, int(it.event.kind));
        s.text(5, it.event.machineId);
        s.text(6, it.event.source);
        s.text(7, it.event.text);
        s.i64(8, it.event.requiresAck ? 1 : 0);
        s.text(9, ocu::alarmKey(it.event)); // the key AlarmModel and the consoles share
        s.run();
        break;
    }
    case Item::Ack: {
        Stmt& s = *insAck;
        s.i64(1, it.t);
        s.text(2, it.a);
        s.text(3, it.b);
        s.i64(4, it.x);
        s.run();
        break;
    }
    case Item::Command: {
        const QJsonObject o = QJsonDocument::fromJson(it.a.toUtf8()).object();
        Stmt& s = *insCommand;
        s.i64(1, it.t);
        s.text(2, o.value(QStringLiteral("origin")).toString());
        s.text(3, o.value(QStringLiteral("action")).toString());
        s.text(4, o.value(QStringLiteral("target")).toString());
        s.i64(5, o.value(QStringLiteral("ok")).toBool() ? 1 : 0);
        s.text(6, it.a);
        s.run();
        break;
    }
    case Item::Link: {
        Stmt& s = *insLink;
        s.i64(1, it.t);
        s.text(2, it.a);
        s.text(3, it.b);
        s.i64(4, it.i);
        s.i64(5, it.x);
        s.text(6, it.c);
        s.run();
        break;
    }
    case Item::SiteMap: {
        Stmt& s = *insMap;
        s.i64(1, it.t);
        s.blob(2, it.blob);
        s.run();
        break;
    }
    case Item::Meta: {
        Stmt s(db, "INSERT OR REPLACE INTO meta(key, value) VALUES(?, ?)");
        s.text(1, it.a);
        s.text(2, it.c);
        s.run();
        break;
    }
    case Item::Message:
        addMessage(it.t, it.blob);
        break;
    case Item::PassCounts: {
        Stmt& s = *insPass;
        s.i64(1, it.t);
        s.blob(2, qCompress(it.blob, 1));
        s.run();
        break;
    }
    case Item::Detail: {
        Stmt& s = *insDetail;
        s.i64(1, it.t);
        s.text(2, it.a);
        s.text(3, it.b);
        s.blob(4, it.blob);
        s.run();
        break;
    }
    }
}

void Recorder::run() {
    Writer& w = *m_writer;
    std::vector<Item> batch;
    const qint64 cpu0 = threadCpuNs();
    for (;;) {
        bool stopping = false;
        {
            std::unique_lock lk(m_mutex);
            m_cv.wait_for(lk, std::chrono::milliseconds(m_options.flushIntervalMs),
                          [&] { return m_stopRequested || m_flushRequested; });
            m_flushRequested = false;
            batch.swap(m_queue);
            stopping = m_stopRequested;
        }
        if (!batch.empty())
            commit(batch);
        {
            std::lock_guard lk(m_mutex);
            m_writtenSeq += batch.size();
        }
        batch.clear();
        m_writerCpuNs.store(quint64(threadCpuNs() - cpu0), std::memory_order_relaxed);
        m_flushedCv.notify_all();
        if (stopping) {
            std::lock_guard lk(m_mutex);
            if (m_queue.empty())
                break;
        }
    }
    {
        Stmt end(w.db, "INSERT OR REPLACE INTO meta(key, value) VALUES('closed', '1')");
        end.run();
    }
    w.exec("PRAGMA wal_checkpoint(TRUNCATE)");
    std::lock_guard lk(m_mutex);
    m_flushedCv.notify_all();
}

void Recorder::commit(const std::vector<Item>& batch) {
    Writer& w = *m_writer;
    w.exec("BEGIN");
    for (const Item& it : batch)
        w.write(it);
    w.writeChunk();
    w.writeMessages();
    const qint64 lastT = batch.back().t;
    if (lastT - w.lastKeyframeT >= w.keyframeIntervalMs) {
        w.closeChunk();
        w.writeKeyframe(std::max(lastT, w.lastChunkT1));
    }
    Stmt end(w.db, "INSERT OR REPLACE INTO meta(key, value) VALUES('end_ms', ?)");
    end.text(1, QString::number(lastT));
    end.run();
    w.trimIfNeeded(lastT);
    w.exec("COMMIT");
    if (w.maxFileBytes > 0)
        w.exec("PRAGMA incremental_vacuum");
    retainDuringRun(lastT);
    m_commits.fetch_add(1, std::memory_order_relaxed);
    m_stateBytes.store(w.stateBytes, std::memory_order_relaxed);
    m_stateRawBytes.store(w.stateRawBytes, std::memory_order_relaxed);
    m_keyframeBytes.store(w.keyframeBytes, std::memory_order_relaxed);
    m_messages.store(w.messages, std::memory_order_relaxed);
    m_messageBytes.store(w.messageBytes, std::memory_order_relaxed);
}

// Every retentionIntervalMs of recording time: the folder's older runs over its limits go, this one stays.
void Recorder::retainDuringRun(qint64 t) {
    Writer& w = *m_writer;
    const bool limited = m_options.maxTotalBytes > 0 || m_options.maxAgeDays > 0;
    if (m_options.retentionDir.isEmpty() || !limited ||
        t - w.lastRetentionT < std::max(1000, m_options.retentionIntervalMs))
        return;
    w.lastRetentionT = t;
    const QStringList gone =
        applyRetention(m_options.retentionDir, m_options.maxTotalBytes, m_options.maxAgeDays, m_options.path);
    if (!gone.isEmpty()) {
        std::lock_guard lk(m_mutex);
        m_retentionDeleted += gone;
    }
}

} // namespace ocu::recording
