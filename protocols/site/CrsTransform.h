#pragma once
// WGS 84 geographic <-> an EPSG-coded projected CRS through PROJ ("coordinate conversion by a
// library, not by hand"). Plain C++, no Qt. One object per thread (it owns its PROJ context).
#include "protocols/common/Result.h"

#include <cstddef>
#include <memory>
#include <string>

namespace ocu {

class CrsTransform {
public:
    // EPSG:4326 (latitude, longitude in degrees) <-> EPSG:epsg (easting, northing in metres).
    static Result<CrsTransform> fromWgs84To(int epsg);
    CrsTransform(CrsTransform&&) noexcept;
    CrsTransform& operator=(CrsTransform&&) noexcept;
    ~CrsTransform();

    int epsg() const { return m_epsg; }
    std::string name() const; // the CRS's name, e.g. "WGS 84 / UTM zone 32N"
    bool toProjected(double lat, double lon, double& e, double& n) const;
    bool toGeographic(double e, double n, double& lat, double& lon) const;
    // In place, n points: lat/lon arrays in, easting/northing out (and back). False if any point failed.
    bool toProjected(double* latE, double* lonN, std::size_t n) const;
    bool toGeographic(double* eLat, double* nLon, std::size_t n) const;

    // The WGS 84 UTM zone of a position: 326zz north, 327zz south.
    static int utmEpsgFor(double lat, double lon);

private:
    CrsTransform() = default;
    struct Impl;
    std::unique_ptr<Impl> m_impl;
    int m_epsg = 0;
};

} // namespace ocu
