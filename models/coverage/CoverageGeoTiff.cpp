// The coverage GeoTIFF: the pass-count raster of one lift through GDAL, georeferenced in the report's
// projected CRS (docs/coverage-report.md).
#include "models/coverage/CoverageReportCommon.h"

#include <QFile>

#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <mutex>
#include <vector>

namespace ocu {

using coverage::liftName;
using coverage::ReportText;
using osyris::PassCountSnapshot;

QString writeCoverageGeoTiff(const CoverageJob& job, const CoverageFrames& frames, int lift,
                             const QString& path, double* maxDeviationM) {
    if (!job.snapshot || job.snapshot->empty())
        return ReportText::tr("no pass counts yet");
    const PassCountSnapshot& snap = *job.snapshot;
    const int l = lift == kAllLifts ? -1 : lift;
    static std::once_flag once;
    std::call_once(once, [] { GDALAllRegister(); });
    GDALDriver* drv = GetGDALDriverManager()->GetDriverByName("GTiff");
    if (!drv)
        return ReportText::tr("GDAL has no GTiff driver");
    const osyris::CellBox box = snap.extent();
    const int cols = box.cx1 - box.cx0 + 1, rows = box.cy1 - box.cy0 + 1;
    if (cols <= 0 || rows <= 0)
        return ReportText::tr("no pass counts yet");
    const double cs = snap.cellSize();
    // Raster row 0 is the northernmost row of cells (cy1); column 0 is cx0. The local grid is not aligned
    // with the projected grid (meridian convergence): an affine geotransform from three corners, and its
    // largest deviation at the fourth corner and the centre is measured (not assumed).
    const double xw = box.cx0 * cs, xe = (box.cx1 + 1) * cs, ys = box.cy0 * cs, yn = (box.cy1 + 1) * cs;
    double e00, n00, e10, n10, e01, n01;
    if (!frames.localToProjected(xw, yn, e00, n00) || !frames.localToProjected(xe, yn, e10, n10) ||
        !frames.localToProjected(xw, ys, e01, n01))
        return ReportText::tr("PROJ could not convert the raster's corners");
    double gt[6] = {e00, (e10 - e00) / cols, (e01 - e00) / rows, n00, (n10 - n00) / cols, (n01 - n00) / rows};
    double dev = 0;
    for (auto [px, py] : {std::pair{double(cols), double(rows)}, std::pair{cols / 2.0, rows / 2.0}}) {
        double e = 0, n = 0;
        frames.localToProjected(xw + px * cs, yn - py * cs, e, n);
        dev = std::max(dev,
                       std::hypot(gt[0] + px * gt[1] + py * gt[2] - e, gt[3] + px * gt[4] + py * gt[5] - n));
    }
    if (maxDeviationM)
        *maxDeviationM = dev;
    char** opts = nullptr;
    opts = CSLSetNameValue(opts, "TILED", "YES");
    opts = CSLSetNameValue(opts, "BLOCKXSIZE", "256");
    opts = CSLSetNameValue(opts, "BLOCKYSIZE", "256");
    opts = CSLSetNameValue(opts, "COMPRESS", "DEFLATE");
    opts = CSLSetNameValue(opts, "SPARSE_OK", "TRUE");
    opts = CSLSetNameValue(opts, "BIGTIFF", "IF_SAFER");
    const QByteArray file = QFile::encodeName(path);
    GDALDataset* ds = drv->Create(file.constData(), cols, rows, 1, GDT_UInt16, opts);
    CSLDestroy(opts);
    if (!ds)
        return ReportText::tr("GDAL cannot create %1: %2").arg(path, QString::fromUtf8(CPLGetLastErrorMsg()));
    ds->SetGeoTransform(gt);
    OGRSpatialReference srs;
    QString err;
    if (srs.importFromEPSG(frames.epsg()) != OGRERR_NONE) {
        err = ReportText::tr("GDAL does not know EPSG:%1").arg(frames.epsg());
    } else {
        char* wkt = nullptr;
        srs.exportToWkt(&wkt);
        ds->SetProjection(wkt);
        CPLFree(wkt);
    }
    GDALRasterBand* band = ds->GetRasterBand(1);
    band->SetNoDataValue(0);
    band->SetDescription(liftName(snap, l).toUtf8().constData());
    std::vector<std::uint16_t> buf(osyris::kTileCells);
    for (const auto& e : snap.tiles(l)) {
        // Tile rows j = 0 (south) .. 31 (north) -> raster rows counted from the north.
        for (int j = 0; j < osyris::kTileSize; ++j)
            for (int i = 0; i < osyris::kTileSize; ++i)
                buf[std::size_t((osyris::kTileSize - 1 - j) * osyris::kTileSize + i)] =
                    e.tile->counts[std::size_t(j * osyris::kTileSize + i)];
        const int col = e.tx * osyris::kTileSize - box.cx0;
        const int row = box.cy1 - (e.ty * osyris::kTileSize + osyris::kTileSize - 1);
        if (err.isEmpty() &&
            band->RasterIO(GF_Write, col, row, osyris::kTileSize, osyris::kTileSize, buf.data(),
                           osyris::kTileSize, osyris::kTileSize, GDT_UInt16, 0, 0) != CE_None)
            err =
                ReportText::tr("GDAL cannot write %1: %2").arg(path, QString::fromUtf8(CPLGetLastErrorMsg()));
    }
    GDALClose(ds);
    if (!err.isEmpty())
        QFile::remove(path);
    return err;
}

} // namespace ocu
