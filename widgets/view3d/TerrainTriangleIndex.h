#pragma once
// Height look-ups on a triangulated terrain: a uniform bucket grid over the triangles, barycentric
// interpolation inside the triangle that holds the point. Plain C++, no VTK.
#include "widgets/view3d/Scene3D.h"

#include <array>
#include <vector>

namespace ocu::scene3d {

class TerrainTriangleIndex {
public:
    void build(std::vector<Enu> pts, std::vector<std::array<int, 3>> tris);

    bool valid() const { return !m_buckets.empty(); }
    double minE() const { return m_minE; }
    double maxE() const { return m_maxE; }
    double minN() const { return m_minN; }
    double maxN() const { return m_maxN; }

    // Outside the hull: clamped into the bounding box, then the nearest vertex of the bucket.
    double height(double e, double n) const;

private:
    int cellX(double e) const;
    int cellY(double n) const;

    std::vector<Enu> m_pts;
    std::vector<std::array<int, 3>> m_tris;
    std::vector<std::vector<int>> m_buckets;
    double m_minE = 0, m_maxE = 0, m_minN = 0, m_maxN = 0, m_cellE = 1, m_cellN = 1, m_meanU = 0;
    int m_nx = 1, m_ny = 1;
};

} // namespace ocu::scene3d
