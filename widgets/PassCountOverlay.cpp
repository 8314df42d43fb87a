#include "widgets/PassCountOverlay.h"

#include <QPainter>

#include <algorithm>
#include <cmath>

namespace ocu {

namespace {
int floorDiv(int a, int b) {
    return a >= 0 ? a / b : -((-a + b - 1) / b);
}
} // namespace

void PassCountOverlay::clear() {
    m_tiles.clear();
    m_stale.clear();
    m_bytes = 0;
    m_revision = 0;
    m_anchored = false;
}

void PassCountOverlay::invalidate(const QRect& cells) {
    if (cells.isEmpty())
        return;
    // Every level's tiles over the changed cells.
    for (int level = 0; level <= m_maxLevel; ++level) {
        const int span = kTileCells << level;
        const int tx0 = floorDiv(cells.left() + m_dc, span), tx1 = floorDiv(cells.right() + m_dc, span);
        const int ty0 = floorDiv(cells.top() + m_dr, span), ty1 = floorDiv(cells.bottom() + m_dr, span);
        for (int ty = ty0; ty <= ty1; ++ty)
            for (int tx = tx0; tx <= tx1; ++tx) {
                auto it = m_tiles.find(key(level, tx, ty));
                if (it != m_tiles.end()) {
                    // Kept as the stand-in until the tile is rendered again (the frame budget).
                    auto old = m_stale.find(it.key());
                    if (old != m_stale.end())
                        m_bytes -= old->image.sizeInBytes();
                    m_stale.insert(it.key(), std::move(*it));
                    m_tiles.erase(it);
                }
            }
    }
}

void PassCountOverlay::retire() {
    for (auto it = m_tiles.begin(); it != m_tiles.end(); ++it) {
        auto old = m_stale.find(it.key());
        if (old != m_stale.end())
            m_bytes -= old->image.sizeInBytes();
        m_stale.insert(it.key(), std::move(*it));
    }
    m_tiles.clear();
}

void PassCountOverlay::trim() {
    if (m_bytes <= m_maxBytes)
        return;
    // Stand-ins go first; then the least recently drawn half of the tiles (never this frame's).
    for (const Tile& t : std::as_const(m_stale))
        m_bytes -= t.image.sizeInBytes();
    m_stale.clear();
    if (m_bytes <= m_maxBytes || m_tiles.isEmpty())
        return;
    std::vector<quint64> uses;
    uses.reserve(size_t(m_tiles.size()));
    for (const Tile& t : std::as_const(m_tiles))
        uses.push_back(t.lastUse);
    std::nth_element(uses.begin(), uses.begin() + uses.size() / 2, uses.end());
    const quint64 cut = std::min(uses[uses.size() / 2], m_frame - 1);
    for (auto it = m_tiles.begin(); it != m_tiles.end();) {
        if (it->lastUse <= cut) {
            m_bytes -= it->image.sizeInBytes();
            it = m_tiles.erase(it);
        } else {
            ++it;
        }
    }
}

bool PassCountOverlay::budgetLeft() const {
    // At least one tile per frame, so a view always completes.
    return m_budgetMs <= 0 || m_stats.tilesRendered == 0 || m_clock.nsecsElapsed() < m_budgetMs * 1e6;
}

bool PassCountOverlay::drawStandIn(QPainter& p, int level, int tx, int ty, const QRectF& target) {
    auto it = m_stale.constFind(key(level, tx, ty));
    if (it != m_stale.constEnd()) {
        if (!it->image.isNull())
            p.drawImage(target, it->image);
        return true;
    }
    // A coarser tile (up to 8x): the part of its image over this tile, enlarged.
    for (int up = 1; up <= 3 && level + up <= m_maxLevel; ++up) {
        const quint64 k = key(level + up, tx >> up, ty >> up);
        const Tile* t = nullptr;
        if (auto a = m_tiles.constFind(k); a != m_tiles.constEnd())
            t = &*a;
        else if (auto b = m_stale.constFind(k); b != m_stale.constEnd())
            t = &*b;
        if (!t)
            continue;
        if (!t->image.isNull()) {
            const int mask = (1 << up) - 1, side = kTileCells >> up;
            // Image row 0 is the northern edge: a higher ty is further up.
            const QRect src((tx & mask) * side, (mask - (ty & mask)) * side, side, side);
            p.drawImage(target, t->image, src);
        }
        return true;
    }
    return false;
}

const PassCountOverlay::Tile* PassCountOverlay::tile(const PassCountLayer& layer, int level, int tx, int ty) {
    const quint64 k = key(level, tx, ty);
    auto it = m_tiles.find(k);
    if (it != m_tiles.end()) {
        it->lastUse = m_frame;
        return &*it;
    }
    Tile t;
    t.lastUse = m_frame;
    if (level == 0) {
        if (!budgetLeft())
            return nullptr;
        // One bulk read of the tile's cells, a table lookup per cell; image row 0 = the northernmost row.
        const QRect got = layer.countsIn(
            QRect(tx * kTileCells - m_dc, ty * kTileCells - m_dr, kTileCells, kTileCells), m_counts);
        bool any = false;
        for (auto c : m_counts)
            if (c) {
                any = true;
                break;
            }
        if (any) {
            t.image = QImage(kTileCells, kTileCells, QImage::Format_ARGB32_Premultiplied);
            t.image.fill(Qt::transparent);
            const int w = got.width();
            for (int r = got.top(); r <= got.bottom(); ++r) {
                auto* line =
                    reinterpret_cast<QRgb*>(t.image.scanLine(kTileCells - 1 - (r + m_dr - ty * kTileCells)));
                const std::uint16_t* src = m_counts.data() + size_t(r - got.top()) * size_t(w);
                for (int c = 0; c < w; ++c)
                    line[got.left() + m_dc - tx * kTileCells + c] = m_lut[std::min<int>(src[c], 15)];
            }
        }
    } else {
        // From the four children, each scaled to half (nearest neighbour: a cell's own colour, never a
        // blend).
        QImage img;
        // Images, not pointers: rendering one child inserts into m_tiles, which may move the others.
        QImage children[2][2];
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i) {
                const Tile* child = tile(layer, level - 1, tx * 2 + i, ty * 2 + j);
                if (!child)
                    return nullptr; // the rendered children stay cached: the next frame goes on from there
                children[j][i] = child->image;
            }
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i) {
                const QImage& child = children[j][i];
                if (child.isNull())
                    continue;
                if (img.isNull()) {
                    img = QImage(kTileCells, kTileCells, QImage::Format_ARGB32_Premultiplied);
                    img.fill(Qt::transparent);
                }
                // Child row j = 1 is the northern half: the upper half of the image.
                const int h = kTileCells / 2;
                const QImage half = child.scaled(h, h, Qt::IgnoreAspectRatio, Qt::FastTransformation);
                for (int y = 0; y < h; ++y)
                    std::copy_n(reinterpret_cast<const QRgb*>(half.constScanLine(y)), h,
                                reinterpret_cast<QRgb*>(img.scanLine((1 - j) * h + y)) + i * h);
            }
        t.image = std::move(img);
    }
    ++m_stats.tilesRendered;
    m_bytes += t.image.sizeInBytes();
    if (auto old = m_stale.find(k); old != m_stale.end()) {
        m_bytes -= old->image.sizeInBytes();
        m_stale.erase(old);
    }
    return &*m_tiles.insert(k, std::move(t));
}

void PassCountOverlay::draw(QPainter& p, const PassCountLayer& layer, PassPalette palette, PassTarget target,
                            const QRectF& world, const QRectF& screen, double budgetMs) {
    m_stats = {};
    m_budgetMs = budgetMs;
    m_clock.start();
    const int cols = layer.columns(), rows = layer.rows();
    if (cols <= 0 || rows <= 0 || world.width() <= 0 || screen.width() <= 0)
        return;
    ++m_frame;
    m_maxLevel = 0;
    while ((kTileCells << m_maxLevel) < std::max(cols, rows) && m_maxLevel < 20)
        ++m_maxLevel;
    const bool newLayer = &layer != m_layer;
    if (newLayer) {
        clear();
        m_layer = &layer;
    }
    if (newLayer || palette != m_palette || target.min != m_target.min || target.max != m_target.max) {
        retire(); // the old colours stand in until the new ones are rendered
        m_palette = palette;
        m_target = target;
        for (int c = 0; c < 16; ++c)
            m_lut[c] = passCountColor(c, palette, target).rgba();
        m_lut[0] = 0;
    }
    const double cell = layer.cellSize();
    const QPointF o = layer.origin();
    if (m_anchored && cell != m_anchorCell)
        clear();
    if (!m_anchored) {
        m_anchored = true;
        m_anchor = o;
        m_anchorCell = cell;
    }
    m_dc = int(std::lround((o.x() - m_anchor.x()) / cell));
    m_dr = int(std::lround((o.y() - m_anchor.y()) / cell));
    if (layer.revision() != m_revision && m_revision != 0)
        invalidate(layer.changedCellsSince(m_revision).intersected(QRect(0, 0, cols, rows)));
    m_revision = layer.revision();
    const double pxPerCell = cell * screen.width() / world.width();
    int level = 0;
    while (level < m_maxLevel && pxPerCell * (1 << (level + 1)) <= 1.0)
        ++level; // the coarsest level whose pixel is still at least one screen pixel
    m_stats.level = level;
    const int span = kTileCells << level;
    const int c0 = std::max(0, int(std::floor((world.left() - o.x()) / cell)));
    const int c1 = std::min(cols - 1, int(std::ceil((world.right() - o.x()) / cell)));
    const int r0 = std::max(0, int(std::floor((world.top() - o.y()) / cell)));
    const int r1 = std::min(rows - 1, int(std::ceil((world.bottom() - o.y()) / cell)));
    if (c0 > c1 || r0 > r1)
        return;
    const double sx = screen.width() / world.width(), sy = screen.height() / world.height();
    auto toScreen = [&](double e, double n) {
        return QPointF(screen.left() + (e - world.left()) * sx, screen.top() + (world.bottom() - n) * sy);
    };
    p.setRenderHint(QPainter::SmoothPixmapTransform, false);
    const QPointF a = m_anchor;
    for (int ty = floorDiv(r0 + m_dr, span); ty <= floorDiv(r1 + m_dr, span); ++ty)
        for (int tx = floorDiv(c0 + m_dc, span); tx <= floorDiv(c1 + m_dc, span); ++tx) {
            const Tile* t = tile(layer, level, tx, ty);
            if (t && t->image.isNull())
                continue;
            const QPointF tl =
                toScreen(a.x() + double(tx) * span * cell, a.y() + double(ty + 1) * span * cell);
            const QPointF br =
                toScreen(a.x() + double(tx + 1) * span * cell, a.y() + double(ty) * span * cell);
            if (!t) {
                ++m_stats.pending;
                if (drawStandIn(p, level, tx, ty, QRectF(tl, br)))
                    ++m_stats.standIns;
                continue;
            }
            p.drawImage(QRectF(tl, br), t->image);
            ++m_stats.tilesDrawn;
        }
    if (m_stats.pending == 0 && !m_stale.isEmpty()) { // the view is complete: the stand-ins are done
        for (const Tile& t : std::as_const(m_stale))
            m_bytes -= t.image.sizeInBytes();
        m_stale.clear();
    }
    trim();
    m_stats.cachedBytes = m_bytes;
    m_stats.cachedTiles = int(m_tiles.size());
}

} // namespace ocu
