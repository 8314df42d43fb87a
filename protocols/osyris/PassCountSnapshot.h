#pragma once
// Pass counts for other threads: copy-on-write tiles and the immutable snapshot that shares them.
//
// PassCountGrid lives on the station's io thread. Another thread (the GUI) never reads the grid itself: the
// io thread publishes a PassCountSnapshot, which holds shared_ptrs to const tiles. The grid copies a tile
// before it changes one that a snapshot already holds, so a published snapshot never changes, readers need
// no lock shared with the io thread, and consecutive snapshots share every tile that did not change between
// them (a snapshot costs one pointer per tile plus a copy of each changed tile).
//
// Lifts: the grid keeps one tile set per lift (an elevation band of the positions' z, of
// PassCountSettings::liftThickness above liftBase) plus a composite "top" tile set: per cell the count of the
// top-most lift with data there and the cell's flags (incomplete: a given-up gap of a ribbon may have passed
// over it). tiles()/countAtCell(cx, cy)/countsInRect() without a lift read the top view.
#include "protocols/osyris/IntervalSet.h"
#include "protocols/osyris/Plausibility.h"

#include <array>
#include <climits>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <span>
#include <vector>

namespace ocu::osyris {

using PassCount = std::uint16_t; // saturates at 65535

constexpr int kTileBits = 5;
constexpr int kTileSize = 1 << kTileBits; // 32 x 32 cells per tile
constexpr int kTileCells = kTileSize * kTileSize;

enum class DirectionFilter { Any, Forward, Backward };
enum class VibrationFilter { Any, On, Off };

// What is counted and how. A change clears the grid, which is then re-fed from the
// ribbons, so every filter applies to the whole job.
struct PassCountSettings {
    double cellSize = 0.34;                          // m (TRex default)
    VibrationFilter vibration = VibrationFilter::On; // On: count only with POS_VIBRATING
    DirectionFilter direction = DirectionFilter::Any;
    std::set<std::uint8_t> machines; // empty = every machine
    // Speed window [m/s] and time window [Unix ms, inclusive]: positions outside count nothing (they still
    // move the machine on, so the traversal is not swept across them).
    std::optional<double> speedMin, speedMax;
    std::optional<std::int64_t> timeFrom, timeTo;
    // Lifts: lift n is z in [liftBase + n*liftThickness, liftBase + (n+1)*liftThickness). Thickness <= 0 puts
    // every position in one lift (0).
    double liftThickness = 0;
    double liftBase = 0;
    double minMove = 0.25;     // m since the last counted position (Trimble GCS900)
    double maxJump = 10.0;     // m; a longer step breaks the traversal (GCS900 "< 10 m")
    double defaultWidth = 2.0; // m when a position carries no extent
    int targetMin = 3;
    int targetMax = 5;
    PlausibilityLimits plausibility; // implausible positions break the traversal and count nothing
    bool operator==(const PassCountSettings&) const = default;
};

struct GridRect { // in metres, local ENU
    double xMin = 0, yMin = 0, xMax = 0, yMax = 0;
};

// One tile of counts. Cell (cx, cy) of the grid is tile (cx >> 5, cy >> 5), index ((cy & 31) << 5) | (cx &
// 31).
struct PassCountTile {
    std::array<PassCount, kTileCells> counts{};
    // The grid generation this version of the tile was written in: equal to the sequence of the first
    // snapshot that holds it, so "changed since snapshot n" is "generation > n".
    std::uint64_t generation = 0;
};

constexpr std::int16_t kNoLift = INT16_MIN;
constexpr std::uint8_t kCellIncomplete = 1;

// A tile of the top view: the count of the top-most lift with data per cell, that lift (absolute index,
// kNoLift where none) and the cell's flags (kCellIncomplete).
struct PassCountTopTile : PassCountTile {
    PassCountTopTile() { lift.fill(kNoLift); }
    std::array<std::int16_t, kTileCells> lift;
    std::array<std::uint8_t, kTileCells> flags{};
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
        std::shared_ptr<const PassCountTile> tile; // a PassCountTopTile in the top view
    };
    // One lift with data: its absolute index (elevation band), its z range and its tiles.
    struct Lift {
        int index = 0;
        double bottom = 0, top = 0; // m z; with lifts off, the z range of the counted positions
        std::vector<Entry> tiles;   // sorted by (ty, tx)
    };

    PassCountSnapshot() = default;
    // tiles sorted by (ty, tx), no duplicates (PassCountGrid::snapshot() builds it); a single-lift picture
    // whose top view is `tiles` (plain PassCountTiles: no flags).
    PassCountSnapshot(std::vector<Entry> tiles, double cellSize, int targetMin, int targetMax,
                      std::uint64_t sequence, std::uint64_t clearedAt);
    // The grid's picture: the top view (PassCountTopTiles), the lifts lowest first, the settings in force,
    // and per machine the slots given up as unobtainable.
    PassCountSnapshot(std::vector<Entry> top, std::vector<Lift> lifts, const PassCountSettings& settings,
                      std::uint64_t sequence, std::uint64_t clearedAt,
                      std::map<std::uint8_t, std::vector<SlotRange>> givenUp);

    // 1, 2, ... for the snapshots of one grid, in the order they were taken.
    std::uint64_t sequence() const { return m_sequence; }
    // Sequence of the first snapshot after the grid was last cleared (settings changed): everything may have
    // changed since an older snapshot, including tiles that are gone.
    std::uint64_t clearedAt() const { return m_clearedAt; }
    double cellSize() const { return m_settings.cellSize; }
    int targetMin() const { return m_settings.targetMin; }
    int targetMax() const { return m_settings.targetMax; }
    // Cell size, targets, the filters in force, lift thickness and base.
    const PassCountSettings& settings() const { return m_settings; }

    bool empty() const { return m_tiles.empty(); }
    const std::vector<Entry>& tiles() const { return m_tiles; } // the top view, sorted by (ty, tx)
    const PassCountTile* tile(std::int32_t tx, std::int32_t ty) const;
    // Bounding box of the covered tiles, in cells (whole tiles); cx1 < cx0 when empty.
    CellBox extent() const { return m_extent; }
    // The same in metres (local ENU); all zero when empty.
    GridRect bounds() const;

    // Lifts with data, 0 = the lowest. liftBottom/liftTop: metres z (0 for a lift out of range).
    int liftCount() const { return static_cast<int>(m_lifts.size()); }
    double liftBottom(int lift) const;
    double liftTop(int lift) const;
    const Lift* lift(int lift) const;
    // Tiles of a lift; lift -1 (or out of range) = the top view.
    const std::vector<Entry>& tiles(int lift) const;

    // lift -1: the top-most lift with data at that cell.
    int countAtCell(std::int32_t cx, std::int32_t cy) const { return countAtCell(cx, cy, -1); }
    int countAtCell(std::int32_t cx, std::int32_t cy, int lift) const;
    // A ribbon gap given up as unobtainable may have passed over this cell: its counts may be too low.
    bool incompleteAtCell(std::int32_t cx, std::int32_t cy) const;
    // f(cx, cy, count, incomplete) for every cell with a count in that lift (-1: the top view, which also
    // visits incomplete cells without a count), tile by tile in (ty, tx) order.
    template <class F> void forEachCell(int lift, F&& f) const;
    // Counts of the cells [cx0, cx0+cols) x [cy0, cy0+rows) into out[row*cols + col] (0 where not covered).
    void countsInRect(std::int32_t cx0, std::int32_t cy0, int cols, int rows, PassCount* out,
                      int lift = -1) const;
    PassCountSummary summary(int lift = -1) const;
    // Bounding box (cells, whole tiles) of the tiles written after snapshot `sequence` was taken, nullopt
    // when none was. Only meaningful when sequence >= clearedAt() (otherwise everything changed).
    std::optional<CellBox> changedSince(std::uint64_t sequence, int lift = -1) const;
    std::vector<TileSnapshot> tileValues(int lift = -1) const; // sorted by (ty, tx)
    // Per machine, the slot ranges of its ribbon counted without (given up as unobtainable).
    const std::map<std::uint8_t, std::vector<SlotRange>>& givenUp() const { return m_givenUp; }
    bool anyIncomplete() const { return m_anyIncomplete; }
    // Unix ms of the earliest and latest counted position (the report's data time range); 0 when
    // no position with a time was counted. Set by PassCountGrid::snapshot() before the snapshot is shared.
    std::int64_t dataFromMs() const { return m_dataFromMs; }
    std::int64_t dataToMs() const { return m_dataToMs; }
    void setDataTime(std::int64_t fromMs, std::int64_t toMs) {
        m_dataFromMs = fromMs;
        m_dataToMs = toMs;
    }

private:
    std::vector<Entry> m_tiles;
    std::vector<Lift> m_lifts;
    PassCountSettings m_settings;
    std::uint64_t m_sequence = 0, m_clearedAt = 0;
    CellBox m_extent;
    bool m_topHasFlags = false; // m_tiles hold PassCountTopTiles
    bool m_anyIncomplete = false;
    std::map<std::uint8_t, std::vector<SlotRange>> m_givenUp;
    std::int64_t m_dataFromMs = 0, m_dataToMs = 0;
    void init();
};

template <class F> void PassCountSnapshot::forEachCell(int lift, F&& f) const {
    const bool top = lift < 0 || lift >= liftCount();
    const auto& entries = tiles(lift);
    for (const auto& e : entries) {
        const PassCountTopTile* flags = nullptr;
        if (m_topHasFlags) {
            if (top)
                flags = static_cast<const PassCountTopTile*>(e.tile.get());
            else
                flags = static_cast<const PassCountTopTile*>(tile(e.tx, e.ty));
        }
        const std::int32_t x0 = e.tx * kTileSize, y0 = e.ty * kTileSize;
        for (int i = 0; i < kTileCells; ++i) {
            const int c = e.tile->counts[static_cast<std::size_t>(i)];
            const bool inc = flags && (flags->flags[static_cast<std::size_t>(i)] & kCellIncomplete);
            if (c == 0 && !(top && inc))
                continue;
            f(x0 + (i & (kTileSize - 1)), y0 + (i >> kTileBits), c, inc);
        }
    }
}

// The summary (histogram, below/within/above target) of a set of tiles; shared by the grid and its snapshots.
PassCountSummary summarizeTiles(std::span<const PassCountTile* const> tiles, double cellSize, int targetMin,
                                int targetMax);

} // namespace ocu::osyris
