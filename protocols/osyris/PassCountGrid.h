#pragma once
// Pass-count engine (rules from research/anchors-features.md §4.2): a sparse tiled grid;
// the drum footprint is swept between consecutive counted positions of one machine's ribbon, processed
// strictly in slot order. Counts are a sum over machines of a function of each ribbon alone, so the
// grid depends only on the ribbons, never on the order datagrams arrived in.
//
// Not thread-safe: the grid belongs to one thread (the station's io thread). Other threads read immutable
// snapshots (snapshot(), PassCountSnapshot.h): the tiles are copy-on-write, so the grid copies a tile before
// it changes one a snapshot holds, and a snapshot never changes under its reader.
#include "protocols/osyris/OsyrisCodec.h"
#include "protocols/osyris/PassCountSnapshot.h"
#include "protocols/osyris/Plausibility.h"

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <unordered_map>
#include <vector>

namespace ocu::osyris {

class RibbonStore;

class PassCountGrid {
public:
    explicit PassCountGrid(PassCountSettings s = {});
    ~PassCountGrid();

    const PassCountSettings& settings() const { return m_settings; }
    // Changing settings clears the grid; the caller re-feeds the ribbons (reset + advanceAll).
    void setSettings(const PassCountSettings& s);
    void reset();

    // Feeds the next position of machine's ribbon. The caller guarantees slot order (advance() does).
    void addPosition(std::uint8_t machine, const CmPos& p);
    // Feeds every consecutive slot of machine's ribbon that has not been processed yet, stepping over the
    // slots given up (giveUp()) to the next held one. Returns how many positions were fed.
    std::uint64_t advance(std::uint8_t machine, const RibbonStore& store);
    std::uint64_t advanceAll(const RibbonStore& store);
    std::uint32_t nextSlot(std::uint8_t machine) const;

    // Late join and gaps: slots [from, to] of machine's ribbon are given up as unobtainable.
    // advance() then continues after them without sweeping across the gap (a new traversal starts at the
    // next held position) and marks the cells the gap may have covered incomplete: the drum-wide corridor
    // from the last counted position before the gap to the first one after it, or, with nothing before it
    // (a late join), the footprint of the first one after it. Given-up slots that arrive later are counted
    // after a recount (reset + advanceAll: the given-up set survives reset(), minus what is held then).
    void giveUp(std::uint8_t machine, std::uint32_t from, std::uint32_t to);
    const std::map<std::uint8_t, IntervalSet>& givenUp() const { return m_givenUp; }
    // The given-up slots of machine that the store holds now (arrived late): the grid needs a recount.
    bool givenUpArrived(std::uint8_t machine, const RibbonStore& store) const;
    // Drops the given-up slots the store now holds, clears the grid and re-feeds every ribbon.
    void recount(const RibbonStore& store);
    bool incompleteAtCell(std::int32_t cx, std::int32_t cy) const;

    // Immutable picture of the counts now, sharing every tile with the grid until the grid writes it (then
    // the grid writes a copy). Cost: one pointer per tile; the first later write to each tile copies it.
    std::shared_ptr<const PassCountSnapshot> snapshot();

    // Readers on the grid's own thread (tests, the simulated site); other threads read a snapshot().
    int countAt(double x, double y) const;
    int countAtCell(std::int32_t cx, std::int32_t cy, int lift = -1) const; // lift as in the snapshot
    int liftCount() const { return static_cast<int>(m_lifts.size()); }
    // Counts of the cells [cx0, cx0+cols) x [cy0, cy0+rows) into out[row*cols + col].
    void countsInRect(std::int32_t cx0, std::int32_t cy0, int cols, int rows, PassCount* out) const;
    std::vector<TileSnapshot> snapshotTiles() const; // values, sorted by (ty, tx)
    PassCountSummary summary() const;                // of the top view
    // Bytes held by the tiles (counts, top view, flags), for the memory benchmark.
    std::size_t memoryBytes() const;
    std::int32_t cellIndex(double v) const;
    // Bounding box of cells changed since the last call, if any.
    std::optional<GridRect> takeDirty();

    // Bounded work: one position sweeps at most this many cells of its bounding box. With the
    // plausibility limits (width <= 6 m, step <= maxJump) a sweep touches at most ((10+6)/0.34)^2 ~ 2,200
    // cells; the cap only guards odd settings (a tiny cell size with a long maxJump): such a step is not
    // counted.
    static constexpr std::int64_t kMaxSweepCells = 1 << 16;
    // Positions the grid refused (implausible ones by fault, sweeps over kMaxSweepCells): for counters/tests.
    std::uint64_t implausiblePositions() const { return m_implausible; }
    std::uint64_t oversizedSweeps() const { return m_oversized; }

private:
    struct MachineState;
    struct LiftData {
        std::unordered_map<std::uint64_t, std::shared_ptr<PassCountTile>> tiles;
        double zMin = 0, zMax = 0;
        bool anyZ = false;
        std::uint64_t lastKey = ~0ull;
        PassCountTile* last = nullptr; // writable: its generation is the current one
    };
    // mark: flag the cells incomplete instead of counting them.
    void sweep(MachineState& m, double ax, double ay, double bx, double by, double width, bool mark = false);
    void markSquare(double x, double y, double width);
    void countCell(std::int32_t cx, std::int32_t cy);
    void markCell(std::int32_t cx, std::int32_t cy);
    PassCountTopTile* topTile(std::int32_t cx, std::int32_t cy);
    void touch(std::int32_t cx, std::int32_t cy);
    const PassCountTopTile* findTile(std::int32_t tx, std::int32_t ty) const;
    int liftOf(double z) const;
    bool counts(std::uint8_t machine, const CmPos& p, int directionKey) const;

    PassCountSettings m_settings;
    double m_inv = 1.0 / 0.34;
    std::unordered_map<std::uint64_t, std::shared_ptr<PassCountTopTile>> m_tiles; // the top view
    std::map<int, LiftData> m_lifts;                                              // by absolute lift index
    LiftData* m_lift = nullptr;                                                   // the lift being written
    int m_liftIndex = 0;
    std::uint64_t m_lastTileKey = ~0ull;
    PassCountTopTile* m_lastTile = nullptr; // writable: its generation is the current one
    std::map<std::uint8_t, IntervalSet> m_givenUp;
    // Tiles written now get m_generation; snapshot() takes sequence m_generation and starts the next one, so
    // a tile of an older generation may be held by a snapshot and is copied before it is written.
    std::uint64_t m_generation = 1;
    std::uint64_t m_clearedAt = 1;
    std::int64_t m_firstMs = 0, m_lastMs = 0; // Unix ms of the earliest/latest counted position; 0 = none
    std::map<std::uint8_t, std::unique_ptr<MachineState>> m_machines;
    bool m_dirty = false;
    std::uint64_t m_implausible = 0;
    std::uint64_t m_oversized = 0;
    std::int32_t m_dx0 = 0, m_dy0 = 0, m_dx1 = 0, m_dy1 = 0;
};

} // namespace ocu::osyris
