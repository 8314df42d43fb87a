#include "protocols/site/CrsTransform.h"

#include <proj.h>

#include <cmath>

namespace ocu {

struct CrsTransform::Impl {
    PJ_CONTEXT* ctx = nullptr;
    PJ* pj = nullptr;
    std::string name;
    ~Impl() {
        if (pj)
            proj_destroy(pj);
        if (ctx)
            proj_context_destroy(ctx);
    }
};

Result<CrsTransform> CrsTransform::fromWgs84To(int epsg) {
    if (epsg <= 0 || epsg > 999999)
        return makeError("EPSG code " + std::to_string(epsg) + " is not valid");
    CrsTransform t;
    t.m_impl = std::make_unique<Impl>();
    t.m_epsg = epsg;
    t.m_impl->ctx = proj_context_create();
    proj_log_level(t.m_impl->ctx, PJ_LOG_NONE);
    const std::string target = "EPSG:" + std::to_string(epsg);
    PJ* crs = proj_create(t.m_impl->ctx, target.c_str());
    if (!crs)
        return makeError("PROJ does not know " + target);
    const PJ_TYPE type = proj_get_type(crs);
    if (const char* n = proj_get_name(crs))
        t.m_impl->name = n;
    proj_destroy(crs);
    if (type != PJ_TYPE_PROJECTED_CRS)
        return makeError(target + " (" + t.m_impl->name + ") is not a projected CRS");
    PJ* raw = proj_create_crs_to_crs(t.m_impl->ctx, "EPSG:4326", target.c_str(), nullptr);
    if (!raw)
        return makeError("PROJ cannot convert between EPSG:4326 and " + target);
    // Axis order lon/lat in, easting/northing out, whatever the CRS definitions say.
    t.m_impl->pj = proj_normalize_for_visualization(t.m_impl->ctx, raw);
    proj_destroy(raw);
    if (!t.m_impl->pj)
        return makeError("PROJ cannot normalise the conversion to " + target);
    return t;
}

CrsTransform::CrsTransform(CrsTransform&&) noexcept = default;
CrsTransform& CrsTransform::operator=(CrsTransform&&) noexcept = default;
CrsTransform::~CrsTransform() = default;

std::string CrsTransform::name() const {
    return m_impl ? m_impl->name : std::string();
}

bool CrsTransform::toProjected(double lat, double lon, double& e, double& n) const {
    if (!m_impl || !std::isfinite(lat) || !std::isfinite(lon))
        return false;
    const PJ_COORD c = proj_trans(m_impl->pj, PJ_FWD, proj_coord(lon, lat, 0, 0));
    if (!std::isfinite(c.xy.x) || !std::isfinite(c.xy.y))
        return false;
    e = c.xy.x;
    n = c.xy.y;
    return true;
}

bool CrsTransform::toGeographic(double e, double n, double& lat, double& lon) const {
    if (!m_impl || !std::isfinite(e) || !std::isfinite(n))
        return false;
    const PJ_COORD c = proj_trans(m_impl->pj, PJ_INV, proj_coord(e, n, 0, 0));
    if (!std::isfinite(c.lp.lam) || !std::isfinite(c.lp.phi))
        return false;
    lon = c.lp.lam;
    lat = c.lp.phi;
    return true;
}

bool CrsTransform::toProjected(double* latE, double* lonN, std::size_t n) const {
    if (!m_impl)
        return false;
    // proj_trans_generic takes x = lon, y = lat (normalised): pass the longitude array first.
    proj_trans_generic(m_impl->pj, PJ_FWD, lonN, sizeof(double), n, latE, sizeof(double), n, nullptr, 0, 0,
                       nullptr, 0, 0);
    bool ok = true;
    for (std::size_t i = 0; i < n; ++i) {
        std::swap(latE[i], lonN[i]); // now latE = easting, lonN = northing
        ok = ok && std::isfinite(latE[i]) && std::isfinite(lonN[i]);
    }
    return ok;
}

bool CrsTransform::toGeographic(double* eLat, double* nLon, std::size_t n) const {
    if (!m_impl)
        return false;
    proj_trans_generic(m_impl->pj, PJ_INV, eLat, sizeof(double), n, nLon, sizeof(double), n, nullptr, 0, 0,
                       nullptr, 0, 0);
    bool ok = true;
    for (std::size_t i = 0; i < n; ++i) {
        std::swap(eLat[i], nLon[i]); // eLat = lat, nLon = lon
        ok = ok && std::isfinite(eLat[i]) && std::isfinite(nLon[i]);
    }
    return ok;
}

int CrsTransform::utmEpsgFor(double lat, double lon) {
    int zone = static_cast<int>(std::floor((lon + 180.0) / 6.0)) + 1;
    zone = zone < 1 ? 1 : zone > 60 ? 60 : zone;
    // Norway and Svalbard exceptions.
    if (lat >= 56 && lat < 64 && lon >= 3 && lon < 12)
        zone = 32;
    if (lat >= 72 && lat < 84) {
        if (lon >= 0 && lon < 9)
            zone = 31;
        else if (lon >= 9 && lon < 21)
            zone = 33;
        else if (lon >= 21 && lon < 33)
            zone = 35;
        else if (lon >= 33 && lon < 42)
            zone = 37;
    }
    return (lat >= 0 ? 32600 : 32700) + zone;
}

} // namespace ocu
