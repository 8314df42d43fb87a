#include "models/coverage/CoverageReportCommon.h"

#include "protocols/site/CrsTransform.h"

#include <cmath>

namespace ocu {

using coverage::ReportText;
using osyris::LocalPoint;

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

} // namespace ocu
