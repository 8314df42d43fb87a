// A recording read back: opening it, the fleet picture at any time and the changes between two, and the
// events, acknowledgements, commands, links, site maps, messages and pass counts recorded. The exports are
// RecordingJsonExport.cpp, RecordingCsvExport.cpp and RecordingSlice.cpp.
#include "models/recording/Recording.h"

#include "models/recording/RecordCodec.h"
#include "models/recording/RecordSchema.h"
#include "models/recording/RecordingQuery.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QFileInfo>
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

constexpr qint64 kMinT = std::numeric_limits<qint64>::min();

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

QVector<RecordedDetail> Recording::details(const QString& kind, qint64 fromExclusive,
                                           qint64 toInclusive) const {
    QVector<RecordedDetail> out;
    Query q(m_db,
            "SELECT t, machine, kind, data FROM details WHERE (?1 = '' OR kind = ?1) AND t > ?2 AND t <= ?3 "
            "ORDER BY id");
    q.bind(1, kind).bind(2, fromExclusive).bind(3, toInclusive);
    while (q.next())
        out.push_back({q.i64(0), q.text(1), q.text(2), q.blob(3)});
    return out;
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

} // namespace ocu::recording
