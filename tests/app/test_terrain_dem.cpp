// The 3D terrain from a DEM read with GDAL. The test writes its own small GeoTIFF (WGS84
// degrees around the site origin: a pit cut into a sloping plain, with a NoData hole), loads it into the
// site frame and checks the heights of the grid and of the 3D scene built from it.
#include "app/TerrainDem.h"
#include "widgets/view3d/SiteSceneRenderer.h"

#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace ocu;

namespace {
constexpr double kLat = 47.0, kLon = 8.0, kAlt = 400.0;
constexpr float kNoData = -9999.0f;

// Height above the ellipsoid at (e, n) of the site frame: a plain rising 5 m per 100 m eastwards with a
// 60 m deep conical pit of radius 300 m at the origin.
double truth(double e, double n) {
    return kAlt + 0.05 * e - 60.0 * std::max(0.0, 1.0 - std::hypot(e, n) / 300.0);
}

// 600 x 600 pixels of 2e-5 degrees (about 1.5 x 2.2 m) centred on the origin; pixels within 20 m of
// (200, 200) are NoData.
QString writeDem(const QString& file, const GeoFrame& frame) {
    GDALAllRegister();
    GDALDriver* drv = GetGDALDriverManager()->GetDriverByName("GTiff");
    const int size = 600;
    const double px = 2e-5;
    std::unique_ptr<GDALDataset> ds(
        drv->Create(file.toUtf8().constData(), size, size, 1, GDT_Float32, nullptr));
    if (!ds)
        return QStringLiteral("cannot create");
    double gt[6] = {kLon - size / 2 * px, px, 0, kLat + size / 2 * px, 0, -px};
    ds->SetGeoTransform(gt);
    OGRSpatialReference srs;
    srs.importFromEPSG(4326);
    ds->SetSpatialRef(&srs);
    std::vector<float> data(static_cast<std::size_t>(size) * size);
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) {
            const GeoPoint g{gt[3] + (j + 0.5) * gt[5], gt[0] + (i + 0.5) * gt[1], 0};
            const EnuPoint p = frame.toLocal(g);
            data[static_cast<std::size_t>(j) * size + i] =
                std::hypot(p.e - 200, p.n - 200) < 20 ? kNoData : static_cast<float>(truth(p.e, p.n));
        }
    GDALRasterBand* b = ds->GetRasterBand(1);
    b->SetNoDataValue(kNoData);
    if (b->RasterIO(GF_Write, 0, 0, size, size, data.data(), size, size, GDT_Float32, 0, 0) != CE_None)
        return QStringLiteral("cannot write");
    return {};
}
} // namespace

class TestTerrainDem : public QObject {
    Q_OBJECT
private slots:
    void pitFromGeoTiff() {
        QTemporaryDir dir;
        const QString file = dir.filePath("pit_dem.tif");
        const GeoFrame frame(GeoPoint{kLat, kLon, kAlt});
        QCOMPARE(writeDem(file, frame), QString());

        auto grid = loadTerrainDem(file.toStdString(), frame, 200);
        QVERIFY2(grid.ok(), grid.ok() ? "" : grid.error().c_str());
        QVERIFY(grid->valid());
        QVERIFY(grid->cols <= 200 && grid->rows <= 200);
        // The raster spans about +-450 m east and +-660 m north of the origin.
        QVERIFY(grid->originE < -400 && grid->originE > -500);
        QVERIFY(grid->originN < -600 && grid->originN > -720);

        // Heights relative to the origin's altitude, resampled: within a metre of the truth away from the
        // hole.
        auto at = [&](double e, double n) {
            const int c = static_cast<int>(std::lround((e - grid->originE) / grid->step));
            const int r = static_cast<int>(std::lround((n - grid->originN) / grid->step));
            const double ge = grid->originE + c * grid->step, gn = grid->originN + r * grid->step;
            return std::pair{grid->u[static_cast<std::size_t>(r) * grid->cols + c], truth(ge, gn) - kAlt};
        };
        for (auto [e, n] : {std::pair{0.0, 0.0}, {150.0, -100.0}, {-350.0, 300.0}, {400.0, -500.0}}) {
            const auto [got, want] = at(e, n);
            QVERIFY2(std::abs(got - want) < 1.0,
                     qPrintable(QStringLiteral("(%1, %2): %3 vs %4").arg(e).arg(n).arg(got).arg(want)));
        }
        QVERIFY(at(0, 0).first < -58.0); // the pit floor is 60 m down
        // The NoData hole is filled with a finite height; every sample is finite.
        for (double u : grid->u)
            QVERIFY(std::isfinite(u));

        // The 3D scene stands on it: the renderer's terrain height follows the DEM (machines and draped
        // layers use this height).
        SiteSceneRenderer scene;
        Scene3D s;
        s.terrain.grid = grid.value();
        Way3D road;
        road.points = {{-300, 0, 0}, {0, 0, 0}, {300, 0, 0}};
        s.ways.push_back(road);
        scene.setScene(s);
        for (auto [e, n] : {std::pair{0.0, 0.0}, {120.0, 80.0}, {-250.0, -40.0}})
            QVERIFY(std::abs(scene.terrainHeight(e, n) - (truth(e, n) - kAlt)) < 1.5);
    }

    void unusableDemIsRefusedWithReason() {
        QTemporaryDir dir;
        const GeoFrame frame(GeoPoint{kLat, kLon, kAlt});
        auto missing = loadTerrainDem(dir.filePath("none.tif").toStdString(), frame);
        QVERIFY(!missing.ok());
        QVERIFY(missing.error().find("cannot open") != std::string::npos);
        // A raster without geo-referencing cannot be placed in the site frame.
        const QString plain = dir.filePath("plain.tif");
        {
            GDALAllRegister();
            std::unique_ptr<GDALDataset> ds(GetGDALDriverManager()->GetDriverByName("GTiff")->Create(
                plain.toUtf8().constData(), 8, 8, 1, GDT_Float32, nullptr));
            QVERIFY(ds != nullptr);
        }
        auto noGeo = loadTerrainDem(plain.toStdString(), frame);
        QVERIFY(!noGeo.ok());
        QVERIFY2(noGeo.error().find("geotransform") != std::string::npos ||
                     noGeo.error().find("coordinate reference") != std::string::npos,
                 noGeo.error().c_str());
        // A text file is no raster.
        QFile text(dir.filePath("dem.tif"));
        QVERIFY(text.open(QIODevice::WriteOnly));
        text.write("not a tiff");
        text.close();
        QVERIFY(!loadTerrainDem(text.fileName().toStdString(), frame).ok());
    }
};

QTEST_MAIN(TestTerrainDem)
#include "test_terrain_dem.moc"
