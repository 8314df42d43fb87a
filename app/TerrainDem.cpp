#include "app/TerrainDem.h"

#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>

namespace ocu {

namespace {

struct DatasetCloser {
    void operator()(GDALDataset* d) const { GDALClose(d); }
};
struct TransformDeleter {
    void operator()(OGRCoordinateTransformation* t) const { OGRCoordinateTransformation::DestroyCT(t); }
};

} // namespace

Result<TerrainGrid3D> loadTerrainDem(const std::string& path, const GeoFrame& frame, int maxSide) {
    static std::once_flag registered;
    std::call_once(registered, [] { GDALAllRegister(); });
    CPLPushErrorHandler(CPLQuietErrorHandler); // errors come back as text, not on stderr
    std::unique_ptr<GDALDataset, DatasetCloser> ds(
        static_cast<GDALDataset*>(GDALOpen(path.c_str(), GA_ReadOnly)));
    CPLPopErrorHandler();
    if (!ds)
        return makeError("terrain DEM " + path + ": cannot open (" + CPLGetLastErrorMsg() + ")");
    const int w = ds->GetRasterXSize(), h = ds->GetRasterYSize();
    if (ds->GetRasterCount() < 1 || w < 2 || h < 2)
        return makeError("terrain DEM " + path + ": needs one band of at least 2 x 2 samples");
    double gt[6];
    if (ds->GetGeoTransform(gt) != CE_None)
        return makeError("terrain DEM " + path + ": has no geotransform (not geo-referenced)");
    double inv[6];
    if (!GDALInvGeoTransform(gt, inv))
        return makeError("terrain DEM " + path + ": geotransform cannot be inverted");
    const OGRSpatialReference* srs = ds->GetSpatialRef();
    if (srs == nullptr || srs->IsEmpty())
        return makeError("terrain DEM " + path + ": has no coordinate reference system");
    OGRSpatialReference wgs84;
    wgs84.SetWellKnownGeogCS("WGS84");
    wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER); // x = longitude, y = latitude
    OGRSpatialReference demSrs(*srs);
    demSrs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    std::unique_ptr<OGRCoordinateTransformation, TransformDeleter> toDem(
        OGRCreateCoordinateTransformation(&wgs84, &demSrs));
    std::unique_ptr<OGRCoordinateTransformation, TransformDeleter> fromDem(
        OGRCreateCoordinateTransformation(&demSrs, &wgs84));
    if (!toDem || !fromDem)
        return makeError("terrain DEM " + path + ": no transformation between its CRS and WGS84");

    // The DEM's extent in the site frame: its four corners and edge midpoints, transformed.
    double minE = 1e300, maxE = -1e300, minN = 1e300, maxN = -1e300;
    for (double fx : {0.0, 0.5, 1.0})
        for (double fy : {0.0, 0.5, 1.0}) {
            double x = gt[0] + fx * w * gt[1] + fy * h * gt[2];
            double y = gt[3] + fx * w * gt[4] + fy * h * gt[5];
            if (!fromDem->Transform(1, &x, &y))
                return makeError("terrain DEM " + path + ": its corners cannot be transformed to WGS84");
            const EnuPoint p = frame.toLocal(GeoPoint{y, x, 0.0});
            minE = std::min(minE, p.e);
            maxE = std::max(maxE, p.e);
            minN = std::min(minN, p.n);
            maxN = std::max(maxN, p.n);
        }
    if (!(maxE > minE) || !(maxN > minN) || maxE - minE > 200'000 || maxN - minN > 200'000)
        return makeError("terrain DEM " + path + ": its extent in the site frame is empty or beyond 200 km");

    // Read the band once (at most 4096 x 4096: larger ones are read decimated by GDAL).
    const int rw = std::min(w, 4096), rh = std::min(h, 4096);
    std::vector<float> band(static_cast<std::size_t>(rw) * rh);
    GDALRasterBand* b = ds->GetRasterBand(1);
    if (b->RasterIO(GF_Read, 0, 0, w, h, band.data(), rw, rh, GDT_Float32, 0, 0) != CE_None)
        return makeError("terrain DEM " + path + ": reading failed (" + CPLGetLastErrorMsg() + ")");
    int hasNoData = 0;
    const double noData = b->GetNoDataValue(&hasNoData);
    const double sx = static_cast<double>(rw) / w, sy = static_cast<double>(rh) / h;
    auto sample = [&](double px, double py) -> double {      // pixel coordinates of the full raster
        const double fx = px * sx - 0.5, fy = py * sy - 0.5; // sample centres
        if (fx < -0.5 || fy < -0.5 || fx > rw - 0.5 || fy > rh - 0.5)
            return NAN;
        const int x0 = std::clamp(static_cast<int>(std::floor(fx)), 0, rw - 1);
        const int y0 = std::clamp(static_cast<int>(std::floor(fy)), 0, rh - 1);
        const int x1 = std::min(x0 + 1, rw - 1), y1 = std::min(y0 + 1, rh - 1);
        const double ax = std::clamp(fx - x0, 0.0, 1.0), ay = std::clamp(fy - y0, 0.0, 1.0);
        double acc = 0.0, wsum = 0.0;
        const int xs[2] = {x0, x1}, ys[2] = {y0, y1};
        const double wx[2] = {1 - ax, ax}, wy[2] = {1 - ay, ay};
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i) {
                const double v = band[static_cast<std::size_t>(ys[j]) * rw + xs[i]];
                const double wgt = wx[i] * wy[j];
                if (!std::isfinite(v) || (hasNoData && v == noData) || wgt <= 0.0)
                    continue;
                acc += v * wgt;
                wsum += wgt;
            }
        return wsum > 1e-9 ? acc / wsum : NAN;
    };

    TerrainGrid3D g;
    maxSide = std::clamp(maxSide, 2, 2048);
    g.step = std::max((maxE - minE), (maxN - minN)) / (maxSide - 1);
    g.cols = std::max(2, static_cast<int>(std::floor((maxE - minE) / g.step)) + 1);
    g.rows = std::max(2, static_cast<int>(std::floor((maxN - minN) / g.step)) + 1);
    g.originE = minE;
    g.originN = minN;
    g.u.resize(static_cast<std::size_t>(g.cols) * g.rows, NAN);
    std::size_t valid = 0;
    double sum = 0.0;
    for (int r = 0; r < g.rows; ++r)
        for (int c = 0; c < g.cols; ++c) {
            const GeoPoint geo =
                frame.toGeodetic(EnuPoint{g.originE + c * g.step, g.originN + r * g.step, 0.0});
            double x = geo.lon, y = geo.lat;
            if (!toDem->Transform(1, &x, &y))
                continue;
            const double px = inv[0] + x * inv[1] + y * inv[2];
            const double py = inv[3] + x * inv[4] + y * inv[5];
            const double u = sample(px, py);
            if (std::isfinite(u)) {
                g.u[static_cast<std::size_t>(r) * g.cols + c] = u;
                sum += u;
                ++valid;
            }
        }
    if (valid == 0)
        return makeError("terrain DEM " + path + ": holds no valid height");
    // Heights are relative to the site origin's altitude, like every other height in the site frame.
    const double fill = sum / static_cast<double>(valid);
    for (double& u : g.u)
        u = (std::isfinite(u) ? u : fill) - frame.origin().alt;
    return g;
}

} // namespace ocu
