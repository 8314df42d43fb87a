#pragma once
// The site frame: WGS84 <-> local East/North/Up around the site origin (GeographicLib LocalCartesian).
#include <memory>

namespace ocu {

struct GeoPoint {
    double lat = 0; // degrees
    double lon = 0; // degrees
    double alt = 0; // metres above the ellipsoid
};

struct EnuPoint {
    double e = 0;
    double n = 0;
    double u = 0;
};

class GeoFrame {
public:
    explicit GeoFrame(GeoPoint origin = {});
    ~GeoFrame();
    GeoFrame(const GeoFrame&);
    GeoFrame& operator=(const GeoFrame&);

    const GeoPoint& origin() const { return m_origin; }
    EnuPoint toLocal(const GeoPoint& p) const;
    GeoPoint toGeodetic(const EnuPoint& p) const;

private:
    struct Impl;
    GeoPoint m_origin;
    std::unique_ptr<Impl> m_impl;
};

} // namespace ocu
