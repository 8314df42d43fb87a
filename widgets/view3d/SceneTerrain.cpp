#include "widgets/view3d/SceneTerrain.h"

#include "protocols/common/Log.h"
#include "widgets/view3d/SceneCommon.h"

#include <vtkCellArray.h>
#include <vtkDelaunay2D.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkProperty.h>

#include <algorithm>
#include <limits>
#include <string>

namespace ocu::scene3d {

SceneTerrain::SceneTerrain() {
    m_actor->SetMapper(m_mapper);
    m_actor->GetProperty()->SetAmbient(0.35);
    m_actor->GetProperty()->SetDiffuse(0.65);
    configureDirectColours(m_mapper, false);
}

double SceneTerrain::height(double e, double n) const {
    if (!m_flat && m_index.valid())
        return m_index.height(e, n);
    return m_flatU;
}

void SceneTerrain::build(Terrain3D& t) {
    m_flat = true;
    vtkSmartPointer<vtkPolyData> surface;
    const auto bad = std::count_if(t.points.begin(), t.points.end(), [](const Enu& p) { return !finite(p); });
    if (bad > 0) {
        logWarning(kLogCategory,
                   "terrain: " + std::to_string(bad) + " point(s) with non-finite coordinates ignored");
        t.points.erase(
            std::remove_if(t.points.begin(), t.points.end(), [](const Enu& p) { return !finite(p); }),
            t.points.end());
    }
    if (t.grid.valid())
        surface = buildGrid(t);
    else if (t.points.size() >= 3)
        surface = buildDelaunay(t);
    if (m_flat)
        surface = buildPlane(t);
    m_mapper->SetInputData(surface);
}

// A DEM grid: two triangles per cell, coloured by height (low = darker, like a pit floor in shadow).
vtkSmartPointer<vtkPolyData> SceneTerrain::buildGrid(const Terrain3D& t) {
    const TerrainGrid3D& g = t.grid;
    std::vector<Enu> verts;
    verts.reserve(g.u.size());
    double uMin = std::numeric_limits<double>::max(), uMax = std::numeric_limits<double>::lowest();
    double sum = 0.0;
    std::size_t good = 0;
    for (double u : g.u)
        if (std::isfinite(u)) {
            uMin = std::min(uMin, u);
            uMax = std::max(uMax, u);
            sum += u;
            ++good;
        }
    if (good == 0)
        return nullptr;
    const double fill = sum / static_cast<double>(good);
    vtkNew<vtkPoints> pts;
    pts->SetNumberOfPoints(static_cast<vtkIdType>(g.u.size()));
    auto colours = makeColours(3, "colour");
    colours->SetNumberOfTuples(static_cast<vtkIdType>(g.u.size()));
    for (int r = 0; r < g.rows; ++r)
        for (int c = 0; c < g.cols; ++c) {
            const std::size_t i = static_cast<std::size_t>(r) * g.cols + c;
            const double u = std::isfinite(g.u[i]) ? g.u[i] : fill;
            const Enu p{g.originE + c * g.step, g.originN + r * g.step, u};
            verts.push_back(p);
            pts->SetPoint(static_cast<vtkIdType>(i), p.e, p.n, p.u);
            const double f = 0.7 + 0.5 * (uMax > uMin ? (u - uMin) / (uMax - uMin) : 0.5);
            colours->SetTuple3(static_cast<vtkIdType>(i), std::min(255.0, t.colour.r * f),
                               std::min(255.0, t.colour.g * f), std::min(255.0, t.colour.b * f));
        }
    std::vector<std::array<int, 3>> tris;
    tris.reserve(static_cast<std::size_t>(g.cols - 1) * (g.rows - 1) * 2);
    vtkNew<vtkCellArray> cells;
    for (int r = 0; r + 1 < g.rows; ++r)
        for (int c = 0; c + 1 < g.cols; ++c) {
            const int a = r * g.cols + c, b = a + 1, d = a + g.cols, e = d + 1;
            for (const std::array<int, 3>& tri : {std::array<int, 3>{a, b, e}, std::array<int, 3>{a, e, d}}) {
                tris.push_back(tri);
                const vtkIdType ids[3] = {tri[0], tri[1], tri[2]};
                cells->InsertNextCell(3, ids);
            }
        }
    m_index.build(verts, std::move(tris));
    m_flat = !m_index.valid();
    m_drapeStep = std::clamp(g.step / 2.0, 1.0, 25.0);
    auto surface = vtkSmartPointer<vtkPolyData>::New();
    surface->SetPoints(pts);
    surface->SetPolys(cells);
    surface->GetPointData()->SetScalars(colours);
    return surface;
}

// A Delaunay surface through the survey points; nullptr when they are too few or collinear.
vtkSmartPointer<vtkPolyData> SceneTerrain::buildDelaunay(const Terrain3D& t) {
    vtkNew<vtkPoints> pts;
    for (const Enu& p : t.points)
        pts->InsertNextPoint(p.e, p.n, p.u);
    vtkNew<vtkPolyData> cloud;
    cloud->SetPoints(pts);
    vtkNew<vtkDelaunay2D> delaunay;
    delaunay->SetInputData(cloud);
    delaunay->Update();
    vtkPolyData* out = delaunay->GetOutput();
    if (out->GetNumberOfPolys() == 0)
        return nullptr;
    std::vector<Enu> verts(static_cast<std::size_t>(out->GetNumberOfPoints()));
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i) {
        double x[3];
        out->GetPoint(i, x);
        verts[static_cast<std::size_t>(i)] = {x[0], x[1], x[2]};
    }
    std::vector<std::array<int, 3>> tris;
    vtkCellArray* polys = out->GetPolys();
    vtkIdType npts = 0;
    const vtkIdType* ids = nullptr;
    for (polys->InitTraversal(); polys->GetNextCell(npts, ids);)
        if (npts == 3)
            tris.push_back({static_cast<int>(ids[0]), static_cast<int>(ids[1]), static_cast<int>(ids[2])});
    m_index.build(verts, std::move(tris));
    m_flat = !m_index.valid();
    // Draped layers are resampled at half the mean terrain point spacing: finer adds triangles
    // (llvmpipe pays per triangle) without following the piecewise-linear surface any better.
    const double area = std::max(1.0, (m_index.maxE() - m_index.minE()) * (m_index.maxN() - m_index.minN()));
    m_drapeStep = std::clamp(std::sqrt(area / static_cast<double>(verts.size())) / 2.0, 1.0, 25.0);
    auto surface = vtkSmartPointer<vtkPolyData>::New();
    surface->SetPoints(out->GetPoints());
    surface->SetPolys(out->GetPolys());
    // Shade by height so benches and ramps read at a glance.
    double uMin = verts[0].u, uMax = verts[0].u;
    for (const Enu& v : verts) {
        uMin = std::min(uMin, v.u);
        uMax = std::max(uMax, v.u);
    }
    auto colours = makeColours(3, "colour");
    for (const Enu& v : verts) {
        const double f = 0.75 + 0.45 * (uMax > uMin ? (v.u - uMin) / (uMax - uMin) : 0.5);
        colours->InsertNextTuple3(std::min(255.0, t.colour.r * f), std::min(255.0, t.colour.g * f),
                                  std::min(255.0, t.colour.b * f));
    }
    surface->GetPointData()->SetScalars(colours);
    return surface;
    return surface;
}

// No usable elevations: the given plane, or (points too few or collinear) a plane through their mean height
// covering their extent plus a margin.
vtkSmartPointer<vtkPolyData> SceneTerrain::buildPlane(const Terrain3D& t) {
    m_flatU = t.planeU;
    m_flatExtent = {std::min(t.minE, t.maxE), std::max(t.minE, t.maxE), std::min(t.minN, t.maxN),
                    std::max(t.minN, t.maxN)};
    if (!t.points.empty()) {
        double sumU = 0.0;
        m_flatExtent = {t.points[0].e, t.points[0].e, t.points[0].n, t.points[0].n};
        for (const Enu& p : t.points) {
            sumU += p.u;
            m_flatExtent[0] = std::min(m_flatExtent[0], p.e - 50.0);
            m_flatExtent[1] = std::max(m_flatExtent[1], p.e + 50.0);
            m_flatExtent[2] = std::min(m_flatExtent[2], p.n - 50.0);
            m_flatExtent[3] = std::max(m_flatExtent[3], p.n + 50.0);
        }
        m_flatU = sumU / static_cast<double>(t.points.size());
    }
    if (m_flatExtent[1] - m_flatExtent[0] < 1.0)
        m_flatExtent[1] = m_flatExtent[0] + 1.0;
    if (m_flatExtent[3] - m_flatExtent[2] < 1.0)
        m_flatExtent[3] = m_flatExtent[2] + 1.0;
    auto surface = vtkSmartPointer<vtkPolyData>::New();
    vtkNew<vtkPoints> pts;
    pts->InsertNextPoint(m_flatExtent[0], m_flatExtent[2], m_flatU);
    pts->InsertNextPoint(m_flatExtent[1], m_flatExtent[2], m_flatU);
    pts->InsertNextPoint(m_flatExtent[1], m_flatExtent[3], m_flatU);
    pts->InsertNextPoint(m_flatExtent[0], m_flatExtent[3], m_flatU);
    vtkNew<vtkCellArray> quad;
    const vtkIdType ids[4] = {0, 1, 2, 3};
    quad->InsertNextCell(4, ids);
    surface->SetPoints(pts);
    surface->SetPolys(quad);
    auto colours = makeColours(3, "colour");
    for (int i = 0; i < 4; ++i)
        colours->InsertNextTuple3(t.colour.r, t.colour.g, t.colour.b);
    surface->GetPointData()->SetScalars(colours);
    return surface;
}

void SceneTerrain::bounds(const Terrain3D& terrain, double b[6]) const {
    if (m_flat) {
        b[0] = m_flatExtent[0];
        b[1] = m_flatExtent[1];
        b[2] = m_flatExtent[2];
        b[3] = m_flatExtent[3];
        b[4] = m_flatU;
        b[5] = m_flatU + 5.0;
        return;
    }
    const TerrainGrid3D& g = terrain.grid;
    if (g.valid()) {
        b[0] = g.originE;
        b[1] = g.originE + (g.cols - 1) * g.step;
        b[2] = g.originN;
        b[3] = g.originN + (g.rows - 1) * g.step;
        b[4] = std::numeric_limits<double>::max();
        b[5] = std::numeric_limits<double>::lowest();
        for (double u : g.u)
            if (std::isfinite(u)) {
                b[4] = std::min(b[4], u);
                b[5] = std::max(b[5], u);
            }
        b[5] += 5.0;
        return;
    }
    const auto& pts = terrain.points;
    b[0] = b[2] = b[4] = std::numeric_limits<double>::max();
    b[1] = b[3] = b[5] = std::numeric_limits<double>::lowest();
    for (const Enu& p : pts) {
        b[0] = std::min(b[0], p.e);
        b[1] = std::max(b[1], p.e);
        b[2] = std::min(b[2], p.n);
        b[3] = std::max(b[3], p.n);
        b[4] = std::min(b[4], p.u);
        b[5] = std::max(b[5], p.u);
    }
    b[5] += 5.0;
}
} // namespace ocu::scene3d
