#pragma once
// Disk cache of the 2D map's warped background tiles (warped into the site frame and cached as tiles): a
// restart does not warp the GeoTIFF/MBTiles again. One entry per source file and site frame, keyed
// by the file's canonical path, size and modification time, the site origin and the pyramid's size limit;
// inside it one PNG per tile and zoom level plus meta.json (written last, the entry is renamed into place
// whole). The cache is bounded (least recently used entries go first); an entry that does not read back
// exactly is discarded and the raster warped again, never a crash.
#include "protocols/common/GeoFrame.h"

#include <QImage>
#include <QRectF>
#include <QSize>
#include <QString>
#include <QVector>
#include <optional>

namespace ocu {

// One zoom level of the tile pyramid: tiles of MapBackground::kTilePx, row-major, row 0 = north.
struct MapTileLevel {
    double mpp = 1; // metres per pixel
    int cols = 0, rows = 0;
    QVector<QImage> tiles;
};

struct MapTilePyramid {
    QRectF bounds;  // site ENU metres
    double mpp = 1; // level 0
    QSize size;     // level 0, px
    QVector<MapTileLevel> levels;
};

class MapTileCache {
public:
    static constexpr qint64 kDefaultMaxBytes = 512ll * 1024 * 1024;
    static constexpr int kFormatVersion = 1;

    // `dir` empty = no cache (load misses, store does nothing).
    explicit MapTileCache(QString dir, qint64 maxBytes = kDefaultMaxBytes);

    // $OCU_TILE_CACHE_DIR if set ("off" = no cache), else <QStandardPaths::CacheLocation>/map-tiles.
    static QString defaultDir();
    // The entry's key for a source file in a site frame; empty when the file cannot be stat'ed.
    static QString keyFor(const QString& sourcePath, const GeoFrame& frame, int maxSidePx, int tilePx);

    QString dir() const { return m_dir; }
    // The pyramid of the entry, or nullopt (no entry, or a corrupt one, which is then removed).
    std::optional<MapTilePyramid> load(const QString& key, int tilePx) const;
    // Writes the entry (atomically: a temporary directory renamed into place), then trims the cache.
    bool store(const QString& key, const MapTilePyramid& pyramid, const QString& sourcePath) const;
    // Bytes of all entries; removes the least recently used entries until at most maxBytes remain.
    qint64 trim() const;
    QString entryPath(const QString& key) const;

private:
    QString m_dir;
    qint64 m_maxBytes;
};

} // namespace ocu
