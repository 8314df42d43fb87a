#include "protocols/common/GeoFrame.h"

#include <GeographicLib/LocalCartesian.hpp>

namespace ocu {

struct GeoFrame::Impl {
    GeographicLib::LocalCartesian lc;
};

GeoFrame::GeoFrame(GeoPoint origin)
    : m_origin(origin), m_impl(std::make_unique<Impl>(
                            Impl{GeographicLib::LocalCartesian(origin.lat, origin.lon, origin.alt)})) {}
GeoFrame::~GeoFrame() = default;
GeoFrame::GeoFrame(const GeoFrame& o) : m_origin(o.m_origin), m_impl(std::make_unique<Impl>(*o.m_impl)) {}
GeoFrame& GeoFrame::operator=(const GeoFrame& o) {
    m_origin = o.m_origin;
    m_impl = std::make_unique<Impl>(*o.m_impl);
    return *this;
}

EnuPoint GeoFrame::toLocal(const GeoPoint& p) const {
    EnuPoint r;
    m_impl->lc.Forward(p.lat, p.lon, p.alt, r.e, r.n, r.u);
    return r;
}

GeoPoint GeoFrame::toGeodetic(const EnuPoint& p) const {
    GeoPoint r;
    m_impl->lc.Reverse(p.e, p.n, p.u, r.lat, r.lon, r.alt);
    return r;
}

} // namespace ocu
