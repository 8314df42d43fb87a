#include "models/recording/MessageLog.h"

#include <algorithm>

namespace ocu::recording {

namespace {

void putVarint(QByteArray& out, std::uint64_t v) {
    while (v >= 0x80) {
        out.append(char(std::uint8_t(v) | 0x80));
        v >>= 7;
    }
    out.append(char(v));
}

bool getVarint(const char*& p, const char* end, std::uint64_t& v) {
    v = 0;
    for (int shift = 0; shift < 64; shift += 7) {
        if (p >= end)
            return false;
        const auto b = std::uint8_t(*p++);
        v |= std::uint64_t(b & 0x7F) << shift;
        if (!(b & 0x80))
            return true;
    }
    return false;
}

void putShort(QByteArray& out, std::string_view s) {
    const std::size_t n = std::min<std::size_t>(s.size(), 255);
    out.append(char(n));
    out.append(s.data(), qsizetype(n));
}

bool getShort(const char*& p, const char* end, QString& s, QByteArray& key) {
    if (p >= end)
        return false;
    const auto n = std::uint8_t(*p);
    if (end - p < 1 + n)
        return false;
    key.append(p, 1 + n);
    s = QString::fromUtf8(p + 1, n);
    p += 1 + n;
    return true;
}

} // namespace

void appendMessage(QByteArray& chunk, std::uint32_t channel, std::uint32_t dtMs, bool raw, const char* data,
                   qsizetype size) {
    putVarint(chunk, channel);
    putVarint(chunk, dtMs);
    chunk.append(char(raw ? 1 : 0));
    putVarint(chunk, std::uint64_t(size));
    chunk.append(data, size);
}

bool decodeMessageChunk(const QByteArray& blob, qint64 t0Ms, qint64 fromMs, qint64 toMs,
                        const std::function<bool(const RecordedMessage&)>& fn) {
    const char* p = blob.constData();
    const char* end = p + blob.size();
    while (p < end) {
        std::uint64_t channel = 0, dt = 0, len = 0;
        if (!getVarint(p, end, channel) || !getVarint(p, end, dt) || p >= end)
            return false;
        const auto flags = std::uint8_t(*p++);
        if (!getVarint(p, end, len) || len > std::uint64_t(end - p) || channel > 0xFFFFFFFFu ||
            dt > 0x7FFFFFFFu)
            return false;
        RecordedMessage m;
        m.t = t0Ms + qint64(dt);
        if (m.t > toMs)
            return true;
        if (m.t >= fromMs) {
            m.channel = std::uint32_t(channel);
            m.raw = flags & 1;
            m.bytes = QByteArray(p, qsizetype(len));
            if (!fn(m))
                return true;
        }
        p += len;
    }
    return true;
}

QByteArray packTapped(std::string_view protocol, std::string_view link, std::string_view peer,
                      std::string_view type, bool raw, const std::uint8_t* data, std::size_t size) {
    QByteArray out;
    out.reserve(qsizetype(4 + protocol.size() + link.size() + peer.size() + type.size() + 1 + size));
    putShort(out, protocol);
    putShort(out, link);
    putShort(out, peer);
    putShort(out, type);
    out.append(char(raw ? 1 : 0));
    out.append(reinterpret_cast<const char*>(data), qsizetype(size));
    return out;
}

bool unpackTapped(const QByteArray& packed, UnpackedTapped& out) {
    const char* p = packed.constData();
    const char* end = p + packed.size();
    out.key.clear();
    if (!getShort(p, end, out.channel.protocol, out.key) || !getShort(p, end, out.channel.link, out.key) ||
        !getShort(p, end, out.channel.peer, out.key) || !getShort(p, end, out.channel.type, out.key) ||
        p >= end)
        return false;
    out.raw = *p++ & 1;
    out.data = p;
    out.size = end - p;
    return true;
}

} // namespace ocu::recording
