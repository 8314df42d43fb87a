#pragma once
// Roads, lanes and areas of the site map draped over the terrain: roads and lanes as ribbons resampled along
// their centre line, areas triangulated and subdivided so they follow the ground instead of cutting through
// it.
#include "widgets/view3d/Scene3D.h"

#include <vtkActor.h>
#include <vtkNew.h>
#include <vtkPolyDataMapper.h>
#include <vtkTriangleFilter.h>

#include <vector>

class vtkCellArray;
class vtkPoints;
class vtkUnsignedCharArray;

namespace ocu::scene3d {

class SceneTerrain;

class SceneWays {
public:
    SceneWays();

    vtkActor* areaActor() const { return m_areaActor; }
    vtkActor* ribbonActor() const { return m_ribbonActor; }

    void build(const std::vector<Way3D>& ways, const SceneTerrain& terrain);

private:
    void buildAreas(const std::vector<Way3D>& ways, const SceneTerrain& terrain);
    static void addRibbon(const Way3D& w, double lift, const SceneTerrain& terrain, vtkPoints* pts,
                          vtkCellArray* tris, vtkUnsignedCharArray* colours);

    vtkNew<vtkActor> m_ribbonActor;
    vtkNew<vtkPolyDataMapper> m_ribbonMapper;
    vtkNew<vtkActor> m_areaActor;
    vtkNew<vtkPolyDataMapper> m_areaMapper;
    vtkNew<vtkTriangleFilter> m_areaTriangles;
};

} // namespace ocu::scene3d
