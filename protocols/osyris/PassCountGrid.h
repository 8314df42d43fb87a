#pragma once
// Pass-count engine (issue 5 §5, rules from research/anchors-features.md §4.2): a sparse tiled grid;
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

enum class DirectionFilter { Any, Forward, Backward };

struct PassCountSettings {
    double cellSize = 0.34;    // m (TRex default)
    bool vibrationOnly = true; // count only with POS_VIBRATING
    DirectionFilter direction = DirectionFilter::Any;
    std::set<std::uint8_t> machines; // empty = every machine
    double minMove = 0.25;           // m since the last counted position (Trimble GCS900)
    double maxJump = 10.0;           // m; a longer step breaks the traversal (GCS900 "< 10 m")
    double defaultWidth = 2.0;       // m when a position carries no extent
    int targetMin = 3;
    int targetMax = 5;
    PlausibilityLimits plausibility; // implausible positions break the traversal and count nothing
    bool operator==(const PassCountSettings&) const = default;
};

struct GridRect { // in metres, local ENU
    double xMin = 0, yMin = 0, xMax = 0, yMax = 0;
};

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
    // Feeds every consecutive slot of machine's ribbon that has not been processed yet. Returns how many.
    std::uint64_t advance(std::uint8_t machine, const RibbonStore& store);
    std::uint64_t advanceAll(const RibbonStore& store);
    std::uint32_t nextSlot(std::uint8_t machine) const;

    // Immutable picture of the counts now, sharing every tile with the grid until the grid writes it (then
    // the grid writes a copy). Cost: one pointer per tile; the first later write to each tile copies it.
    std::shared_ptr<const PassCountSnapshot> snapshot();

    // Readers on the grid's own thread (tests, the simulated site); other threads read a snapshot().
    int countAt(double x, double y) const;
    int countAtCell(std::int32_t cx, std::int32_t cy) const;
    // Counts of the cells [cx0, cx0+cols) x [cy0, cy0+rows) into out[row*cols + col].
    void countsInRect(std::int32_t cx0, std::int32_t cy0, int cols, int rows, PassCount* out) const;
    std::vector<TileSnapshot> snapshotTiles() const; // values, sorted by (ty, tx)
    PassCountSummary summary() const;
    std::int32_t cellIndex(double v) const;
    // Bounding box of cells changed since the last call, if any.
    std::optional<GridRect> takeDirty();

    // Bounded work (issue 14 §3): one position sweeps at most this many cells of its bounding box. With the
    // plausibility limits (width <= 6 m, step <= maxJump) a sweep touches at most ((10+6)/0.34)^2 ~ 2,200
    // cells; the cap only guards odd settings (a tiny cell size with a long maxJump): such a step is not
    // counted.
    static constexpr std::int64_t kMaxSweepCells = 1 << 16;
    // Positions the grid refused (implausible ones by fault, sweeps over kMaxSweepCells): for counters/tests.
    std::uint64_t implausiblePositions() const { return m_implausible; }
    std::uint64_t oversizedSweeps() const { return m_oversized; }

private:
    struct MachineState;
    void sweep(MachineState& m, double ax, double ay, double bx, double by, double width);
    PassCount* cell(std::int32_t cx, std::int32_t cy);
    const PassCountTile* findTile(std::int32_t tx, std::int32_t ty) const;

    PassCountSettings m_settings;
    double m_inv = 1.0 / 0.34;
    std::unordered_map<std::uint64_t, std::shared_ptr<PassCountTile>> m_tiles;
    std::uint64_t m_lastTileKey = ~0ull;
    PassCountTile* m_lastTile = nullptr; // writable: its generation is the current one
    // Tiles written now get m_generation; snapshot() takes sequence m_generation and starts the next one, so
    // a tile of an older generation may be held by a snapshot and is copied before it is written.
    std::uint64_t m_generation = 1;
    std::uint64_t m_clearedAt = 1;
    std::map<std::uint8_t, std::unique_ptr<MachineState>> m_machines;
    bool m_dirty = false;
    std::uint64_t m_implausible = 0;
    std::uint64_t m_oversized = 0;
    std::int32_t m_dx0 = 0, m_dy0 = 0, m_dx1 = 0, m_dy1 = 0;
};

} // namespace ocu::osyris
