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

bool decodeChunk(const QByteArray& blob, qint64 t0Ms, QHash<std::uint32_t, MachineState>& states,
                 qint64 fromExclusiveMs, qint64 untilMs, const RecordVisitor& visit) {
    Reader r{blob.constData(), blob.constData() + blob.size()};
    while (r.p < r.end) {
        if (r.end - r.p < kHeader)
            return false;
        DecodedRecord rec;
        const auto type = r.get<std::uint8_t>();
        rec.idx = r.get<std::uint32_t>();
        rec.tMs = t0Ms + r.get<std::int32_t>();
        if (rec.tMs > untilMs)
            return true;
        const bool apply = rec.tMs > fromExclusiveMs;
        switch (RecordType(type)) {
        case RecordType::Full: {
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
            for (QString* str : {&s.id, &s.name, &s.type, &s.modeText, &s.stopText, &s.controller,
                                 &s.healthText, &s.workText})
                *str = r.getString();
            if (!r.ok)
                return false;
            if (apply)
                states.insert(rec.idx, std::move(s));
            break;
        }
        case RecordType::Position: {
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
                break;
            auto it = states.find(rec.idx);
            if (it == states.end())
                break; // no base (a file trimmed in the middle of nowhere): nothing to move
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
            break;
        }
        case RecordType::Delta: {
            // Position as differences to the machine's state before it (what the recorder's base was).
            rec.type = RecordType::Position;
            const std::int64_t de = unzigzag(r.getVar()), dn = unzigzag(r.getVar()),
                               du = unzigzag(r.getVar());
            const std::uint64_t lat = r.getVar(), lon = r.getVar(), heading = r.getVar(), speed = r.getVar();
            const std::int64_t data = unzigzag(r.getVar()), msg = unzigzag(r.getVar());
            if (!r.ok)
                return false;
            if (!apply)
                break;
            auto it = states.find(rec.idx);
            if (it == states.end())
                break; // no base: nothing to move
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
            s.lastMessageMs =
                msg == kNoMessageTime ? 0 : qint64(std::uint64_t(s.lastDataMs) + std::uint64_t(msg));
            break;
        }
        case RecordType::Removed:
            rec.type = RecordType::Removed;
            if (apply)
                states.remove(rec.idx);
            break;
        default:
            return false;
        }
        if (apply && visit)
            visit(rec);
    }
    return true;
}

} // namespace ocu::recording
