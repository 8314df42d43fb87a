#pragma once
// The recorder's inside (Recorder.cpp, RecorderTap.cpp, RecorderWriter.cpp): the queued item, and the
// writer that lives on the writer thread and encodes items into the SQLite file.
#include "models/recording/RecordCodec.h"
#include "models/recording/Recorder.h"

#include <QByteArray>
#include <QHash>

#include <sqlite3.h>

#include <memory>

namespace ocu::recording {

// One thing to record, as queued by record*() (any thread) for the writer thread.
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
        PassCounts,
        Detail
    } kind = State;
    qint64 t = 0;
    MachineState state;
    FleetEvent event;
    QString a, b, c;
    QByteArray blob;
    qint64 x = 0;
    int i = 0;
};

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

// Creates the recording's file whole or not at all (RecorderWriter.cpp); an empty string or why not.
QString createRecordingFile(const RecorderOptions& options, qint64 startMs, int keyframeIntervalMs);

// Lives on the writer thread once started: the open file, its prepared statements, and the chunks being
// filled (machine states, inbound messages).
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
        insMap, insChannel, insMessages, insPass, insDetail;
    // Inbound messages: channel (protocol, link, peer, type) -> index, and the chunk being filled.
    QHash<QByteArray, std::uint32_t> channelOf;
    std::uint32_t nextChannel = 1;
    QByteArray msgChunk;
    qint64 msgT0 = 0, msgT1 = 0;
    int msgN = 0;
    quint64 messages = 0, messageBytes = 0;

    ~Writer();
    // Opens the file createRecordingFile() made and prepares the statements; an empty string or why not.
    QString open(const RecorderOptions& options);
    bool exec(const char* sql) { return sqlite3_exec(db, sql, nullptr, nullptr, nullptr) == SQLITE_OK; }

    // One queued item into the open transaction.
    void write(const Item& item);
    void addMessage(qint64 t, const QByteArray& packed);
    void writeMessages();
    std::uint32_t indexOf(const QString& id);
    QByteArray pack(const QByteArray& data) const;
    void startRecord(qint64 t);
    void addState(qint64 t, const MachineState& state);
    void addRemoval(qint64 t, const QString& id);
    void writeChunk();
    void closeChunk();
    void writeKeyframe(qint64 t);
    void trimIfNeeded(qint64 t);
};

} // namespace ocu::recording
