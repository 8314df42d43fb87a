#pragma once
// The pass-count overlay of the 2D map at any zoom: a tile pyramid of cached images.
// Level 0 tiles hold 256 x 256 cells, one pixel per cell; a tile of level L covers 256 * 2^L cells a side at
// one pixel per 2^L cells, rendered once from its four children (nearest neighbour). A frame draws only the
// tiles of the level whose pixel is about one screen pixel, so a redraw costs about the screen's pixels,
// whatever the job's size; a change of the counts re-renders only the level-0 tiles it touched and their
// ancestors. Memory: a tile image is 256 KB; tiles without any count are not kept (one shared "empty"), and
// the cache is bounded (kMaxCachedBytes: the least recently drawn tiles go first).
// Frame budget: rendering every level-0 tile of a whole job once (first view, new palette or target) takes
// hundreds of ms; with a budget a frame renders tiles only until the budget is spent (at least one) and
// stands in for the rest with what it has (the tile before the change, else a coarser cached ancestor);
// stats().pending says how many are owed, and the caller paints again until none are.
#include "models/PassCountLayer.h"

#include <QElapsedTimer>
#include <QHash>
#include <QImage>
#include <QRectF>

class QPainter;

namespace ocu {

class PassCountOverlay {
public:
    static constexpr int kTileCells = 256;
    static constexpr qint64 kMaxCachedBytes = 96ll << 20;

    // Draws the layer into `target` (screen pixels) for the world rectangle `world` (E, N) shown in it.
    // budgetMs <= 0: render everything this frame (reports, screenshots, benchmarks of the cold cost).
    void draw(QPainter& p, const PassCountLayer& layer, PassPalette palette, PassTarget target,
              const QRectF& world, const QRectF& screen, double budgetMs = 0);
    void clear();
    // Bound of the tile cache (default kMaxCachedBytes); stand-ins are dropped first.
    void setCacheLimit(qint64 bytes) { m_maxBytes = bytes; }

    struct Stats {
        int level = 0;
        int tilesDrawn = 0;
        int tilesRendered = 0; // this frame
        int pending = 0;       // tiles of this view not rendered for lack of budget (stand-ins drawn)
        int standIns = 0;      // of which something was drawn in their place
        qint64 cachedBytes = 0;
        int cachedTiles = 0;
    };
    const Stats& stats() const { return m_stats; }

private:
    struct Tile {
        QImage image; // null: no counts in the tile
        quint64 lastUse = 0;
    };
    static quint64 key(int level, int tx, int ty) {
        return (quint64(quint32(level)) << 58) ^ (quint64(quint32(tx) & 0x1FFFFFFF) << 29) ^
               quint64(quint32(ty) & 0x1FFFFFFF);
    }
    // nullptr: not cached and the frame's budget is spent.
    const Tile* tile(const PassCountLayer& layer, int level, int tx, int ty);
    bool budgetLeft() const;
    // What is drawn for a tile not rendered yet: its image from before the change, else a part of a
    // coarser cached tile. Returns false when there is nothing.
    bool drawStandIn(QPainter& p, int level, int tx, int ty, const QRectF& target);
    void invalidate(const QRect& cells);
    void retire(); // every tile becomes a stand-in (palette/target changed)
    void trim();

    QHash<quint64, Tile> m_tiles;
    QHash<quint64, Tile> m_stale; // stand-ins: tiles of the previous palette or counts
    double m_budgetMs = 0;
    qint64 m_maxBytes = kMaxCachedBytes;
    QElapsedTimer m_clock;
    const PassCountLayer* m_layer = nullptr;
    quint64 m_revision = 0;
    PassPalette m_palette = PassPalette::Discrete;
    PassTarget m_target{-1, -1};
    QRgb m_lut[16] = {};
    quint64 m_frame = 0;
    qint64 m_bytes = 0;
    int m_maxLevel = 0;
    Stats m_stats;
    std::vector<std::uint16_t> m_counts;
    // Tiles are anchored in the world, not in the layer's frame: a layer whose extent grows (its origin
    // moves by whole cells) keeps its cached tiles. Layer cell (col, row) = anchored cell (col + m_dc, row +
    // m_dr).
    bool m_anchored = false;
    QPointF m_anchor;
    double m_anchorCell = 0;
    int m_dc = 0, m_dr = 0;
};

} // namespace ocu
