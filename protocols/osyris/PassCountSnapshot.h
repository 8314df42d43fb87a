#pragma once
// Pass counts for other threads: copy-on-write tiles and the immutable snapshot that shares them.
//
// PassCountGrid lives on the station's io thread. Another thread (the GUI) never reads the grid itself: the
// io thread publishes a PassCountSnapshot, which holds shared_ptrs to const tiles. The grid copies a tile
// before it changes one that a snapshot already holds, so a published snapshot never changes, readers need
// no lock shared with the io thread, and consecutive snapshots share every tile that did not change between
// them (a snapshot costs one pointer per tile plus a copy of each changed tile).
//
// Shaped for larger jobs (issue 17): one snapshot per grid, so per-lift or per-machine counts are more grids
// with their own snapshots; tiles are the unit of change, sharing and (later) level of detail; the count type
// is one alias.
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace ocu::osyris {

using PassCount = std::uint16_t; // saturates at 65535

constexpr int kTileBits = 5;
constexpr int kTileSize = 1 << kTileBits; // 32 x 32 cells per tile
constexpr int kTileCells = kTileSize * kTileSize;

// One tile of counts. Cell (cx, cy) of the grid is tile (cx >> 5, cy >> 5), index ((cy & 31) << 5) | (cx &
// 31).
struct PassCountTile {
    std::array<PassCount, kTileCells> counts{};
    // The grid generation this version of the tile was written in: equal to the sequence of the first
    // snapshot that holds it, so "changed since snapshot n" is "generation > n".
    std::uint64_t generation = 0;
};

// A tile's counts as a plain value (tests compare grids with these).
struct TileSnapshot {
    std::int32_t tx = 0, ty = 0;                // tile index; cell (cx, cy) = (tx*32 + i, ty*32 + j)
    std::array<PassCount, kTileCells> counts{}; // [j*32 + i]
    bool operator==(const TileSnapshot&) const = default;
};

struct PassCountSummary {
    std::uint64_t coveredCells = 0;
    double coveredAreaM2 = 0;
    double percentBelow = 0;
    double percentWithin = 0;
    double percentAbove = 0;
    std::vector<std::uint64_t>
        histogram; // [n] = cells with exactly n passes (n >= 1); last bin = "n or more"
    int targetMin = 3;
    int targetMax = 5;
};

// Inclusive range of cells [cx0, cx1] x [cy0, cy1].
struct CellBox {
    std::int32_t cx0 = 0, cy0 = 0, cx1 = -1, cy1 = -1;
};

class PassCountSnapshot {
public:
    struct Entry {
        std::int32_t tx = 0, ty = 0;
        std::shared_ptr<const PassCountTile> tile;
    };

    PassCountSnapshot() = default;
    // tiles sorted by (ty, tx), no duplicates (PassCountGrid::snapshot() builds it).
    PassCountSnapshot(std::vector<Entry> tiles, double cellSize, int targetMin, int targetMax,
                      std::uint64_t sequence, std::uint64_t clearedAt);

    // 1, 2, ... for the snapshots of one grid, in the order they were taken.
    std::uint64_t sequence() const { return m_sequence; }
    // Sequence of the first snapshot after the grid was last cleared (settings changed): everything may have
    // changed since an older snapshot, including tiles that are gone.
    std::uint64_t clearedAt() const { return m_clearedAt; }
    double cellSize() const { return m_cellSize; }
    int targetMin() const { return m_targetMin; }
    int targetMax() const { return m_targetMax; }

    bool empty() const { return m_tiles.empty(); }
    const std::vector<Entry>& tiles() const { return m_tiles; } // sorted by (ty, tx)
    const PassCountTile* tile(std::int32_t tx, std::int32_t ty) const;
    // Bounding box of the covered tiles, in cells (whole tiles); cx1 < cx0 when empty.
    CellBox extent() const { return m_extent; }

    int countAtCell(std::int32_t cx, std::int32_t cy) const;
    // Counts of the cells [cx0, cx0+cols) x [cy0, cy0+rows) into out[row*cols + col] (0 where not covered).
    void countsInRect(std::int32_t cx0, std::int32_t cy0, int cols, int rows, PassCount* out) const;
    PassCountSummary summary() const;
    // Bounding box (cells, whole tiles) of the tiles written after snapshot `sequence` was taken, nullopt
    // when none was. Only meaningful when sequence >= clearedAt() (otherwise everything changed).
    std::optional<CellBox> changedSince(std::uint64_t sequence) const;
    std::vector<TileSnapshot> tileValues() const; // sorted by (ty, tx)

private:
    std::vector<Entry> m_tiles;
    double m_cellSize = 0.34;
    int m_targetMin = 3, m_targetMax = 5;
    std::uint64_t m_sequence = 0, m_clearedAt = 0;
    CellBox m_extent;
};

// The summary (histogram, below/within/above target) of a set of tiles; shared by the grid and its snapshots.
PassCountSummary summarizeTiles(std::span<const PassCountTile* const> tiles, double cellSize, int targetMin,
                                int targetMax);

} // namespace ocu::osyris
