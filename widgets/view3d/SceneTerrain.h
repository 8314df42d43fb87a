#pragma once
// The ground of the 3D scene: a DEM grid, a Delaunay surface through survey points, or a flat plane, shaded
// by height. Answers the terrain height everywhere, which the draped layers (ways, pass counts) and the
// machines clamped to the ground use, and the site bounds the camera frames.
#include "widgets/view3d/Scene3D.h"
#include "widgets/view3d/TerrainTriangleIndex.h"

#include <vtkActor.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkSmartPointer.h>

#include <array>

namespace ocu::scene3d {

class SceneTerrain {
public:
    SceneTerrain();

    vtkActor* actor() const { return m_actor; }

    // Rebuilds the surface. Points with non-finite coordinates are dropped from `terrain` (with a warning).
    void build(Terrain3D& terrain);

    // Terrain height at (e, n): barycentric on the surface, the plane height when flat.
    double height(double e, double n) const;
    bool flat() const { return m_flat; }
    // Resampling distance of draped layers (m): about half the terrain's sample spacing.
    double drapeStep() const { return m_drapeStep; }
    // minE, maxE, minN, maxN, minU, maxU + 5 m of the surface built from `terrain`.
    void bounds(const Terrain3D& terrain, double b[6]) const;

private:
    vtkSmartPointer<vtkPolyData> buildGrid(const Terrain3D& t);
    vtkSmartPointer<vtkPolyData> buildDelaunay(const Terrain3D& t);
    vtkSmartPointer<vtkPolyData> buildPlane(const Terrain3D& t);

    vtkNew<vtkActor> m_actor;
    vtkNew<vtkPolyDataMapper> m_mapper;
    TerrainTriangleIndex m_index;
    bool m_flat = true;
    double m_drapeStep = 2.0;
    double m_flatU = 0.0;                           // plane height when flat
    std::array<double, 4> m_flatExtent{0, 0, 0, 0}; // minE, maxE, minN, maxN of the plane
};

} // namespace ocu::scene3d
