#include "widgets/MapBackground.h"

#include <QFileInfo>
#include <QPainter>
#include <cmath>
#include <cpl_conv.h>
#include <cpl_error.h>
#include <gdal.h>
#include <gdal_alg.h>
#include <gdal_utils.h>
#include <mutex>
#include <vector>

namespace ocu {

namespace {

// GDAL's error handler stack is per thread: collects the messages of one load.
class GdalErrors {
public:
    GdalErrors() { CPLPushErrorHandlerEx(&GdalErrors::handler, this); }
    ~GdalErrors() { CPLPopErrorHandler(); }
    QString text() const { return m_text; }

private:
    static void CPL_STDCALL handler(CPLErr level, CPLErrorNum, const char* msg) {
        auto* self = static_cast<GdalErrors*>(CPLGetErrorHandlerUserData());
        if (self && level >= CE_Failure && self->m_text.size() < 500)
            self->m_text +=
                (self->m_text.isEmpty() ? QString() : QStringLiteral("; ")) + QString::fromUtf8(msg);
    }
    QString m_text;
};

struct DatasetCloser {
    void operator()(void* ds) const {
        if (ds)
            GDALClose(ds);
    }
};
using Dataset = std::unique_ptr<void, DatasetCloser>;

// The site frame as a projection: the ellipsoidal orthographic projection centred at the origin is the local
// tangent plane, so its x/y are site east/north in metres.
std::string siteSrs(const GeoFrame& frame) {
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  "+proj=ortho +lat_0=%.10f +lon_0=%.10f +x_0=0 +y_0=0 +ellps=WGS84 +units=m +no_defs",
                  frame.origin().lat, frame.origin().lon);
    return buf;
}

// gdalwarp into an in-memory dataset of outW x outH pixels covering `extent` (minx, miny, maxx, maxy in site
// metres) in the site frame `dstSrs`; an alpha band is added when the source has none. Null when it fails.
Dataset warpIntoSite(GDALDatasetH src, const std::string& dst, const double extent[4], int outW, int outH,
                     bool nearest, bool srcAlpha) {
    std::vector<std::string> args = {"-of",
                                     "MEM",
                                     "-t_srs",
                                     dst,
                                     "-r",
                                     nearest ? "near" : "bilinear",
                                     "-te",
                                     std::to_string(extent[0]),
                                     std::to_string(extent[1]),
                                     std::to_string(extent[2]),
                                     std::to_string(extent[3]),
                                     "-ts",
                                     std::to_string(outW),
                                     std::to_string(outH)};
    if (!srcAlpha)
        args.push_back("-dstalpha");
    std::vector<char*> argv;
    for (auto& a : args)
        argv.push_back(a.data());
    argv.push_back(nullptr);
    GDALWarpAppOptions* wo = GDALWarpAppOptionsNew(argv.data(), nullptr);
    GDALDatasetH srcs[] = {src};
    int usageError = 0;
    Dataset out(GDALWarp("", nullptr, 1, srcs, wo, &usageError));
    GDALWarpAppOptionsFree(wo);
    return out;
}

// The warped bands as one premultiplied ARGB image: colours through the palette, RGB bands, or grey (8 bit
// as is, other grey data stretched over its range). A null image when a band cannot be read.
QImage readWarped(GDALDatasetH out, int outW, int outH, int dataBands, GDALColorTableH palette,
                  GDALDataType type) {
    const int n = outW * outH;
    auto readBand = [&](int band, std::vector<double>& v) {
        v.resize(size_t(n));
        return GDALRasterIO(GDALGetRasterBand(out, band), GF_Read, 0, 0, outW, outH, v.data(), outW, outH,
                            GDT_Float64, 0, 0) == CE_None;
    };
    std::vector<double> r, g, b, a;
    const int alphaBand = dataBands + 1;
    bool ok = readBand(1, r) && readBand(alphaBand, a);
    if (ok && dataBands >= 3)
        ok = readBand(2, g) && readBand(3, b);
    if (!ok)
        return {};
    // Grey data that is not 8 bit (e.g. a DEM given as background): stretched over its range.
    double lo = 0, hi = 255;
    if (!palette && type != GDT_Byte) {
        lo = 1e300;
        hi = -1e300;
        for (int i = 0; i < n; ++i)
            if (a[size_t(i)] > 0 && std::isfinite(r[size_t(i)])) {
                lo = std::min(lo, r[size_t(i)]);
                hi = std::max(hi, r[size_t(i)]);
            }
        if (!(hi > lo)) {
            lo = 0;
            hi = 1;
        }
    }
    auto to8 = [&](double v) { return std::clamp(int(std::lround((v - lo) * 255.0 / (hi - lo))), 0, 255); };
    QImage img(outW, outH, QImage::Format_ARGB32_Premultiplied);
    for (int y = 0; y < outH; ++y) {
        auto* line = reinterpret_cast<QRgb*>(img.scanLine(y));
        for (int x = 0; x < outW; ++x) {
            const size_t i = size_t(y) * size_t(outW) + size_t(x);
            const int alpha = std::clamp(int(std::lround(a[i])), 0, 255);
            int cr, cg, cb;
            if (palette) {
                const GDALColorEntry* e = GDALGetColorEntry(palette, int(r[i]));
                cr = e ? e->c1 : 0;
                cg = e ? e->c2 : 0;
                cb = e ? e->c3 : 0;
            } else if (dataBands >= 3) {
                cr = to8(r[i]);
                cg = to8(g[i]);
                cb = to8(b[i]);
            } else {
                cr = cg = cb = to8(r[i]);
            }
            line[x] = qPremultiply(qRgba(cr, cg, cb, alpha));
        }
    }
    return img;
}

} // namespace

MapBackground::LoadResult MapBackground::load(const QString& path, const GeoFrame& frame) {
    return load(path, frame, MapTileCache::defaultDir());
}

MapBackground::LoadResult MapBackground::load(const QString& path, const GeoFrame& frame,
                                              const QString& cacheDir) {
    const MapTileCache cache(cacheDir);
    const QString key = MapTileCache::keyFor(path, frame, kMaxSidePx, kTilePx);
    if (auto p = cache.load(key, kTilePx))
        return {fromPyramid(path, std::move(*p)), {}, true};
    LoadResult r = warp(path, frame);
    if (r.background && !key.isEmpty()) {
        MapTilePyramid p;
        p.bounds = r.background->m_bounds;
        p.mpp = r.background->m_mpp;
        p.size = r.background->m_size;
        p.levels = r.background->m_levels;
        cache.store(key, p, path); // a full disk or read-only cache only costs the next start a warp
    }
    return r;
}

std::shared_ptr<MapBackground> MapBackground::fromPyramid(const QString& path, MapTilePyramid pyramid) {
    auto bg = std::make_shared<MapBackground>();
    bg->m_path = path;
    bg->m_bounds = pyramid.bounds;
    bg->m_mpp = pyramid.mpp;
    bg->m_size = pyramid.size;
    bg->m_levels = std::move(pyramid.levels);
    // Level 0 as one image again (colorAt).
    const Level& L = bg->m_levels.front();
    QImage full(bg->m_size, QImage::Format_ARGB32_Premultiplied);
    full.fill(Qt::transparent);
    QPainter p(&full);
    p.setCompositionMode(QPainter::CompositionMode_Source);
    for (int ty = 0; ty < L.rows; ++ty)
        for (int tx = 0; tx < L.cols; ++tx)
            p.drawImage(QPoint(tx * kTilePx, ty * kTilePx), L.tiles[ty * L.cols + tx]);
    p.end();
    bg->m_full = std::move(full);
    return bg;
}

MapBackground::LoadResult MapBackground::warp(const QString& path, const GeoFrame& frame) {
    static std::once_flag once;
    std::call_once(once, [] { GDALAllRegister(); });
    auto fail = [&](const QString& why) {
        return LoadResult{nullptr, QStringLiteral("%1: %2").arg(path, why)};
    };
    if (path.isEmpty())
        return fail(QStringLiteral("no file named"));
    const QFileInfo fi(path);
    if (!fi.exists())
        return fail(QStringLiteral("no such file"));
    if (!fi.isFile() || !fi.isReadable())
        return fail(QStringLiteral("not a readable file"));

    GdalErrors errors;
    const QByteArray p8 = path.toUtf8();
    Dataset src(GDALOpenEx(p8.constData(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr));
    if (!src)
        return fail(QStringLiteral("not a raster GDAL can read (%1)")
                        .arg(errors.text().isEmpty() ? QStringLiteral("unknown format") : errors.text()));
    const int bands = GDALGetRasterCount(src.get());
    if (bands < 1)
        return fail(QStringLiteral("has no raster bands"));
    const char* wkt = GDALGetProjectionRef(src.get());
    if ((!wkt || !*wkt) && GDALGetGCPCount(src.get()) == 0)
        return fail(QStringLiteral("has no georeferencing (no coordinate reference system)"));
    if (GDALGetRasterXSize(src.get()) < 1 || GDALGetRasterYSize(src.get()) < 1)
        return fail(QStringLiteral("is empty"));

    GDALRasterBandH b1 = GDALGetRasterBand(src.get(), 1);
    const bool srcAlpha =
        GDALGetRasterColorInterpretation(GDALGetRasterBand(src.get(), bands)) == GCI_AlphaBand;
    const int dataBands = srcAlpha ? bands - 1 : bands;
    if (dataBands < 1)
        return fail(QStringLiteral("has only an alpha band"));
    GDALColorTableH palette = dataBands == 1 ? GDALGetRasterColorTable(b1) : nullptr;

    // The output grid: GDAL's suggestion (native resolution), capped at kMaxSidePx.
    const std::string dst = siteSrs(frame);
    const std::string dstOpt = "DST_SRS=" + dst;
    const char* trOpts[] = {dstOpt.c_str(), nullptr};
    void* tr = GDALCreateGenImgProjTransformer2(src.get(), nullptr, const_cast<char**>(trOpts));
    if (!tr)
        return fail(QStringLiteral("cannot be transformed into the site frame (%1)").arg(errors.text()));
    double gt[6];
    int px = 0, lines = 0;
    double extent[4];
    const CPLErr sug =
        GDALSuggestedWarpOutput2(src.get(), GDALGenImgProjTransform, tr, gt, &px, &lines, extent, 0);
    GDALDestroyGenImgProjTransformer(tr);
    if (sug != CE_None || px <= 0 || lines <= 0)
        return fail(QStringLiteral("cannot be placed in the site frame (%1)").arg(errors.text()));
    // extent: minx, miny, maxx, maxy in site metres
    const double w = extent[2] - extent[0], h = extent[3] - extent[1];
    if (!(w > 0 && h > 0) || w > 2e5 || h > 2e5)
        return fail(QStringLiteral("covers %1 x %2 km around the site: not a site background (wrong CRS?)")
                        .arg(w / 1000, 0, 'f', 0)
                        .arg(h / 1000, 0, 'f', 0));
    const double shrink = std::max(1.0, double(std::max(px, lines)) / kMaxSidePx);
    const int outW = std::max(1, int(std::lround(px / shrink))),
              outH = std::max(1, int(std::lround(lines / shrink)));

    Dataset out = warpIntoSite(src.get(), dst, extent, outW, outH, palette != nullptr, srcAlpha);
    if (!out)
        return fail(QStringLiteral("warping into the site frame failed (%1)").arg(errors.text()));

    const QImage img = readWarped(out.get(), outW, outH, dataBands, palette, GDALGetRasterDataType(b1));
    if (img.isNull())
        return fail(QStringLiteral("cannot read the warped raster (%1)").arg(errors.text()));

    auto bg = std::make_shared<MapBackground>();
    bg->m_path = path;
    bg->m_size = QSize(outW, outH);
    bg->m_mpp = w / outW; // square pixels: -ts keeps the suggested aspect
    bg->m_bounds = QRectF(extent[0], extent[1], w, h);
    bg->m_full = img;
    // The tile pyramid: level k has 2^k metres-per-pixel of level 0.
    QImage level = img;
    double mpp = bg->m_mpp;
    while (true) {
        Level L;
        L.mpp = mpp;
        L.cols = (level.width() + kTilePx - 1) / kTilePx;
        L.rows = (level.height() + kTilePx - 1) / kTilePx;
        for (int ty = 0; ty < L.rows; ++ty)
            for (int tx = 0; tx < L.cols; ++tx)
                L.tiles.push_back(level.copy(tx * kTilePx, ty * kTilePx, kTilePx, kTilePx));
        bg->m_levels.push_back(std::move(L));
        if (level.width() <= kTilePx && level.height() <= kTilePx)
            break;
        // Halve (exactly, so tiles of every level line up with level 0's pixel grid).
        level = level.scaled(std::max(1, (level.width() + 1) / 2), std::max(1, (level.height() + 1) / 2),
                             Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
        mpp *= 2;
    }
    return {bg, {}};
}

QColor MapBackground::colorAt(QPointF en) const {
    const int x = int(std::floor((en.x() - m_bounds.left()) / m_mpp));
    const int y = int(std::floor((m_bounds.bottom() - en.y()) / m_mpp));
    if (x < 0 || y < 0 || x >= m_full.width() || y >= m_full.height())
        return Qt::transparent;
    return QColor::fromRgba(qUnpremultiply(m_full.pixel(x, y)));
}

int MapBackground::draw(QPainter& p, QPointF centre, double scale, const QSizeF& size) const {
    if (m_levels.isEmpty())
        return 0;
    // The finest level whose pixels are not smaller than half a screen pixel.
    const double texel = m_mpp * scale; // screen px per level-0 pixel
    int li = texel >= 0.5 ? 0 : int(std::floor(std::log2(0.5 / texel))) + 0;
    li = std::clamp(li, 0, int(m_levels.size()) - 1);
    const Level& L = m_levels[li];
    const double cx = size.width() / 2.0, cy = size.height() / 2.0;
    auto sx = [&](double e) { return std::round(cx + (e - centre.x()) * scale); };
    auto sy = [&](double nn) { return std::round(cy - (nn - centre.y()) * scale); };
    const double tileM = kTilePx * L.mpp;
    const double north = m_bounds.bottom();
    const QRectF view(0, 0, size.width(), size.height());
    p.save();
    p.setRenderHint(QPainter::SmoothPixmapTransform, true);
    int drawn = 0;
    for (int ty = 0; ty < L.rows; ++ty) {
        const double n0 = north - ty * tileM;
        const double top = sy(n0), bottom = sy(n0 - tileM);
        if (bottom < 0 || top > size.height())
            continue;
        for (int tx = 0; tx < L.cols; ++tx) {
            const double e0 = m_bounds.left() + tx * tileM;
            const QRectF target(QPointF(sx(e0), top), QPointF(sx(e0 + tileM), bottom));
            if (!target.intersects(view))
                continue;
            p.drawImage(target, L.tiles[ty * L.cols + tx]);
            ++drawn;
        }
    }
    p.restore();
    return drawn;
}

} // namespace ocu
