#pragma once
// The 2D map's background raster: an orthophoto or hillshade from a GeoTIFF, or an MBTiles
// file, read with GDAL, warped once into the site frame (the local tangent plane at the site origin, i.e.
// site ENU metres) and cut into a pyramid of 256 px tiles, so a repaint draws only the few visible tiles of
// the level that matches the zoom. GDAL stays in the .cpp.
#include "protocols/common/GeoFrame.h"
#include "widgets/MapTileCache.h"

#include <QColor>
#include <QImage>
#include <QRectF>
#include <QString>
#include <QVector>
#include <memory>

class QPainter;

namespace ocu {

class MapBackground {
public:
    // The largest side of the warped raster (px); bigger sources are read at a coarser resolution (GDAL picks
    // an overview when there is one).
    static constexpr int kMaxSidePx = 4096;
    static constexpr int kTilePx = 256;

    struct LoadResult {
        std::shared_ptr<const MapBackground> background; // null on failure
        QString error;                                   // what went wrong, naming the file
        bool fromCache = false;                          // the tiles came from the disk cache (no warp)
    };
    // Loads and warps the raster (GeoTIFF, MBTiles or anything else GDAL reads with georeferencing).
    // Blocking: call it off the GUI thread for big files. Never throws; bad files give an error.
    // The warped tiles are cached on disk (MapTileCache::defaultDir()): a restart reads them back.
    static LoadResult load(const QString& path, const GeoFrame& frame);
    // The same with the given cache directory (empty: no disk cache).
    static LoadResult load(const QString& path, const GeoFrame& frame, const QString& cacheDir);

    QString path() const { return m_path; }
    QRectF bounds() const { return m_bounds; }      // site ENU (x = east, y = north; top() = south edge)
    double metresPerPixel() const { return m_mpp; } // of level 0
    QSize sizePx() const { return m_size; }         // of level 0
    int levels() const { return int(m_levels.size()); }
    // The warped colour at a site position (level 0, nearest pixel); transparent outside.
    QColor colorAt(QPointF en) const;

    // Draws the visible part: `scale` px per metre, `centre` the site point at the middle of a view of
    // `size`. Returns the number of tiles drawn.
    int draw(QPainter& p, QPointF centre, double scale, const QSizeF& size) const;

private:
    using Level = MapTileLevel; // tiles row-major, row 0 = north
    static std::shared_ptr<MapBackground> fromPyramid(const QString& path, MapTilePyramid pyramid);
    static LoadResult warp(const QString& path, const GeoFrame& frame);
    QString m_path;
    QRectF m_bounds;
    double m_mpp = 1;
    QSize m_size;
    QImage m_full; // level 0 as one image (for colorAt)
    QVector<Level> m_levels;
};

} // namespace ocu
