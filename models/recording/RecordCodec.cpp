#include "models/recording/RecordCodec.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace ocu::recording {

namespace {

constexpr int kHeader = 1 + 4 + 4;
constexpr std::int32_t kNoMessageTime = std::numeric_limits<std::int32_t>::min();

template <typename T> void put(QByteArray& out, T v) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T)); // the recorder runs on little-endian hosts only (x86-64, aarch64)
    out.append(b, sizeof(T));
}

void putString(QByteArray& out, const QString& s) {
    const QByteArray u = s.toUtf8();
    put<std::uint32_t>(out, std::uint32_t(u.size()));
    out.append(u);
}

// LEB128 varints; zigzag for signed values.
void putVar(QByteArray& out, std::uint64_t v) {
    while (v >= 0x80) {
        out.append(char(std::uint8_t(v) | 0x80));
        v >>= 7;
    }
    out.append(char(v));
}
std::uint64_t zigzag(std::int64_t v) {
    return (std::uint64_t(v) << 1) ^ std::uint64_t(v >> 63);
}
std::int64_t unzigzag(std::uint64_t v) {
    return std::int64_t(v >> 1) ^ -std::int64_t(v & 1);
}
template <typename F, typename U> U bitsOf(F f) {
    static_assert(sizeof(F) == sizeof(U));
    U u;
    std::memcpy(&u, &f, sizeof u);
    return u;
}
template <typename F, typename U> F fromBits(U u) {
    F f;
    std::memcpy(&f, &u, sizeof f);
    return f;
}

struct Reader {
    const char* p;
    const char* end;
    bool ok = true;
    std::uint64_t getVar() {
        std::uint64_t v = 0;
        for (int shift = 0; shift < 64; shift += 7) {
            if (p >= end) {
                ok = false;
                return 0;
            }
            const auto b = std::uint8_t(*p++);
            v |= std::uint64_t(b & 0x7f) << shift;
            if (!(b & 0x80))
                return v;
        }
        ok = false; // longer than 10 bytes
        p = end;
        return 0;
    }
    template <typename T> T get() {
        T v{};
        if (end - p < qint64(sizeof(T))) {
            ok = false;
            p = end;
            return v;
        }
        std::memcpy(&v, p, sizeof(T));
        p += sizeof(T);
        return v;
    }
    QString getString() {
        const auto n = get<std::uint32_t>();
        if (!ok || qint64(n) > end - p) {
            ok = false;
            p = end;
            return {};
        }
        QString s = QString::fromUtf8(p, qsizetype(n));
        p += n;
        return s;
    }
};

std::int32_t mm(double m) {
    return std::int32_t(std::llround(m * 1000.0));
}

std::int32_t messageDelta(const MachineState& s) {
    if (s.lastMessageMs == 0)
        return kNoMessageTime;
    return std::int32_t(std::clamp<qint64>(s.lastMessageMs - s.lastDataMs, qint64(kNoMessageTime) + 1,
                                           std::numeric_limits<std::int32_t>::max()));
}

template <typename E> E enumOf(std::uint8_t v, E max) {
    return v <= std::uint8_t(max) ? E(v) : E(0);
}

} // namespace

bool sameStatus(const MachineState& a, const MachineState& b) {
    return a.id == b.id && a.protocol == b.protocol && a.name == b.name && a.type == b.type &&
           a.link == b.link && a.hasPosition == b.hasPosition && a.length == b.length && a.width == b.width &&
           a.height == b.height && a.modeText == b.modeText && a.mode == b.mode && a.stop == b.stop &&
           a.stopText == b.stopText && a.controller == b.controller && a.control == b.control &&
           a.health == b.health && a.healthText == b.healthText && a.workText == b.workText;
}

bool positionEncodable(const MachineState& s) {
    constexpr double lim = 2.0e6; // m: int32 millimetres
    return std::isfinite(s.e) && std::isfinite(s.n) && std::isfinite(s.u) && std::abs(s.e) < lim &&
           std::abs(s.n) < lim && std::abs(s.u) < lim && std::isfinite(s.headingDeg) &&
           std::isfinite(s.speed);
}

static void header(QByteArray& out, RecordType t, std::uint32_t idx, std::int32_t dtMs) {
    put<std::uint8_t>(out, std::uint8_t(t));
    put<std::uint32_t>(out, idx);
    put<std::int32_t>(out, dtMs);
}

void appendFull(QByteArray& out, std::uint32_t idx, std::int32_t dtMs, const MachineState& s) {
    header(out, RecordType::Full, idx, dtMs);
    for (int v : {int(s.protocol), int(s.link), int(s.mode), int(s.stop), int(s.control), int(s.health),
                  int(s.hasPosition)})
        put<std::uint8_t>(out, std::uint8_t(v));
    for (double d : {s.e, s.n, s.u, s.lat, s.lon, s.headingDeg, s.speed, s.length, s.width, s.height})
        put<double>(out, d);
    put<std::int64_t>(out, s.lastDataMs);
    put<std::int64_t>(out, s.lastMessageMs);
    for (const QString* str :
         {&s.id, &s.name, &s.type, &s.modeText, &s.stopText, &s.controller, &s.healthText, &s.workText})
        putString(out, *str);
}

void appendPosition(QByteArray& out, std::uint32_t idx, std::int32_t dtMs, qint64 tMs,
                    const MachineState& s) {
    header(out, RecordType::Position, idx, dtMs);
    put<std::int32_t>(out, mm(s.e));
    put<std::int32_t>(out, mm(s.n));
    put<std::int32_t>(out, mm(s.u));
    put<double>(out, s.lat);
    put<double>(out, s.lon);
    put<float>(out, float(s.headingDeg));
    put<float>(out, float(s.speed));
    put<std::int64_t>(out, s.lastDataMs - tMs);
    put<std::int32_t>(out, messageDelta(s));
}

void appendDelta(QByteArray& out, std::uint32_t idx, std::int32_t dtMs, qint64 tMs, const MachineState& base,
                 const MachineState& s) {
    header(out, RecordType::Delta, idx, dtMs);
    putVar(out, zigzag(std::int64_t(mm(s.e)) - mm(base.e)));
    putVar(out, zigzag(std::int64_t(mm(s.n)) - mm(base.n)));
    putVar(out, zigzag(std::int64_t(mm(s.u)) - mm(base.u)));
    putVar(out, bitsOf<double, std::uint64_t>(s.lat) ^ bitsOf<double, std::uint64_t>(base.lat));
    putVar(out, bitsOf<double, std::uint64_t>(s.lon) ^ bitsOf<double, std::uint64_t>(base.lon));
    putVar(out, bitsOf<float, std::uint32_t>(float(s.headingDeg)) ^
                    bitsOf<float, std::uint32_t>(float(base.headingDeg)));
    putVar(out,
           bitsOf<float, std::uint32_t>(float(s.speed)) ^ bitsOf<float, std::uint32_t>(float(base.speed)));
    putVar(out, zigzag(s.lastDataMs - tMs));
    putVar(out, zigzag(messageDelta(s)));
}

void applyPosition(MachineState& base, const MachineState& in, qint64 tMs) {
    // Exactly what decodeChunk makes of appendPosition's fields.
    base.e = mm(in.e) / 1000.0;
    base.n = mm(in.n) / 1000.0;
    base.u = mm(in.u) / 1000.0;
    base.lat = in.lat;
    base.lon = in.lon;
    base.headingDeg = float(in.headingDeg);
    base.speed = float(in.speed);
    base.lastDataMs = tMs + (in.lastDataMs - tMs);
    const std::int32_t msg = messageDelta(in);
    base.lastMessageMs = msg == kNoMessageTime ? 0 : base.lastDataMs + msg;
}

void appendRemoved(QByteArray& out, std::uint32_t idx, std::int32_t dtMs) {
    header(out, RecordType::Removed, idx, dtMs);
}

namespace {

std::int64_t fixed(double v, double scale) {
    return std::llround(v * scale);
}

// Values a Move can carry: finite and far inside int64 after scaling.
bool moveEncodable(const MachineState& s) {
    constexpr double lim = 1.0e9;
    return positionEncodable(s) && std::abs(s.headingDeg) < lim && std::abs(s.speed) < lim &&
           std::isfinite(s.lat) && std::isfinite(s.lon) && std::abs(s.lat) <= 1000 && std::abs(s.lon) <= 1000;
}

// Unsigned arithmetic: differences from a hostile blob wrap instead of overflowing.
std::int64_t wrapAdd(std::int64_t a, std::int64_t b) {
    return std::int64_t(std::uint64_t(a) + std::uint64_t(b));
}

} // namespace

void ChunkEncoder::begin(qint64 t0) {
    for (QByteArray& c : m_cols)
        c.clear();
    m_tracks.clear();
    m_t0 = m_prevT = t0;
    m_prevIdx = 0;
}

QByteArray ChunkEncoder::data() const {
    QByteArray out;
    qsizetype size = 1 + kColumns * 5;
    for (const QByteArray& c : m_cols)
        size += c.size();
    out.reserve(size);
    put<std::uint8_t>(out, kColumns);
    for (const QByteArray& c : m_cols)
        putVar(out, std::uint64_t(c.size()));
    for (const QByteArray& c : m_cols)
        out.append(c);
    return out;
}

void ChunkEncoder::header(RecordType type, std::uint32_t idx, qint64 tMs) {
    QByteArray& out = m_cols[0];
    put<std::uint8_t>(out, std::uint8_t(type));
    putVar(out, zigzag(std::int64_t(idx) - std::int64_t(m_prevIdx)));
    putVar(out, std::uint64_t(std::max<qint64>(0, tMs - m_prevT)));
    m_prevIdx = idx;
    m_prevT = std::max(m_prevT, tMs);
}

void ChunkEncoder::full(std::uint32_t idx, qint64 tMs, const MachineState& s) {
    header(RecordType::Full, idx, tMs);
    QByteArray& out = m_cols[0];
    const qsizetype at = out.size();
    appendFull(out, idx, 0, s);
    out.remove(at, kHeader); // the body only: the compact header is written above
    m_tracks.remove(idx);
}

void ChunkEncoder::removed(std::uint32_t idx, qint64 tMs) {
    header(RecordType::Removed, idx, tMs);
    m_tracks.remove(idx);
}

bool ChunkEncoder::move(std::uint32_t idx, qint64 tMs, MachineState& base, const MachineState& s) {
    if (!moveEncodable(s) || !moveEncodable(base))
        return false;
    const std::int64_t e = fixed(s.e, kMoveMetre), n = fixed(s.n, kMoveMetre), u = fixed(s.u, kMoveMetre);
    // Derived lat/lon when the site frame gives them back from the quantised e/n/u (what the bridges did).
    bool derived = false;
    GeoPoint g;
    if (m_frame) {
        g = m_frame->toGeodetic({double(e) / kMoveMetre, double(n) / kMoveMetre, double(u) / kMoveMetre});
        derived = std::abs(g.lat - s.lat) <= kDerivedGeoTolerance &&
                  std::abs(g.lon - s.lon) <= kDerivedGeoTolerance;
    }
    Track& tr = m_tracks[idx];
    header(derived ? RecordType::Move : RecordType::MoveGeodetic, idx, tMs);
    const std::int64_t de = e - fixed(base.e, kMoveMetre), dn = n - fixed(base.n, kMoveMetre);
    putVar(m_cols[1], zigzag(de - (tr.moved ? tr.ve : 0)));
    putVar(m_cols[2], zigzag(dn - (tr.moved ? tr.vn : 0)));
    putVar(m_cols[3], zigzag(u - fixed(base.u, kMoveMetre)));
    const std::int64_t heading = fixed(s.headingDeg, kMoveDegree), speed = fixed(s.speed, kMoveSpeed);
    putVar(m_cols[4], zigzag(heading - fixed(base.headingDeg, kMoveDegree)));
    putVar(m_cols[5], zigzag(speed - fixed(base.speed, kMoveSpeed)));
    const std::int64_t dataOffset = s.lastDataMs - tMs, messageOffset = messageDelta(s);
    putVar(m_cols[6], zigzag(dataOffset - (tr.moved ? tr.dataOffset : 0)));
    putVar(m_cols[7], zigzag(messageOffset - (tr.moved ? tr.messageOffset : 0)));
    tr.ve = de;
    tr.vn = dn;
    tr.dataOffset = dataOffset;
    tr.messageOffset = messageOffset;
    tr.moved = true;
    base.e = double(e) / kMoveMetre;
    base.n = double(n) / kMoveMetre;
    base.u = double(u) / kMoveMetre;
    base.headingDeg = double(heading) / kMoveDegree;
    base.speed = double(speed) / kMoveSpeed;
    base.lastDataMs = tMs + dataOffset;
    base.lastMessageMs = messageOffset == kNoMessageTime ? 0 : base.lastDataMs + messageOffset;
    if (derived) {
        tr.geodetic = false;
        base.lat = g.lat;
        base.lon = g.lon;
    } else {
        const std::int64_t lat = fixed(s.lat, kMoveGeodetic), lon = fixed(s.lon, kMoveGeodetic);
        const std::int64_t dlat = lat - fixed(base.lat, kMoveGeodetic),
                           dlon = lon - fixed(base.lon, kMoveGeodetic);
        putVar(m_cols[8], zigzag(dlat - (tr.geodetic ? tr.vlat : 0)));
        putVar(m_cols[9], zigzag(dlon - (tr.geodetic ? tr.vlon : 0)));
        tr.vlat = dlat;
        tr.vlon = dlon;
        tr.geodetic = true;
        base.lat = double(lat) / kMoveGeodetic;
        base.lon = double(lon) / kMoveGeodetic;
    }
    return true;
}

void resolveGeodetic(QHash<std::uint32_t, MachineState>& states, QSet<std::uint32_t>& pending,
                     const GeoFrame& frame) {
    for (std::uint32_t idx : std::as_const(pending)) {
        auto it = states.find(idx);
        if (it == states.end())
            continue;
        const GeoPoint g = frame.toGeodetic({it->e, it->n, it->u});
        it->lat = g.lat;
        it->lon = g.lon;
    }
    pending.clear();
}

namespace {

using Tracks = QHash<std::uint32_t, ChunkEncoder::Track>;

// What decodeChunk applies records to.
struct DecodeTarget {
    QHash<std::uint32_t, MachineState>& states;
    QSet<std::uint32_t>* defer; // DecodeOptions::deferGeodetic
    const GeoFrame* frame;      // DecodeOptions::frame
    // A record that sets lat/lon itself ends a deferred derivation of them.
    void settle(std::uint32_t idx, bool apply) {
        if (defer && apply)
            defer->remove(idx);
    }
};

// Compact chunks: the column table; r then reads the headers column, col[i] the Move fields' columns.
bool openColumns(Reader& r, Reader (&col)[ChunkEncoder::columns() - 1]) {
    if (r.get<std::uint8_t>() != ChunkEncoder::columns())
        return false;
    std::uint64_t len[ChunkEncoder::columns()];
    for (auto& l : len)
        l = r.getVar();
    if (!r.ok)
        return false;
    const char* p = r.p;
    const char* const end = r.end;
    for (int i = 0; i < ChunkEncoder::columns(); ++i) {
        if (len[i] > std::uint64_t(end - p))
            return false;
        Reader& c = i == 0 ? r : col[i - 1];
        c = Reader{p, p + len[i]};
        p += len[i];
    }
    return p == end;
}

// A record's header: type, machine index and time (compact: differences to the record before).
bool readHeader(Reader& r, bool compact, qint64 t0Ms, std::uint32_t& prevIdx, qint64& prevT,
                DecodedRecord& rec, std::uint8_t& type) {
    if (compact) {
        type = r.get<std::uint8_t>();
        rec.idx = std::uint32_t(wrapAdd(prevIdx, unzigzag(r.getVar())));
        rec.tMs = wrapAdd(prevT, std::int64_t(r.getVar()));
        if (!r.ok)
            return false;
        prevIdx = rec.idx;
        prevT = rec.tMs;
        return true;
    }
    if (r.end - r.p < kHeader)
        return false;
    type = r.get<std::uint8_t>();
    rec.idx = r.get<std::uint32_t>();
    rec.tMs = t0Ms + r.get<std::int32_t>();
    return true;
}

bool decodeFull(Reader& r, DecodedRecord& rec, bool apply, DecodeTarget& to, Tracks& tracks) {
    rec.type = RecordType::Full;
    MachineState s;
    std::uint8_t e[7];
    for (auto& v : e)
        v = r.get<std::uint8_t>();
    s.protocol = enumOf(e[0], Protocol::Other);
    s.link = enumOf(e[1], LinkState::Down);
    s.mode = enumOf(e[2], ModeCategory::Shutdown);
    s.stop = enumOf(e[3], StopState::Stopped);
    s.control = enumOf(e[4], ControlState::Denied);
    s.health = enumOf(e[5], HealthLevel::Fault);
    s.hasPosition = e[6] != 0;
    for (double* d :
         {&s.e, &s.n, &s.u, &s.lat, &s.lon, &s.headingDeg, &s.speed, &s.length, &s.width, &s.height})
        *d = r.get<double>();
    s.lastDataMs = r.get<std::int64_t>();
    s.lastMessageMs = r.get<std::int64_t>();
    for (QString* str :
         {&s.id, &s.name, &s.type, &s.modeText, &s.stopText, &s.controller, &s.healthText, &s.workText})
        *str = r.getString();
    if (!r.ok)
        return false;
    tracks.remove(rec.idx);
    to.settle(rec.idx, apply);
    if (apply)
        to.states.insert(rec.idx, std::move(s));
    return true;
}

bool decodePosition(Reader& r, DecodedRecord& rec, bool apply, DecodeTarget& to) {
    rec.type = RecordType::Position;
    const double e = r.get<std::int32_t>() / 1000.0;
    const double n = r.get<std::int32_t>() / 1000.0;
    const double u = r.get<std::int32_t>() / 1000.0;
    const double lat = r.get<double>();
    const double lon = r.get<double>();
    const float heading = r.get<float>();
    const float speed = r.get<float>();
    const qint64 lastData = rec.tMs + r.get<std::int64_t>();
    const std::int32_t msg = r.get<std::int32_t>();
    if (!r.ok)
        return false;
    if (!apply)
        return true;
    auto it = to.states.find(rec.idx);
    if (it == to.states.end())
        return true; // no base (a file trimmed in the middle of nowhere): nothing to move
    to.settle(rec.idx, apply);
    MachineState& s = *it;
    s.e = e;
    s.n = n;
    s.u = u;
    s.lat = lat;
    s.lon = lon;
    s.headingDeg = heading;
    s.speed = speed;
    s.lastDataMs = lastData;
    s.lastMessageMs = msg == kNoMessageTime ? 0 : lastData + msg;
    return true;
}

// A Position as differences to the machine's state before it (what the recorder's base was).
bool decodeDelta(Reader& r, DecodedRecord& rec, bool apply, DecodeTarget& to) {
    rec.type = RecordType::Position;
    const std::int64_t de = unzigzag(r.getVar()), dn = unzigzag(r.getVar()), du = unzigzag(r.getVar());
    const std::uint64_t lat = r.getVar(), lon = r.getVar(), heading = r.getVar(), speed = r.getVar();
    const std::int64_t data = unzigzag(r.getVar()), msg = unzigzag(r.getVar());
    if (!r.ok)
        return false;
    if (!apply)
        return true;
    auto it = to.states.find(rec.idx);
    if (it == to.states.end())
        return true; // no base: nothing to move
    to.settle(rec.idx, apply);
    MachineState& s = *it;
    // Unsigned arithmetic: hostile differences wrap instead of overflowing.
    s.e = double(std::int64_t(std::uint64_t(mm(s.e)) + std::uint64_t(de))) / 1000.0;
    s.n = double(std::int64_t(std::uint64_t(mm(s.n)) + std::uint64_t(dn))) / 1000.0;
    s.u = double(std::int64_t(std::uint64_t(mm(s.u)) + std::uint64_t(du))) / 1000.0;
    s.lat = fromBits<double>(bitsOf<double, std::uint64_t>(s.lat) ^ lat);
    s.lon = fromBits<double>(bitsOf<double, std::uint64_t>(s.lon) ^ lon);
    s.headingDeg =
        fromBits<float>(bitsOf<float, std::uint32_t>(float(s.headingDeg)) ^ std::uint32_t(heading));
    s.speed = fromBits<float>(bitsOf<float, std::uint32_t>(float(s.speed)) ^ std::uint32_t(speed));
    s.lastDataMs = qint64(std::uint64_t(rec.tMs) + std::uint64_t(data));
    s.lastMessageMs = msg == kNoMessageTime ? 0 : qint64(std::uint64_t(s.lastDataMs) + std::uint64_t(msg));
    return true;
}

// A Move (compact chunks): the moving part as differences to the machine's previous step in this chunk.
bool decodeMove(Reader (&col)[ChunkEncoder::columns() - 1], DecodedRecord& rec, bool geodetic, bool apply,
                DecodeTarget& to, Tracks& tracks) {
    rec.type = RecordType::Position;
    const std::int64_t re = unzigzag(col[0].getVar()), rn = unzigzag(col[1].getVar()),
                       du = unzigzag(col[2].getVar());
    const std::int64_t dh = unzigzag(col[3].getVar()), ds = unzigzag(col[4].getVar());
    const std::int64_t rData = unzigzag(col[5].getVar()), rMsg = unzigzag(col[6].getVar());
    const std::int64_t rLat = geodetic ? unzigzag(col[7].getVar()) : 0;
    const std::int64_t rLon = geodetic ? unzigzag(col[8].getVar()) : 0;
    for (const Reader& c : col)
        if (!c.ok)
            return false;
    // The steps follow from the records alone: kept whether or not this one is applied.
    ChunkEncoder::Track& tr = tracks[rec.idx];
    const std::int64_t de = wrapAdd(re, tr.moved ? tr.ve : 0), dn = wrapAdd(rn, tr.moved ? tr.vn : 0);
    const std::int64_t dataOffset = wrapAdd(rData, tr.moved ? tr.dataOffset : 0);
    const std::int64_t messageOffset = wrapAdd(rMsg, tr.moved ? tr.messageOffset : 0);
    tr.ve = de;
    tr.vn = dn;
    tr.dataOffset = dataOffset;
    tr.messageOffset = messageOffset;
    tr.moved = true;
    std::int64_t dlat = 0, dlon = 0;
    if (geodetic) {
        dlat = wrapAdd(rLat, tr.geodetic ? tr.vlat : 0);
        dlon = wrapAdd(rLon, tr.geodetic ? tr.vlon : 0);
        tr.vlat = dlat;
        tr.vlon = dlon;
    }
    tr.geodetic = geodetic;
    if (!apply)
        return true;
    auto it = to.states.find(rec.idx);
    if (it == to.states.end())
        return true; // no base: nothing to move
    MachineState& s = *it;
    if (geodetic && to.defer && to.defer->remove(rec.idx) && to.frame) {
        // The base's lat/lon were still owed (derived from the position before this record).
        const GeoPoint g = to.frame->toGeodetic({s.e, s.n, s.u});
        s.lat = g.lat;
        s.lon = g.lon;
    }
    s.e = double(wrapAdd(fixed(s.e, kMoveMetre), de)) / kMoveMetre;
    s.n = double(wrapAdd(fixed(s.n, kMoveMetre), dn)) / kMoveMetre;
    s.u = double(wrapAdd(fixed(s.u, kMoveMetre), du)) / kMoveMetre;
    s.headingDeg = double(wrapAdd(fixed(s.headingDeg, kMoveDegree), dh)) / kMoveDegree;
    s.speed = double(wrapAdd(fixed(s.speed, kMoveSpeed), ds)) / kMoveSpeed;
    s.lastDataMs = wrapAdd(rec.tMs, dataOffset);
    s.lastMessageMs = messageOffset == kNoMessageTime ? 0 : wrapAdd(s.lastDataMs, messageOffset);
    if (geodetic) {
        s.lat = double(wrapAdd(fixed(s.lat, kMoveGeodetic), dlat)) / kMoveGeodetic;
        s.lon = double(wrapAdd(fixed(s.lon, kMoveGeodetic), dlon)) / kMoveGeodetic;
    } else if (to.defer) {
        to.defer->insert(rec.idx);
    } else if (to.frame) {
        const GeoPoint g = to.frame->toGeodetic({s.e, s.n, s.u});
        s.lat = g.lat;
        s.lon = g.lon;
    }
    return true;
}

} // namespace

bool decodeChunk(const QByteArray& blob, qint64 t0Ms, QHash<std::uint32_t, MachineState>& states,
                 qint64 fromExclusiveMs, qint64 untilMs, const RecordVisitor& visit,
                 const DecodeOptions& options) {
    Reader r{blob.constData(), blob.constData() + blob.size()};
    const bool compact = options.format == ChunkFormat::Compact;
    Reader col[ChunkEncoder::columns() - 1] = {};
    if (compact && !blob.isEmpty() && !openColumns(r, col))
        return false;
    DecodeTarget to{states, options.deferGeodetic, options.frame};
    // Move records: each machine's previous step in this chunk (from the records alone, applied or not).
    Tracks tracks;
    std::uint32_t prevIdx = 0;
    qint64 prevT = t0Ms;
    while (r.p < r.end) {
        DecodedRecord rec;
        std::uint8_t type = 0;
        if (!readHeader(r, compact, t0Ms, prevIdx, prevT, rec, type))
            return false;
        if (rec.tMs > untilMs)
            return true;
        const bool apply = rec.tMs > fromExclusiveMs;
        bool ok = true;
        switch (RecordType(type)) {
        case RecordType::Full:
            ok = decodeFull(r, rec, apply, to, tracks);
            break;
        case RecordType::Position:
            ok = decodePosition(r, rec, apply, to);
            break;
        case RecordType::Delta:
            ok = decodeDelta(r, rec, apply, to);
            break;
        case RecordType::Move:
        case RecordType::MoveGeodetic:
            ok = compact &&
                 decodeMove(col, rec, RecordType(type) == RecordType::MoveGeodetic, apply, to, tracks);
            break;
        case RecordType::Removed:
            rec.type = RecordType::Removed;
            tracks.remove(rec.idx);
            to.settle(rec.idx, apply);
            if (apply)
                states.remove(rec.idx);
            break;
        default:
            return false;
        }
        if (!ok)
            return false;
        if (apply && visit)
            visit(rec);
    }
    return true;
}

} // namespace ocu::recording
