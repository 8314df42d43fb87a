#include "protocols/osyris/PassCountSnapshot.h"

#include <algorithm>
#include <climits>
#include <cstring>

namespace ocu::osyris {

namespace {

bool before(const PassCountSnapshot::Entry& e, std::int32_t tx, std::int32_t ty) {
    return e.ty != ty ? e.ty < ty : e.tx < tx;
}

std::size_t cellOffset(std::int32_t cx, std::int32_t cy) {
    return static_cast<std::size_t>(((cy & (kTileSize - 1)) << kTileBits) | (cx & (kTileSize - 1)));
}

} // namespace

PassCountSummary summarizeTiles(std::span<const PassCountTile* const> tiles, double cellSize, int targetMin,
                                int targetMax) {
    PassCountSummary s;
    s.targetMin = targetMin;
    s.targetMax = targetMax;
    std::size_t bins = static_cast<std::size_t>(std::max(15, targetMax + 3)) + 1;
    s.histogram.assign(bins, 0);
    std::uint64_t below = 0, within = 0, above = 0;
    for (const PassCountTile* t : tiles)
        for (auto c : t->counts) {
            if (!c)
                continue;
            ++s.coveredCells;
            ++s.histogram[std::min<std::size_t>(c, bins - 1)];
            if (c < targetMin)
                ++below;
            else if (c > targetMax)
                ++above;
            else
                ++within;
        }
    s.coveredAreaM2 = double(s.coveredCells) * cellSize * cellSize;
    if (s.coveredCells) {
        s.percentBelow = 100.0 * double(below) / double(s.coveredCells);
        s.percentWithin = 100.0 * double(within) / double(s.coveredCells);
        s.percentAbove = 100.0 * double(above) / double(s.coveredCells);
    }
    return s;
}

namespace {

const PassCountTile* findIn(const std::vector<PassCountSnapshot::Entry>& v, std::int32_t tx,
                            std::int32_t ty) {
    auto it = std::lower_bound(
        v.begin(), v.end(), std::pair(tx, ty),
        [](const PassCountSnapshot::Entry& e, const std::pair<std::int32_t, std::int32_t>& k) {
            return before(e, k.first, k.second);
        });
    return it != v.end() && it->tx == tx && it->ty == ty ? it->tile.get() : nullptr;
}

} // namespace

PassCountSnapshot::PassCountSnapshot(std::vector<Entry> tiles, double cellSize, int targetMin, int targetMax,
                                     std::uint64_t sequence, std::uint64_t clearedAt)
    : m_tiles(std::move(tiles)), m_sequence(sequence), m_clearedAt(clearedAt) {
    m_settings.cellSize = cellSize;
    m_settings.targetMin = targetMin;
    m_settings.targetMax = targetMax;
    if (!m_tiles.empty())
        m_lifts.push_back({0, 0, 0, m_tiles});
    init();
}

PassCountSnapshot::PassCountSnapshot(std::vector<Entry> top, std::vector<Lift> lifts,
                                     const PassCountSettings& settings, std::uint64_t sequence,
                                     std::uint64_t clearedAt,
                                     std::map<std::uint8_t, std::vector<SlotRange>> givenUp)
    : m_tiles(std::move(top)), m_lifts(std::move(lifts)), m_settings(settings), m_sequence(sequence),
      m_clearedAt(clearedAt), m_topHasFlags(true), m_givenUp(std::move(givenUp)) {
    init();
    for (const auto& e : m_tiles) {
        const auto* t = static_cast<const PassCountTopTile*>(e.tile.get());
        for (auto f : t->flags)
            if (f & kCellIncomplete) {
                m_anyIncomplete = true;
                break;
            }
        if (m_anyIncomplete)
            break;
    }
}

void PassCountSnapshot::init() {
    if (m_tiles.empty())
        return;
    std::int32_t tx0 = INT_MAX, tx1 = INT_MIN;
    for (const auto& e : m_tiles) {
        tx0 = std::min(tx0, e.tx);
        tx1 = std::max(tx1, e.tx);
    }
    // Sorted by (ty, tx): the first and last entries bound the rows.
    m_extent = {tx0 * kTileSize, m_tiles.front().ty * kTileSize, tx1 * kTileSize + kTileSize - 1,
                m_tiles.back().ty * kTileSize + kTileSize - 1};
}

GridRect PassCountSnapshot::bounds() const {
    if (m_tiles.empty())
        return {};
    const double cs = m_settings.cellSize;
    return {m_extent.cx0 * cs, m_extent.cy0 * cs, (m_extent.cx1 + 1) * cs, (m_extent.cy1 + 1) * cs};
}

double PassCountSnapshot::liftBottom(int l) const {
    return l >= 0 && l < liftCount() ? m_lifts[static_cast<std::size_t>(l)].bottom : 0.0;
}

double PassCountSnapshot::liftTop(int l) const {
    return l >= 0 && l < liftCount() ? m_lifts[static_cast<std::size_t>(l)].top : 0.0;
}

const PassCountSnapshot::Lift* PassCountSnapshot::lift(int l) const {
    return l >= 0 && l < liftCount() ? &m_lifts[static_cast<std::size_t>(l)] : nullptr;
}

const std::vector<PassCountSnapshot::Entry>& PassCountSnapshot::tiles(int l) const {
    if (l < 0 || l >= liftCount())
        return m_tiles;
    return m_lifts[static_cast<std::size_t>(l)].tiles;
}

const PassCountTile* PassCountSnapshot::tile(std::int32_t tx, std::int32_t ty) const {
    return findIn(m_tiles, tx, ty);
}

int PassCountSnapshot::countAtCell(std::int32_t cx, std::int32_t cy, int l) const {
    const PassCountTile* t = findIn(tiles(l), cx >> kTileBits, cy >> kTileBits);
    return t ? t->counts[cellOffset(cx, cy)] : 0;
}

bool PassCountSnapshot::incompleteAtCell(std::int32_t cx, std::int32_t cy) const {
    if (!m_topHasFlags || !m_anyIncomplete)
        return false;
    const auto* t = static_cast<const PassCountTopTile*>(tile(cx >> kTileBits, cy >> kTileBits));
    return t && (t->flags[cellOffset(cx, cy)] & kCellIncomplete);
}

void PassCountSnapshot::countsInRect(std::int32_t cx0, std::int32_t cy0, int cols, int rows, PassCount* out,
                                     int l) const {
    if (cols <= 0 || rows <= 0)
        return;
    std::fill_n(out, std::size_t(cols) * std::size_t(rows), PassCount(0));
    const auto& entries = tiles(l);
    if (entries.empty())
        return;
    // Tile by tile: a binary search per tile row, then row segments copied out of each covered tile.
    const std::int64_t cx1 = std::int64_t(cx0) + cols - 1, cy1 = std::int64_t(cy0) + rows - 1;
    const auto tx0 = static_cast<std::int32_t>(cx0 >> kTileBits),
               tx1 = static_cast<std::int32_t>(cx1 >> kTileBits);
    const auto ty0 = static_cast<std::int32_t>(cy0 >> kTileBits),
               ty1 = static_cast<std::int32_t>(cy1 >> kTileBits);
    for (std::int64_t ty = ty0; ty <= ty1; ++ty) {
        const auto tyi = static_cast<std::int32_t>(ty);
        auto it = std::lower_bound(entries.begin(), entries.end(), tx0,
                                   [tyi](const Entry& e, std::int32_t tx) { return before(e, tx, tyi); });
        for (; it != entries.end() && it->ty == tyi && it->tx <= tx1; ++it) {
            const std::int64_t tcx0 = std::int64_t(it->tx) * kTileSize, tcy0 = ty * kTileSize;
            const std::int64_t xa = std::max<std::int64_t>(cx0, tcx0),
                               xb = std::min<std::int64_t>(cx1, tcx0 + kTileSize - 1);
            const std::int64_t ya = std::max<std::int64_t>(cy0, tcy0),
                               yb = std::min<std::int64_t>(cy1, tcy0 + kTileSize - 1);
            const auto n = static_cast<std::size_t>(xb - xa + 1);
            for (std::int64_t cy = ya; cy <= yb; ++cy) {
                const PassCount* src = it->tile->counts.data() + cellOffset(static_cast<std::int32_t>(xa),
                                                                            static_cast<std::int32_t>(cy));
                PassCount* dst = out + static_cast<std::size_t>(cy - cy0) * std::size_t(cols) +
                                 static_cast<std::size_t>(xa - cx0);
                std::memcpy(dst, src, n * sizeof(PassCount));
            }
        }
    }
}

PassCountSummary PassCountSnapshot::summary(int l) const {
    const auto& entries = tiles(l);
    std::vector<const PassCountTile*> ts;
    ts.reserve(entries.size());
    for (const auto& e : entries)
        ts.push_back(e.tile.get());
    return summarizeTiles(ts, m_settings.cellSize, m_settings.targetMin, m_settings.targetMax);
}

std::optional<CellBox> PassCountSnapshot::changedSince(std::uint64_t sequence, int l) const {
    std::optional<CellBox> box;
    for (const auto& e : tiles(l)) {
        if (e.tile->generation <= sequence)
            continue;
        const std::int32_t x0 = e.tx * kTileSize, y0 = e.ty * kTileSize;
        if (!box) {
            box = CellBox{x0, y0, x0 + kTileSize - 1, y0 + kTileSize - 1};
        } else {
            box->cx0 = std::min(box->cx0, x0);
            box->cy0 = std::min(box->cy0, y0);
            box->cx1 = std::max(box->cx1, x0 + kTileSize - 1);
            box->cy1 = std::max(box->cy1, y0 + kTileSize - 1);
        }
    }
    return box;
}

std::vector<TileSnapshot> PassCountSnapshot::tileValues(int l) const {
    const auto& entries = tiles(l);
    std::vector<TileSnapshot> out;
    out.reserve(entries.size());
    for (const auto& e : entries)
        out.push_back({e.tx, e.ty, e.tile->counts});
    return out;
}

} // namespace ocu::osyris
