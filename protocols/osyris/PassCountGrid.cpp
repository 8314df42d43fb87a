#include "protocols/osyris/PassCountGrid.h"

#include "protocols/osyris/RibbonStore.h"

#include <algorithm>
#include <cmath>

namespace ocu::osyris {

namespace {

// Open-addressing set of cell keys with O(1) clear (generation stamps): the cells already counted in the
// current traversal of one machine.
class CellSet {
public:
    CellSet() { resize(1024); }
    void clear() {
        ++m_gen;
        m_size = 0;
    }
    bool insert(std::uint64_t key) {
        if ((m_size + 1) * 2 > m_keys.size())
            grow();
        std::size_t mask = m_keys.size() - 1;
        std::size_t i = hash(key) & mask;
        while (m_gens[i] == m_gen) {
            if (m_keys[i] == key)
                return false;
            i = (i + 1) & mask;
        }
        m_gens[i] = m_gen;
        m_keys[i] = key;
        ++m_size;
        return true;
    }

private:
    static std::size_t hash(std::uint64_t k) {
        k ^= k >> 33;
        k *= 0xff51afd7ed558ccdull;
        k ^= k >> 33;
        return static_cast<std::size_t>(k);
    }
    void resize(std::size_t n) {
        m_keys.assign(n, 0);
        m_gens.assign(n, 0);
        m_gen = 1;
        m_size = 0;
    }
    void grow() {
        std::vector<std::uint64_t> live;
        live.reserve(m_size);
        for (std::size_t i = 0; i < m_keys.size(); ++i)
            if (m_gens[i] == m_gen)
                live.push_back(m_keys[i]);
        resize(m_keys.size() * 2);
        for (auto k : live)
            insert(k);
    }
    std::vector<std::uint64_t> m_keys;
    std::vector<std::uint32_t> m_gens;
    std::uint32_t m_gen = 1;
    std::size_t m_size = 0;
};

std::uint64_t cellKey(std::int32_t cx, std::int32_t cy) {
    return (std::uint64_t(std::uint32_t(cx)) << 32) | std::uint32_t(cy);
}

bool usable(const CmPos& p) {
    // Only valid positions with at least medium accuracy and not in a GPS shadow (issue 5 §5).
    return (p.flags & kPosValid) && !(p.flags & kPosGpsShadow) &&
           (p.flags & (kPosAccuracyMed | kPosAccuracyHigh)) && std::isfinite(p.x) && std::isfinite(p.y);
}

int directionKey(std::uint32_t flags) {
    if (flags & kPosForward)
        return 1;
    if (flags & kPosBackward)
        return 2;
    return 0;
}

} // namespace

struct PassCountGrid::MachineState {
    std::uint32_t nextSlot = 0;
    bool hasAnchor = false;
    double ax = 0, ay = 0;
    int key = -1; // direction of the current traversal
    CellSet counted;
    void newTraversal(int k) {
        key = k;
        counted.clear();
    }
};

PassCountGrid::PassCountGrid(PassCountSettings s) {
    setSettings(s);
}
PassCountGrid::~PassCountGrid() = default;

void PassCountGrid::setSettings(const PassCountSettings& s) {
    m_settings = s;
    if (!(m_settings.cellSize > 0.01))
        m_settings.cellSize = 0.34;
    m_inv = 1.0 / m_settings.cellSize;
    m_tiles.clear();
    m_machines.clear();
    m_lastTile = nullptr;
    m_lastTileKey = ~0ull;
    m_dirty = false;
    m_clearedAt = m_generation; // snapshots before this one cannot be patched into the next
}

void PassCountGrid::reset() {
    setSettings(PassCountSettings(m_settings));
}

std::int32_t PassCountGrid::cellIndex(double v) const {
    // Clamped: a cast of a double beyond int32 is undefined (reader queries may ask anywhere).
    return static_cast<std::int32_t>(std::clamp(std::floor(v * m_inv), -1073741824.0, 1073741823.0));
}

PassCount* PassCountGrid::cell(std::int32_t cx, std::int32_t cy) {
    std::int32_t tx = cx >> kTileBits, ty = cy >> kTileBits;
    std::uint64_t key = cellKey(tx, ty);
    if (key != m_lastTileKey || !m_lastTile) { // ~0 is also tile (-1, -1): check the pointer too
        auto& t = m_tiles[key];
        if (!t) {
            t = std::make_shared<PassCountTile>();
            t->generation = m_generation;
        } else if (t->generation != m_generation) {
            // Copy on write: a snapshot may hold this version; it stays as it is, the grid goes on with a
            // copy.
            t = std::make_shared<PassCountTile>(*t);
            t->generation = m_generation;
        }
        m_lastTile = t.get();
        m_lastTileKey = key;
    }
    return &m_lastTile->counts[static_cast<std::size_t>(((cy & (kTileSize - 1)) << kTileBits) |
                                                        (cx & (kTileSize - 1)))];
}

void PassCountGrid::sweep(MachineState& m, double ax, double ay, double bx, double by, double width) {
    double vx = bx - ax, vy = by - ay;
    double len = std::sqrt(vx * vx + vy * vy);
    double ux = vx / len, uy = vy / len;
    double nx = -uy, ny = ux;
    double h = width / 2;
    double xs[4] = {ax + nx * h, ax - nx * h, bx + nx * h, bx - nx * h};
    double ys[4] = {ay + ny * h, ay - ny * h, by + ny * h, by - ny * h};
    double cs = m_settings.cellSize;
    std::int32_t cx0 = cellIndex(*std::min_element(xs, xs + 4)),
                 cx1 = cellIndex(*std::max_element(xs, xs + 4));
    std::int32_t cy0 = cellIndex(*std::min_element(ys, ys + 4)),
                 cy1 = cellIndex(*std::max_element(ys, ys + 4));
    if ((std::int64_t(cx1) - cx0 + 1) * (std::int64_t(cy1) - cy0 + 1) > kMaxSweepCells) {
        ++m_oversized;
        return;
    }
    bool any = false;
    for (std::int32_t cy = cy0; cy <= cy1; ++cy) {
        double py = (cy + 0.5) * cs - ay;
        double tRow = py * uy, sRow = py * ny;
        for (std::int32_t cx = cx0; cx <= cx1; ++cx) {
            double px = (cx + 0.5) * cs - ax;
            double t = px * ux + tRow; // along track: half-open [0, len) so segments tile without overlap
            if (t < 0 || t >= len)
                continue;
            double s = px * nx + sRow; // across track: half-open [-h, h)
            if (s < -h || s >= h)
                continue;
            if (!m.counted.insert(cellKey(cx, cy)))
                continue; // a cell is counted once per traversal
            PassCount* c = cell(cx, cy);
            if (*c < 0xFFFF)
                ++*c;
            if (!m_dirty) {
                m_dirty = true;
                m_dx0 = m_dx1 = cx;
                m_dy0 = m_dy1 = cy;
            }
            any = true;
        }
    }
    if (any && m_dirty) {
        m_dx0 = std::min(m_dx0, cx0);
        m_dx1 = std::max(m_dx1, cx1);
        m_dy0 = std::min(m_dy0, cy0);
        m_dy1 = std::max(m_dy1, cy1);
    }
}

void PassCountGrid::addPosition(std::uint8_t machine, const CmPos& p) {
    auto& mp = m_machines[machine];
    if (!mp)
        mp = std::make_unique<MachineState>();
    MachineState& m = *mp;
    m.nextSlot = p.slot + 1;
    const bool plausible = checkPosition(p, m_settings.plausibility) == PositionFault::None;
    if (!plausible)
        ++m_implausible;
    if (!plausible || !usable(p)) {
        m.hasAnchor = false; // no footprint is swept across an invalid stretch
        m.key = -1;
        return;
    }
    int k = directionKey(p.flags);
    if (!m.hasAnchor) {
        m.hasAnchor = true;
        m.ax = p.x;
        m.ay = p.y;
        m.newTraversal(k);
        return;
    }
    double dx = p.x - m.ax, dy = p.y - m.ay;
    double d2 = dx * dx + dy * dy;
    if (d2 < m_settings.minMove * m_settings.minMove)
        return; // not moved enough: keep the anchor
    if (d2 > m_settings.maxJump * m_settings.maxJump) {
        m.ax = p.x;
        m.ay = p.y;
        m.newTraversal(k);
        return;
    }
    if (k != m.key)
        m.newTraversal(k); // forward and backward runs are separate passes (Carlson)
    const auto& s = m_settings;
    bool count =
        (s.machines.empty() || s.machines.count(machine)) &&
        (!s.vibrationOnly || (p.flags & kPosVibrating)) &&
        (s.direction == DirectionFilter::Any || (s.direction == DirectionFilter::Forward && k == 1) ||
         (s.direction == DirectionFilter::Backward && k == 2));
    if (count) {
        double w = p.dx > kNoExtentBelowM ? p.dx : s.defaultWidth;
        sweep(m, m.ax, m.ay, p.x, p.y, w);
    }
    m.ax = p.x;
    m.ay = p.y;
}

std::uint64_t PassCountGrid::advance(std::uint8_t machine, const RibbonStore& store) {
    std::uint64_t n = 0;
    store.forEachConsecutive(machine, nextSlot(machine), [&](const PositionRecord& r) {
        addPosition(machine, r.pos);
        ++n;
        return true;
    });
    return n;
}

std::uint64_t PassCountGrid::advanceAll(const RibbonStore& store) {
    std::uint64_t n = 0;
    for (auto idx : store.machines())
        n += advance(idx, store);
    return n;
}

std::uint32_t PassCountGrid::nextSlot(std::uint8_t machine) const {
    auto it = m_machines.find(machine);
    return it == m_machines.end() ? 0 : it->second->nextSlot;
}

const PassCountTile* PassCountGrid::findTile(std::int32_t tx, std::int32_t ty) const {
    auto it = m_tiles.find(cellKey(tx, ty));
    return it == m_tiles.end() ? nullptr : it->second.get();
}

int PassCountGrid::countAtCell(std::int32_t cx, std::int32_t cy) const {
    const PassCountTile* t = findTile(cx >> kTileBits, cy >> kTileBits);
    if (!t)
        return 0;
    return t
        ->counts[static_cast<std::size_t>(((cy & (kTileSize - 1)) << kTileBits) | (cx & (kTileSize - 1)))];
}

int PassCountGrid::countAt(double x, double y) const {
    return countAtCell(cellIndex(x), cellIndex(y));
}

void PassCountGrid::countsInRect(std::int32_t cx0, std::int32_t cy0, int cols, int rows,
                                 PassCount* out) const {
    std::uint64_t lastKey = 0;
    bool looked = false;
    const PassCountTile* tile = nullptr;
    for (int r = 0; r < rows; ++r) {
        std::int32_t cy = cy0 + r;
        for (int c = 0; c < cols; ++c) {
            std::int32_t cx = cx0 + c;
            std::uint64_t key = cellKey(cx >> kTileBits, cy >> kTileBits);
            if (!looked || key != lastKey) {
                looked = true;
                tile = findTile(cx >> kTileBits, cy >> kTileBits);
                lastKey = key;
            }
            out[static_cast<std::size_t>(r) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(c)] =
                tile ? tile->counts[static_cast<std::size_t>(((cy & (kTileSize - 1)) << kTileBits) |
                                                             (cx & (kTileSize - 1)))]
                     : 0;
        }
    }
}

std::shared_ptr<const PassCountSnapshot> PassCountGrid::snapshot() {
    std::vector<PassCountSnapshot::Entry> tiles;
    tiles.reserve(m_tiles.size());
    for (auto& [key, t] : m_tiles)
        tiles.push_back({static_cast<std::int32_t>(std::uint32_t(key >> 32)),
                         static_cast<std::int32_t>(std::uint32_t(key)), t});
    std::sort(tiles.begin(), tiles.end(),
              [](const PassCountSnapshot::Entry& a, const PassCountSnapshot::Entry& b) {
                  return a.ty != b.ty ? a.ty < b.ty : a.tx < b.tx;
              });
    auto snap =
        std::make_shared<const PassCountSnapshot>(std::move(tiles), m_settings.cellSize, m_settings.targetMin,
                                                  m_settings.targetMax, m_generation, m_clearedAt);
    // Every tile is now shared with the snapshot: the next write to each copies it first.
    ++m_generation;
    m_lastTile = nullptr;
    m_lastTileKey = ~0ull;
    return snap;
}

std::vector<TileSnapshot> PassCountGrid::snapshotTiles() const {
    std::vector<TileSnapshot> out;
    out.reserve(m_tiles.size());
    for (auto& [key, t] : m_tiles)
        out.push_back({static_cast<std::int32_t>(std::uint32_t(key >> 32)),
                       static_cast<std::int32_t>(std::uint32_t(key)), t->counts});
    std::sort(out.begin(), out.end(), [](const TileSnapshot& a, const TileSnapshot& b) {
        return a.ty != b.ty ? a.ty < b.ty : a.tx < b.tx;
    });
    return out;
}

PassCountSummary PassCountGrid::summary() const {
    std::vector<const PassCountTile*> tiles;
    tiles.reserve(m_tiles.size());
    for (auto& [key, t] : m_tiles)
        tiles.push_back(t.get());
    return summarizeTiles(tiles, m_settings.cellSize, m_settings.targetMin, m_settings.targetMax);
}

std::optional<GridRect> PassCountGrid::takeDirty() {
    if (!m_dirty)
        return std::nullopt;
    m_dirty = false;
    double cs = m_settings.cellSize;
    return GridRect{m_dx0 * cs, m_dy0 * cs, (m_dx1 + 1) * cs, (m_dy1 + 1) * cs};
}

} // namespace ocu::osyris
