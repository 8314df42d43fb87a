#pragma once
// Building blocks of the JAUS message codecs (protocols/jaus/Messages*.cpp): the message ID frame, strings,
// blobs, presence vectors and scaled integers. Internal to those files; everything else uses Messages.h.
#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>

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

// ---- Field tables ----------------------------------------------------------------------------------------
// A message's optional scaled fields as data: member, wire width and JSIDL range uN[lo,hi]. Field i of a
// table owns presence-vector bit (first + i), and present fields follow each other on the wire in table order
// (jaus-wire.md §3). The tables are constexpr and walked by fold expressions, so each field compiles to the
// same straight-line code as a hand-written codec (constant ranges, no loop, no division).
template <class T> struct ScaledField {
    std::optional<double> T::*member;
    int bytes; // 1, 2 or 4: u8, u16 or u32 on the wire
    double lo, hi;
};

template <int Bytes>
using WireUInt = std::conditional_t<Bytes == 4, std::uint32_t,
                                    std::conditional_t<Bytes == 2, std::uint16_t, std::uint8_t>>;

template <class U> void putUInt(ByteWriter& w, U v) {
    if constexpr (sizeof(U) == 4)
        w.u32(v);
    else if constexpr (sizeof(U) == 2)
        w.u16(v);
    else
        w.u8(v);
}
template <class U> U getUInt(ByteReader& r) {
    if constexpr (sizeof(U) == 4)
        return r.u32();
    else if constexpr (sizeof(U) == 2)
        return r.u16();
    else
        return r.u8();
}

// Presence-vector bits of the table's fields that m carries, bit 0 = Table[0].
template <const auto& Table, class T> std::uint32_t presenceOf(const T& m) {
    return [&]<std::size_t... I>(std::index_sequence<I...>) {
        return ((std::uint32_t((m.*(Table[I].member)).has_value()) << I) | ... | 0u);
    }
    (std::make_index_sequence<Table.size()>{});
}

template <const auto& Table, std::size_t I, class T> void putField(ByteWriter& w, const T& m) {
    constexpr ScaledField<T> f = Table[I];
    using U = WireUInt<f.bytes>;
    if (const auto& v = m.*(f.member))
        putUInt<U>(w, scaleToInt<U>(*v, f.lo, f.hi));
}
template <const auto& Table, std::size_t I, class T>
void getField(ByteReader& r, std::uint32_t pv, int first, T& m) {
    constexpr ScaledField<T> f = Table[I];
    using U = WireUInt<f.bytes>;
    if (pv & (1u << (first + int(I))))
        m.*(f.member) = intToScale<U>(getUInt<U>(r), f.lo, f.hi);
}

// Writes the fields m carries, in table order.
template <const auto& Table, class T> void putFields(ByteWriter& w, const T& m) {
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        (putField<Table, I>(w, m), ...);
    }
    (std::make_index_sequence<Table.size()>{});
}
// Reads the fields whose bits (first, first + 1, ...) are set in pv.
template <const auto& Table, class T> void getFields(ByteReader& r, std::uint32_t pv, int first, T& m) {
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        (getField<Table, I>(r, pv, first, m), ...);
    }
    (std::make_index_sequence<Table.size()>{});
}

} // namespace ocu::jaus::codec
