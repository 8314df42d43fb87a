#include "models/recording/Recorder.h"

#include "models/AlarmModel.h"
#include "models/CommandGate.h"
#include "models/FleetBridge.h"
#include "models/FleetContext.h"
#include "models/FleetModel.h"
#include "models/recording/BlobCodec.h"
#include "models/recording/MessageLog.h"
#include "models/recording/PassCountLog.h"
#include "models/recording/RecordCodec.h"
#include "models/recording/RecordSchema.h"
#include "protocols/common/MessageTap.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTimer>

#include <sqlite3.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ctime>

namespace ocu::recording {

struct Recorder::Item {
    enum Kind : std::uint8_t {
        State,
        Removed,
        Event,
        Ack,
        Command,
        Link,
        SiteMap,
        Meta,
        Message,
        PassCounts
    } kind = State;
    qint64 t = 0;
    MachineState state;
    FleetEvent event;
    QString a, b, c;
    QByteArray blob;
    qint64 x = 0;
    int i = 0;
};

namespace {

qint64 threadCpuNs() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return qint64(ts.tv_sec) * 1000000000 + ts.tv_nsec;
}

// A prepared statement, finalized on scope exit.
struct Stmt {
    sqlite3_stmt* s = nullptr;
    Stmt(sqlite3* db, const char* sql) { sqlite3_prepare_v2(db, sql, -1, &s, nullptr); }
    ~Stmt() { sqlite3_finalize(s); }
    Stmt(const Stmt&) = delete;
    Stmt& operator=(const Stmt&) = delete;
    void text(int i, const QString& v) {
        const QByteArray u = v.toUtf8();
        sqlite3_bind_text(s, i, u.constData(), int(u.size()), SQLITE_TRANSIENT);
    }
    void blob(int i, const QByteArray& v) {
        sqlite3_bind_blob(s, i, v.constData(), int(v.size()), SQLITE_TRANSIENT);
    }
    void i64(int i, qint64 v) { sqlite3_bind_int64(s, i, v); }
    bool run() {
        const int rc = sqlite3_step(s);
        sqlite3_reset(s);
        return rc == SQLITE_DONE || rc == SQLITE_ROW;
    }
};

// A recording is created whole or not at all: its schema and meta data are committed in one transaction
// under a temporary name that neither a reader nor retention takes for a recording, and the file gets its
// name only then (rename(2) is atomic). A console killed while creating it leaves a stray "<name>.part" of a
// few kilobytes (retention removes it), never a file named like a recording that does not open. The file is
// closed before the rename: SQLite names its journals after the path it was opened with.
QString createFile(const RecorderOptions& options, qint64 startMs, int keyframeIntervalMs) {
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

} // namespace

// Lives on the writer thread once started.
struct Recorder::Writer {
    sqlite3* db = nullptr;
    QHash<QString, std::uint32_t> idxOf;
    QHash<std::uint32_t, MachineState> last; // what the file says each machine is now
    std::uint32_t nextIdx = 1;
    qint64 lastKeyframeT = 0;
    qint64 lastChunkT1 = 0;
    qint64 lastChunkId = 0;
    qint64 openChunkId = 0; // the states row still being filled (schema 4)
    quint64 openChunkBytes = 0, openChunkRawBytes = 0;
    qint64 lastTrimCheckT = 0;
    qint64 maxFileBytes = 0;
    qint64 lastRetentionT = 0;
    QStringList retentionDeleted; // older runs deleted while this one ran
    int keyframeIntervalMs = 10000;
    quint64 stateBytes = 0, stateRawBytes = 0, keyframeBytes = 0;
    // Schema 4 (legacy = false): the chunk being filled, in the site frame of the fleet's e/n/u.
    bool legacy = false;
    int zstdLevel = 6;
    std::unique_ptr<GeoFrame> frame;
    std::unique_ptr<ChunkEncoder> enc;
    QByteArray legacyChunk;
    qint64 chunkT0 = 0, chunkT1 = 0;
    int chunkN = 0;
    std::unique_ptr<Stmt> insState, updState, insMachine, insKeyframe, insEvent, insAck, insCommand, insLink,
        insMap, insChannel, insMessages, insPass;
    // Inbound messages: channel (protocol, link, peer, type) -> index, and the chunk being filled.
    QHash<QByteArray, std::uint32_t> channelOf;
    std::uint32_t nextChannel = 1;
    QByteArray msgChunk;
    qint64 msgT0 = 0, msgT1 = 0;
    int msgN = 0;
    quint64 messages = 0, messageBytes = 0;

    void addMessage(qint64 t, const QByteArray& packed) {
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
    void writeMessages() {
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

    ~Writer() {
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
        if (db)
            sqlite3_close(db);
    }
    bool exec(const char* sql) { return sqlite3_exec(db, sql, nullptr, nullptr, nullptr) == SQLITE_OK; }

    std::uint32_t indexOf(const QString& id) {
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

    QByteArray pack(const QByteArray& data) const {
        // Schema 3: zlib at its fastest. Schema 4: zstd, which shrinks the varint records further for less
        // CPU (bench_recording compares both).
        return legacy ? qCompress(data, 1) : compressBlob(data, BlobCodec::Zstd, zstdLevel);
    }

    // A state record at t: cuts the chunk after 1 s so that a seek decodes little past its target.
    void startRecord(qint64 t) {
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

    void addState(qint64 t, const MachineState& state) {
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

    void addRemoval(qint64 t, const QString& id) {
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
    void writeChunk() {
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
    void closeChunk() {
        openChunkId = 0;
        openChunkBytes = openChunkRawBytes = 0;
        chunkN = 0;
    }

    void writeKeyframe(qint64 t) {
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
    void trimIfNeeded(qint64 t) {
        if (maxFileBytes <= 0 || t - lastTrimCheckT < 10000)
            return;
        lastTrimCheckT = t;
        Stmt size(db, "SELECT page_count * page_size FROM pragma_page_count(), pragma_page_size()");
        if (sqlite3_step(size.s) != SQLITE_ROW || sqlite3_column_int64(size.s, 0) <= maxFileBytes)
            return;
        Stmt kf(
            db,
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
};

// The stacks' tap: packs and queues, nothing else (io threads).
class Recorder::Tap final : public MessageTap {
public:
    explicit Tap(Recorder& r) : m_r(r) {}
    void onDecoded(const TappedMessage& m) override {
        if (m_r.m_options.messages)
            queue(m, false);
    }
    void onRaw(const TappedMessage& m) override { queue(m, true); }
    bool wantsRaw() const override { return m_r.m_options.raw; }

private:
    void queue(const TappedMessage& m, bool raw) {
        if (!m_r.m_running)
            return;
        Item it;
        it.kind = Item::Message;
        it.blob = packTapped(m.protocol, m.link, m.peer, m.type, raw, m.bytes.data(), m.bytes.size());
        m_r.push(std::move(it));
    }
    Recorder& m_r;
};

Recorder::Recorder(QObject* parent) : QObject(parent), m_tap(std::make_unique<Tap>(*this)) {}

MessageTap* Recorder::messageTap() const {
    return m_tap.get();
}

Recorder::~Recorder() {
    stop();
}

qint64 Recorder::now() const {
    return m_options.clock ? m_options.clock() : QDateTime::currentMSecsSinceEpoch();
}

QString Recorder::start(const RecorderOptions& options) {
    if (m_running)
        return tr("the recorder is already running");
    m_options = options;
    if (QFileInfo::exists(options.path))
        return tr("%1 exists already; a recording is never overwritten").arg(options.path);
    QDir().mkpath(QFileInfo(options.path).absolutePath());
    auto w = std::make_unique<Writer>();
    w->keyframeIntervalMs = std::max(100, options.keyframeIntervalMs);
    const qint64 t = now();
    if (const QString e = createFile(options, t, w->keyframeIntervalMs); !e.isEmpty())
        return e;
    if (sqlite3_open_v2(options.path.toUtf8().constData(), &w->db,
                        SQLITE_OPEN_READWRITE | SQLITE_OPEN_NOMUTEX, nullptr) != SQLITE_OK) {
        const QString err = w->db ? QString::fromUtf8(sqlite3_errmsg(w->db)) : tr("out of memory");
        return tr("cannot create %1: %2").arg(options.path, err);
    }
    sqlite3_busy_timeout(w->db, 2000);
    // Schema 4: 1-KiB pages. A chunk's blob (a few KB) fills overflow pages, and half a page per chunk is
    // lost on average: 4-KiB pages made that a fifth of the file.
    if (!w->exec(options.legacySchema3 ? "PRAGMA page_size=4096" : "PRAGMA page_size=1024") ||
        !w->exec("PRAGMA auto_vacuum=INCREMENTAL") || !w->exec("PRAGMA journal_mode=WAL") ||
        !w->exec("PRAGMA synchronous=NORMAL") || !w->exec(kSchemaSql))
        return tr("cannot create the recording schema in %1: %2")
            .arg(options.path, QString::fromUtf8(sqlite3_errmsg(w->db)));
    w->insState = std::make_unique<Stmt>(w->db, "INSERT INTO states(t0, t1, n, data) VALUES(?,?,?,?)");
    w->updState = std::make_unique<Stmt>(w->db, "UPDATE states SET t1 = ?, n = ?, data = ? WHERE id = ?");
    w->insMachine = std::make_unique<Stmt>(w->db, "INSERT OR REPLACE INTO machines(idx, id) VALUES(?,?)");
    w->insKeyframe =
        std::make_unique<Stmt>(w->db, "INSERT OR REPLACE INTO keyframes(t, chunk, n, data) VALUES(?,?,?,?)");
    w->insEvent =
        std::make_unique<Stmt>(w->db, "INSERT INTO events(t, time_ms, severity, kind, machine, source, "
                                      "text, requires_ack, key) VALUES(?,?,?,?,?,?,?,?,?)");
    w->insAck = std::make_unique<Stmt>(w->db, "INSERT INTO acks(t, key, by, at_ms) VALUES(?,?,?,?)");
    w->insCommand =
        std::make_unique<Stmt>(w->db, "INSERT INTO commands(t, origin, action, target, ok, audit) "
                                      "VALUES(?,?,?,?,?,?)");
    w->insLink = std::make_unique<Stmt>(w->db, "INSERT INTO links(t, protocol, link, state, age_ms, detail) "
                                               "VALUES(?,?,?,?,?,?)");
    w->insMap = std::make_unique<Stmt>(w->db, "INSERT INTO sitemaps(t, data) VALUES(?,?)");
    w->insChannel = std::make_unique<Stmt>(
        w->db, "INSERT OR REPLACE INTO msg_channels(idx, protocol, link, peer, type) VALUES(?,?,?,?,?)");
    w->insMessages = std::make_unique<Stmt>(w->db, "INSERT INTO messages(t0, t1, n, data) VALUES(?,?,?,?)");
    w->insPass = std::make_unique<Stmt>(w->db, "INSERT INTO passcounts(t, data) VALUES(?,?)");
    w->legacy = options.legacySchema3;
    w->zstdLevel = options.zstdLevel;
    if (!w->legacy) {
        // The frame the bridges put the fleet's e/n/u in: a Move's lat/lon are derived from them through it.
        w->frame =
            std::make_unique<GeoFrame>(GeoPoint{options.originLat, options.originLon, options.originAlt});
        w->enc = std::make_unique<ChunkEncoder>(w->frame.get());
    }
    w->maxFileBytes = options.maxFileBytes;
    m_lastT = t;
    w->lastKeyframeT = t;
    w->lastRetentionT = t;
    m_writer = std::move(w);
    m_stopRequested = false;
    m_running = true;
    m_thread = std::thread([this] { run(); });
    return {};
}

void Recorder::stop() {
    if (!m_running)
        return;
    {
        std::lock_guard lk(m_mutex);
        m_stopRequested = true;
    }
    m_cv.notify_all();
    m_thread.join();
    m_writer.reset();
    m_running = false;
}

bool Recorder::push(Item&& item) {
    if (!m_running)
        return false;
    std::lock_guard lk(m_mutex);
    if (m_stopRequested || int(m_queue.size()) >= m_options.queueCapacity) {
        m_dropped.fetch_add(1, std::memory_order_relaxed);
        return false;
    }
    // Record times never go backwards (a stepped wall clock), so the file stays in time order.
    item.t = std::max(now(), m_lastT.load(std::memory_order_relaxed));
    m_lastT.store(item.t, std::memory_order_relaxed);
    m_queue.push_back(std::move(item));
    ++m_pushedSeq;
    return true;
}

void Recorder::recordStates(const QVector<MachineState>& states) {
    for (const MachineState& s : states) {
        Item it;
        it.kind = Item::State;
        it.state = s;
        push(std::move(it));
    }
}

void Recorder::recordRemoval(const QString& id) {
    Item it;
    it.kind = Item::Removed;
    it.a = id;
    push(std::move(it));
}

void Recorder::recordEvent(const FleetEvent& event) {
    Item it;
    it.kind = Item::Event;
    it.event = event;
    push(std::move(it));
}

void Recorder::recordAck(const QString& key, const QString& by, qint64 atMs) {
    Item it;
    it.kind = Item::Ack;
    it.a = key;
    it.b = by;
    it.x = atMs;
    push(std::move(it));
}

void Recorder::recordCommand(const QString& auditJson) {
    Item it;
    it.kind = Item::Command;
    it.a = auditJson;
    push(std::move(it));
}

void Recorder::recordLink(const QString& protocol, const LinkStatus& status) {
    Item it;
    it.kind = Item::Link;
    it.a = protocol;
    it.b = status.link;
    it.c = status.detail;
    it.i = int(status.state);
    it.x = status.dataAgeMs;
    push(std::move(it));
}

void Recorder::recordSiteMap(const SiteMapData& map) {
    Item it;
    it.kind = Item::SiteMap;
    it.blob = siteMapToJson(map);
    push(std::move(it));
}

void Recorder::recordRaw(const QString& link, const QByteArray& frame) {
    if (!m_options.raw)
        return;
    const QByteArray l = link.toUtf8();
    Item it;
    it.kind = Item::Message;
    it.blob = packTapped({}, std::string_view(l.constData(), size_t(l.size())), {}, {}, true,
                         reinterpret_cast<const std::uint8_t*>(frame.constData()), size_t(frame.size()));
    push(std::move(it));
}

void Recorder::flush() {
    if (!m_running)
        return;
    std::unique_lock lk(m_mutex);
    const quint64 target = m_pushedSeq;
    m_flushRequested = true;
    m_cv.notify_all();
    m_flushedCv.wait(lk, [&] { return m_writtenSeq >= target || !m_running; });
}

Recorder::Stats Recorder::stats() const {
    Stats s;
    {
        std::lock_guard lk(m_mutex);
        s.queued = m_pushedSeq;
        s.written = m_writtenSeq;
    }
    s.dropped = m_dropped.load();
    s.commits = m_commits.load();
    s.stateBytes = m_stateBytes.load();
    s.stateRawBytes = m_stateRawBytes.load();
    s.keyframeBytes = m_keyframeBytes.load();
    s.writerCpuNs = m_writerCpuNs.load();
    s.messages = m_messages.load();
    s.messageBytes = m_messageBytes.load();
    return s;
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
        if (!batch.empty()) {
            w.exec("BEGIN");
            for (Item& it : batch) {
                switch (it.kind) {
                case Item::State:
                    w.addState(it.t, it.state);
                    break;
                case Item::Removed:
                    w.addRemoval(it.t, it.a);
                    break;
                case Item::Event: {
                    Stmt& s = *w.insEvent;
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
                    Stmt& s = *w.insAck;
                    s.i64(1, it.t);
                    s.text(2, it.a);
                    s.text(3, it.b);
                    s.i64(4, it.x);
                    s.run();
                    break;
                }
                case Item::Command: {
                    const QJsonObject o = QJsonDocument::fromJson(it.a.toUtf8()).object();
                    Stmt& s = *w.insCommand;
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
                    Stmt& s = *w.insLink;
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
                    Stmt& s = *w.insMap;
                    s.i64(1, it.t);
                    s.blob(2, it.blob);
                    s.run();
                    break;
                }
                case Item::Meta: {
                    Stmt s(w.db, "INSERT OR REPLACE INTO meta(key, value) VALUES(?, ?)");
                    s.text(1, it.a);
                    s.text(2, it.c);
                    s.run();
                    break;
                }
                case Item::Message:
                    w.addMessage(it.t, it.blob);
                    break;
                case Item::PassCounts: {
                    Stmt& s = *w.insPass;
                    s.i64(1, it.t);
                    s.blob(2, qCompress(it.blob, 1));
                    s.run();
                    break;
                }
                }
            }
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
            if (!m_options.retentionDir.isEmpty() &&
                (m_options.maxTotalBytes > 0 || m_options.maxAgeDays > 0) &&
                lastT - w.lastRetentionT >= std::max(1000, m_options.retentionIntervalMs)) {
                w.lastRetentionT = lastT;
                const QStringList gone = applyRetention(m_options.retentionDir, m_options.maxTotalBytes,
                                                        m_options.maxAgeDays, m_options.path);
                if (!gone.isEmpty()) {
                    std::lock_guard lk(m_mutex);
                    m_retentionDeleted += gone;
                }
            }
            m_commits.fetch_add(1, std::memory_order_relaxed);
            m_stateBytes.store(w.stateBytes, std::memory_order_relaxed);
            m_stateRawBytes.store(w.stateRawBytes, std::memory_order_relaxed);
            m_keyframeBytes.store(w.keyframeBytes, std::memory_order_relaxed);
            m_messages.store(w.messages, std::memory_order_relaxed);
            m_messageBytes.store(w.messageBytes, std::memory_order_relaxed);
        }
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

void Recorder::attach(FleetContext* ctx) {
    m_ctx = ctx;
    FleetModel* fleet = ctx->fleet();
    connect(fleet, &FleetModel::machinesChanged, this, [this, fleet](const QStringList& ids) {
        QVector<MachineState> out;
        out.reserve(ids.size());
        for (const QString& id : ids)
            if (const MachineState* m = fleet->machine(id))
                out.push_back(*m);
        recordStates(out);
    });
    connect(fleet, &FleetModel::machineRemoved, this, &Recorder::recordRemoval);
    connect(ctx->alarms(), &AlarmModel::eventAdded, this, &Recorder::recordEvent);
    connect(ctx->alarms(), &AlarmModel::alarmAcknowledged, this, &Recorder::recordAck);
    connect(ctx->gate(), &CommandGate::audited, this, &Recorder::recordCommand);
    auto watch = [this](FleetBridge* b) {
        const QString protocol = toText(b->protocol());
        connect(b, &FleetBridge::linkChanged, this,
                [this, protocol](const LinkStatus& s) { recordLink(protocol, s); });
        for (const LinkStatus& s : b->links())
            recordLink(protocol, s);
    };
    for (FleetBridge* b : ctx->bridges())
        watch(b);
    connect(ctx, &FleetContext::bridgeAdded, this, watch);
    // The staleness thresholds, so a replay greys out what the console greyed out.
    QJsonObject stale;
    for (Protocol p : {Protocol::Jaus, Protocol::Iso23725, Protocol::Osyris, Protocol::Other})
        stale[toText(p)] = double(fleet->staleAfterMs(p));
    Item it;
    it.kind = Item::Meta;
    it.a = QStringLiteral("stale_after_ms");
    it.c = QString::fromUtf8(QJsonDocument(stale).toJson(QJsonDocument::Compact));
    push(std::move(it));
    // What is already in the models when the recorder starts late.
    recordStates(fleet->machinesSnapshot());
    // A writer that falls behind drops (the io threads never wait for it): the operator hears of it, at most
    // once every 5 s, with the count.
    auto* dropWatch = new QTimer(this);
    connect(dropWatch, &QTimer::timeout, this, [this] {
        const quint64 dropped = m_dropped.load(std::memory_order_relaxed);
        if (dropped == m_droppedReported || !m_ctx)
            return;
        const quint64 n = dropped - m_droppedReported;
        m_droppedReported = dropped;
        m_ctx->alarms()->add(makeEvent(EventSeverity::Warning, EventKind::Info, {},
                                       tr("Flight recorder behind: %n record(s) dropped (%1 in all)", nullptr,
                                          int(std::min<quint64>(n, INT32_MAX)))
                                           .arg(dropped),
                                       QStringLiteral("recorder")));
    });
    dropWatch->start(5000);
}

void Recorder::watchPassCounts(const PassCountLayer* layer) {
    m_passLayer = layer;
    m_passRevision = 0;
    m_passSize = QSize();
    if (!m_passTimer) {
        m_passTimer = new QTimer(this);
        m_passTimer->setSingleShot(true);
        m_passTimer->setInterval(1000);
        connect(m_passTimer, &QTimer::timeout, this, &Recorder::recordPassCountsNow);
    }
    recordPassCountsNow();
}

void Recorder::passCountsChanged() {
    if (m_passLayer && m_passTimer && !m_passTimer->isActive())
        m_passTimer->start();
}

void Recorder::recordPassCountsNow() {
    const PassCountLayer* l = m_passLayer;
    if (!l || !m_running || (m_passRevision != 0 && l->revision() == m_passRevision))
        return;
    PassCountChange c;
    c.origin = l->origin();
    c.cellSize = l->cellSize();
    c.columns = l->columns();
    c.rows = l->rows();
    const QRectF grid(c.origin, QSizeF(c.cellSize, c.cellSize));
    const bool sameGrid = m_passRevision != 0 && grid == m_passGrid && m_passSize == QSize(c.columns, c.rows);
    const QRect all(0, 0, c.columns, c.rows);
    const QRect want = sameGrid ? l->changedCellsSince(m_passRevision).intersected(all) : all;
    const quint64 revision = l->revision();
    c.cells = want.isEmpty() ? QRect(0, 0, 0, 0) : l->countsIn(want, c.counts);
    if (c.counts.size() !=
        std::size_t(std::max(0, c.cells.width())) * std::size_t(std::max(0, c.cells.height())))
        c.cells = QRect(0, 0, 0, 0), c.counts.clear();
    m_passRevision = revision;
    m_passGrid = grid;
    m_passSize = QSize(c.columns, c.rows);
    Item it;
    it.kind = Item::PassCounts;
    it.blob = encodePassCounts(c);
    push(std::move(it));
}

QStringList Recorder::deletedByRetention() const {
    std::lock_guard lk(m_mutex);
    return m_retentionDeleted;
}

qint64 effectiveMaxFileBytes(double maxFileMb, double maxTotalMb) {
    const double mb = maxFileMb > 0 ? maxFileMb : std::max(0.0, maxTotalMb);
    return qint64(mb * 1024 * 1024);
}

QString newRecordingPath(const QString& dir) {
    const QString stamp = QDateTime::currentDateTimeUtc().toString(QStringLiteral("yyyyMMdd-HHmmss"));
    return QDir(dir).filePath(
        QStringLiteral("ocu-%1-%2.sqlite").arg(stamp).arg(QCoreApplication::applicationPid()));
}

QStringList applyRetention(const QString& dir, qint64 maxTotalBytes, double maxAgeDays, const QString& keep) {
    QDir d(dir);
    QFileInfoList files = d.entryInfoList({QStringLiteral("ocu-*.sqlite")}, QDir::Files,
                                          QDir::Time | QDir::Reversed); // oldest first
    const QDateTime now = QDateTime::currentDateTimeUtc();
    const QString keepAbs = keep.isEmpty() ? QString() : QFileInfo(keep).absoluteFilePath();
    auto sizeOf = [](const QFileInfo& f) {
        return f.size() + QFileInfo(f.absoluteFilePath() + QStringLiteral("-wal")).size();
    };
    qint64 total = 0;
    for (const QFileInfo& f : files)
        total += sizeOf(f);
    QStringList deleted;
    // A recording whose creation was cut off (createFile): not a recording, nothing to keep.
    for (const QFileInfo& f : d.entryInfoList({QStringLiteral("ocu-*.sqlite.part")}, QDir::Files)) {
        if (f.lastModified().secsTo(now) < 300)
            continue;
        for (const QString& suffix : {QString(), QStringLiteral("-journal")})
            QFile::remove(f.absoluteFilePath() + suffix);
        deleted << f.fileName();
    }
    for (const QFileInfo& f : files) {
        if (f.absoluteFilePath() == keepAbs || f.lastModified().secsTo(now) < 300)
            continue;
        const bool tooOld = maxAgeDays > 0 && f.lastModified().secsTo(now) > qint64(maxAgeDays * 86400);
        const bool tooMuch = maxTotalBytes > 0 && total > maxTotalBytes;
        if (!tooOld && !tooMuch)
            continue;
        total -= sizeOf(f);
        for (const QString& suffix : {QString(), QStringLiteral("-wal"), QStringLiteral("-shm")})
            QFile::remove(f.absoluteFilePath() + suffix);
        deleted << f.fileName();
    }
    return deleted;
}

} // namespace ocu::recording
