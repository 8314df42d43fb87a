#include "models/recording/Recording.h"
#include "models/MachineJson.h"

#include "models/recording/RecordCodec.h"
#include "models/recording/RecordSchema.h"
#include "models/recording/Recorder.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QSet>
#include <QTimeZone>

#include <sqlite3.h>

#include <algorithm>
#include <limits>

namespace ocu::recording {

namespace {

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

constexpr qint64 kMinT = std::numeric_limits<qint64>::min();

QString isoTime(qint64 ms) {
    return QDateTime::fromMSecsSinceEpoch(ms, Qt::UTC).toString(Qt::ISODateWithMs);
}

QByteArray csvField(const QString& s) {
    QString v = s;
    if (v.contains(QLatin1Char('"')) || v.contains(QLatin1Char(',')) || v.contains(QLatin1Char('\n')) ||
        v.contains(QLatin1Char('\r'))) {
        v.replace(QLatin1String("\""), QLatin1String("\"\""));
        v = QLatin1Char('"') + v + QLatin1Char('"');
    }
    return v.toUtf8();
}

} // namespace

Recording::~Recording() {
    if (m_db)
        sqlite3_close(m_db);
}

std::unique_ptr<Recording> Recording::open(const QString& path, QString* error) {
    auto fail = [&](const QString& why) -> std::unique_ptr<Recording> {
        if (error)
            *error = why;
        return nullptr;
    };
    if (!QFileInfo(path).isFile())
        return fail(QCoreApplication::translate("Recording", "%1: no such file").arg(path));
    std::unique_ptr<Recording> r(new Recording);
    r->m_path = path;
    // Read-write so SQLite can recover the WAL of a killed writer; nothing is ever written through it.
    if (sqlite3_open_v2(path.toUtf8().constData(), &r->m_db, SQLITE_OPEN_READWRITE | SQLITE_OPEN_NOMUTEX,
                        nullptr) != SQLITE_OK) {
        if (r->m_db) {
            sqlite3_close(r->m_db);
            r->m_db = nullptr;
        }
        if (sqlite3_open_v2(path.toUtf8().constData(), &r->m_db, SQLITE_OPEN_READONLY | SQLITE_OPEN_NOMUTEX,
                            nullptr) != SQLITE_OK)
            return fail(QCoreApplication::translate("Recording", "%1: cannot open: %2")
                            .arg(path, QString::fromUtf8(sqlite3_errmsg(r->m_db))));
    }
    sqlite3_busy_timeout(r->m_db, 2000);
    {
        Query q(r->m_db, "SELECT value FROM meta WHERE key = 'schema'");
        if (!q.s)
            return fail(QCoreApplication::translate("Recording", "%1 is not an OCU recording (%2)")
                            .arg(path, QString::fromUtf8(sqlite3_errmsg(r->m_db))));
        if (!q.next())
            return fail(QCoreApplication::translate("Recording", "%1 is not an OCU recording").arg(path));
        const int v = q.text(0).toInt();
        r->m_schema = v;
        if (v < 1 || v > kSchemaVersion)
            return fail(QCoreApplication::translate("Recording", "%1: recording schema %2 is not supported")
                            .arg(path)
                            .arg(v));
    }
    r->m_statesCodec = blobCodecFromName(r->meta(QStringLiteral("states_codec")));
    // Message chunks were always zlib before schema 4 said otherwise.
    const QString messagesCodec = r->meta(QStringLiteral("messages_codec"));
    r->m_messagesCodec = messagesCodec.isEmpty() ? BlobCodec::Zlib : blobCodecFromName(messagesCodec);
    r->m_frame = GeoFrame(GeoPoint{r->meta(QStringLiteral("origin_lat")).toDouble(),
                                   r->meta(QStringLiteral("origin_lon")).toDouble(),
                                   r->meta(QStringLiteral("origin_alt")).toDouble()});
    r->m_startMs = r->meta(QStringLiteral("start_ms")).toLongLong();
    // The end as committed: the newest row of any table (end_ms is updated with every commit too).
    qint64 end = r->meta(QStringLiteral("end_ms")).toLongLong();
    for (const char* sql : {"SELECT MAX(t1) FROM states", "SELECT MAX(t) FROM events",
                            "SELECT MAX(t) FROM links", "SELECT MAX(t) FROM commands"}) {
        Query q(r->m_db, sql);
        if (q.next())
            end = std::max(end, q.i64(0));
    }
    r->m_endMs = std::max(end, r->m_startMs);
    r->loadMachineIds();
    return r;
}

QString Recording::meta(const QString& key) const {
    Query q(m_db, "SELECT value FROM meta WHERE key = ?");
    q.bind(1, key);
    return q.next() ? q.text(0) : QString();
}

QHash<Protocol, qint64> Recording::staleAfterMs() const {
    QHash<Protocol, qint64> out;
    const QJsonObject o = QJsonDocument::fromJson(meta(QStringLiteral("stale_after_ms")).toUtf8()).object();
    for (auto it = o.begin(); it != o.end(); ++it)
        out.insert(protocolFromString(it.key()), qint64(it.value().toDouble()));
    return out;
}

void Recording::loadMachineIds() const {
    Query q(m_db, "SELECT idx, id FROM machines");
    while (q.next())
        m_ids.insert(std::uint32_t(q.i64(0)), q.text(1));
}

Recording::StateMap Recording::statesAtIdx(qint64 t) const {
    StateMap states;
    qint64 afterChunk = 0;
    // Derived lat/lon once per machine at the end, not once per record.
    QSet<std::uint32_t> pending;
    const DecodeOptions options = decodeOptions(&pending);
    {
        Query kf(m_db, "SELECT chunk, data, t FROM keyframes WHERE t <= ? ORDER BY t DESC LIMIT 1");
        kf.bind(1, t);
        if (kf.next()) {
            afterChunk = kf.i64(0);
            decodeChunk(stateBlob(kf.blob(1)), kf.i64(2), states, kMinT, std::numeric_limits<qint64>::max(),
                        {}, options);
        }
    }
    // Chunks are in time order: walk them by id from the keyframe's and stop at the first one after t (a
    // range condition on t0 alone would make SQLite visit every later chunk of the file).
    Query q(m_db, "SELECT t0, data FROM states WHERE id > ? ORDER BY id");
    q.bind(1, afterChunk);
    while (q.next() && q.i64(0) <= t)
        decodeChunk(stateBlob(q.blob(1)), q.i64(0), states, kMinT, t, {}, options);
    resolveGeodetic(states, pending, m_frame);
    return states;
}

QHash<QString, MachineState> Recording::statesAt(qint64 t) const {
    QHash<QString, MachineState> out;
    const auto states = statesAtIdx(t);
    for (auto it = states.cbegin(); it != states.cend(); ++it)
        out.insert(it->id, *it);
    return out;
}

QString Recording::idOf(std::uint32_t idx) const {
    auto it = m_ids.constFind(idx);
    if (it != m_ids.cend())
        return *it;
    loadMachineIds(); // a recording still being written gained machines
    return m_ids.value(idx);
}

void Recording::walk(StateMap& states, qint64 fromExclusive, qint64 toInclusive,
                     const std::function<bool(const StateChange&)>& fn,
                     QSet<std::uint32_t>* deferGeodetic) const {
    const DecodeOptions options = decodeOptions(deferGeodetic);
    // The first chunk ending after `fromExclusive` (index on t1), then by id until one starts after the end.
    qint64 first = -1;
    {
        Query f(m_db, "SELECT id FROM states WHERE t1 > ? ORDER BY t1, id LIMIT 1");
        f.bind(1, fromExclusive);
        if (!f.next())
            return;
        first = f.i64(0);
    }
    Query q(m_db, "SELECT t0, data FROM states WHERE id >= ? ORDER BY id");
    q.bind(1, first);
    bool go = true;
    while (go && q.next() && q.i64(0) <= toInclusive) {
        decodeChunk(
            stateBlob(q.blob(1)), q.i64(0), states, fromExclusive, toInclusive,
            [&](const DecodedRecord& r) {
                if (!go || !fn)
                    return;
                StateChange c;
                c.t = r.tMs;
                if (r.type == RecordType::Removed) {
                    c.removed = true;
                    c.state.id = idOf(r.idx);
                } else {
                    auto it = states.constFind(r.idx);
                    if (it == states.cend())
                        return;
                    c.state = *it;
                }
                go = fn(c);
            },
            options);
    }
}

void Recording::changes(qint64 fromExclusive, qint64 toInclusive,
                        const std::function<bool(const StateChange&)>& fn) const {
    // The base: the picture at `fromExclusive` (Position records need the machine's last Full).
    StateMap states = statesAtIdx(fromExclusive);
    walk(states, fromExclusive, toInclusive, fn);
}

QStringList Recording::advance(StateMap& states, qint64 fromExclusive, qint64 toInclusive,
                               QStringList* removed) const {
    QStringList changed;
    QSet<QString> seen;
    // Only the ids are needed per record: derived lat/lon once per machine at the end.
    QSet<std::uint32_t> pending;
    walk(
        states, fromExclusive, toInclusive,
        [&](const StateChange& c) {
            if (c.removed) {
                if (removed)
                    removed->push_back(c.state.id);
                changed.removeAll(c.state.id);
                seen.remove(c.state.id);
            } else if (!seen.contains(c.state.id)) {
                seen.insert(c.state.id);
                changed << c.state.id;
            }
            return true;
        },
        &pending);
    resolveGeodetic(states, pending, m_frame);
    return changed;
}

namespace {
constexpr const char* kEventColumns =
    "SELECT id, t, time_ms, severity, kind, machine, source, text, requires_ack, key "
    "FROM events ";

RecordedEvent eventRow(const Query& q) {
    RecordedEvent e;
    e.id = q.i64(0);
    e.t = q.i64(1);
    e.event.timeMs = q.i64(2);
    e.event.severity = EventSeverity(std::clamp<qint64>(q.i64(3), 0, int(EventSeverity::Critical)));
    e.event.kind = EventKind(std::clamp<qint64>(q.i64(4), 0, int(EventKind::Info)));
    e.event.machineId = q.text(5);
    e.event.source = q.text(6);
    e.event.text = q.text(7);
    e.event.requiresAck = q.i64(8) != 0;
    e.key = q.text(9);
    return e;
}
} // namespace

QVector<RecordedEvent> Recording::events(qint64 fromExclusive, qint64 toInclusive) const {
    QVector<RecordedEvent> out;
    Query q(m_db, (QByteArray(kEventColumns) + "WHERE t > ? AND t <= ? ORDER BY id").constData());
    q.bind(1, fromExclusive).bind(2, toInclusive);
    while (q.next())
        out.push_back(eventRow(q));
    return out;
}

QVector<RecordedEvent> Recording::eventsById(const QVector<qint64>& ids) const {
    QVector<RecordedEvent> out(ids.size());
    if (ids.isEmpty())
        return out;
    const auto [lo, hi] = std::minmax_element(ids.cbegin(), ids.cend());
    if (*hi - *lo < 4 * qint64(ids.size())) {
        // Most of a stretch of rows: read it in order, decoding only the rows asked for (a lookup per row
        // costs more than stepping over the few others).
        QHash<qint64, qsizetype> where;
        where.reserve(ids.size());
        for (qsizetype i = 0; i < ids.size(); ++i)
            where.insert(ids[i], i);
        Query q(m_db, (QByteArray(kEventColumns) + "WHERE id >= ? AND id <= ? ORDER BY id").constData());
        q.bind(1, *lo).bind(2, *hi);
        while (q.next())
            if (const auto it = where.constFind(q.i64(0)); it != where.constEnd())
                out[it.value()] = eventRow(q);
        return out;
    }
    // A few rows spread over the file: one prepared statement, looked up by row id.
    Query q(m_db, (QByteArray(kEventColumns) + "WHERE id = ?").constData());
    if (!q.s)
        return out;
    for (qsizetype i = 0; i < ids.size(); ++i) {
        sqlite3_reset(q.s);
        q.bind(1, ids[i]);
        if (q.next())
            out[i] = eventRow(q);
    }
    return out;
}

QVector<RecordedAck> Recording::acks(qint64 fromExclusive, qint64 toInclusive) const {
    QVector<RecordedAck> out;
    Query q(m_db, "SELECT t, key, by FROM acks WHERE t > ? AND t <= ? ORDER BY id");
    q.bind(1, fromExclusive).bind(2, toInclusive);
    while (q.next())
        out.push_back({q.i64(0), q.text(1), q.text(2)});
    return out;
}

QVector<RecordedCommand> Recording::commands(qint64 fromExclusive, qint64 toInclusive) const {
    QVector<RecordedCommand> out;
    Query q(m_db,
            "SELECT t, origin, action, target, ok, audit FROM commands WHERE t > ? AND t <= ? ORDER BY id");
    q.bind(1, fromExclusive).bind(2, toInclusive);
    while (q.next())
        out.push_back({q.i64(0), q.text(1), q.text(2), q.text(3), q.i64(4) != 0, q.text(5)});
    return out;
}

namespace {

// One row of SELECT t, protocol, link, state, age_ms, detail FROM links.
RecordedLink linkRow(Query& q) {
    RecordedLink l;
    l.t = q.i64(0);
    l.protocol = q.text(1);
    l.link = q.text(2);
    l.state = LinkState(std::clamp<qint64>(q.i64(3), 0, int(LinkState::Down)));
    l.dataAgeMs = q.i64(4);
    l.detail = q.text(5);
    return l;
}

} // namespace

QVector<RecordedLink> Recording::links(qint64 fromExclusive, qint64 toInclusive) const {
    QVector<RecordedLink> out;
    Query q(m_db,
            "SELECT t, protocol, link, state, age_ms, detail FROM links WHERE t > ? AND t <= ? ORDER BY id");
    q.bind(1, fromExclusive).bind(2, toInclusive);
    while (q.next())
        out.push_back(linkRow(q));
    return out;
}

void Recording::messages(qint64 from, qint64 to,
                         const std::function<bool(const RecordedMessage&)>& fn) const {
    // Chunks span at most ~1 s (the recorder cuts them), in time order by id.
    Query q(m_db, "SELECT t0, data FROM messages WHERE t1 >= ? AND t0 <= ? ORDER BY id");
    q.bind(1, from).bind(2, to);
    bool go = true;
    while (go && q.next())
        decodeMessageChunk(uncompressBlob(q.blob(1), m_messagesCodec), q.i64(0), from, to,
                           [&](const RecordedMessage& m) { return go = fn(m); });
}

void Recording::passCounts(qint64 fromExclusive, qint64 toInclusive,
                           const std::function<void(qint64, const PassCountChange&)>& fn) const {
    Query q(m_db, "SELECT t, data FROM passcounts WHERE t > ? AND t <= ? ORDER BY id");
    q.bind(1, fromExclusive).bind(2, toInclusive);
    PassCountChange c;
    while (q.next())
        if (decodePassCounts(qUncompress(q.blob(1)), c))
            fn(q.i64(0), c);
}

bool Recording::hasPassCounts() const {
    Query q(m_db, "SELECT 1 FROM passcounts LIMIT 1");
    return q.next();
}

QHash<std::uint32_t, MessageChannel> Recording::messageChannels() const {
    QHash<std::uint32_t, MessageChannel> out;
    Query q(m_db, "SELECT idx, protocol, link, peer, type FROM msg_channels");
    while (q.next())
        out.insert(std::uint32_t(q.i64(0)), MessageChannel{q.text(1), q.text(2), q.text(3), q.text(4)});
    return out;
}

QJsonObject Recording::messageJson(const RecordedMessage& m, const MessageChannel& c) {
    QJsonObject o{{QStringLiteral("type"), m.raw ? QStringLiteral("raw") : QStringLiteral("message")},
                  {QStringLiteral("protocol"), c.protocol},
                  {QStringLiteral("link"), c.link},
                  {QStringLiteral("peer"), c.peer},
                  {QStringLiteral("msg_type"), c.type},
                  {QStringLiteral("bytes"), QString::fromLatin1(m.bytes.toHex())}};
    if (!m.raw && c.protocol == QLatin1String("iso23725")) {
        const QJsonDocument d = QJsonDocument::fromJson(m.bytes);
        if (d.isObject())
            o[QStringLiteral("json")] = d.object();
    }
    return o;
}

QVector<RecordedLink> Recording::linksAt(qint64 t) const {
    // The newest row of each link at t, looked up per link (index links_key, schema 4), not by reading every
    // link change since the start: a seek late in a long recording stays as fast as an early one.
    QVector<RecordedLink> out;
    Query q(m_db, "SELECT l.t, l.protocol, l.link, l.state, l.age_ms, l.detail "
                  "FROM (SELECT DISTINCT protocol, link FROM links) k JOIN links l ON l.id = "
                  "(SELECT id FROM links WHERE protocol IS k.protocol AND link IS k.link AND t <= ?1 "
                  "ORDER BY t DESC, id DESC LIMIT 1) ORDER BY l.protocol, l.link");
    q.bind(1, t);
    while (q.next())
        out.push_back(linkRow(q));
    return out;
}

SiteMapData Recording::siteMapAt(qint64 t) const {
    Query q(m_db, "SELECT data FROM sitemaps WHERE t <= ? ORDER BY id DESC LIMIT 1");
    q.bind(1, t);
    if (q.next())
        return siteMapFromJson(q.blob(0));
    Query first(m_db, "SELECT data FROM sitemaps ORDER BY id LIMIT 1");
    return first.next() ? siteMapFromJson(first.blob(0)) : SiteMapData{};
}

QVector<Marker> Recording::markers() const {
    QVector<Marker> out;
    {
        Query q(m_db, "SELECT t, severity, machine, text FROM events WHERE requires_ack != 0 ORDER BY id");
        while (q.next()) {
            Marker m;
            m.kind = Marker::Kind::Alarm;
            m.t = q.i64(0);
            m.bad = q.i64(1) >= int(EventSeverity::Alarm);
            const QString machine = q.text(2);
            m.text = machine.isEmpty() ? q.text(3) : machine + QStringLiteral(": ") + q.text(3);
            out.push_back(std::move(m));
        }
    }
    {
        Query q(m_db, "SELECT t, origin, action, target, ok FROM commands ORDER BY id");
        while (q.next()) {
            Marker m;
            m.kind = Marker::Kind::Command;
            m.t = q.i64(0);
            m.bad = q.i64(4) == 0;
            m.text = QStringLiteral("%1 %2 (%3)%4")
                         .arg(q.text(2), q.text(3), q.text(1),
                              m.bad ? QCoreApplication::translate("Recording", " - not every target reached")
                                    : QString());
            out.push_back(std::move(m));
        }
    }
    std::stable_sort(out.begin(), out.end(), [](const Marker& a, const Marker& b) { return a.t < b.t; });
    return out;
}

bool Recording::exportJsonLines(QIODevice* out, qint64 from, qint64 to, QString* error) const {
    if (!out || !out->isWritable()) {
        if (error)
            *error = QCoreApplication::translate("Recording", "the output is not writable");
        return false;
    }
    // Merge the tables in time order: machine changes stream; the rest is small and loaded whole.
    QVector<QPair<qint64, QJsonObject>> other;
    for (const RecordedEvent& e : events(from - 1, to)) {
        QJsonObject o{{QStringLiteral("type"), QStringLiteral("event")},
                      {QStringLiteral("time"), isoTime(e.event.timeMs)},
                      {QStringLiteral("severity"), toText(e.event.severity)},
                      {QStringLiteral("kind"), toText(e.event.kind)},
                      {QStringLiteral("machine"), e.event.machineId},
                      {QStringLiteral("source"), e.event.source},
                      {QStringLiteral("text"), e.event.text},
                      {QStringLiteral("requires_ack"), e.event.requiresAck}};
        other.push_back({e.t, o});
    }
    for (const RecordedAck& a : acks(from - 1, to))
        other.push_back({a.t, QJsonObject{{QStringLiteral("type"), QStringLiteral("ack")},
                                          {QStringLiteral("key"), a.key},
                                          {QStringLiteral("by"), a.by}}});
    for (const RecordedCommand& c : commands(from - 1, to)) {
        QJsonObject o = QJsonDocument::fromJson(c.audit.toUtf8()).object();
        o[QStringLiteral("type")] = QStringLiteral("command");
        other.push_back({c.t, o});
    }
    for (const RecordedLink& l : links(from - 1, to))
        other.push_back({l.t, QJsonObject{{QStringLiteral("type"), QStringLiteral("link")},
                                          {QStringLiteral("protocol"), l.protocol},
                                          {QStringLiteral("link"), l.link},
                                          {QStringLiteral("state"), toText(l.state)},
                                          {QStringLiteral("age_ms"), double(l.dataAgeMs)},
                                          {QStringLiteral("detail"), l.detail}}});
    {
        const QHash<std::uint32_t, MessageChannel> channels = messageChannels();
        messages(from, to, [&](const RecordedMessage& m) {
            other.push_back({m.t, messageJson(m, channels.value(m.channel))});
            return true;
        });
    }
    std::stable_sort(other.begin(), other.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    int next = 0;
    bool ok = true;
    auto write = [&](qint64 t, QJsonObject o) {
        o[QStringLiteral("t")] = double(t);
        ok = ok && out->write(QJsonDocument(o).toJson(QJsonDocument::Compact) + '\n') > 0;
    };
    changes(from - 1, to, [&](const StateChange& c) {
        while (next < other.size() && other[next].first <= c.t) {
            write(other[next].first, other[next].second);
            ++next;
        }
        write(c.t, c.removed ? QJsonObject{{QStringLiteral("type"), QStringLiteral("machine_removed")},
                                           {QStringLiteral("id"), c.state.id}}
                             : machineStateJson(c.state));
        return ok;
    });
    for (; next < other.size(); ++next)
        write(other[next].first, other[next].second);
    if (!ok && error)
        *error = QCoreApplication::translate("Recording", "write failed: %1").arg(out->errorString());
    return ok;
}

bool Recording::exportCsv(QIODevice* out, qint64 from, qint64 to, QString* error) const {
    if (!out || !out->isWritable()) {
        if (error)
            *error = QCoreApplication::translate("Recording", "the output is not writable");
        return false;
    }
    bool ok =
        out->write("time,t_ms,id,name,protocol,e,n,u,lat,lon,heading,speed,mode,stop,health,link\r\n") > 0;
    changes(from - 1, to, [&](const StateChange& c) {
        if (c.removed)
            return true;
        const MachineState& m = c.state;
        QByteArray line;
        line += isoTime(c.t).toUtf8() + ',' + QByteArray::number(c.t) + ',' + csvField(m.id) + ',' +
                csvField(m.name) + ',' + toText(m.protocol).toUtf8() + ',';
        if (m.hasPosition)
            line += QByteArray::number(m.e, 'f', 3) + ',' + QByteArray::number(m.n, 'f', 3) + ',' +
                    QByteArray::number(m.u, 'f', 3) + ',' + QByteArray::number(m.lat, 'f', 8) + ',' +
                    QByteArray::number(m.lon, 'f', 8) + ',' + QByteArray::number(m.headingDeg, 'f', 1) + ',';
        else
            line += ",,,,,,";
        line += QByteArray::number(m.speed, 'f', 3) + ',' +
                csvField(m.modeText.isEmpty() ? toText(m.mode) : m.modeText) + ',' + toText(m.stop).toUtf8() +
                ',' + toText(m.health).toUtf8() + ',' + toText(m.link).toUtf8() + "\r\n";
        ok = ok && out->write(line) > 0;
        return ok;
    });
    if (!ok && error)
        *error = QCoreApplication::translate("Recording", "write failed: %1").arg(out->errorString());
    return ok;
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
    auto exec = [&](const char* sql) {
        return sqlite3_exec(dst, sql, nullptr, nullptr, nullptr) == SQLITE_OK;
    };
    // 1-KiB pages as the recorder writes schema 4 (less of each chunk's last overflow page lost).
    bool ok =
        exec("PRAGMA page_size=1024") && exec("PRAGMA journal_mode=WAL") && exec(kSchemaSql) && exec("BEGIN");
    {
        Query attach(dst, "ATTACH DATABASE ? AS src");
        attach.bind(1, m_path);
        ok = ok && attach.run();
    }
    ok = ok && exec("INSERT INTO meta SELECT * FROM src.meta") &&
         exec("INSERT INTO machines SELECT * FROM src.machines");
    {
        Query q(dst, "INSERT OR REPLACE INTO meta(key, value) VALUES(?, ?)");
        for (const auto& [k, v] : {std::pair{QStringLiteral("start_ms"), QString::number(from)},
                                   std::pair{QStringLiteral("end_ms"), QString::number(to)},
                                   std::pair{QStringLiteral("slice_of"), QFileInfo(m_path).fileName()},
                                   std::pair{QStringLiteral("schema"), QString::number(kSchemaVersion)},
                                   std::pair{QStringLiteral("states_codec"), QStringLiteral("zstd")}}) {
            q.bind(1, k).bind(2, v);
            ok = ok && q.run();
        }
    }
    // The picture at `from` as a keyframe, then the machine changes re-encoded (as the recorder does).
    QHash<std::uint32_t, MachineState> last = statesAtIdx(from);
    QHash<QString, std::uint32_t> idxOf;
    for (auto it = m_ids.cbegin(); it != m_ids.cend(); ++it)
        idxOf.insert(it.value(), it.key());
    // Schema 4, as the recorder writes it (Moves' lat/lon derived through the same site frame).
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
    // Everything else of the window; the site map and the links as they were at its start.
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
    if (Query has(m_db, "SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = 'passcounts'");
        has.next()) {
        Query q(
            dst,
            "INSERT INTO passcounts(t, data) SELECT t, data FROM src.passcounts WHERE t <= ?2 ORDER BY id");
        q.bind(2, to);
        ok = ok && q.run();
    }
    // Inbound messages (schema 2): the chunks overlapping the window (a chunk spans at most ~1 s).
    if (Query has(m_db, "SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = 'messages'"); has.next())
        for (const char* sql :
             {"INSERT INTO msg_channels SELECT * FROM src.msg_channels",
              "INSERT INTO messages(t0, t1, n, data) SELECT t0, t1, n, data FROM src.messages "
              "WHERE t1 >= ?1 AND t0 <= ?2 ORDER BY id"}) {
            Query q(dst, sql);
            q.bind(1, from).bind(2, to);
            ok = ok && q.run();
        }
    ok = ok && exec("COMMIT") && exec("DETACH DATABASE src") && exec("PRAGMA wal_checkpoint(TRUNCATE)");
    const QString why = QString::fromUtf8(sqlite3_errmsg(dst));
    sqlite3_close(dst);
    if (!ok) {
        for (const QString& suffix : {QString(), QStringLiteral("-wal"), QStringLiteral("-shm")})
            QFile::remove(path + suffix);
        return fail(QCoreApplication::translate("Recording", "slice to %1 failed: %2").arg(path, why));
    }
    return true;
}

qint64 parseReplayTime(const QString& text, qint64 startMs) {
    const QString s = text.trimmed();
    static const QRegularExpression secs(QStringLiteral("^(\\d+(?:\\.\\d+)?)\\s*s?$"));
    if (auto m = secs.match(s); m.hasMatch())
        return startMs + qint64(m.captured(1).toDouble() * 1000.0 + 0.5);
    static const QRegularExpression clock(QStringLiteral("^(\\d{1,2}):(\\d{2}):(\\d{2})(?:\\.(\\d{1,3}))?$"));
    if (auto m = clock.match(s); m.hasMatch()) {
        const QDate day = QDateTime::fromMSecsSinceEpoch(startMs, Qt::UTC).date();
        const QTime t(m.captured(1).toInt(), m.captured(2).toInt(), m.captured(3).toInt(),
                      m.captured(4).isEmpty() ? 0 : m.captured(4).leftJustified(3, QLatin1Char('0')).toInt());
        if (!t.isValid())
            return -1;
        return QDateTime(day, t, Qt::UTC).toMSecsSinceEpoch();
    }
    QDateTime dt = QDateTime::fromString(s, Qt::ISODateWithMs);
    if (!dt.isValid())
        dt = QDateTime::fromString(s, Qt::ISODate);
    if (!dt.isValid())
        return -1;
    if (dt.timeSpec() == Qt::LocalTime)
        dt.setTimeSpec(Qt::UTC);
    return dt.toMSecsSinceEpoch();
}

QByteArray siteMapToJson(const SiteMapData& map) {
    QJsonArray features;
    for (const MapFeature& f : map.features) {
        QJsonArray pts;
        for (const QPointF& p : f.points) {
            pts.append(p.x());
            pts.append(p.y());
        }
        features.append(QJsonObject{{QStringLiteral("id"), f.id},
                                    {QStringLiteral("name"), f.name},
                                    {QStringLiteral("kind"), int(f.kind)},
                                    {QStringLiteral("task"), f.defaultTask},
                                    {QStringLiteral("auto"), f.autonomous},
                                    {QStringLiteral("width"), f.width},
                                    {QStringLiteral("points"), pts}});
    }
    return QJsonDocument(QJsonObject{{QStringLiteral("revision"), double(map.revision)},
                                     {QStringLiteral("features"), features}})
        .toJson(QJsonDocument::Compact);
}

SiteMapData siteMapFromJson(const QByteArray& json) {
    SiteMapData map;
    const QJsonObject o = QJsonDocument::fromJson(json).object();
    map.revision = quint64(o.value(QStringLiteral("revision")).toDouble());
    for (const QJsonValue& v : o.value(QStringLiteral("features")).toArray()) {
        const QJsonObject fo = v.toObject();
        MapFeature f;
        f.id = fo.value(QStringLiteral("id")).toString();
        f.name = fo.value(QStringLiteral("name")).toString();
        f.kind = MapFeatureKind(
            std::clamp(fo.value(QStringLiteral("kind")).toInt(), 0, int(MapFeatureKind::Area)));
        f.defaultTask = fo.value(QStringLiteral("task")).toString();
        f.autonomous = fo.value(QStringLiteral("auto")).toBool();
        f.width = fo.value(QStringLiteral("width")).toDouble();
        const QJsonArray pts = fo.value(QStringLiteral("points")).toArray();
        for (qsizetype i = 0; i + 1 < pts.size(); i += 2)
            f.points.push_back(QPointF(pts[i].toDouble(), pts[i + 1].toDouble()));
        map.features.push_back(std::move(f));
    }
    return map;
}

} // namespace ocu::recording
