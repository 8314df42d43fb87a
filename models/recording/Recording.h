#pragma once
// A flight recording opened for reading (replay, export; docs/recording.md). Read-only: a recording still
// being written by a running console can be opened too (WAL readers see the last commit).
#include "models/FleetEvent.h"
#include "models/MachineState.h"
#include "models/SiteMapData.h"
#include "models/recording/BlobCodec.h"
#include "models/recording/MessageLog.h"
#include "models/recording/PassCountLog.h"
#include "models/recording/RecordCodec.h"
#include "protocols/common/GeoFrame.h"

#include <QHash>
#include <QIODevice>
#include <QJsonObject>
#include <QString>
#include <QVector>

#include <cstdint>
#include <functional>
#include <memory>

struct sqlite3;

namespace ocu::recording {

struct RecordedEvent {
    qint64 id = 0; // the row in the file (events are numbered in the order they were recorded)
    qint64 t = 0;  // when the console received it
    FleetEvent event;
    QString key; // alarmKey(event)
};
struct RecordedAck {
    qint64 t = 0;
    QString key, by;
};
struct RecordedCommand {
    qint64 t = 0;
    QString origin, action, target;
    bool ok = false;
    QString audit; // the gate's audit line (JSON)
};
struct RecordedLink {
    qint64 t = 0;
    QString protocol, link, detail;
    LinkState state = LinkState::Unknown;
    qint64 dataAgeMs = -1;
};
// A protocol's own record about a machine (FleetBridge::publishDetail: a UGV's mission), as it was given.
struct RecordedDetail {
    qint64 t = 0;
    QString machine, kind;
    QByteArray data;
};
struct Marker {
    enum class Kind { Alarm, Command };
    Kind kind = Kind::Alarm;
    qint64 t = 0;
    QString text;
    bool bad = false; // an alarm of severity Alarm/Critical, a command that did not reach every target
};

// One change of the fleet picture, in time order (play, export).
struct StateChange {
    qint64 t = 0;
    bool removed = false;
    MachineState state; // for a removal only the id
};

class Recording {
public:
    ~Recording();
    // nullptr and `error` when the file is not a recording (or cannot be opened).
    static std::unique_ptr<Recording> open(const QString& path, QString* error = nullptr);

    QString path() const { return m_path; }
    qint64 startMs() const { return m_startMs; }
    qint64 endMs() const { return m_endMs; }
    QString meta(const QString& key) const;
    // Staleness per protocol as the console had it (FleetModel::staleAfterMs); empty = defaults.
    QHash<Protocol, qint64> staleAfterMs() const;

    // The fleet picture at t: every machine as the console's fleet model had it after all records <= t.
    // From the newest keyframe <= t plus the records after it.
    QHash<QString, MachineState> statesAt(qint64 t) const;
    // Changes in (from, to], in order. `fn` returning false stops the walk.
    void changes(qint64 fromExclusive, qint64 toInclusive,
                 const std::function<bool(const StateChange&)>& fn) const;
    // The same keyed by the file's machine index (what advance() continues).
    using StateMap = QHash<std::uint32_t, MachineState>;
    StateMap statesAtIdx(qint64 t) const;
    // Continues `states` (the picture at `fromExclusive`) to `toInclusive` without a new seek; returns the
    // ids changed and, in `removed`, those that left.
    QStringList advance(StateMap& states, qint64 fromExclusive, qint64 toInclusive,
                        QStringList* removed) const;

    QVector<RecordedEvent> events(qint64 fromExclusive, qint64 toInclusive) const;
    // The events of these rows (RecordedEvent::id), in the same order; a row not in the file gives id 0.
    QVector<RecordedEvent> eventsById(const QVector<qint64>& ids) const;
    QVector<RecordedAck> acks(qint64 fromExclusive, qint64 toInclusive) const;
    QVector<RecordedCommand> commands(qint64 fromExclusive, qint64 toInclusive) const;
    QVector<RecordedLink> links(qint64 fromExclusive, qint64 toInclusive) const;
    // The last state of every link at t.
    QVector<RecordedLink> linksAt(qint64 t) const;
    // The newest site map recorded at or before t (or the first one when none is yet).
    SiteMapData siteMapAt(qint64 t) const;
    // The protocols' own records of `kind` (empty: of every kind) in (from, to], in order (none in a file
    // from before the details table).
    QVector<RecordedDetail> details(const QString& kind, qint64 fromExclusive, qint64 toInclusive) const;
    // Alarms (events that required acknowledgement) and commands, for the timeline.
    QVector<Marker> markers() const;
    // Inbound protocol messages (and record.raw frames) received in [from, to], in time order; `fn` returning
    // false stops the walk. Their channels (protocol, link, peer, type) by index.
    void messages(qint64 from, qint64 to, const std::function<bool(const RecordedMessage&)>& fn) const;
    QHash<std::uint32_t, MessageChannel> messageChannels() const;
    // The pass-count changes recorded in (from, to], in order (malformed rows are skipped).
    void passCounts(qint64 fromExclusive, qint64 toInclusive,
                    const std::function<void(qint64 t, const PassCountChange&)>& fn) const;
    bool hasPassCounts() const;
    // The message as JSON for the export and the headless view: protocol, link, peer, msg_type, raw, the
    // bytes as hex and, for ISO 23725 (JSON text on the wire), the message itself under "json".
    static QJsonObject messageJson(const RecordedMessage& m, const MessageChannel& channel);

    // ---- export ----
    // JSON lines in time order: {"type":"machine",...} per state change (the headless monitor's fields plus
    // "t"), {"type":"machine_removed"}, {"type":"event"}, {"type":"ack"}, {"type":"command"},
    // {"type":"link"}, {"type":"detail"} (a protocol's own record: machine, kind, data).
    bool exportJsonLines(QIODevice* out, qint64 from, qint64 to, QString* error = nullptr) const;
    // CSV per machine state change: time (ISO 8601 UTC), t_ms, id, name, protocol, e, n, u, lat, lon,
    // heading, speed (m/s), mode, stop, health, link.
    bool exportCsv(QIODevice* out, qint64 from, qint64 to, QString* error = nullptr) const;
    // A new recording holding [from, to]: a keyframe at `from` (the picture then) plus everything after it up
    // to `to`, and the meta data. Refuses to overwrite.
    bool exportSlice(const QString& path, qint64 from, qint64 to, QString* error = nullptr) const;

private:
    Recording() = default;
    void loadMachineIds() const;
    // exportSlice: the keyframe at `from` and the machine changes up to `to` into `dst` (ok false on a
    // fault).
    void writeSliceStates(sqlite3* dst, qint64 from, qint64 to, bool& ok) const;
    QString idOf(std::uint32_t idx) const;
    // Decodes the chunks after `fromExclusive` up to `toInclusive` onto `states`. With `deferGeodetic`, the
    // lat/lon of Move records are left to the caller (resolveGeodetic): fn must not need them.
    void walk(StateMap& states, qint64 fromExclusive, qint64 toInclusive,
              const std::function<bool(const StateChange&)>& fn,
              QSet<std::uint32_t>* deferGeodetic = nullptr) const;
    // A states/keyframes blob as the codec reads it (schema 3: qCompress'ed, 4: zstd).
    QByteArray stateBlob(const QByteArray& stored) const { return uncompressBlob(stored, m_statesCodec); }
    DecodeOptions decodeOptions(QSet<std::uint32_t>* defer) const {
        return {m_schema >= 4 ? ChunkFormat::Compact : ChunkFormat::Fixed, &m_frame, defer};
    }
    sqlite3* m_db = nullptr;
    QString m_path;
    qint64 m_startMs = 0, m_endMs = 0;
    int m_schema = 0;
    BlobCodec m_statesCodec = BlobCodec::None;
    BlobCodec m_messagesCodec = BlobCodec::Zlib;
    GeoFrame m_frame; // the site frame (meta origin_*): schema 4 derives lat/lon from e/n/u through it
    mutable QHash<std::uint32_t, QString> m_ids;
};

// "30", "30.5", "30s" = seconds after the start; "12:00:05" = UTC time of the start's day; an ISO 8601 date
// and time ("2026-11-23T21:00:05Z"). Returns ms since the epoch, or -1 when not understood.
qint64 parseReplayTime(const QString& text, qint64 startMs);

} // namespace ocu::recording
