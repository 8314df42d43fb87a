#pragma once
// The foreign vehicle's little-endian field helpers (JAUS byte order, AS5669A §3.1), shared by its services;
// written from the standard, nothing from protocols/ or sim/.
#include <cstdint>
#include <string>
#include <vector>

namespace foreign {

using Buf = std::vector<std::uint8_t>;

inline void put8(Buf& b, std::uint8_t v) {
    b.push_back(v);
}
inline void put16(Buf& b, std::uint16_t v) {
    b.push_back(std::uint8_t(v));
    b.push_back(std::uint8_t(v >> 8));
}
inline void put32(Buf& b, std::uint32_t v) {
    for (int i = 0; i < 4; ++i)
        b.push_back(std::uint8_t(v >> (8 * i)));
}
inline void putStr8(Buf& b, const std::string& s) {
    put8(b, std::uint8_t(s.size()));
    b.insert(b.end(), s.begin(), s.end());
}
inline std::uint16_t get16(const std::uint8_t* p) {
    return std::uint16_t(p[0] | p[1] << 8);
}
inline std::uint32_t get32(const std::uint8_t* p) {
    return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 |
           std::uint32_t(p[3]) << 24;
}

} // namespace foreign
