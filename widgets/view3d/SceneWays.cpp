#include "widgets/view3d/SceneWays.h"

#include "widgets/view3d/SceneCommon.h"
#include "widgets/view3d/SceneTerrain.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace ocu::scene3d {

SceneWays::SceneWays() {
    m_ribbonActor->SetMapper(m_ribbonMapper);
    configureDirectColours(m_ribbonMapper, true);
    m_areaTriangles->PassLinesOff();
    m_areaTriangles->PassVertsOff();
    m_areaActor->SetMapper(m_areaMapper);
    configureDirectColours(m_areaMapper, true);
    // Draped layers are pulled towards the camera in depth so that they win over the terrain at any distance
    // (the pass-count surface more still, see ScenePassTexture).
    m_areaMapper->SetRelativeCoincidentTopologyPolygonOffsetParameters(-1, -2);
    m_ribbonMapper->SetRelativeCoincidentTopologyPolygonOffsetParameters(-2, -4);
    for (vtkActor* a : {m_ribbonActor.Get(), m_areaActor.Get()}) {
        a->GetProperty()->SetAmbient(0.5);
        a->GetProperty()->SetDiffuse(0.5);
    }
}

// Draped ribbon: the centre line is resampled every `step` metres so the ribbon follows the terrain.
void SceneWays::addRibbon(const Way3D& w, double lift, const SceneTerrain& terrain, vtkPoints* pts,
                          vtkCellArray* tris, vtkUnsignedCharArray* colours) {
    if (w.points.size() < 2 || !(w.width > 0.0) || !std::isfinite(w.width))
        return;
    const double step = terrain.flat() ? 1e9 : terrain.drapeStep();
    std::vector<std::pair<double, double>> line;
    for (std::size_t i = 0; i + 1 < w.points.size(); ++i) {
        const Enu& a = w.points[i];
        const Enu& b = w.points[i + 1];
        const double len = std::hypot(b.e - a.e, b.n - a.n);
        const int n = std::max(1, static_cast<int>(std::ceil(len / step)));
        for (int k = 0; k < n; ++k)
            line.emplace_back(a.e + (b.e - a.e) * k / n, a.n + (b.n - a.n) * k / n);
    }
    line.emplace_back(w.points.back().e, w.points.back().n);
    // Drop repeated points (zero-length segments have no direction).
    line.erase(std::unique(line.begin(), line.end(),
                           [](const auto& p, const auto& q) {
                               return std::abs(p.first - q.first) < 1e-6 &&
                                      std::abs(p.second - q.second) < 1e-6;
                           }),
               line.end());
    if (line.size() < 2)
        return;
    const double half = w.width / 2.0;
    const vtkIdType base = pts->GetNumberOfPoints();
    for (std::size_t i = 0; i < line.size(); ++i) {
        const auto& prev = line[i == 0 ? 0 : i - 1];
        const auto& next = line[std::min(i + 1, line.size() - 1)];
        double de = next.first - prev.first, dn = next.second - prev.second;
        const double len = std::hypot(de, dn);
        de /= len;
        dn /= len;
        // Left normal of the direction (de, dn) is (-dn, de).
        const double le = line[i].first - dn * half, ln = line[i].second + de * half;
        const double re = line[i].first + dn * half, rn = line[i].second - de * half;
        pts->InsertNextPoint(le, ln, terrain.height(le, ln) + lift);
        pts->InsertNextPoint(re, rn, terrain.height(re, rn) + lift);
    }
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
        const vtkIdType l0 = base + 2 * static_cast<vtkIdType>(i), r0 = l0 + 1, l1 = l0 + 2, r1 = l0 + 3;
        const vtkIdType t1[3] = {l0, r0, r1};
        const vtkIdType t2[3] = {l0, r1, l1};
        tris->InsertNextCell(3, t1);
        tris->InsertNextCell(3, t2);
        colours->InsertNextTuple3(w.colour.r, w.colour.g, w.colour.b);
        colours->InsertNextTuple3(w.colour.r, w.colour.g, w.colour.b);
    }
}

void SceneWays::build(const std::vector<Way3D>& ways, const SceneTerrain& terrain) {
    vtkNew<vtkPoints> rPts;
    vtkNew<vtkCellArray> rTris;
    auto rColours = makeColours(3, "colour");
    // Areas first, roads, then lanes on top.
    for (WayKind kind : {WayKind::Road, WayKind::Lane})
        for (const Way3D& w : ways)
            if (w.kind == kind)
                addRibbon(w, kind == WayKind::Road ? kLiftRoad : kLiftLane, terrain, rPts, rTris, rColours);
    vtkNew<vtkPolyData> ribbons;
    ribbons->SetPoints(rPts);
    ribbons->SetPolys(rTris);
    ribbons->GetCellData()->SetScalars(rColours);
    m_ribbonMapper->SetInputData(ribbons);
    buildAreas(ways, terrain);
}

// Areas: triangulate the outline in 2D (concave outlines allowed), then subdivide every triangle so the
// surface follows the terrain instead of cutting through it.
void SceneWays::buildAreas(const std::vector<Way3D>& ways, const SceneTerrain& terrain) {
    vtkNew<vtkPoints> aPts;
    vtkNew<vtkCellArray> aPolys;
    auto aColours = makeColours(3, "colour");
    vtkNew<vtkPoints> outlinePts;
    vtkNew<vtkCellArray> outlines;
    auto outlineColours = makeColours(3, "colour");
    for (const Way3D& w : ways) {
        if (w.kind != WayKind::Area || w.points.size() < 3)
            continue;
        std::vector<vtkIdType> ids;
        for (const Enu& p : w.points)
            ids.push_back(outlinePts->InsertNextPoint(p.e, p.n, 0.0));
        outlines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
        outlineColours->InsertNextTuple3(w.colour.r, w.colour.g, w.colour.b);
    }
    vtkNew<vtkPolyData> outlineData;
    outlineData->SetPoints(outlinePts);
    outlineData->SetPolys(outlines);
    outlineData->GetCellData()->SetScalars(outlineColours);
    m_areaTriangles->SetInputData(outlineData);
    m_areaTriangles->Update();
    vtkPolyData* tri = m_areaTriangles->GetOutput();
    vtkDataArray* triColours = tri->GetCellData()->GetScalars();
    const double step = terrain.flat() ? 1e9 : terrain.drapeStep();
    vtkIdType npts = 0;
    const vtkIdType* ids = nullptr;
    vtkIdType cell = 0;
    vtkCellArray* polys = tri->GetPolys();
    for (polys->InitTraversal(); polys->GetNextCell(npts, ids); ++cell) {
        if (npts != 3)
            continue;
        double a[3], b[3], c[3];
        tri->GetPoint(ids[0], a);
        tri->GetPoint(ids[1], b);
        tri->GetPoint(ids[2], c);
        const double longest =
            std::max({std::hypot(b[0] - a[0], b[1] - a[1]), std::hypot(c[0] - b[0], c[1] - b[1]),
                      std::hypot(a[0] - c[0], a[1] - c[1])});
        const int k = std::clamp(static_cast<int>(std::ceil(longest / step)), 1, 64);
        double rgb[3] = {128, 128, 128};
        if (triColours != nullptr)
            triColours->GetTuple(cell, rgb);
        // Uniform barycentric subdivision into k*k triangles.
        auto vertex = [&](int i, int j) {
            const double u = static_cast<double>(i) / k, v = static_cast<double>(j) / k, w0 = 1.0 - u - v;
            const double e = w0 * a[0] + u * b[0] + v * c[0], n = w0 * a[1] + u * b[1] + v * c[1];
            return aPts->InsertNextPoint(e, n, terrain.height(e, n) + kLiftArea);
        };
        for (int i = 0; i < k; ++i)
            for (int j = 0; j + i < k; ++j) {
                const vtkIdType t1[3] = {vertex(i, j), vertex(i + 1, j), vertex(i, j + 1)};
                aPolys->InsertNextCell(3, t1);
                aColours->InsertNextTuple(rgb);
                if (i + j + 1 < k) {
                    const vtkIdType t2[3] = {vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j + 1)};
                    aPolys->InsertNextCell(3, t2);
                    aColours->InsertNextTuple(rgb);
                }
            }
    }
    vtkNew<vtkPolyData> areas;
    areas->SetPoints(aPts);
    areas->SetPolys(aPolys);
    areas->GetCellData()->SetScalars(aColours);
    m_areaMapper->SetInputData(areas);
}

} // namespace ocu::scene3d
