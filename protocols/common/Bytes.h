#pragma once
// Little-endian byte writer/reader shared by the binary codecs (JAUS, OSYRIS).
// The reader never throws and never reads past the end: after the first short read ok() is false and
// every later read returns 0, so decoders check ok() once at the end of a structure.
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace ocu {

using Bytes = std::vector<std::uint8_t>;
using ByteSpan = std::span<const std::uint8_t>;

class ByteWriter {
public:
    explicit ByteWriter(Bytes& out) : m_out(out) {}

    void u8(std::uint8_t v) { m_out.push_back(v); }
    void u16(std::uint16_t v) { putLe(v, 2); }
    void u32(std::uint32_t v) { putLe(v, 4); }
    void u64(std::uint64_t v) { putLe(v, 8); }
    void i8(std::int8_t v) { u8(static_cast<std::uint8_t>(v)); }
    void i16(std::int16_t v) { u16(static_cast<std::uint16_t>(v)); }
    void i32(std::int32_t v) { u32(static_cast<std::uint32_t>(v)); }
    void i64(std::int64_t v) { u64(static_cast<std::uint64_t>(v)); }
    void f32(float v) {
        std::uint32_t b;
        std::memcpy(&b, &v, 4);
        u32(b);
    }
    void f64(double v) {
        std::uint64_t b;
        std::memcpy(&b, &v, 8);
        u64(b);
    }
    void bytes(ByteSpan b) { m_out.insert(m_out.end(), b.begin(), b.end()); }
    // Fixed-size text field: truncated or zero-padded to exactly n bytes.
    void fixedString(std::string_view s, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i)
            m_out.push_back(i < s.size() ? static_cast<std::uint8_t>(s[i]) : 0);
    }
    std::size_t size() const { return m_out.size(); }
    // Overwrite a little-endian value already written at byte offset pos.
    void patchU16(std::size_t pos, std::uint16_t v) {
        m_out[pos] = static_cast<std::uint8_t>(v);
        m_out[pos + 1] = static_cast<std::uint8_t>(v >> 8);
    }
    void patchU32(std::size_t pos, std::uint32_t v) {
        for (int i = 0; i < 4; ++i)
            m_out[pos + i] = static_cast<std::uint8_t>(v >> (8 * i));
    }

private:
    void putLe(std::uint64_t v, int n) {
        for (int i = 0; i < n; ++i)
            m_out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
    }
    Bytes& m_out;
};

class ByteReader {
public:
    explicit ByteReader(ByteSpan data) : m_data(data) {}

    bool ok() const { return m_ok; }
    std::size_t position() const { return m_pos; }
    std::size_t remaining() const { return m_ok ? m_data.size() - m_pos : 0; }
    bool atEnd() const { return remaining() == 0; }
    void fail() { m_ok = false; }

    std::uint8_t u8() { return static_cast<std::uint8_t>(getLe(1)); }
    std::uint16_t u16() { return static_cast<std::uint16_t>(getLe(2)); }
    std::uint32_t u32() { return static_cast<std::uint32_t>(getLe(4)); }
    std::uint64_t u64() { return getLe(8); }
    std::int8_t i8() { return static_cast<std::int8_t>(u8()); }
    std::int16_t i16() { return static_cast<std::int16_t>(u16()); }
    std::int32_t i32() { return static_cast<std::int32_t>(u32()); }
    std::int64_t i64() { return static_cast<std::int64_t>(u64()); }
    float f32() {
        std::uint32_t b = u32();
        float v;
        std::memcpy(&v, &b, 4);
        return v;
    }
    double f64() {
        std::uint64_t b = u64();
        double v;
        std::memcpy(&v, &b, 8);
        return v;
    }
    ByteSpan bytes(std::size_t n) {
        if (!need(n))
            return {};
        ByteSpan s = m_data.subspan(m_pos, n);
        m_pos += n;
        return s;
    }
    // Fixed-size text field; stops at the first NUL.
    std::string fixedString(std::size_t n) {
        ByteSpan s = bytes(n);
        std::string out;
        for (auto c : s) {
            if (c == 0)
                break;
            out.push_back(static_cast<char>(c));
        }
        return out;
    }
    ByteSpan rest() { return bytes(remaining()); }
    void skip(std::size_t n) { bytes(n); }

private:
    bool need(std::size_t n) {
        if (!m_ok || m_data.size() - m_pos < n) {
            m_ok = false;
            return false;
        }
        return true;
    }
    std::uint64_t getLe(int n) {
        if (!need(static_cast<std::size_t>(n)))
            return 0;
        std::uint64_t v = 0;
        for (int i = 0; i < n; ++i)
            v |= static_cast<std::uint64_t>(m_data[m_pos + i]) << (8 * i);
        m_pos += static_cast<std::size_t>(n);
        return v;
    }
    ByteSpan m_data;
    std::size_t m_pos = 0;
    bool m_ok = true;
};

// Scaled integers as JSIDL defines them: value = lower + raw * (upper - lower) / (2^bits - 1).
// Encoding rounds to nearest; decoding is exact, so peers that truncate still decode within one step.
template <class U> U scaleToInt(double value, double lower, double upper) {
    constexpr double maxRaw = static_cast<double>(static_cast<U>(~U{0}));
    if (value <= lower)
        return 0;
    if (value >= upper)
        return static_cast<U>(~U{0});
    double raw = (value - lower) / (upper - lower) * maxRaw;
    return static_cast<U>(raw + 0.5);
}
template <class U> double intToScale(U raw, double lower, double upper) {
    constexpr double maxRaw = static_cast<double>(static_cast<U>(~U{0}));
    return lower + static_cast<double>(raw) * (upper - lower) / maxRaw;
}

} // namespace ocu
