// The coverage report of a 10 km x 12 m job with 0.34 m cells and 3 lifts (about 3.1 M counted
// cells): statistics (one area over the whole job, 270 station ranges of the shipped design), the CSV of every
// lift through PROJ, the GeoTIFF of the top view through GDAL, and the PDF. Prints wall and CPU time per part
// and in all (target: the whole report in <= 10 s), and the snapshot's memory.
//   bench_coverage_report [output-dir]   (default: a temporary directory, removed afterwards)
#include "models/coverage/CoverageReport.h"
#include "tests/models/coverage/CoverageTestJob.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QGuiApplication>
#include <QTemporaryDir>

#include <cstdio>
#include <ctime>

using namespace ocu;

int main(int argc, char** argv) {
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QGuiApplication app(argc, argv);
    QTemporaryDir tmp;
    const QString dir = argc > 1 ? QString::fromLocal8Bit(argv[1]) : tmp.path();
    testing::HandJob h;
    h.x0 = 0;
    h.x1 = 10000;
    h.y0 = -6;
    h.y1 = 6;
    h.xSplit = h.xThird = 10000; // every lift everywhere
    h.incFrom = 1000;
    h.incTo = 1100;
    QElapsedTimer build;
    build.start();
    CoverageJob job;
    job.snapshot = testing::makeSnapshot(h);
    job.worksiteOrigin = testing::worksiteOrigin();
    if (auto d = landxml::loadLandXml(OCU_SOURCE_DIR "/resources/designs/paving-job.xml"))
        job.design = std::make_shared<landxml::LandXmlDesign>(std::move(d.value()));
    job.designPath = QStringLiteral("paving-job.xml");
    job.siteName = QStringLiteral("Benchmark: 10 km x 12 m, 3 lifts");
    const GeoFrame ws(job.worksiteOrigin);
    CompactionArea all{QStringLiteral("Whole job"), QStringLiteral("drawn"), {}};
    for (auto [x, y] : {std::pair{0.0, -6.0}, {10000.0, -6.0}, {10000.0, 6.0}, {0.0, 6.0}})
        all.ring.push_back(ws.toGeodetic({x, y, 0}));
    job.areas.push_back(all);
    std::size_t cells = 0, tiles = 0;
    for (int l = 0; l < job.snapshot->liftCount(); ++l) {
        tiles += job.snapshot->tiles(l).size();
        job.snapshot->forEachCell(l, [&](std::int32_t, std::int32_t, int, bool) { ++cells; });
    }
    tiles += job.snapshot->tiles().size();
    std::printf("job: %zu counted cells in %d lifts, %zu tiles (%.1f MB of tiles incl. the top view), built in %.1f s\n",
                cells, job.snapshot->liftCount(), tiles,
                double(tiles) * double(sizeof(osyris::PassCountTopTile)) / 1e6, build.elapsed() / 1000.0);

    CoverageFrames frames;
    if (const QString e = frames.init(job); !e.isEmpty()) {
        std::printf("frames: %s\n", qPrintable(e));
        return 1;
    }
    auto part = [&](const char* name, auto&& f) {
        QElapsedTimer t;
        t.start();
        const std::clock_t c0 = std::clock();
        f();
        const double cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;
        std::printf("%-38s wall %6.2f s  cpu %6.2f s\n", name, t.elapsed() / 1000.0, cpu);
    };
    CoverageReportRequest r;
    r.pdf = dir + QStringLiteral("/bench.pdf");
    r.csv = dir + QStringLiteral("/bench.csv");
    r.geotiff = dir + QStringLiteral("/bench.tif");
    r.lift = -1;
    CoverageTables t;
    part("statistics (area + 270 station ranges)", [&] { t = computeCoverageTables(job, frames, -1); });
    qint64 rows = 0;
    part("CSV, every lift (PROJ)", [&] { writeCoverageCsv(job, frames, kAllLifts, {}, r.csv, &rows); });
    part("GeoTIFF, top view (GDAL)", [&] { writeCoverageGeoTiff(job, frames, -1, r.geotiff); });
    part("PDF", [&] { writeCoveragePdf(job, frames, t, -1, {}, r.pdf, r.mapSize); });
    QJsonObject res;
    part("whole report (writeCoverageReport)", [&] { res = writeCoverageReport(job, r); });
    std::printf("result ok=%d, %lld CSV rows (%.0f MB), GeoTIFF %.1f MB, PDF %.1f MB, whole-area coverage %.1f %%\n",
                res.value(QStringLiteral("ok")).toBool() ? 1 : 0, rows, QFileInfo(r.csv).size() / 1e6,
                QFileInfo(r.geotiff).size() / 1e6, QFileInfo(r.pdf).size() / 1e6,
                t.areas.isEmpty() ? 0.0 : t.areas.front().stats.coveragePercent());
    return res.value(QStringLiteral("ok")).toBool() ? 0 : 1;
}
