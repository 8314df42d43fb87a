#pragma once
// Building blocks of the JAUS message codecs (protocols/jaus/Messages*.cpp): the message ID frame, strings,
// blobs, presence vectors and scaled integers. Internal to those files; everything else uses Messages.h.
#include <algorithm>
#include <optional>
#include <string>

#include "protocols/common/Bytes.h"
#include "protocols/common/Result.h"
#include "protocols/jaus/Messages.h"

namespace ocu::jaus::codec {

inline ByteWriter start(Bytes& out, std::uint16_t id) {
    out.reserve(48); // most messages fit: one allocation instead of several regrowths
    ByteWriter w(out);
    w.u16(id);
    return w;
}

// Opens a reader positioned after the message ID; fails when the ID differs.
inline Result<ByteReader> open(ByteSpan payload, std::uint16_t id) {
    if (payload.size() < 2)
        return makeError("short: payload has no message ID");
    const std::uint16_t got = peekMessageId(payload);
    if (got != id)
        return makeError("message_id: expected " + std::string(messageName(id)) + ", got 0x" +
                         std::to_string(got));
    ByteReader r(payload);
    r.u16();
    return r;
}

template <class T> Result<T> finish(const ByteReader& r, T value, std::uint16_t id) {
    if (!r.ok())
        return makeError(std::string("truncated: ") + messageName(id) + " body is too short");
    return value;
}

inline void putString8(ByteWriter& w, const std::string& s) {
    const std::size_t n = std::min<std::size_t>(s.size(), 255);
    w.u8(std::uint8_t(n));
    w.bytes(ByteSpan(reinterpret_cast<const std::uint8_t*>(s.data()), n));
}
inline std::string getString8(ByteReader& r) {
    auto n = r.u8();
    auto b = r.bytes(n);
    return std::string(b.begin(), b.end());
}
inline void putBlob32(ByteWriter& w, const Bytes& b) {
    w.u32(std::uint32_t(b.size()));
    w.bytes(b);
}
inline Bytes getBlob32(ByteReader& r) {
    auto n = r.u32();
    if (n > r.remaining()) {
        r.fail();
        return {};
    }
    auto b = r.bytes(n);
    return Bytes(b.begin(), b.end());
}

// Presence-vector helpers: each optional field is one bit, in declaration order.
struct PvWriter {
    std::uint32_t pv = 0;
    int bit = 0;
    template <class T> void mark(const std::optional<T>& v) {
        if (v)
            pv |= 1u << bit;
        ++bit;
    }
};

inline void putU32s(ByteWriter& w, const std::optional<double>& v, double lo, double hi) {
    if (v)
        w.u32(scaleToInt<std::uint32_t>(*v, lo, hi));
}
inline void putU16s(ByteWriter& w, const std::optional<double>& v, double lo, double hi) {
    if (v)
        w.u16(scaleToInt<std::uint16_t>(*v, lo, hi));
}
inline void putU8s(ByteWriter& w, const std::optional<double>& v, double lo, double hi) {
    if (v)
        w.u8(scaleToInt<std::uint8_t>(*v, lo, hi));
}
inline void getU32s(ByteReader& r, std::uint32_t pv, int bit, std::optional<double>& v, double lo,
                    double hi) {
    if (pv & (1u << bit))
        v = intToScale<std::uint32_t>(r.u32(), lo, hi);
}
inline void getU16s(ByteReader& r, std::uint32_t pv, int bit, std::optional<double>& v, double lo,
                    double hi) {
    if (pv & (1u << bit))
        v = intToScale<std::uint16_t>(r.u16(), lo, hi);
}
inline void getU8s(ByteReader& r, std::uint32_t pv, int bit, std::optional<double>& v, double lo, double hi) {
    if (pv & (1u << bit))
        v = intToScale<std::uint8_t>(r.u8(), lo, hi);
}

} // namespace ocu::jaus::codec
