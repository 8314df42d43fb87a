#include "protocols/osyris/PassCountGrid.h"

#include "protocols/osyris/RibbonStore.h"

#include <algorithm>
#include <cmath>
#include <limits>

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
    // Only valid positions with at least medium accuracy and not in a GPS shadow.
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

template <class T>
T* writable(std::unordered_map<std::uint64_t, std::shared_ptr<T>>& map, std::uint64_t key,
            std::uint64_t gen) {
    auto& t = map[key];
    if (!t) {
        t = std::make_shared<T>();
        t->generation = gen;
    } else if (t->generation != gen) {
        // Copy on write: a snapshot may hold this version; it stays as it is, the grid goes on with a copy.
        t = std::make_shared<T>(*t);
        t->generation = gen;
    }
    return t.get();
}

std::size_t offsetOf(std::int32_t cx, std::int32_t cy) {
    return static_cast<std::size_t>(((cy & (kTileSize - 1)) << kTileBits) | (cx & (kTileSize - 1)));
}

template <class Map> std::vector<PassCountSnapshot::Entry> sortedEntries(const Map& map) {
    std::vector<PassCountSnapshot::Entry> tiles;
    tiles.reserve(map.size());
    for (auto& [key, t] : map)
        tiles.push_back({static_cast<std::int32_t>(std::uint32_t(key >> 32)),
                         static_cast<std::int32_t>(std::uint32_t(key)), t});
    std::sort(tiles.begin(), tiles.end(),
              [](const PassCountSnapshot::Entry& a, const PassCountSnapshot::Entry& b) {
                  return a.ty != b.ty ? a.ty < b.ty : a.tx < b.tx;
              });
    return tiles;
}

} // namespace

struct PassCountGrid::MachineState {
    std::uint32_t nextSlot = 0;
    bool hasAnchor = false;
    double ax = 0, ay = 0, aw = 0;
    int key = -1; // direction of the current traversal
    int lift = 0; // lift of the current traversal
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
    if (!std::isfinite(m_settings.liftThickness) || m_settings.liftThickness < 0.005)
        m_settings.liftThickness = 0; // lifts off (a thinner band than 5 mm is GNSS noise)
    if (!std::isfinite(m_settings.liftBase))
        m_settings.liftBase = 0;
    m_inv = 1.0 / m_settings.cellSize;
    m_tiles.clear();
    m_lifts.clear();
    m_lift = nullptr;
    m_machines.clear();
    m_lastTile = nullptr;
    m_lastTileKey = ~0ull;
    m_dirty = false;
    m_firstMs = m_lastMs = 0;
    m_clearedAt = m_generation; // snapshots before this one cannot be patched into the next
}

void PassCountGrid::reset() {
    setSettings(PassCountSettings(m_settings));
}

std::int32_t PassCountGrid::cellIndex(double v) const {
    // Clamped: a cast of a double beyond int32 is undefined (reader queries may ask anywhere).
    return static_cast<std::int32_t>(std::clamp(std::floor(v * m_inv), -1073741824.0, 1073741823.0));
}

int PassCountGrid::liftOf(double z) const {
    if (m_settings.liftThickness <= 0 || !std::isfinite(z))
        return 0;
    return static_cast<int>(
        std::clamp(std::floor((z - m_settings.liftBase) / m_settings.liftThickness), -30000.0, 30000.0));
}

PassCountTopTile* PassCountGrid::topTile(std::int32_t cx, std::int32_t cy) {
    const std::uint64_t key = cellKey(cx >> kTileBits, cy >> kTileBits);
    if (key != m_lastTileKey || !m_lastTile) { // ~0 is also tile (-1, -1): check the pointer too
        m_lastTile = writable(m_tiles, key, m_generation);
        m_lastTileKey = key;
    }
    return m_lastTile;
}

void PassCountGrid::touch(std::int32_t cx, std::int32_t cy) {
    if (!m_dirty) {
        m_dirty = true;
        m_dx0 = m_dx1 = cx;
        m_dy0 = m_dy1 = cy;
        return;
    }
    m_dx0 = std::min(m_dx0, cx);
    m_dx1 = std::max(m_dx1, cx);
    m_dy0 = std::min(m_dy0, cy);
    m_dy1 = std::max(m_dy1, cy);
}

void PassCountGrid::countCell(std::int32_t cx, std::int32_t cy) {
    LiftData& l = *m_lift;
    const std::uint64_t key = cellKey(cx >> kTileBits, cy >> kTileBits);
    if (key != l.lastKey || !l.last) {
        l.last = writable(l.tiles, key, m_generation);
        l.lastKey = key;
    }
    const std::size_t i = offsetOf(cx, cy);
    PassCount& c = l.last->counts[i];
    if (c < std::numeric_limits<PassCount>::max())
        ++c;
    PassCountTopTile* top = topTile(cx, cy);
    // Counts only grow until the grid is cleared, so the top-most lift with data at a cell only rises.
    if (top->lift[i] == kNoLift || m_liftIndex >= top->lift[i]) {
        top->lift[i] = static_cast<std::int16_t>(m_liftIndex);
        top->counts[i] = c;
    }
}

void PassCountGrid::markCell(std::int32_t cx, std::int32_t cy) {
    topTile(cx, cy)->flags[offsetOf(cx, cy)] |= kCellIncomplete;
    touch(cx, cy);
}

void PassCountGrid::markSquare(double x, double y, double width) {
    const double h = std::clamp(width, m_settings.cellSize, 10.0) / 2;
    for (std::int32_t cy = cellIndex(y - h); cy <= cellIndex(y + h); ++cy)
        for (std::int32_t cx = cellIndex(x - h); cx <= cellIndex(x + h); ++cx)
            markCell(cx, cy);
}

void PassCountGrid::sweep(MachineState& m, double ax, double ay, double bx, double by, double width,
                          bool mark) {
    double vx = bx - ax, vy = by - ay;
    double len = std::sqrt(vx * vx + vy * vy);
    if (!(len > 1e-6)) {
        if (mark)
            markSquare(bx, by, width);
        return;
    }
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
        if (mark) { // a long gap: only where the machine is known to have been
            markSquare(ax, ay, width);
            markSquare(bx, by, width);
        } else {
            ++m_oversized;
        }
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
            if (mark) {
                markCell(cx, cy);
                continue;
            }
            if (!m.counted.insert(cellKey(cx, cy)))
                continue; // a cell is counted once per traversal
            countCell(cx, cy);
            any = true;
        }
    }
    if (any) {
        touch(cx0, cy0);
        touch(cx1, cy1);
    }
}

bool PassCountGrid::counts(std::uint8_t machine, const CmPos& p, int k) const {
    const auto& s = m_settings;
    if (!s.machines.empty() && !s.machines.count(machine))
        return false;
    const bool vib = p.flags & kPosVibrating;
    if ((s.vibration == VibrationFilter::On && !vib) || (s.vibration == VibrationFilter::Off && vib))
        return false;
    if ((s.direction == DirectionFilter::Forward && k != 1) ||
        (s.direction == DirectionFilter::Backward && k != 2))
        return false;
    if ((s.speedMin && !(p.speed >= *s.speedMin)) || (s.speedMax && !(p.speed <= *s.speedMax)))
        return false;
    if (s.timeFrom || s.timeTo) {
        const std::int64_t t = fileTimeToUnixMillis(p.time);
        if ((s.timeFrom && t < *s.timeFrom) || (s.timeTo && t > *s.timeTo))
            return false;
    }
    return true;
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
    const int k = directionKey(p.flags);
    const int lift = liftOf(p.z);
    const double w = p.dx > kNoExtentBelowM ? p.dx : m_settings.defaultWidth;
    if (!m.hasAnchor) {
        m.hasAnchor = true;
        m.ax = p.x;
        m.ay = p.y;
        m.aw = w;
        m.lift = lift;
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
        m.aw = w;
        m.lift = lift;
        m.newTraversal(k);
        return;
    }
    if (k != m.key || lift != m.lift) {
        m.lift = lift;
        m.newTraversal(k); // forward and backward runs are separate passes (Carlson); so are lifts
    }
    if (counts(machine, p, k)) {
        auto [it, fresh] = m_lifts.try_emplace(lift);
        LiftData& l = it->second;
        if (!l.anyZ || p.z < l.zMin)
            l.zMin = p.z;
        if (!l.anyZ || p.z > l.zMax)
            l.zMax = p.z;
        l.anyZ = true;
        m_lift = &l;
        m_liftIndex = lift;
        sweep(m, m.ax, m.ay, p.x, p.y, w);
        if (p.time != 0) { // the data time range of the report
            const std::int64_t t = fileTimeToUnixMillis(p.time);
            if (t > 0) {
                m_firstMs = m_firstMs == 0 ? t : std::min(m_firstMs, t);
                m_lastMs = std::max(m_lastMs, t);
            }
        }
    }
    m.ax = p.x;
    m.ay = p.y;
    m.aw = w;
}

void PassCountGrid::giveUp(std::uint8_t machine, std::uint32_t from, std::uint32_t to) {
    m_givenUp[machine].insert(from, to);
}

bool PassCountGrid::givenUpArrived(std::uint8_t machine, const RibbonStore& store) const {
    auto it = m_givenUp.find(machine);
    if (it == m_givenUp.end())
        return false;
    const IntervalSet held = store.held(machine);
    for (const auto& r : it->second.ranges())
        if (!held.intersect(r.from, r.to).empty())
            return true;
    return false;
}

std::uint64_t PassCountGrid::advance(std::uint8_t machine, const RibbonStore& store) {
    std::uint64_t n = 0;
    for (;;) {
        store.forEachConsecutive(machine, nextSlot(machine), [&](const PositionRecord& r) {
            addPosition(machine, r.pos);
            ++n;
            return true;
        });
        auto git = m_givenUp.find(machine);
        if (git == m_givenUp.end())
            break;
        const std::uint32_t next = nextSlot(machine);
        if (!git->second.contains(next))
            break;
        // The first held slot after the given-up stretch; every slot before it must be given up.
        std::optional<std::uint32_t> after;
        for (const auto& r : store.held(machine).ranges())
            if (r.to >= next) {
                after = std::max(r.from, next);
                break;
            }
        if (!after || (*after > next && !git->second.containsAll(next, *after - 1)))
            break;
        auto rec = store.get(machine, *after);
        if (!rec)
            break;
        auto& mp = m_machines[machine];
        if (!mp)
            mp = std::make_unique<MachineState>();
        MachineState& m = *mp;
        const CmPos& p = rec->pos;
        const bool good = checkPosition(p, m_settings.plausibility) == PositionFault::None && usable(p);
        const double w = good && p.dx > kNoExtentBelowM ? p.dx : m_settings.defaultWidth;
        if (good && m.hasAnchor)
            sweep(m, m.ax, m.ay, p.x, p.y, std::max(w, m.aw), true);
        else if (good)
            markSquare(p.x, p.y, w);
        else if (m.hasAnchor)
            markSquare(m.ax, m.ay, m.aw);
        m.hasAnchor = false; // never sweep across the gap: a new traversal starts after it
        m.key = -1;
        m.nextSlot = *after;
    }
    return n;
}

std::uint64_t PassCountGrid::advanceAll(const RibbonStore& store) {
    std::uint64_t n = 0;
    for (auto idx : store.machines())
        n += advance(idx, store);
    return n;
}

void PassCountGrid::recount(const RibbonStore& store) {
    for (auto& [machine, slots] : m_givenUp)
        for (const auto& r : store.held(machine).ranges())
            slots.erase(r.from, r.to);
    reset();
    advanceAll(store);
}

std::uint32_t PassCountGrid::nextSlot(std::uint8_t machine) const {
    auto it = m_machines.find(machine);
    return it == m_machines.end() ? 0 : it->second->nextSlot;
}

const PassCountTopTile* PassCountGrid::findTile(std::int32_t tx, std::int32_t ty) const {
    auto it = m_tiles.find(cellKey(tx, ty));
    return it == m_tiles.end() ? nullptr : it->second.get();
}

int PassCountGrid::countAtCell(std::int32_t cx, std::int32_t cy, int lift) const {
    if (lift < 0 || lift >= liftCount()) {
        const PassCountTopTile* t = findTile(cx >> kTileBits, cy >> kTileBits);
        return t ? t->counts[offsetOf(cx, cy)] : 0;
    }
    const LiftData& l = std::next(m_lifts.begin(), lift)->second;
    auto it = l.tiles.find(cellKey(cx >> kTileBits, cy >> kTileBits));
    return it == l.tiles.end() ? 0 : it->second->counts[offsetOf(cx, cy)];
}

bool PassCountGrid::incompleteAtCell(std::int32_t cx, std::int32_t cy) const {
    const PassCountTopTile* t = findTile(cx >> kTileBits, cy >> kTileBits);
    return t && (t->flags[offsetOf(cx, cy)] & kCellIncomplete);
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
                tile ? tile->counts[offsetOf(cx, cy)] : 0;
        }
    }
}

std::shared_ptr<const PassCountSnapshot> PassCountGrid::snapshot() {
    std::vector<PassCountSnapshot::Lift> lifts;
    lifts.reserve(m_lifts.size());
    for (auto& [index, l] : m_lifts) {
        PassCountSnapshot::Lift out;
        out.index = index;
        if (m_settings.liftThickness > 0) {
            out.bottom = m_settings.liftBase + index * m_settings.liftThickness;
            out.top = out.bottom + m_settings.liftThickness;
        } else {
            out.bottom = l.zMin;
            out.top = l.zMax;
        }
        out.tiles = sortedEntries(l.tiles);
        lifts.push_back(std::move(out));
        l.last = nullptr;
        l.lastKey = ~0ull;
    }
    std::map<std::uint8_t, std::vector<SlotRange>> givenUp;
    for (const auto& [machine, slots] : m_givenUp)
        if (!slots.empty())
            givenUp[machine] = slots.ranges();
    auto snap = std::make_shared<PassCountSnapshot>(sortedEntries(m_tiles), std::move(lifts), m_settings,
                                                    m_generation, m_clearedAt, std::move(givenUp));
    snap->setDataTime(m_firstMs, m_lastMs);
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

std::size_t PassCountGrid::memoryBytes() const {
    std::size_t n = m_tiles.size() * (sizeof(PassCountTopTile) + 64);
    for (const auto& [index, l] : m_lifts)
        n += l.tiles.size() * (sizeof(PassCountTile) + 64);
    return n;
}

std::optional<GridRect> PassCountGrid::takeDirty() {
    if (!m_dirty)
        return std::nullopt;
    m_dirty = false;
    double cs = m_settings.cellSize;
    return GridRect{m_dx0 * cs, m_dy0 * cs, (m_dx1 + 1) * cs, (m_dy1 + 1) * cs};
}

} // namespace ocu::osyris
