// The 2D map's background raster. Small rasters written here with GDAL (a GeoTIFF in WGS84, one
// in UTM, an MBTiles file in Web Mercator) must land at the right site position; bad or missing files give a
// message naming the file and the reason, a failure signal, and keep the background that was good.
#include "models/FleetModel.h"
#include "models/FleetSelection.h"
#include "widgets/MapBackground.h"
#include "widgets/SiteMapView.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QPainter>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>
#include <cpl_conv.h>
#include <gdal.h>
#include <ogr_srs_api.h>

using namespace ocu;

namespace {
const GeoPoint kOrigin{48.2085, 11.4702, 480.0};

// An RGB raster of `size` px, grey, with a red square of `mark` px whose centre is pixel (mx, my); written
// with the given driver in the given CRS and geotransform.
bool writeRaster(const QString& path, const char* driver, int epsg, const double gt[6], int size, int mx,
                 int my, int mark) {
    GDALAllRegister();
    GDALDriverH mem = GDALGetDriverByName("MEM");
    GDALDatasetH ds = GDALCreate(mem, "", size, size, 3, GDT_Byte, nullptr);
    if (!ds)
        return false;
    GDALSetGeoTransform(ds, const_cast<double*>(gt));
    OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
    OSRImportFromEPSG(srs, epsg);
    char* wkt = nullptr;
    OSRExportToWkt(srs, &wkt);
    GDALSetProjection(ds, wkt);
    CPLFree(wkt);
    OSRDestroySpatialReference(srs);
    std::vector<unsigned char> r(size_t(size) * size, 128), g = r, b = r;
    for (int y = my - mark / 2; y < my + (mark + 1) / 2; ++y)
        for (int x = mx - mark / 2; x < mx + (mark + 1) / 2; ++x) {
            r[size_t(y) * size + x] = 255;
            g[size_t(y) * size + x] = 0;
            b[size_t(y) * size + x] = 0;
        }
    bool ok = true;
    int band = 1;
    for (auto* v : {&r, &g, &b})
        ok = ok && GDALRasterIO(GDALGetRasterBand(ds, band++), GF_Write, 0, 0, size, size, v->data(), size,
                                size, GDT_Byte, 0, 0) == CE_None;
    GDALDatasetH out = GDALCreateCopy(GDALGetDriverByName(driver), path.toUtf8().constData(), ds, FALSE,
                                      nullptr, nullptr, nullptr);
    ok = ok && out;
    if (out)
        GDALClose(out);
    GDALClose(ds);
    return ok;
}

// Transforms a WGS84 lat/lon into the given EPSG (x, y).
QPointF project(int epsg, double lat, double lon) {
    OGRSpatialReferenceH wgs = OSRNewSpatialReference(nullptr), dst = OSRNewSpatialReference(nullptr);
    OSRImportFromEPSG(wgs, 4326);
    OSRImportFromEPSG(dst, epsg);
    OSRSetAxisMappingStrategy(wgs, OAMS_TRADITIONAL_GIS_ORDER);
    OSRSetAxisMappingStrategy(dst, OAMS_TRADITIONAL_GIS_ORDER);
    OGRCoordinateTransformationH ct = OCTNewCoordinateTransformation(wgs, dst);
    double x = lon, y = lat;
    OCTTransform(ct, 1, &x, &y, nullptr);
    OCTDestroyCoordinateTransformation(ct);
    OSRDestroySpatialReference(wgs);
    OSRDestroySpatialReference(dst);
    return {x, y};
}

bool isRed(QColor c) {
    return c.alpha() > 200 && c.red() > 200 && c.green() < 60 && c.blue() < 60;
}
bool isGrey(QColor c) {
    return c.alpha() > 200 && std::abs(c.red() - 128) < 20 && std::abs(c.green() - 128) < 20;
}
} // namespace

class TestMapBackground : public QObject {
    Q_OBJECT
    QTemporaryDir dir;

private slots:
    void initTestCase() {
        // The default disk cache goes into the test's directory, never the user's home.
        qputenv("OCU_TILE_CACHE_DIR", dir.filePath(QStringLiteral("default-cache")).toUtf8());
    }

    void geotiffInWgs84IsPlacedInTheSiteFrame() {
        // 400 x 400 px over 0.008° x 0.008° around the origin; the mark 200 m east and 150 m north of it.
        const GeoFrame frame(kOrigin);
        const GeoPoint markGeo = frame.toGeodetic({200, 150, 0});
        const double px = 0.008 / 400;
        const double gt[6] = {kOrigin.lon - 0.004, px, 0, kOrigin.lat + 0.004, 0, -px};
        const int mx = int((markGeo.lon - gt[0]) / px), my = int((gt[3] - markGeo.lat) / px);
        const QString path = dir.filePath(QStringLiteral("wgs84.tif"));
        QVERIFY(writeRaster(path, "GTiff", 4326, gt, 400, mx, my, 6));
        const auto r = MapBackground::load(path, frame);
        QVERIFY2(r.background, qPrintable(r.error));
        const auto& bg = *r.background;
        // The mark's centre pixel, in site metres (a pixel is ~1.5 m x 2.2 m).
        const GeoPoint c{gt[3] - (my + 0.0) * px, gt[0] + (mx + 0.0) * px, 0};
        const EnuPoint e = frame.toLocal({c.lat, c.lon, kOrigin.alt});
        QVERIFY2(isRed(bg.colorAt({e.e, e.n})), qPrintable(bg.colorAt({e.e, e.n}).name()));
        QVERIFY(isGrey(bg.colorAt({e.e + 25, e.n})));
        QVERIFY(isGrey(bg.colorAt({e.e, e.n - 25})));
        QVERIFY(isGrey(bg.colorAt({0, 0})));
        // Bounds: about ±300 m east-west and ±445 m north-south around the origin.
        QVERIFY(std::abs(bg.bounds().center().x()) < 5 && std::abs(bg.bounds().center().y()) < 5);
        QVERIFY(std::abs(bg.bounds().width() - 594) < 10);
        QVERIFY(std::abs(bg.bounds().height() - 890) < 10);
        QVERIFY(!bg.colorAt({2000, 0}).isValid() || bg.colorAt({2000, 0}).alpha() == 0);
    }

    void geotiffInUtmIsReprojected() {
        const GeoFrame frame(kOrigin);
        const GeoPoint markGeo = frame.toGeodetic({-250, 120, 0});
        const QPointF o = project(32632, kOrigin.lat, kOrigin.lon),
                      m = project(32632, markGeo.lat, markGeo.lon);
        const double gt[6] = {std::floor(o.x()) - 500, 2.0, 0, std::floor(o.y()) + 500, 0, -2.0};
        const int mx = int((m.x() - gt[0]) / 2.0), my = int((gt[3] - m.y()) / 2.0);
        const QString path = dir.filePath(QStringLiteral("utm.tif"));
        QVERIFY(writeRaster(path, "GTiff", 32632, gt, 500, mx, my, 4));
        const auto r = MapBackground::load(path, frame);
        QVERIFY2(r.background, qPrintable(r.error));
        // UTM grid north differs from true north here by ~1°: placed right only if really reprojected.
        const double cx = gt[0] + (mx + 0.0) * 2.0, cy = gt[3] - (my + 0.0) * 2.0;
        Q_UNUSED(cx);
        Q_UNUSED(cy);
        QVERIFY2(isRed(r.background->colorAt({-250, 120})),
                 qPrintable(r.background->colorAt({-250, 120}).name()));
        QVERIFY(isGrey(r.background->colorAt({-250 + 12, 120})));
        QVERIFY(isGrey(r.background->colorAt({-250, 120 + 12})));
    }

    void mbtilesIsPlacedInTheSiteFrame() {
        const GeoFrame frame(kOrigin);
        const GeoPoint markGeo = frame.toGeodetic({150, -100, 0});
        const QPointF o = project(3857, kOrigin.lat, kOrigin.lon),
                      m = project(3857, markGeo.lat, markGeo.lon);
        // Web Mercator metres are ~1.5 ground metres here; 3 m pixels.
        const double gt[6] = {o.x() - 600, 3.0, 0, o.y() + 600, 0, -3.0};
        const int mx = int((m.x() - gt[0]) / 3.0), my = int((gt[3] - m.y()) / 3.0);
        const QString path = dir.filePath(QStringLiteral("site.mbtiles"));
        QVERIFY(writeRaster(path, "MBTiles", 3857, gt, 400, mx, my, 8));
        const auto r = MapBackground::load(path, frame);
        QVERIFY2(r.background, qPrintable(r.error));
        QVERIFY2(isRed(r.background->colorAt({150, -100})),
                 qPrintable(r.background->colorAt({150, -100}).name()));
        QVERIFY(isGrey(r.background->colorAt({150 + 30, -100})));
        QVERIFY(isGrey(r.background->colorAt({0, 0})));
    }

    void viewDrawsTheBackgroundAtTheRightPixels() {
        const GeoFrame frame(kOrigin);
        const GeoPoint markGeo = frame.toGeodetic({200, 150, 0});
        const double px = 0.008 / 400;
        const double gt[6] = {kOrigin.lon - 0.004, px, 0, kOrigin.lat + 0.004, 0, -px};
        const int mx = int((markGeo.lon - gt[0]) / px), my = int((gt[3] - markGeo.lat) / px);
        const QString path = dir.filePath(QStringLiteral("view.tif"));
        QVERIFY(writeRaster(path, "GTiff", 4326, gt, 400, mx, my, 10));
        SiteMapView v;
        v.resize(800, 600);
        v.setGeoFrame(frame);
        QSignalSpy loaded(&v, &SiteMapView::backgroundLoaded);
        v.loadBackground(path);
        QTRY_COMPARE_WITH_TIMEOUT(loaded.size(), 1, 30000);
        QVERIFY(v.background());
        const EnuPoint e = frame.toLocal({gt[3] - my * px, gt[0] + mx * px, kOrigin.alt});
        for (double scale : {0.5, 2.0, 8.0}) { // different pyramid levels
            v.setView({e.e, e.n}, scale);
            QImage img(800, 600, QImage::Format_ARGB32_Premultiplied);
            QPainter p(&img);
            v.paintScene(p, img.size());
            p.end();
            const QPoint c = v.worldToScreen({e.e, e.n}).toPoint();
            QVERIFY2(isRed(img.pixel(c)),
                     qPrintable(QStringLiteral("scale %1: %2").arg(scale).arg(QColor(img.pixel(c)).name())));
            const QPoint off = v.worldToScreen({e.e + 25, e.n + 25}).toPoint(); // beyond the 15 m mark
            QVERIFY(isGrey(img.pixel(off)));
        }
        v.setBackgroundVisible(false);
        QImage img(800, 600, QImage::Format_ARGB32_Premultiplied);
        QPainter p(&img);
        v.paintScene(p, img.size());
        p.end();
        QVERIFY(!isRed(img.pixel(400, 300)));
    }

    void badFilesGiveAClearMessageNotACrash() {
        const GeoFrame frame(kOrigin);
        // Missing.
        auto r = MapBackground::load(dir.filePath(QStringLiteral("missing.tif")), frame);
        QVERIFY(!r.background);
        QVERIFY2(r.error.contains(QLatin1String("missing.tif")) &&
                     r.error.contains(QLatin1String("no such file")),
                 qPrintable(r.error));
        // Not a raster at all.
        const QString junk = dir.filePath(QStringLiteral("junk.tif"));
        {
            QFile f(junk);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("II*\0this is not really a tiff at all, just bytes", 48);
        }
        r = MapBackground::load(junk, frame);
        QVERIFY(!r.background);
        QVERIFY2(r.error.contains(QLatin1String("junk.tif")), qPrintable(r.error));
        // A truncated copy of a good GeoTIFF.
        const double gt[6] = {kOrigin.lon - 0.004, 0.00002, 0, kOrigin.lat + 0.004, 0, -0.00002};
        const QString good = dir.filePath(QStringLiteral("good.tif"));
        QVERIFY(writeRaster(good, "GTiff", 4326, gt, 400, 200, 200, 4));
        QFile g(good);
        QVERIFY(g.open(QIODevice::ReadOnly));
        const QByteArray bytes = g.readAll();
        const QString cut = dir.filePath(QStringLiteral("cut.tif"));
        {
            QFile f(cut);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(bytes.left(bytes.size() / 3));
        }
        r = MapBackground::load(cut, frame); // either refused or loaded with what is there: never a crash
        if (!r.background)
            QVERIFY(r.error.contains(QLatin1String("cut.tif")));
        // Without georeferencing.
        const QString plain = dir.filePath(QStringLiteral("plain.tif"));
        {
            GDALDatasetH ds = GDALCreate(GDALGetDriverByName("GTiff"), plain.toUtf8().constData(), 50, 50, 1,
                                         GDT_Byte, nullptr);
            QVERIFY(ds);
            GDALClose(ds);
        }
        r = MapBackground::load(plain, frame);
        QVERIFY(!r.background);
        QVERIFY2(r.error.contains(QLatin1String("georeferencing")), qPrintable(r.error));
        // A raster far from the site (a wrong CRS or site): refused, not a 10,000 km warp.
        const double far[6] = {-70, 0.01, 0, -30, 0, -0.01};
        const QString farPath = dir.filePath(QStringLiteral("far.tif"));
        QVERIFY(writeRaster(farPath, "GTiff", 4326, far, 100, 50, 50, 4));
        r = MapBackground::load(farPath, frame);
        QVERIFY(!r.background);
        QVERIFY2(!r.error.isEmpty(), "far raster accepted");

        // Through the view: the failure signal, and the good background stays.
        SiteMapView v;
        v.setGeoFrame(frame);
        QSignalSpy loaded(&v, &SiteMapView::backgroundLoaded);
        QSignalSpy failed(&v, &SiteMapView::backgroundFailed);
        v.loadBackground(good);
        QTRY_COMPARE_WITH_TIMEOUT(loaded.size(), 1, 30000);
        const auto before = v.background();
        v.loadBackground(junk);
        QTRY_COMPARE_WITH_TIMEOUT(failed.size(), 1, 30000);
        QVERIFY(failed.at(0).at(0).toString().contains(QLatin1String("junk.tif")));
        QCOMPARE(v.background(), before);
        QImage img(400, 300, QImage::Format_ARGB32_Premultiplied);
        QPainter p(&img);
        v.paintScene(p, img.size()); // still paints
    }

    // Warped once and cached as tiles: the second load (a restart) reads the tiles back from the
    // disk cache, identical to the warped ones; a changed file, another site origin or a corrupt entry warps
    // again (and a corrupt entry is replaced, never a crash); the cache stays within its size bound.
    void tilesAreCachedOnDisk() {
        const GeoFrame frame(kOrigin);
        const GeoPoint markGeo = frame.toGeodetic({-120, 80, 0});
        const double px = 0.012 / 600;
        const double gt[6] = {kOrigin.lon - 0.006, px, 0, kOrigin.lat + 0.006, 0, -px};
        const int mx = int((markGeo.lon - gt[0]) / px), my = int((gt[3] - markGeo.lat) / px);
        const QString path = dir.filePath(QStringLiteral("cached.tif"));
        QVERIFY(writeRaster(path, "GTiff", 4326, gt, 600, mx, my, 8));
        const QString cacheDir = dir.filePath(QStringLiteral("tile-cache"));

        const auto first = MapBackground::load(path, frame, cacheDir);
        QVERIFY2(first.background, qPrintable(first.error));
        QVERIFY(!first.fromCache);
        const QString key =
            MapTileCache::keyFor(path, frame, MapBackground::kMaxSidePx, MapBackground::kTilePx);
        QVERIFY(!key.isEmpty());
        const QString entry = MapTileCache(cacheDir).entryPath(key);
        QVERIFY(QFile::exists(entry + QStringLiteral("/meta.json")));

        auto sameAsFirst = [&](const MapBackground& bg) {
            if (bg.bounds() != first.background->bounds() || bg.sizePx() != first.background->sizePx() ||
                bg.levels() != first.background->levels() ||
                bg.metresPerPixel() != first.background->metresPerPixel())
                return false;
            // Every 7th level-0 pixel the same, and the mark where it was.
            const QRectF b = bg.bounds();
            const double m = bg.metresPerPixel();
            for (double n = b.top() + m / 2; n < b.bottom(); n += 7 * m)
                for (double e = b.left() + m / 2; e < b.right(); e += 7 * m)
                    if (bg.colorAt({e, n}) != first.background->colorAt({e, n}))
                        return false;
            return true;
        };
        const auto second = MapBackground::load(path, frame, cacheDir);
        QVERIFY2(second.background, qPrintable(second.error));
        QVERIFY(second.fromCache);
        QVERIFY(sameAsFirst(*second.background));
        const EnuPoint e = frame.toLocal({gt[3] - my * px, gt[0] + mx * px, kOrigin.alt});
        QVERIFY(isRed(second.background->colorAt({e.e, e.n})));
        // The tiles it draws are the cached ones.
        QImage a(500, 400, QImage::Format_ARGB32_Premultiplied),
            b(500, 400, QImage::Format_ARGB32_Premultiplied);
        a.fill(Qt::black);
        b.fill(Qt::black);
        for (double scale : {0.2, 1.0, 3.0}) {
            QPainter pa(&a), pb(&b);
            QVERIFY(first.background->draw(pa, {e.e, e.n}, scale, a.size()) > 0);
            QVERIFY(second.background->draw(pb, {e.e, e.n}, scale, b.size()) > 0);
        }
        QCOMPARE(a, b);

        // Another site origin: another entry.
        const GeoFrame moved(GeoPoint{kOrigin.lat + 0.001, kOrigin.lon, kOrigin.alt});
        QVERIFY(MapTileCache::keyFor(path, moved, MapBackground::kMaxSidePx, MapBackground::kTilePx) != key);
        QVERIFY(!MapBackground::load(path, moved, cacheDir).fromCache);

        // A corrupt tile: discarded, warped again, the entry rewritten and good again.
        QFile tile(entry + QStringLiteral("/L0_0_0.png"));
        QVERIFY(tile.open(QIODevice::WriteOnly | QIODevice::Truncate));
        tile.write("\x89PNG this is not a png");
        tile.close();
        const auto afterCorruptTile = MapBackground::load(path, frame, cacheDir);
        QVERIFY2(afterCorruptTile.background, qPrintable(afterCorruptTile.error));
        QVERIFY(!afterCorruptTile.fromCache);
        QVERIFY(sameAsFirst(*afterCorruptTile.background));
        QVERIFY(MapBackground::load(path, frame, cacheDir).fromCache);
        // Corrupt or hostile meta data: not JSON, absurd sizes, a missing tile.
        for (const QByteArray& meta :
             {QByteArray("{not json"),
              QByteArray("{\"version\":1,\"tile\":256,\"bounds\":[0,0,1,1],\"mpp\":1,"
                         "\"width\":100000000,\"height\":1,\"levels\":[]}"),
              QByteArray("[]"), QByteArray()}) {
            QFile f(entry + QStringLiteral("/meta.json"));
            QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
            f.write(meta);
            f.close();
            const auto r = MapBackground::load(path, frame, cacheDir);
            QVERIFY2(r.background, qPrintable(r.error));
            QVERIFY2(!r.fromCache, meta.constData());
            QVERIFY(sameAsFirst(*r.background));
        }
        QVERIFY(QFile::remove(entry + QStringLiteral("/L0_1_1.png")));
        QVERIFY(!MapBackground::load(path, frame, cacheDir).fromCache);
        QVERIFY(MapBackground::load(path, frame, cacheDir).fromCache);

        // The source file changed (size and time): a new key, the new picture.
        QTest::qWait(20);
        QVERIFY(writeRaster(path, "GTiff", 4326, gt, 600, 300, 300, 30));
        {
            QFile f(path);
            QVERIFY(f.open(QIODevice::ReadWrite));
            QVERIFY(
                f.setFileTime(QDateTime::currentDateTimeUtc().addSecs(5), QFileDevice::FileModificationTime));
        }
        QVERIFY(MapTileCache::keyFor(path, frame, MapBackground::kMaxSidePx, MapBackground::kTilePx) != key);
        const auto changed = MapBackground::load(path, frame, cacheDir);
        QVERIFY(changed.background && !changed.fromCache);
        QVERIFY(!isRed(changed.background->colorAt({e.e, e.n})));

        // Bounded: trimmed to 1 byte, nothing stays.
        const qint64 oneEntry = MapTileCache(cacheDir, 1ll << 40).trim();
        QVERIFY(oneEntry > 0);
        const qint64 kept = MapTileCache(cacheDir, 1).trim();
        QCOMPARE(kept, qint64(0));
        QVERIFY(QDir(cacheDir).entryList(QDir::Dirs | QDir::NoDotAndDotDot).isEmpty());
        // An unwritable cache directory: still loads (no cache), no crash.
        const QString file = dir.filePath(QStringLiteral("not-a-dir"));
        {
            QFile f(file);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("x");
        }
        const auto noCache = MapBackground::load(path, frame, file + QStringLiteral("/sub"));
        QVERIFY(noCache.background && !noCache.fromCache);
    }
};

QTEST_MAIN(TestMapBackground)
#include "test_map_background.moc"
