#pragma once
// What the compaction widgets see of the site manager's job: Qt types only, so widgets/ never
// reach a stack header through it (house plan, tests/test_include_rules). CompactionSession implements it
// over the LandXML design, the OSYRIS pass-count snapshot and the coverage report.
#include <QJsonObject>
#include <QObject>
#include <QPair>
#include <QPolygonF>
#include <QString>
#include <QStringList>
#include <QVector>

namespace ocu {

class CompactionView : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;

    // Geometry in the site frame (ENU metres) for the 2D/3D maps.
    struct Tick {
        QPointF left, right; // across the centre line
        double station = 0;
    };
    struct MapGeometry {
        QVector<QPolygonF> centreLines;
        QVector<QPolygonF> boundaries;
        QVector<Tick> ticks; // every kTickSpacing m
        QVector<QPair<QString, QPolygonF>> areas;
        QVector<bool> areaFromDesign; // per area: a design boundary (usually the whole job), not drawn
    };
    static constexpr double kTickSpacing = 100;
    virtual const MapGeometry& mapGeometry() const = 0;
    // "1+250.00" style stationing of a design station (metres), `decimals` after the point.
    static QString stationText(double station, int decimals);

    struct DesignInfo {
        bool loaded = false;
        QString path;
        int alignments = 0, boundaries = 0;
        QStringList warnings;
    };
    virtual DesignInfo designInfo() const = 0;

    // The areas' statistics at one lift (-1: the top view), computed from the current pass counts.
    // The figures of one area or station range.
    struct CoverageFigures {
        bool hasStats = false; // counts cover part of it
        double coveragePercent = 0, atTargetPercent = 0, underPercent = 0, overPercent = 0;
        quint64 incompleteCells = 0;
    };
    struct AreaRow : CoverageFigures {
        QString name;
        bool fromDesign = false;
    };
    struct LiftRange {
        double bottom = 0, top = 0; // z, metres
    };
    // One station range along the design's first alignment (every stationStep m, the band bandLeft m left
    // to bandRight m right of the centre line), as the report's per-station table.
    struct StationRow : CoverageFigures {
        double from = 0, to = 0; // stations, m
        QPolygonF band;          // site ENU, for the map
    };
    struct CoverageTable {
        QVector<LiftRange> lifts; // of the counted data
        QVector<AreaRow> areas;   // every area, in the session's order
        QString alignment;        // of the station ranges; empty: no design alignment (or no CRS for it)
        double stationStep = 0, bandLeft = 0, bandRight = 0;
        QVector<StationRow> stations;
    };
    virtual CoverageTable coverageTable(int lift) const = 0;

    virtual int areaCount() const = 0;
    // A ring drawn on the map (site ENU metres); empty string on success, else why not.
    virtual QString addArea(const QString& name, const QPolygonF& siteEN) = 0;
    virtual bool removeArea(const QString& name) = 0;
    virtual QString saveAreas() = 0;
    virtual QString areasFile() const = 0;
    virtual bool hasWorksite() const = 0;
    // The headless/CLI command: {"pdf","csv","geotiff","area","lift"} -> the report's result.
    virtual QJsonObject reportCommand(const QJsonObject& cmd) const = 0;

signals:
    void changed(); // design or areas
    // The pass counts behind the session changed (a new snapshot, a recount after a filter change).
    void countsChanged();
};

} // namespace ocu
