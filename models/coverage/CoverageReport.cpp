#include "models/coverage/CoverageReport.h"

#include "models/PdfPageWriter.h"

#include "models/PassCountLayer.h"
#include "protocols/site/CrsTransform.h"

#include <QCoreApplication>
#include <QFile>
#include <QJsonArray>
#include <QPageSize>
#include <QPainter>
#include <QPainterPath>
#include <QPdfWriter>
#include <QSaveFile>

#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <mutex>

namespace ocu {

using osyris::CoverageStats;
using osyris::LocalPoint;
using osyris::LocalRing;
using osyris::PassCountSnapshot;

namespace {
// The report's texts in the translation context "ocu::CoverageReport"; a class, so that lupdate sees the
// context and no free tr() shadows QObject::tr.
struct ReportText {
    Q_DECLARE_TR_FUNCTIONS(ocu::CoverageReport)
};
} // namespace

struct CoverageFrames::Crs {
    CrsTransform t;
};

QString CoverageFrames::init(const CoverageJob& job) {
    m_worksite = GeoFrame(job.worksiteOrigin);
    int epsg = job.epsg;
    if (epsg <= 0 && job.design && job.design->epsg > 0)
        epsg = job.design->epsg;
    if (epsg <= 0)
        epsg = CrsTransform::utmEpsgFor(job.worksiteOrigin.lat, job.worksiteOrigin.lon);
    auto t = CrsTransform::fromWgs84To(epsg);
    if (!t)
        return QString::fromStdString(t.error());
    m_crs = std::make_shared<Crs>(Crs{std::move(t.value())});
    m_epsg = epsg;
    m_crsName = QString::fromStdString(m_crs->t.name());
    m_designCrs.reset();
    if (job.design && job.design->epsg > 0) {
        if (job.design->epsg == epsg) {
            m_designCrs = m_crs;
        } else {
            auto d = CrsTransform::fromWgs84To(job.design->epsg);
            if (!d)
                return ReportText::tr("design CRS: %1").arg(QString::fromStdString(d.error()));
            m_designCrs = std::make_shared<Crs>(Crs{std::move(d.value())});
        }
    }
    return {};
}

GeoPoint CoverageFrames::localToGeo(double x, double y) const {
    return m_worksite.toGeodetic({x, y, 0});
}

std::optional<LocalPoint> CoverageFrames::geoToLocal(const GeoPoint& g) const {
    if (!std::isfinite(g.lat) || !std::isfinite(g.lon))
        return std::nullopt;
    const EnuPoint p = m_worksite.toLocal({g.lat, g.lon, m_worksite.origin().alt});
    return LocalPoint{p.e, p.n};
}

bool CoverageFrames::localToProjected(double x, double y, double& e, double& n, double* lat,
                                      double* lon) const {
    if (!m_crs)
        return false;
    const GeoPoint g = localToGeo(x, y);
    if (lat)
        *lat = g.lat;
    if (lon)
        *lon = g.lon;
    return m_crs->t.toProjected(g.lat, g.lon, e, n);
}

bool CoverageFrames::localToProjected(const double* x, const double* y, std::size_t n, double* e, double* nn,
                                      double* lat, double* lon) const {
    if (!m_crs)
        return false;
    for (std::size_t i = 0; i < n; ++i) {
        const GeoPoint g = m_worksite.toGeodetic({x[i], y[i], 0});
        e[i] = lat[i] = g.lat;
        nn[i] = lon[i] = g.lon;
    }
    return m_crs->t.toProjected(e, nn, n);
}

bool CoverageFrames::projectedToLocal(double e, double n, double& x, double& y) const {
    double lat = 0, lon = 0;
    if (!m_crs || !m_crs->t.toGeographic(e, n, lat, lon))
        return false;
    const auto p = geoToLocal({lat, lon, 0});
    if (!p)
        return false;
    x = p->x;
    y = p->y;
    return true;
}

bool CoverageFrames::designToLocal(const landxml::PlanPoint& p, LocalPoint& out) const {
    double lat = 0, lon = 0;
    if (!m_designCrs || !m_designCrs->t.toGeographic(p.e, p.n, lat, lon))
        return false;
    const auto l = geoToLocal({lat, lon, 0});
    if (!l)
        return false;
    out = *l;
    return true;
}

namespace {

LocalRing areaRing(const CoverageFrames& f, const CompactionArea& a) {
    LocalRing r;
    for (const GeoPoint& g : a.ring)
        if (auto p = f.geoToLocal(g))
            r.push_back(*p);
    return r;
}

const CompactionArea* findArea(const CoverageJob& job, const QString& name) {
    for (const auto& a : job.areas)
        if (a.name == name)
            return &a;
    return nullptr;
}

QString liftName(const PassCountSnapshot& s, int lift) {
    if (lift == kAllLifts)
        return ReportText::tr("every lift");
    if (lift < 0 || lift >= s.liftCount())
        return ReportText::tr("top view (top-most lift per cell)");
    return ReportText::tr("lift %1 (z %2 … %3 m)")
        .arg(lift + 1)
        .arg(s.liftBottom(lift), 0, 'f', 2)
        .arg(s.liftTop(lift), 0, 'f', 2);
}

QString num(double v, int d) {
    return QString::number(v, 'f', d);
}

} // namespace

CoverageTables computeCoverageTables(const CoverageJob& job, const CoverageFrames& frames, int lift,
                                     const QString& area) {
    CoverageTables t;
    t.epsg = frames.epsg();
    t.crsName = frames.crsName();
    if (!job.snapshot) {
        t.problems << ReportText::tr("no pass counts yet");
        return t;
    }
    const PassCountSnapshot& snap = *job.snapshot;
    const int l = lift == kAllLifts ? -1 : lift;
    // The whole lift: every cell with a count (and, in the top view, incomplete cells without one).
    CoverageStats w;
    w.cellSize = snap.cellSize();
    w.targetMin = snap.targetMin();
    w.targetMax = snap.targetMax();
    std::uint64_t sum = 0;
    int mn = INT32_MAX;
    snap.forEachCell(l, [&](std::int32_t, std::int32_t, int c, bool inc) {
        ++w.cells;
        if (inc)
            ++w.incomplete;
        if (c == 0)
            return;
        ++w.covered;
        sum += std::uint64_t(c);
        mn = std::min(mn, c);
        w.maxPasses = std::max(w.maxPasses, c);
        (c < w.targetMin ? w.under : c <= w.targetMax ? w.atTarget : w.over)++;
    });
    w.uncovered = w.cells - w.covered;
    if (w.covered) {
        w.minPasses = mn;
        w.meanPasses = double(sum) / double(w.covered);
    }
    t.whole = w;

    for (const CompactionArea& a : job.areas) {
        if (!area.isEmpty() && a.name != area)
            continue;
        const LocalRing ring = areaRing(frames, a);
        if (ring.size() < 3) {
            t.problems << ReportText::tr("area \"%1\" has fewer than 3 usable vertices").arg(a.name);
            continue;
        }
        t.areas.push_back({a.name, a.source, osyris::coverageInRings(snap, {ring}, l)});
    }
    if (!area.isEmpty() && t.areas.isEmpty() && !findArea(job, area))
        t.problems << ReportText::tr("no area named \"%1\"").arg(area);

    if (job.design && !job.design->alignments.empty()) {
        if (!frames.hasDesignCrs()) {
            t.problems << ReportText::tr("the design names no EPSG code: station ranges cannot be placed");
        } else {
            const landxml::Alignment& al = job.design->alignments.front();
            t.alignment = QString::fromStdString(al.name);
            osyris::StationPointFn fn = [&](double s, double off) -> std::optional<LocalPoint> {
                const auto p = al.pointAt(s, off);
                LocalPoint out;
                if (!p || !frames.designToLocal(*p, out))
                    return std::nullopt;
                return out;
            };
            double from = al.staStart, to = al.staEnd();
            const double step = job.stationStep > 0 ? job.stationStep : 20;
            const auto bins =
                osyris::coverageByStation(snap, fn, from, to, step, job.bandLeft, job.bandRight, l, 2.0);
            t.stations = QVector<osyris::StationBin>(bins.begin(), bins.end());
        }
    }
    return t;
}

// ---- CSV ----

QString writeCoverageCsv(const CoverageJob& job, const CoverageFrames& frames, int lift, const QString& area,
                         const QString& path, qint64* rowsOut) {
    if (!job.snapshot)
        return ReportText::tr("no pass counts yet");
    const PassCountSnapshot& snap = *job.snapshot;
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly))
        return ReportText::tr("cannot write %1: %2").arg(path, f.errorString());
    LocalRing ring;
    if (!area.isEmpty()) {
        const CompactionArea* a = findArea(job, area);
        if (!a)
            return ReportText::tr("no area named \"%1\"").arg(area);
        ring = areaRing(frames, *a);
    }
    const double cs = snap.cellSize();
    QByteArray head;
    auto tag = [&](const char* k, const QString& v) {
        head += "# ";
        head += k;
        head += ": ";
        head += v.toUtf8();
        head += '\n';
    };
    // The Veta tagged-data header items that apply to gridded pass counts (anchors-features.md §4.1).
    tag("data-lot-name", job.siteName.isEmpty() ? QStringLiteral("OCU coverage") : job.siteName);
    tag("gridding-width", num(cs, 3));
    tag("gridding-height", num(cs, 3));
    tag("gridding-process", QStringLiteral("gridded"));
    tag("machine-name", job.machines.join(QStringLiteral("; ")));
    tag("machine-type", QStringLiteral("compactor"));
    tag("spatial-reference-authority", QStringLiteral("EPSG"));
    tag("spatial-reference-id", QString::number(frames.epsg()));
    tag("spatial-reference-name", frames.crsName());
    tag("measurement-name", QStringLiteral("pass-count"));
    tag("target-passes", QStringLiteral("%1-%2").arg(snap.targetMin()).arg(snap.targetMax()));
    tag("lift", liftName(snap, lift));
    if (!area.isEmpty())
        tag("area", area);
    for (int i = 0; i < snap.liftCount(); ++i)
        tag(QStringLiteral("lift-%1").arg(i + 1).toUtf8().constData(), QStringLiteral("z %1 .. %2 m")
                                                                           .arg(snap.liftBottom(i), 0, 'f', 3)
                                                                           .arg(snap.liftTop(i), 0, 'f', 3));
    head += "easting,northing,lift,pass-count,target-status,incomplete,cell-x,cell-y\n";
    f.write(head);

    std::vector<int> lifts;
    if (lift == kAllLifts)
        for (int i = 0; i < snap.liftCount(); ++i)
            lifts.push_back(i);
    else
        lifts.push_back(lift);
    // Cells in the area (by centre), if one was named.
    struct Span {
        std::int32_t cy, cx0, cx1;
    };
    std::vector<Span> areaSpans;
    if (!ring.empty())
        osyris::rasterizeRings({ring}, cs, [&](std::int32_t cy, std::int32_t a, std::int32_t b) {
            areaSpans.push_back({cy, a, b});
        });
    auto inArea = [&](std::int32_t cx, std::int32_t cy) {
        if (ring.empty())
            return true;
        auto it = std::lower_bound(areaSpans.begin(), areaSpans.end(), cy,
                                   [](const Span& s, std::int32_t y) { return s.cy < y; });
        for (; it != areaSpans.end() && it->cy == cy; ++it)
            if (cx >= it->cx0 && cx <= it->cx1)
                return true;
        return false;
    };

    qint64 rows = 0;
    // Tile by tile of the top view (every cell with a count in any lift is in it): each cell's position goes
    // through the geodetic position and PROJ once, then one row per lift asked for.
    const bool top = lifts.size() == 1 && (lifts[0] < 0 || lifts[0] >= snap.liftCount());
    auto findTile = [&](int l, std::int32_t tx, std::int32_t ty) -> const osyris::PassCountTile* {
        const auto& v = snap.tiles(l);
        auto it = std::lower_bound(v.begin(), v.end(), std::pair{ty, tx}, [](const auto& e, const auto& k) {
            return std::pair{e.ty, e.tx} < k;
        });
        return it != v.end() && it->tx == tx && it->ty == ty ? it->tile.get() : nullptr;
    };
    std::vector<double> xs, ys, es, ns, lats, lons;
    std::vector<int> idx;
    std::vector<const osyris::PassCountTile*> liftTiles(lifts.size());
    QByteArray block;
    char num[64];
    auto put = [&](double v, int prec) {
        auto [end, ec] = std::to_chars(num, num + sizeof num, v, std::chars_format::fixed, prec);
        block.append(num, int(end - num));
    };
    auto putInt = [&](long long v) {
        auto [end, ec] = std::to_chars(num, num + sizeof num, v);
        block.append(num, int(end - num));
    };
    std::vector<QByteArray> liftNo;
    for (int l : lifts)
        liftNo.push_back(l < 0 || l >= snap.liftCount() ? QByteArray("top") : QByteArray::number(l + 1));
    for (const auto& e : snap.tiles(-1)) {
        bool any = false;
        for (std::size_t k = 0; k < lifts.size(); ++k) {
            liftTiles[k] = top ? e.tile.get() : findTile(lifts[k], e.tx, e.ty);
            any = any || liftTiles[k];
        }
        if (!any)
            continue;
        const auto* flags =
            snap.anyIncomplete() ? static_cast<const osyris::PassCountTopTile*>(e.tile.get()) : nullptr;
        idx.clear();
        const std::int32_t x0 = e.tx * osyris::kTileSize, y0 = e.ty * osyris::kTileSize;
        for (int i = 0; i < osyris::kTileCells; ++i) {
            bool has = flags && top && (flags->flags[std::size_t(i)] & osyris::kCellIncomplete);
            for (std::size_t k = 0; k < lifts.size() && !has; ++k)
                has = liftTiles[k] && liftTiles[k]->counts[std::size_t(i)] > 0;
            if (has && inArea(x0 + (i & (osyris::kTileSize - 1)), y0 + (i >> osyris::kTileBits)))
                idx.push_back(i);
        }
        if (idx.empty())
            continue;
        const std::size_t n = idx.size();
        xs.resize(n);
        ys.resize(n);
        es.resize(n);
        ns.resize(n);
        lats.resize(n);
        lons.resize(n);
        for (std::size_t k = 0; k < n; ++k) {
            xs[k] = (x0 + (idx[k] & (osyris::kTileSize - 1)) + 0.5) * cs;
            ys[k] = (y0 + (idx[k] >> osyris::kTileBits) + 0.5) * cs;
        }
        if (!frames.localToProjected(xs.data(), ys.data(), n, es.data(), ns.data(), lats.data(), lons.data()))
            return ReportText::tr("PROJ could not convert a cell to EPSG:%1").arg(frames.epsg());
        block.clear();
        for (std::size_t k = 0; k < n; ++k) {
            const int i = idx[k];
            const bool inc = flags && (flags->flags[std::size_t(i)] & osyris::kCellIncomplete);
            for (std::size_t l = 0; l < lifts.size(); ++l) {
                const int c = liftTiles[l] ? liftTiles[l]->counts[std::size_t(i)] : 0;
                if (c == 0 && !(top && inc))
                    continue;
                const char* status = c == 0                  ? "none"
                                     : c < snap.targetMin()  ? "under"
                                     : c <= snap.targetMax() ? "at"
                                                             : "over";
                put(es[k], 4);
                block.append(',');
                put(ns[k], 4);
                block.append(',');
                block.append(liftNo[l]);
                block.append(',');
                putInt(c);
                block.append(',');
                block.append(status);
                block.append(inc ? ",1," : ",0,");
                putInt(x0 + (i & (osyris::kTileSize - 1)));
                block.append(',');
                putInt(y0 + (i >> osyris::kTileBits));
                block.append('\n');
                ++rows;
            }
        }
        if (f.write(block) != block.size())
            return ReportText::tr("cannot write %1: %2").arg(path, f.errorString());
    }
    if (!f.commit())
        return ReportText::tr("cannot write %1: %2").arg(path, f.errorString());
    if (rowsOut)
        *rowsOut = rows;
    return {};
}

// ---- GeoTIFF ----

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

// ---- map snapshot ----

QImage renderCoverageMap(const CoverageJob& job, const CoverageFrames& frames, int lift, const QString& area,
                         QSize size) {
    QImage img(size, QImage::Format_ARGB32_Premultiplied);
    img.fill(QColor(0xf4, 0xf4, 0xf0));
    if (!job.snapshot)
        return img;
    const PassCountSnapshot& snap = *job.snapshot;
    const int l = lift == kAllLifts ? -1 : lift;
    const double cs = snap.cellSize();
    // Extent: the chosen area, else the covered cells (at least 40 m), with a margin.
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool have = false;
    if (const CompactionArea* a = area.isEmpty() ? nullptr : findArea(job, area)) {
        for (const LocalPoint& p : areaRing(frames, *a)) {
            x0 = have ? std::min(x0, p.x) : p.x;
            x1 = have ? std::max(x1, p.x) : p.x;
            y0 = have ? std::min(y0, p.y) : p.y;
            y1 = have ? std::max(y1, p.y) : p.y;
            have = true;
        }
    }
    if (!have && !snap.empty()) {
        const osyris::GridRect b = snap.bounds();
        // Tighter than whole tiles: the covered cells themselves.
        std::int32_t cx0 = INT32_MAX, cy0 = INT32_MAX, cx1 = INT32_MIN, cy1 = INT32_MIN;
        snap.forEachCell(l, [&](std::int32_t cx, std::int32_t cy, int, bool) {
            cx0 = std::min(cx0, cx);
            cy0 = std::min(cy0, cy);
            cx1 = std::max(cx1, cx);
            cy1 = std::max(cy1, cy);
        });
        if (cx1 >= cx0) {
            x0 = cx0 * cs;
            y0 = cy0 * cs;
            x1 = (cx1 + 1) * cs;
            y1 = (cy1 + 1) * cs;
        } else {
            x0 = b.xMin, y0 = b.yMin, x1 = b.xMax, y1 = b.yMax;
        }
        have = true;
    }
    if (!have)
        return img;
    const double minSpan = 40;
    if (x1 - x0 < minSpan) {
        const double c = (x0 + x1) / 2;
        x0 = c - minSpan / 2;
        x1 = c + minSpan / 2;
    }
    if (y1 - y0 < minSpan) {
        const double c = (y0 + y1) / 2;
        y0 = c - minSpan / 2;
        y1 = c + minSpan / 2;
    }
    const double margin = 0.08 * std::max(x1 - x0, y1 - y0);
    x0 -= margin;
    x1 += margin;
    y0 -= margin;
    y1 += margin;
    const double scale = std::min(size.width() / (x1 - x0), size.height() / (y1 - y0)); // px per m
    const double ox = size.width() / 2.0 - scale * (x0 + x1) / 2,
                 oy = size.height() / 2.0 + scale * (y0 + y1) / 2;
    auto toPx = [&](double x, double y) { return QPointF(ox + scale * x, oy - scale * y); };

    QPainter p(&img);
    p.setRenderHint(QPainter::Antialiasing);
    // Cells: the largest count per pixel when cells are smaller than pixels.
    const PassTarget target{snap.targetMin(), snap.targetMax()};
    const QRectF view(0, 0, size.width(), size.height());
    if (scale * cs >= 1.5) {
        snap.forEachCell(l, [&](std::int32_t cx, std::int32_t cy, int c, bool inc) {
            const QPointF a = toPx(cx * cs, (cy + 1) * cs);
            const QRectF r(a, QSizeF(scale * cs + 0.5, scale * cs + 0.5));
            if (!view.intersects(r))
                return;
            if (c > 0)
                p.fillRect(r, passCountColor(c, PassPalette::Discrete, target));
            else if (inc)
                p.fillRect(r, QColor(0x80, 0x80, 0x80, 120));
        });
    } else {
        std::vector<std::uint16_t> px(std::size_t(size.width()) * std::size_t(size.height()), 0);
        snap.forEachCell(l, [&](std::int32_t cx, std::int32_t cy, int c, bool) {
            const QPointF a = toPx((cx + 0.5) * cs, (cy + 0.5) * cs);
            const int ix = int(a.x()), iy = int(a.y());
            if (ix < 0 || iy < 0 || ix >= size.width() || iy >= size.height())
                return;
            auto& v = px[std::size_t(iy) * std::size_t(size.width()) + std::size_t(ix)];
            v = std::max<std::uint16_t>(v, std::uint16_t(c));
        });
        for (int y = 0; y < size.height(); ++y) {
            auto* line = reinterpret_cast<QRgb*>(img.scanLine(y));
            for (int x = 0; x < size.width(); ++x)
                if (int c = px[std::size_t(y) * std::size_t(size.width()) + std::size_t(x)])
                    line[x] = passCountColor(c, PassPalette::Discrete, target).rgba();
        }
    }
    // Design: boundary, centre line with station ticks every 100 m.
    if (job.design && frames.hasDesignCrs()) {
        p.setPen(QPen(QColor(0x30, 0x30, 0x30), 1.5, Qt::DashLine));
        for (const auto& b : job.design->boundaries) {
            QPolygonF poly;
            for (const auto& q : b.points) {
                LocalPoint lp;
                if (frames.designToLocal(q, lp))
                    poly << toPx(lp.x, lp.y);
            }
            p.drawPolygon(poly);
        }
        for (const auto& al : job.design->alignments) {
            QPolygonF line;
            for (const auto& q : al.polyline(std::max(1.0, 2 / scale))) {
                LocalPoint lp;
                if (frames.designToLocal(q, lp))
                    line << toPx(lp.x, lp.y);
            }
            p.setPen(QPen(QColor(0xd0, 0x60, 0x00), 2));
            p.drawPolyline(line);
            QFont f = p.font();
            f.setPixelSize(std::max(11, size.height() / 70));
            p.setFont(f);
            const double first = std::ceil(al.staStart / 100) * 100;
            for (double s = first; s <= al.staEnd() + 1e-6; s += 100) {
                auto c = al.pointAt(s), r = al.pointAt(s, 3), lft = al.pointAt(s, -3);
                LocalPoint lc, lr, ll;
                if (!c || !frames.designToLocal(*c, lc) || !frames.designToLocal(*r, lr) ||
                    !frames.designToLocal(*lft, ll))
                    continue;
                const QPointF pc = toPx(lc.x, lc.y);
                if (!view.contains(pc))
                    continue;
                p.drawLine(toPx(ll.x, ll.y), toPx(lr.x, lr.y));
                p.drawText(toPx(lr.x, lr.y) + QPointF(4, 4),
                           QString::fromStdString(landxml::formatStation(s, 0)));
            }
        }
    }
    // Areas.
    for (const CompactionArea& a : job.areas) {
        QPolygonF poly;
        for (const LocalPoint& q : areaRing(frames, a))
            poly << toPx(q.x, q.y);
        const bool chosen = a.name == area;
        p.setPen(QPen(chosen ? QColor(0x10, 0x40, 0xc0) : QColor(0x40, 0x40, 0xa0), chosen ? 3 : 1.5));
        p.setBrush(Qt::NoBrush);
        p.drawPolygon(poly);
        if (!poly.isEmpty())
            p.drawText(poly.boundingRect().topLeft() + QPointF(4, -4), a.name);
    }
    // Legend (top right) and scale bar (bottom left).
    QFont f = p.font();
    f.setPixelSize(std::max(12, size.height() / 38));
    p.setFont(f);
    const int lh = p.fontMetrics().height();
    const QStringList labels{QStringLiteral("1"), QStringLiteral("2"), QStringLiteral("3"),
                             QStringLiteral("4"), QStringLiteral("5"), QStringLiteral("6"),
                             QStringLiteral("7"), QStringLiteral("8"), QStringLiteral("9+")};
    const int lw = lh * 7;
    QRect legend(size.width() - lw - 10, 10, lw, lh * (labels.size() + 3));
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(255, 255, 255, 225));
    p.drawRect(legend);
    p.setBrush(Qt::NoBrush);
    p.setPen(Qt::black);
    p.drawText(QRect(legend.left() + 6, legend.top() + 2, lw, lh), Qt::AlignLeft | Qt::AlignVCenter,
               ReportText::tr("Passes"));
    for (int i = 0; i < labels.size(); ++i) {
        const QRect sw(legend.left() + 6, legend.top() + lh * (i + 1) + 4, lh - 2, lh - 4);
        p.fillRect(sw, passCountColor(i + 1, PassPalette::Discrete, target));
        p.drawRect(sw);
        p.drawText(QRect(sw.right() + 6, sw.top() - 2, lw, lh), Qt::AlignLeft | Qt::AlignVCenter,
                   labels[i] + ((i + 1 >= target.min && i + 1 <= target.max) ? ReportText::tr(" (target)")
                                                                             : QString()));
    }
    const QRect inc(legend.left() + 6, legend.top() + lh * (labels.size() + 1) + 6, lh - 2, lh - 4);
    p.fillRect(inc, QColor(0x80, 0x80, 0x80, 120));
    p.drawRect(inc);
    p.drawText(QRect(inc.right() + 6, inc.top() - 2, lw, lh), Qt::AlignLeft | Qt::AlignVCenter,
               ReportText::tr("incomplete"));
    // Scale bar: a round length about a fifth of the width.
    const double target_m = size.width() / 5.0 / scale;
    const double pow10 = std::pow(10, std::floor(std::log10(target_m)));
    double len = pow10;
    for (double m : {1.0, 2.0, 5.0})
        if (m * pow10 <= target_m)
            len = m * pow10;
    const int bx = 20, by = size.height() - 24, bw = int(len * scale);
    p.fillRect(QRect(bx - 6, by - lh - 6, bw + 12 + lh * 3, lh + 16), QColor(255, 255, 255, 225));
    p.setPen(QPen(Qt::black, 3));
    p.drawLine(bx, by, bx + bw, by);
    p.drawLine(bx, by - 6, bx, by + 4);
    p.drawLine(bx + bw, by - 6, bx + bw, by + 4);
    p.setPen(Qt::black);
    p.drawText(QPoint(bx, by - 8),
               len >= 1000 ? QStringLiteral("%1 km").arg(len / 1000) : QStringLiteral("%1 m").arg(len));
    // North arrow (the worksite frame is north-up).
    p.drawText(QPoint(size.width() - 30, size.height() - 12), QStringLiteral("N↑"));
    return img;
}

// ---- PDF ----

namespace {

QStringList statsRow(const QString& name, const CoverageStats& s) {
    return {name,
            num(s.areaM2(), 0),
            num(s.coveragePercent(), 1),
            num(s.percentOf(s.under), 1),
            num(s.percentOf(s.atTarget), 1),
            num(s.percentOf(s.over), 1),
            s.covered ? QString::number(s.minPasses) : QStringLiteral("–"),
            s.covered ? num(s.meanPasses, 2) : QStringLiteral("–"),
            s.covered ? QString::number(s.maxPasses) : QStringLiteral("–"),
            QString::number(s.incomplete)};
}

QString filtersText(const osyris::PassCountSettings& st) {
    QStringList f;
    f << (st.vibration == osyris::VibrationFilter::On    ? ReportText::tr("vibration on only")
          : st.vibration == osyris::VibrationFilter::Off ? ReportText::tr("vibration off only")
                                                         : ReportText::tr("vibration on or off"));
    f << (st.direction == osyris::DirectionFilter::Forward    ? ReportText::tr("forward passes only")
          : st.direction == osyris::DirectionFilter::Backward ? ReportText::tr("backward passes only")
                                                              : ReportText::tr("both directions"));
    if (st.speedMin || st.speedMax)
        f << ReportText::tr("speed %1 … %2 m/s")
                 .arg(st.speedMin ? num(*st.speedMin, 2) : QStringLiteral("0"),
                      st.speedMax ? num(*st.speedMax, 2) : QStringLiteral("∞"));
    if (st.timeFrom || st.timeTo)
        f << ReportText::tr("time %1 … %2")
                 .arg(st.timeFrom ? QDateTime::fromMSecsSinceEpoch(*st.timeFrom).toString(Qt::ISODate)
                                  : QStringLiteral("–"),
                      st.timeTo ? QDateTime::fromMSecsSinceEpoch(*st.timeTo).toString(Qt::ISODate)
                                : QStringLiteral("–"));
    if (!st.machines.empty()) {
        QStringList m;
        for (auto i : st.machines)
            m << QString::number(i);
        f << ReportText::tr("machines %1 only").arg(m.join(QStringLiteral(", ")));
    }
    return f.join(QStringLiteral(" · "));
}

} // namespace

QString writeCoveragePdf(const CoverageJob& job, const CoverageFrames& frames, const CoverageTables& t,
                         int lift, const QString& area, const QString& path, QSize mapSize) {
    if (!job.snapshot)
        return ReportText::tr("no pass counts yet");
    const PassCountSnapshot& snap = *job.snapshot;
    {
        QFile probe(path);
        if (!probe.open(QIODevice::WriteOnly))
            return ReportText::tr("cannot write %1: %2").arg(path, probe.errorString());
    }
    QPdfWriter pdf(path);
    pdf.setPageSize(QPageSize(QPageSize::A4));
    pdf.setResolution(150);
    pdf.setPageMargins(QMarginsF(12, 12, 12, 12), QPageLayout::Millimeter);
    pdf.setTitle(ReportText::tr("Compaction coverage report"));
    pdf.setCreator(QStringLiteral("OCU"));
    QPainter p;
    if (!p.begin(&pdf))
        return ReportText::tr("cannot write %1").arg(path);
    p.setRenderHint(QPainter::Antialiasing);
    p.setRenderHint(QPainter::SmoothPixmapTransform);
    PdfPageWriter w(pdf, p, 8.5);
    const int W = w.width();
    w.heading(job.siteName.isEmpty() ? ReportText::tr("Compaction coverage report")
                                     : ReportText::tr("Compaction coverage report — %1").arg(job.siteName),
              15);
    w.text(ReportText::tr("Written %1 · %2 · cell %3 m · target %4–%5 passes")
               .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyy-MM-dd HH:mm")),
                    liftName(snap, lift), num(snap.cellSize(), 2))
               .arg(snap.targetMin())
               .arg(snap.targetMax()));
    w.text(ReportText::tr("CRS: EPSG:%1 (%2) · design: %3")
               .arg(t.epsg)
               .arg(t.crsName, job.design ? QStringLiteral("%1 (%2 alignments, %3 boundaries)")
                                                .arg(job.designPath)
                                                .arg(job.design->alignments.size())
                                                .arg(job.design->boundaries.size())
                                          : ReportText::tr("none")));
    w.text(ReportText::tr("Machines: %1 · data %2")
               .arg(job.machines.isEmpty() ? ReportText::tr("none known")
                                           : job.machines.join(QStringLiteral(", ")),
                    job.dataFrom.isValid()
                        ? ReportText::tr("%1 to %2")
                              .arg(job.dataFrom.toUTC().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss")),
                                   job.dataTo.toUTC().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss 'UTC'")))
                        : ReportText::tr("time range not known")));
    w.text(ReportText::tr("Filters: %1").arg(filtersText(snap.settings())));
    QStringList lifts;
    for (int i = 0; i < snap.liftCount(); ++i)
        lifts << ReportText::tr("%1: z %2 … %3 m")
                     .arg(i + 1)
                     .arg(snap.liftBottom(i), 0, 'f', 2)
                     .arg(snap.liftTop(i), 0, 'f', 2);
    w.text(ReportText::tr("Lifts (thickness %1): %2")
               .arg(snap.settings().liftThickness > 0
                        ? QStringLiteral("%1 m").arg(snap.settings().liftThickness)
                        : ReportText::tr("off"),
                    lifts.isEmpty() ? ReportText::tr("none") : lifts.join(QStringLiteral("; "))));
    // The incomplete statement: always said, one way or the other.
    if (snap.anyIncomplete() || t.whole.incomplete) {
        QStringList gaps;
        for (const auto& [idx, ranges] : snap.givenUp())
            gaps << ReportText::tr("machine %1: %2 slot ranges").arg(idx).arg(ranges.size());
        w.text(ReportText::tr("INCOMPLETE: %1 cells may be under-counted: ribbon data that never arrived was "
                              "given up (%2). "
                              "Their counts are lower bounds.")
                   .arg(t.whole.incomplete)
                   .arg(gaps.join(QStringLiteral(", "))));
    } else {
        w.text(ReportText::tr(
            "Complete: every ribbon slot of every machine was received; no cell is marked incomplete."));
    }
    for (const QString& prob : t.problems)
        w.text(ReportText::tr("Note: %1").arg(prob));
    w.y() += 8;
    const QImage map = renderCoverageMap(job, frames, lift, area, mapSize);
    const QImage scaled = map.scaled(W, W * 5 / 8, Qt::KeepAspectRatio, Qt::SmoothTransformation);
    w.need(scaled.height());
    p.drawImage(QPoint((W - scaled.width()) / 2, w.y()), scaled);
    p.setPen(QColor(0x80, 0x80, 0x80));
    p.drawRect(QRect((W - scaled.width()) / 2, w.y(), scaled.width(), scaled.height()));
    p.setPen(Qt::black);
    w.y() += scaled.height() + 10;

    const QStringList header{ReportText::tr("Area"),      ReportText::tr("m²"),   ReportText::tr("covered %"),
                             ReportText::tr("under %"),   ReportText::tr("at %"), ReportText::tr("over %"),
                             ReportText::tr("min"),       ReportText::tr("mean"), ReportText::tr("max"),
                             ReportText::tr("incomplete")};
    const QVector<double> widths{0.19, 0.08, 0.11, 0.09, 0.08, 0.09, 0.06, 0.08, 0.06, 0.13};
    w.heading(ReportText::tr("Statistics per area"), 11);
    QVector<QStringList> rows;
    rows << statsRow(ReportText::tr("All counted cells"), t.whole);
    for (const AreaStats& a : t.areas)
        rows << statsRow(a.name, a.stats);
    w.table(header, rows, widths, {3});
    w.text(ReportText::tr(
        "Cells belong to an area when their centre lies inside it. covered = at least one pass; "
        "under/at/over "
        "the target as % of the area's cells; min/mean/max over covered cells."));
    if (!t.stations.isEmpty()) {
        w.y() += 6;
        w.heading(
            ReportText::tr("Statistics per station range — %1, %2 m left to %3 m right of the centre line")
                .arg(t.alignment)
                .arg(job.bandLeft)
                .arg(job.bandRight),
            11);
        QVector<QStringList> srows;
        QStringList sh = header;
        sh[0] = ReportText::tr("Stations");
        for (const auto& b : t.stations)
            srows << statsRow(
                QStringLiteral("%1 – %2").arg(QString::fromStdString(landxml::formatStation(b.from, 0)),
                                              QString::fromStdString(landxml::formatStation(b.to, 0))),
                b.stats);
        w.table(sh, srows, widths, {3});
    }
    p.end();
    return {};
}

// ---- all together ----

QJsonObject writeCoverageReport(const CoverageJob& job, const CoverageReportRequest& r) {
    QJsonObject o;
    QJsonObject written{
        {QStringLiteral("pdf"), false}, {QStringLiteral("csv"), false}, {QStringLiteral("geotiff"), false}};
    QJsonArray errors;
    auto finish = [&](const QString& msg) {
        o[QStringLiteral("written")] = written;
        o[QStringLiteral("errors")] = errors;
        const bool asked = !r.pdf.isEmpty() || !r.csv.isEmpty() || !r.geotiff.isEmpty();
        o[QStringLiteral("ok")] = asked && errors.isEmpty();
        o[QStringLiteral("message")] =
            msg.isEmpty()
                ? (errors.isEmpty() ? ReportText::tr("coverage report written") : errors.first().toString())
                : msg;
        return o;
    };
    if (r.pdf.isEmpty() && r.csv.isEmpty() && r.geotiff.isEmpty())
        errors << ReportText::tr("give \"pdf\", \"csv\" and/or \"geotiff\" (file names)");
    if (!job.snapshot) {
        errors << ReportText::tr("no pass counts yet (no OSYRIS station, or nothing counted)");
        return finish({});
    }
    CoverageFrames frames;
    if (const QString e = frames.init(job); !e.isEmpty()) {
        errors << e;
        return finish({});
    }
    if (!r.area.isEmpty() && !findArea(job, r.area)) {
        errors << ReportText::tr("no area named \"%1\"").arg(r.area);
        return finish({});
    }
    const int lift = r.lift;
    if (lift != -1 && lift != kAllLifts && (lift < 0 || lift >= job.snapshot->liftCount())) {
        errors << ReportText::tr("no lift %1 (the data has %2)").arg(lift + 1).arg(job.snapshot->liftCount());
        return finish({});
    }
    const CoverageTables t = computeCoverageTables(job, frames, lift, r.area);
    o[QStringLiteral("epsg")] = t.epsg;
    o[QStringLiteral("crs")] = t.crsName;
    o[QStringLiteral("cells")] = double(t.whole.covered);
    o[QStringLiteral("incomplete_cells")] = double(t.whole.incomplete);
    o[QStringLiteral("lifts")] = job.snapshot->liftCount();
    QJsonArray areas;
    for (const AreaStats& a : t.areas)
        areas << QJsonObject{{QStringLiteral("name"), a.name},
                             {QStringLiteral("cells"), double(a.stats.cells)},
                             {QStringLiteral("coverage_pct"), a.stats.coveragePercent()},
                             {QStringLiteral("at_target_pct"), a.stats.percentOf(a.stats.atTarget)},
                             {QStringLiteral("incomplete"), double(a.stats.incomplete)}};
    o[QStringLiteral("areas")] = areas;
    o[QStringLiteral("station_ranges")] = int(t.stations.size());
    if (job.dataFrom.isValid()) { // the counted data's time range (UTC, ISO 8601)
        o[QStringLiteral("data_from")] = job.dataFrom.toUTC().toString(Qt::ISODate);
        o[QStringLiteral("data_to")] = job.dataTo.toUTC().toString(Qt::ISODate);
    }
    if (!r.csv.isEmpty()) {
        qint64 rows = 0;
        const QString e = writeCoverageCsv(job, frames, lift == -1 ? kAllLifts : lift, r.area, r.csv, &rows);
        if (e.isEmpty()) {
            written[QStringLiteral("csv")] = true;
            o[QStringLiteral("csv_rows")] = double(rows);
        } else {
            errors << e;
        }
    }
    if (!r.geotiff.isEmpty()) {
        double dev = 0;
        const QString e = writeCoverageGeoTiff(job, frames, lift, r.geotiff, &dev);
        if (e.isEmpty()) {
            written[QStringLiteral("geotiff")] = true;
            o[QStringLiteral("geotiff_affine_deviation_m")] = dev;
        } else {
            errors << e;
        }
    }
    if (!r.pdf.isEmpty()) {
        const QString e = writeCoveragePdf(job, frames, t, lift, r.area, r.pdf, r.mapSize);
        if (e.isEmpty())
            written[QStringLiteral("pdf")] = true;
        else
            errors << e;
    }
    return finish({});
}

} // namespace ocu
