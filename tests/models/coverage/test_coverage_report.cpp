// The coverage report of a hand-made three-lift job on the simulated road with the shipped
// design: the CSV re-read with every coordinate taken back through the CRS (PROJ, a separate instance) and
// the worksite frame to its cell centre within 1 mm; the GeoTIFF read back with GDAL (size, geotransform,
// EPSG, known cell values, nodata); the PDF's first page rendered with pdftoppm and checked for content;
// per-area and per-station statistics; a truthful result when something cannot be written.
#include "models/coverage/CoverageReport.h"
#include "protocols/site/CrsTransform.h"
#include "tests/models/coverage/CoverageTestJob.h"

#include <QFile>
#include <QImage>
#include <QJsonArray>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <gdal_priv.h>
#include <ogr_spatialref.h>

using namespace ocu;
using namespace ocu::testing;

namespace {

CoverageJob makeJob(const HandJob& h) {
    CoverageJob job;
    job.snapshot = makeSnapshot(h);
    job.worksiteOrigin = worksiteOrigin();
    auto d = landxml::loadLandXml(OCU_SOURCE_DIR "/resources/designs/paving-job.xml");
    if (d)
        job.design = std::make_shared<landxml::LandXmlDesign>(std::move(d.value()));
    job.designPath = QStringLiteral("paving-job.xml");
    job.siteName = QStringLiteral("Test job");
    job.machines = {QStringLiteral("Roller 1"), QStringLiteral("Roller 2")};
    // A drawn area: the local rectangle x 45..60, y -2..2 (whole cells: 44.2 .. 60.18 are not cell edges, so
    // the count is taken by centre below).
    const GeoFrame ws(job.worksiteOrigin);
    CompactionArea drawn{QStringLiteral("Box"), QStringLiteral("drawn"), {}};
    for (auto [x, y] : {std::pair{45.0, -2.0}, {60.0, -2.0}, {60.0, 2.0}, {45.0, 2.0}}) {
        const GeoPoint g = ws.toGeodetic({x, y, 0});
        drawn.ring.push_back(g);
    }
    job.areas.push_back(drawn);
    // The design's boundary as an area (its vertices through PROJ to WGS 84).
    auto crs = CrsTransform::fromWgs84To(32632);
    CompactionArea bnd{QStringLiteral("Paving area"), QStringLiteral("design"), {}};
    for (const auto& p : job.design->boundaries.front().points) {
        double lat = 0, lon = 0;
        crs->toGeographic(p.e, p.n, lat, lon);
        bnd.ring.push_back({lat, lon, 0});
    }
    job.areas.push_back(bnd);
    return job;
}

QVector<QByteArray> split(const QByteArray& line) {
    QVector<QByteArray> out;
    for (const QByteArray& f : line.split(','))
        out << f;
    return out;
}

} // namespace

class TestCoverageReport : public QObject {
    Q_OBJECT
private slots:
    void statistics() {
        const HandJob h;
        const CoverageJob job = makeJob(h);
        QVERIFY(job.design);
        CoverageFrames f;
        QCOMPARE(f.init(job), QString());
        QCOMPARE(f.epsg(), 32632); // the design's EPSG
        // Lift 0 in the drawn box: cells with centres in x 45..60, y -2..2; every one has 1 + (cx % 4)
        // passes.
        const CoverageTables t = computeCoverageTables(job, f, 0, QStringLiteral("Box"));
        QCOMPARE(t.areas.size(), 1);
        const auto& s = t.areas[0].stats;
        int cells = 0, at = 0, sum = 0;
        for (int cy = -10; cy < 10; ++cy)
            for (int cx = 120; cx < 190; ++cx) {
                // The box's corners went through the geodetic position and back: compare by centre with a
                // margin-free rule only where the centre is clearly inside (>= 1 mm from an edge).
                const double x = (cx + 0.5) * h.cell, y = (cy + 0.5) * h.cell;
                if (x > 45 && x < 60 && y > -2 && y < 2) {
                    ++cells;
                    const int c = countIn(h, 0, cx, cy);
                    sum += c;
                    at += (c >= 3 && c <= 5);
                }
            }
        QCOMPARE(int(s.cells), cells);
        QCOMPARE(int(s.covered), cells);
        QCOMPARE(int(s.atTarget), at);
        QCOMPARE(s.minPasses, 1);
        QCOMPARE(s.maxPasses, 4);
        QVERIFY(std::fabs(s.meanPasses - double(sum) / cells) < 1e-9);
        // Station ranges along the 5.4 km alignment: 270 of 20 m; the rollers' road starts 60 m west of the
        // worksite origin, so x 40..102 m is station 100..162: ranges 5..8 hold counts, 0..4 none.
        QCOMPARE(t.stations.size(), 270);
        QCOMPARE(t.stations[4].stats.covered, 0u);
        QVERIFY(t.stations[5].stats.covered > 0);
        QVERIFY(t.stations[7].stats.covered > 0);
        QCOMPARE(t.stations[9].stats.covered, 0u);
        // 12 m x 20 m band of 0.34 m cells: about 240 / 0.1156 = 2076 cells.
        QVERIFY(std::abs(int(t.stations[100].stats.cells) - 2076) < 40);
        // The whole top view: incomplete cells counted.
        const CoverageTables top = computeCoverageTables(job, f, -1);
        // cx 200..204 over the rows the helper visits (cy -9 .. 8), with or without a count.
        QCOMPARE(int(top.whole.incomplete), 5 * 18);
    }

    void csvRoundTripsThroughTheCrs() {
        const HandJob h;
        const CoverageJob job = makeJob(h);
        QTemporaryDir dir;
        CoverageReportRequest r;
        r.csv = dir.filePath(QStringLiteral("cov.csv"));
        r.lift = kAllLifts;
        const QJsonObject res = writeCoverageReport(job, r);
        QVERIFY2(res.value(QStringLiteral("ok")).toBool(),
                 qPrintable(res.value(QStringLiteral("message")).toString()));
        QVERIFY(res.value(QStringLiteral("written")).toObject().value(QStringLiteral("csv")).toBool());
        QFile f(r.csv);
        QVERIFY(f.open(QIODevice::ReadOnly));
        auto back = CrsTransform::fromWgs84To(32632);
        QVERIFY(back.ok());
        const GeoFrame ws(job.worksiteOrigin);
        int rows = 0, header = 0;
        bool sawEpsg = false;
        QVector<QByteArray> columns;
        double worst = 0;
        std::map<int, int> perLift;
        while (!f.atEnd()) {
            const QByteArray line = f.readLine().trimmed();
            if (line.startsWith('#')) {
                sawEpsg |= line == "# spatial-reference-id: 32632";
                continue;
            }
            if (columns.isEmpty()) {
                columns = split(line);
                ++header;
                continue;
            }
            const auto v = split(line);
            QCOMPARE(v.size(), columns.size());
            const double e = v[0].toDouble(), n = v[1].toDouble();
            const int lift = v[2].toInt() - 1;
            const int count = v[3].toInt();
            const int cx = v[6].toInt(), cy = v[7].toInt();
            double lat = 0, lon = 0;
            QVERIFY(back->toGeographic(e, n, lat, lon));
            const EnuPoint p = ws.toLocal({lat, lon, ws.origin().alt});
            worst = std::max(worst, std::hypot(p.e - (cx + 0.5) * h.cell, p.n - (cy + 0.5) * h.cell));
            QCOMPARE(count, countIn(h, lift, cx, cy));
            QCOMPARE(v[4], QByteArray(count < 3 ? "under" : count <= 5 ? "at" : "over"));
            QCOMPARE(v[5], QByteArray(cx >= h.incFrom && cx < h.incTo ? "1" : "0"));
            ++perLift[lift];
            ++rows;
        }
        QVERIFY(sawEpsg);
        QCOMPARE(columns.value(0), QByteArray("easting"));
        QCOMPARE(columns.value(1), QByteArray("northing"));
        QVERIFY2(worst < 0.001, qPrintable(QString::number(worst)));
        // Every counted cell of every lift, once.
        int expected[3] = {0, 0, 0};
        for (int l = 0; l < 3; ++l)
            for (int cy = -20; cy < 20; ++cy)
                for (int cx = 100; cx < 320; ++cx)
                    expected[l] += countIn(h, l, cx, cy) > 0;
        for (int l = 0; l < 3; ++l)
            QCOMPARE(perLift[l], expected[l]);
        QCOMPARE(double(rows), res.value(QStringLiteral("csv_rows")).toDouble());
    }

    void geoTiffReadBack() {
        const HandJob h;
        const CoverageJob job = makeJob(h);
        QTemporaryDir dir;
        CoverageReportRequest r;
        r.geotiff = dir.filePath(QStringLiteral("cov.tif"));
        r.lift = 0;
        const QJsonObject res = writeCoverageReport(job, r);
        QVERIFY2(res.value(QStringLiteral("ok")).toBool(),
                 qPrintable(res.value(QStringLiteral("message")).toString()));
        GDALAllRegister();
        GDALDataset* ds =
            static_cast<GDALDataset*>(GDALOpen(QFile::encodeName(r.geotiff).constData(), GA_ReadOnly));
        QVERIFY(ds);
        const osyris::CellBox box = job.snapshot->extent();
        QCOMPARE(ds->GetRasterXSize(), box.cx1 - box.cx0 + 1);
        QCOMPARE(ds->GetRasterYSize(), box.cy1 - box.cy0 + 1);
        const OGRSpatialReference* srs = ds->GetSpatialRef();
        QVERIFY(srs);
        QCOMPARE(QByteArray(srs->GetAuthorityCode(nullptr)), QByteArray("32632"));
        double gt[6];
        QCOMPARE(ds->GetGeoTransform(gt), CE_None);
        GDALRasterBand* b = ds->GetRasterBand(1);
        int hasNoData = 0;
        QCOMPARE(b->GetNoDataValue(&hasNoData), 0.0);
        QVERIFY(hasNoData);
        auto crs = CrsTransform::fromWgs84To(32632);
        const GeoFrame ws(job.worksiteOrigin);
        // Known cells: value and where the geotransform puts the pixel centre (affine over 70 m: < 1 cm).
        for (auto [cx, cy] : {std::pair{130, 0}, {131, -5}, {250, 6}, {295, -7}}) {
            const int col = cx - box.cx0, row = box.cy1 - cy;
            std::uint16_t v = 99;
            QCOMPARE(b->RasterIO(GF_Read, col, row, 1, 1, &v, 1, 1, GDT_UInt16, 0, 0), CE_None);
            QCOMPARE(int(v), countIn(h, 0, cx, cy));
            const double e = gt[0] + (col + 0.5) * gt[1] + (row + 0.5) * gt[2];
            const double n = gt[3] + (col + 0.5) * gt[4] + (row + 0.5) * gt[5];
            const GeoPoint g = ws.toGeodetic({(cx + 0.5) * h.cell, (cy + 0.5) * h.cell, 0});
            double ee = 0, nn = 0;
            QVERIFY(crs->toProjected(g.lat, g.lon, ee, nn));
            QVERIFY2(std::hypot(e - ee, n - nn) < 0.01,
                     qPrintable(QString::number(std::hypot(e - ee, n - nn))));
        }
        // A cell without data: nodata.
        std::uint16_t v = 99;
        QCOMPARE(b->RasterIO(GF_Read, 0, 0, 1, 1, &v, 1, 1, GDT_UInt16, 0, 0), CE_None);
        QCOMPARE(int(v), 0);
        GDALClose(ds);
    }

    void pdfFirstPageHasContent() {
        // poppler-utils is one of the project's dependencies (scripts/install-deps.sh): its absence is a
        // failure, not a reason to skip the acceptance check.
        QVERIFY2(!QStandardPaths::findExecutable(QStringLiteral("pdftoppm")).isEmpty(),
                 "pdftoppm (poppler-utils, scripts/install-deps.sh) is not installed");
        const HandJob h;
        const CoverageJob job = makeJob(h);
        QTemporaryDir dir;
        CoverageReportRequest r;
        r.pdf = dir.filePath(QStringLiteral("cov.pdf"));
        r.lift = -1;
        const QJsonObject res = writeCoverageReport(job, r);
        QVERIFY2(res.value(QStringLiteral("ok")).toBool(),
                 qPrintable(res.value(QStringLiteral("message")).toString()));
        QCOMPARE(res.value(QStringLiteral("station_ranges")).toInt(), 270);
        QProcess pp;
        pp.start(QStringLiteral("pdftoppm"),
                 {QStringLiteral("-r"), QStringLiteral("60"), QStringLiteral("-f"), QStringLiteral("1"),
                  QStringLiteral("-l"), QStringLiteral("1"), QStringLiteral("-png"), r.pdf,
                  dir.filePath(QStringLiteral("page"))});
        QVERIFY(pp.waitForFinished(60000));
        QCOMPARE(pp.exitCode(), 0);
        QDir d(dir.path());
        const QStringList pngs = d.entryList({QStringLiteral("page*.png")});
        QCOMPARE(pngs.size(), 1);
        QImage page(d.filePath(pngs.first()));
        QVERIFY(!page.isNull());
        int dark = 0, coloured = 0;
        for (int y = 0; y < page.height(); ++y)
            for (int x = 0; x < page.width(); ++x) {
                const QColor c = page.pixelColor(x, y);
                dark += c.value() < 100;
                coloured += c.saturation() > 150 && c.value() > 120; // pass-count colours of the map
            }
        QVERIFY2(dark > 2000, qPrintable(QString::number(dark)));
        QVERIFY2(coloured > 500, qPrintable(QString::number(coloured)));
        // The report states the incomplete cells (the hand job has 5 x 18 of them), in the
        // result and on the first page.
        QCOMPARE(res.value(QStringLiteral("incomplete_cells")).toInt(), 5 * 18);
        QProcess text;
        text.start(QStringLiteral("pdftotext"),
                   {QStringLiteral("-f"), QStringLiteral("1"), QStringLiteral("-l"), QStringLiteral("1"),
                    r.pdf, QStringLiteral("-")});
        QVERIFY(text.waitForFinished(60000));
        QCOMPARE(text.exitCode(), 0);
        const QString page1 = QString::fromUtf8(text.readAllStandardOutput()).simplified();
        QVERIFY2(page1.contains(QStringLiteral("INCOMPLETE: 90 cells may be under-counted")),
                 qPrintable(page1));
    }

    void truthfulResult() {
        const HandJob h;
        CoverageJob job = makeJob(h);
        QTemporaryDir dir;
        CoverageReportRequest r;
        r.csv = dir.filePath(QStringLiteral("ok.csv"));
        r.pdf = QStringLiteral("/nonexistent-dir/x.pdf");
        QJsonObject res = writeCoverageReport(job, r);
        QVERIFY(!res.value(QStringLiteral("ok")).toBool());
        QVERIFY(res.value(QStringLiteral("written")).toObject().value(QStringLiteral("csv")).toBool());
        QVERIFY(!res.value(QStringLiteral("written")).toObject().value(QStringLiteral("pdf")).toBool());
        QVERIFY(res.value(QStringLiteral("errors"))
                    .toArray()
                    .first()
                    .toString()
                    .contains(QStringLiteral("x.pdf")));
        // Unknown area, unknown lift, nothing asked for, no data.
        r = {};
        r.csv = dir.filePath(QStringLiteral("a.csv"));
        r.area = QStringLiteral("Nope");
        QVERIFY(!writeCoverageReport(job, r).value(QStringLiteral("ok")).toBool());
        r.area.clear();
        r.lift = 7;
        QVERIFY(writeCoverageReport(job, r)
                    .value(QStringLiteral("message"))
                    .toString()
                    .contains(QStringLiteral("lift")));
        QVERIFY(!writeCoverageReport(job, {}).value(QStringLiteral("ok")).toBool());
        job.snapshot.reset();
        r.lift = -1;
        QVERIFY(!writeCoverageReport(job, r).value(QStringLiteral("ok")).toBool());
        // An unknown EPSG code.
        job = makeJob(h);
        job.epsg = 999999;
        QVERIFY(!writeCoverageReport(job, r).value(QStringLiteral("ok")).toBool());
    }
};

QTEST_MAIN(TestCoverageReport)
#include "test_coverage_report.moc"
