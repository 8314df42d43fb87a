#pragma once
// A capture time stamped into a video frame's pixels: the simulated cameras draw it, the console's
// glass-to-glass benchmark reads it back from the rendered image. It survives H.264 because each bit is a
// large flat cell and readers sample only the cell's centre.
//
// Layout, on an 8-bit luma (or any single 8-bit channel) plane of width W:
//   cell = max(4, W / 80) pixels square; row 1 at y in [0, cell), row 2 at y in [cell, 2*cell);
//   bit i (i = 0 is the most significant of 64) at x in [i*cell, (i+1)*cell);
//   row 1 carries the value, row 2 the same bits inverted (a reader accepts only when they agree);
//   a 1 is bright (235), a 0 dark (16); readers threshold the mean of the centre half of the cell at 128.
// The value is microseconds since the Unix epoch (std::chrono::system_clock).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>

namespace ocu::timecode {

constexpr int kBits = 64;
constexpr std::uint8_t kHigh = 235, kLow = 16;

constexpr int cellSize(int width) {
    return std::max(4, width / 80);
}
// The code needs 64 cells across and two rows.
constexpr bool fits(int width, int height) {
    return width >= kBits * cellSize(width) && height >= 2 * cellSize(width);
}

// Draws value into plane (width x height, stride bytes per row). Returns false when the frame is too small.
inline bool stamp(std::uint8_t* plane, int width, int height, std::ptrdiff_t stride, std::uint64_t value) {
    if (!plane || !fits(width, height))
        return false;
    const int c = cellSize(width);
    for (int row = 0; row < 2; ++row) {
        for (int i = 0; i < kBits; ++i) {
            bool bit = (value >> (kBits - 1 - i)) & 1u;
            if (row == 1)
                bit = !bit;
            const std::uint8_t v = bit ? kHigh : kLow;
            for (int y = row * c; y < (row + 1) * c; ++y)
                std::fill_n(plane + y * stride + i * c, c, v);
        }
    }
    return true;
}

// Reads the value back; pixelStep is the distance in bytes between horizontally adjacent pixels of the
// channel (1 for a luma plane, 4 for one channel of RGBA/BGRA). nullopt when the two rows disagree.
inline std::optional<std::uint64_t> read(const std::uint8_t* plane, int width, int height,
                                         std::ptrdiff_t stride, int pixelStep = 1) {
    if (!plane || !fits(width, height))
        return std::nullopt;
    const int c = cellSize(width);
    const int q = std::max(1, c / 4);
    std::uint64_t rows[2] = {0, 0};
    for (int row = 0; row < 2; ++row) {
        for (int i = 0; i < kBits; ++i) {
            unsigned sum = 0, n = 0;
            for (int y = row * c + q; y < (row + 1) * c - q; ++y)
                for (int x = i * c + q; x < (i + 1) * c - q; ++x, ++n)
                    sum += plane[y * stride + static_cast<std::ptrdiff_t>(x) * pixelStep];
            const bool bit = n && sum / n >= 128;
            rows[row] = (rows[row] << 1) | (bit ? 1u : 0u);
        }
    }
    if (rows[1] != ~rows[0])
        return std::nullopt;
    return rows[0];
}

} // namespace ocu::timecode
