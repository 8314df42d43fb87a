// The simulated pit's DEM agrees with the map the AHS serves (every road and area node lies
// on the ground), has benches and a ramp, and is written as georeferenced GeoTIFFs (DEM and hillshade) that
// GDAL reads back at the right place.
#include "sim/iso23725/PitTerrain.h"

#include <QTemporaryDir>
#include <QTest>
#include <cmath>
#include <gdal.h>
#include <set>

using namespace ocu;
using namespace ocu::sim;

class TestPitTerrain : public QObject {
    Q_OBJECT
private slots:
    void demAgreesWithTheMap() {
        const PitLayout layout{2, 2, {48.2085, 11.4702, 480.0}};
        const PitMap pit = generatePitMap(layout, 0);
        const PitTerrainModel model(pit);
        int checked = 0;
        for (const auto& [id, way] : pit.map.ways) {
            if (!way.tag("autonomy:area").empty())
                continue; // the operating zone is a zone, not ground
            for (auto nid : way.nodes) {
                const EnuPoint& p = pit.map.nodes.at(nid).enu;
                const double u = model.up(p.e, p.n);
                QVERIFY2(std::abs(u - p.u) < 0.5,
                         qPrintable(QStringLiteral("%1 node at %2/%3: map %4 m, DEM %5 m")
                                        .arg(QString::fromStdString(way.name()))
                                        .arg(p.e)
                                        .arg(p.n)
                                        .arg(p.u)
                                        .arg(u)));
                ++checked;
            }
        }
        QVERIFY(checked > 50);
        // Benches: walking out of the pit to the south, the ground rises in 10 m steps with flat berms.
        std::set<int> berms;
        double last = model.up(-150, -480);
        QCOMPARE(last, -60.0);
        for (double n = -480; n > -800; n -= 1) {
            const double u = model.up(-150, n);
            QVERIFY(u >= last - 1e-9); // never down on the way out
            if (std::abs(u - std::round(u / 10) * 10) < 1e-6)
                berms.insert(int(std::round(u)));
            last = u;
        }
        QCOMPARE(last, 0.0);
        QCOMPARE(int(berms.size()), 7); // floor, five berms, surface
        // The ramp: its lanes descend steadily; beside the ramp the benches step.
        const auto lane = pit.wayPoints(pit.rampDown, false);
        for (std::size_t i = 0; i + 1 < lane.size(); ++i)
            QVERIFY(model.up(lane[i + 1].e, lane[i + 1].n) <= model.up(lane[i].e, lane[i].n) + 1e-9);
    }

    void writesGeoreferencedDemAndHillshade() {
        QTemporaryDir dir;
        const PitLayout layout{2, 2, {48.2085, 11.4702, 480.0}};
        const PitMap pit = generatePitMap(layout, 0);
        const auto files = writePitTerrain(pit, layout.origin, dir.path().toStdString(), 4.0);
        QVERIFY2(files.error.empty(), files.error.c_str());
        QVERIFY(files.dem.ends_with("pit_dem.tif") && files.hillshade.ends_with("pit_hillshade.tif"));
        GDALAllRegister();
        GDALDatasetH dem = GDALOpen(files.dem.c_str(), GA_ReadOnly);
        QVERIFY(dem);
        QVERIFY(std::string(GDALGetProjectionRef(dem)).find("Orthographic") != std::string::npos);
        double gt[6];
        QCOMPARE(GDALGetGeoTransform(dem, gt), CE_None);
        QCOMPARE(gt[1], 4.0);
        // The ground height (above the ellipsoid) at the loading area of shovel 1 and at the hub.
        auto sample = [&](double e, double n) {
            const int x = int((e - gt[0]) / gt[1]), y = int((n - gt[3]) / gt[5]);
            float v = 0;
            if (GDALRasterIO(GDALGetRasterBand(dem, 1), GF_Read, x, y, 1, 1, &v, 1, 1, GDT_Float32, 0, 0) !=
                CE_None)
                return -1e9;
            return double(v);
        };
        const auto& area = pit.map.ways.at(pit.loadAreas[0]);
        const EnuPoint c = pit.map.nodes.at(area.nodes[0]).enu;
        QVERIFY(std::abs(sample(c.e + 20, c.n + 20) - (480.0 - 60.0)) < 0.5);
        QVERIFY(std::abs(sample(0, 200) - 480.0) < 0.5);
        const int w = GDALGetRasterXSize(dem), h = GDALGetRasterYSize(dem);
        GDALClose(dem);
        GDALDatasetH hs = GDALOpen(files.hillshade.c_str(), GA_ReadOnly);
        QVERIFY(hs);
        QCOMPARE(GDALGetRasterXSize(hs), w);
        QCOMPARE(GDALGetRasterYSize(hs), h);
        QCOMPARE(GDALGetRasterDataType(GDALGetRasterBand(hs, 1)), GDT_Byte);
        GDALClose(hs);
        // A second run reuses the files.
        const auto again = writePitTerrain(pit, layout.origin, dir.path().toStdString(), 4.0);
        QVERIFY(again.error.empty());
        QCOMPARE(again.dem, files.dem);
        // A folder that cannot be created: an error, no crash.
        const auto bad = writePitTerrain(pit, layout.origin, "/proc/ocu-no-such/terrain", 4.0);
        QVERIFY(!bad.error.empty());
    }
};

QTEST_MAIN(TestPitTerrain)
#include "test_pit_terrain.moc"
