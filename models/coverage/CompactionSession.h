#pragma once
// The site manager's compaction job in the console: the LandXML design, the named compaction
// areas (from the design's boundaries or drawn on the map, saved with the site configuration), their
// geometry in the site frame for the maps, and the coverage report of the current pass counts.
#include "models/coverage/CompactionView.h"
#include "models/coverage/CoverageReport.h"
#include "protocols/site/SiteConfig.h"

#include <QHash>
#include <QObject>
#include <QPolygonF>

#include <functional>

namespace ocu {

class CrsTransform;

class CompactionSession : public CompactionView {
    Q_OBJECT
public:
    CompactionSession(const CompactionConfig& config, const GeoFrame& siteFrame, QObject* parent = nullptr);
    ~CompactionSession() override;

    // Reads a LandXML file (a Qt resource path works too); empty string on success, else why not. The
    // design's boundaries become areas (source "design").
    QString loadDesign(const QString& path);
    std::shared_ptr<const landxml::LandXmlDesign> design() const { return m_design; }
    QString designPath() const { return m_designPath; }
    QStringList designWarnings() const;

    const QVector<CompactionArea>& areas() const { return m_areas; }
    int areaCount() const override { return int(m_areas.size()); }
    // A ring drawn on the map (site ENU metres). Names are unique: an existing area of that name is replaced.
    QString addArea(const QString& name, const QPolygonF& siteEN) override;
    bool removeArea(const QString& name) override;
    // Writes the drawn areas into the site configuration file's "compaction" section (other keys untouched);
    // a configuration that is not a writable file (the built-in site) saves next to the user's data. Empty
    // string on success.
    QString saveAreas() override;
    QString areasFile() const override; // where saveAreas writes

    const MapGeometry& mapGeometry() const override { return m_geometry; }
    DesignInfo designInfo() const override;
    CoverageTable coverageTable(int lift) const override;

    // Where the pass counts come from (the OSYRIS layer's snapshot) and who made them.
    void setSnapshotSource(std::function<std::shared_ptr<const osyris::PassCountSnapshot>()> f) {
        m_snapshot = std::move(f);
    }
    void setWorksiteOrigin(const GeoPoint& g) {
        m_worksite = g;
        m_haveWorksite = true;
    }
    bool hasWorksite() const override { return m_haveWorksite; }
    void setMachines(const QStringList& names) { m_machines = names; }
    void setSiteName(const QString& n) { m_siteName = n; }

    CoverageJob job() const;
    // The headless/CLI command: {"pdf","csv","geotiff","area","lift"} -> the report's result.
    QJsonObject reportCommand(const QJsonObject& cmd) const override;

private:
    void rebuildGeometry();
    std::optional<QPointF> designToSite(const landxml::PlanPoint& p) const;

    CompactionConfig m_config;
    GeoFrame m_site;
    std::shared_ptr<const landxml::LandXmlDesign> m_design;
    QString m_designPath;
    std::unique_ptr<CrsTransform> m_designCrs;
    QVector<CompactionArea> m_areas;
    MapGeometry m_geometry;
    // Station-range bands in the site frame by (from, to): they depend on the design only (PROJ per vertex),
    // not on the counts the table is refreshed for. Cleared with the geometry.
    mutable QHash<QPair<double, double>, QPolygonF> m_stationBands;
    std::function<std::shared_ptr<const osyris::PassCountSnapshot>()> m_snapshot;
    GeoPoint m_worksite;
    bool m_haveWorksite = false;
    QStringList m_machines;
    QString m_siteName;
};

} // namespace ocu
