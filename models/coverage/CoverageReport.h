#pragma once
// The coverage report of a compaction job: statistics per area and per station range, a PDF
// (map snapshot with legend and scale bar, targets, statistics, lifts, machines, time range, filters, CRS,
// the "incomplete" statement), a CSV in Veta-style columns in an EPSG-coded projected CRS (PROJ), and a
// GeoTIFF of the pass-count raster (GDAL). docs/coverage-report.md describes the files.
//
// Frames: pass-count cells are in the OSYRIS worksite's local ENU frame (worksite origin); they reach the
// projected CRS through the geodetic position (GeographicLib LocalCartesian, then PROJ), never by a
// hand-made formula. The design (LandXML) is in its own CRS (its epsgCode) and reaches the worksite frame
// the same way back.
#include "protocols/common/GeoFrame.h"
#include "protocols/osyris/CoverageStats.h"
#include "protocols/site/LandXml.h"

#include <QDateTime>
#include <QImage>
#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <QVector>

#include <memory>
#include <optional>

namespace ocu {

// A named compaction area: a closed ring in WGS 84 (lat, lon), drawn on the map or taken from a design
// boundary.
struct CompactionArea {
    QString name;
    QString source; // "drawn" or "design"
    QVector<GeoPoint> ring;
};

// Everything a report is made of.
struct CoverageJob {
    std::shared_ptr<const osyris::PassCountSnapshot> snapshot;
    GeoPoint worksiteOrigin; // the OSYRIS worksite frame's origin
    std::shared_ptr<const landxml::LandXmlDesign> design;
    QString designPath;
    QVector<CompactionArea> areas;
    QStringList machines;       // names of the machines whose passes are counted
    QDateTime dataFrom, dataTo; // time range of the counted data (invalid: not known)
    QString siteName;
    double stationStep = 20;            // m per station range
    double bandLeft = 6, bandRight = 6; // m left / right of the centre line for the station ranges
    int epsg = 0;                       // report CRS; 0 = the design's, else the worksite's UTM zone
};

constexpr int kAllLifts = -2;

struct CoverageReportRequest {
    QString pdf, csv, geotiff; // empty: not written
    QString area;              // one area by name; empty = every area
    int lift = -1; // -1 = top view (top-most lift per cell), n = lift n; CSV: kAllLifts = every lift
    QSize mapSize{1600, 1000}; // map snapshot in pixels
};

struct AreaStats {
    QString name;
    QString source;
    osyris::CoverageStats stats;
};

// The statistics of a report (also for the pass-count panel).
struct CoverageTables {
    int epsg = 0;
    QString crsName;
    QVector<AreaStats> areas;
    QVector<osyris::StationBin> stations; // along the design's first alignment
    QString alignment;
    osyris::CoverageStats whole; // all covered cells of the lift (cells = covered + incomplete-only)
    QStringList problems;        // what could not be computed and why
};

// Frames of one job: worksite local <-> WGS 84 <-> report CRS / design CRS.
class CoverageFrames {
public:
    // Empty string when usable; else why not (e.g. an unknown EPSG code).
    QString init(const CoverageJob& job);
    int epsg() const { return m_epsg; }
    QString crsName() const { return m_crsName; }
    bool localToProjected(double x, double y, double& e, double& n, double* lat = nullptr,
                          double* lon = nullptr) const;
    bool projectedToLocal(double e, double n, double& x, double& y) const;
    std::optional<osyris::LocalPoint> geoToLocal(const GeoPoint& g) const;
    GeoPoint localToGeo(double x, double y) const;
    // Design CRS -> local (the design's epsg; false when the design has none or PROJ refuses).
    bool designToLocal(const landxml::PlanPoint& p, osyris::LocalPoint& out) const;
    bool hasDesignCrs() const { return m_designCrs != nullptr; }
    // Batch: local (x, y) arrays -> easting/northing and lat/lon (all arrays n long).
    bool localToProjected(const double* x, const double* y, std::size_t n, double* e, double* nn, double* lat,
                          double* lon) const;

private:
    struct Crs;
    std::shared_ptr<Crs> m_crs, m_designCrs;
    GeoFrame m_worksite;
    int m_epsg = 0;
    QString m_crsName;
};

CoverageTables computeCoverageTables(const CoverageJob& job, const CoverageFrames& frames, int lift,
                                     const QString& area = {});

// Writes what the request names; {"ok","message","written":{"pdf","csv","geotiff"},"errors":[..],
// "epsg","cells","areas":[{"name","coverage_pct",..}],"incomplete_cells"}. ok only when something was asked
// for and everything asked for was written.
QJsonObject writeCoverageReport(const CoverageJob& job, const CoverageReportRequest& request);

// The pieces (each returns an empty string on success, else the reason).
QString writeCoverageCsv(const CoverageJob& job, const CoverageFrames& frames, int lift, const QString& area,
                         const QString& path, qint64* rows = nullptr);
QString writeCoverageGeoTiff(const CoverageJob& job, const CoverageFrames& frames, int lift,
                             const QString& path, double* maxDeviationM = nullptr);
QImage renderCoverageMap(const CoverageJob& job, const CoverageFrames& frames, int lift, const QString& area,
                         QSize size);
QString writeCoveragePdf(const CoverageJob& job, const CoverageFrames& frames, const CoverageTables& tables,
                         int lift, const QString& area, const QString& path, QSize mapSize);

} // namespace ocu
