#include "widgets/view3d/TerrainTriangleIndex.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ocu::scene3d {

void TerrainTriangleIndex::build(std::vector<Enu> pts, std::vector<std::array<int, 3>> tris) {
    m_pts = std::move(pts);
    m_tris = std::move(tris);
    m_buckets.clear();
    if (m_pts.empty() || m_tris.empty())
        return;
    m_minE = m_maxE = m_pts[0].e;
    m_minN = m_maxN = m_pts[0].n;
    double sumU = 0.0;
    for (const Enu& p : m_pts) {
        m_minE = std::min(m_minE, p.e);
        m_maxE = std::max(m_maxE, p.e);
        m_minN = std::min(m_minN, p.n);
        m_maxN = std::max(m_maxN, p.n);
        sumU += p.u;
    }
    m_meanU = sumU / static_cast<double>(m_pts.size());
    const int n = static_cast<int>(std::clamp(std::sqrt(static_cast<double>(m_tris.size())), 1.0, 256.0));
    m_nx = m_ny = n;
    m_cellE = std::max((m_maxE - m_minE) / n, 1e-6);
    m_cellN = std::max((m_maxN - m_minN) / n, 1e-6);
    m_buckets.assign(static_cast<std::size_t>(m_nx * m_ny), {});
    for (int t = 0; t < static_cast<int>(m_tris.size()); ++t) {
        double e0 = 1e300, e1 = -1e300, n0 = 1e300, n1 = -1e300;
        for (int k : m_tris[t]) {
            e0 = std::min(e0, m_pts[k].e);
            e1 = std::max(e1, m_pts[k].e);
            n0 = std::min(n0, m_pts[k].n);
            n1 = std::max(n1, m_pts[k].n);
        }
        for (int j = cellY(n0); j <= cellY(n1); ++j)
            for (int i = cellX(e0); i <= cellX(e1); ++i)
                m_buckets[static_cast<std::size_t>(j * m_nx + i)].push_back(t);
    }
}

double TerrainTriangleIndex::height(double e, double n) const {
    // Outside the hull: clamp into the bounding box, then fall back to the nearest vertex of the bucket.
    const double ce = std::clamp(e, m_minE, m_maxE);
    const double cn = std::clamp(n, m_minN, m_maxN);
    const auto& bucket = m_buckets[static_cast<std::size_t>(cellY(cn) * m_nx + cellX(ce))];
    for (int t : bucket) {
        const Enu& a = m_pts[m_tris[t][0]];
        const Enu& b = m_pts[m_tris[t][1]];
        const Enu& c = m_pts[m_tris[t][2]];
        const double det = (b.n - c.n) * (a.e - c.e) + (c.e - b.e) * (a.n - c.n);
        if (std::abs(det) < 1e-12)
            continue;
        const double l1 = ((b.n - c.n) * (ce - c.e) + (c.e - b.e) * (cn - c.n)) / det;
        const double l2 = ((c.n - a.n) * (ce - c.e) + (a.e - c.e) * (cn - c.n)) / det;
        const double l3 = 1.0 - l1 - l2;
        constexpr double eps = -1e-9;
        if (l1 >= eps && l2 >= eps && l3 >= eps)
            return l1 * a.u + l2 * b.u + l3 * c.u;
    }
    double best = std::numeric_limits<double>::max();
    double u = m_meanU;
    for (int t : bucket)
        for (int k : m_tris[t]) {
            const double d2 = (m_pts[k].e - ce) * (m_pts[k].e - ce) + (m_pts[k].n - cn) * (m_pts[k].n - cn);
            if (d2 < best) {
                best = d2;
                u = m_pts[k].u;
            }
        }
    return u;
}

int TerrainTriangleIndex::cellX(double e) const {
    return std::clamp(static_cast<int>((e - m_minE) / m_cellE), 0, m_nx - 1);
}

int TerrainTriangleIndex::cellY(double n) const {
    return std::clamp(static_cast<int>((n - m_minN) / m_cellN), 0, m_ny - 1);
}

} // namespace ocu::scene3d
