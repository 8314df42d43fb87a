#include "widgets/view3d/ScenePassTexture.h"

#include "protocols/common/Log.h"
#include "widgets/view3d/SceneCommon.h"
#include "widgets/view3d/SceneTerrain.h"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace ocu::scene3d {

namespace {

constexpr std::int64_t kMaxRasterCells = 64'000'000; // beyond this the raster is refused (256 MB of RGBA)
constexpr int kMaxTextureSide = 8192;                // larger rasters are sampled down for the texture

} // namespace

ScenePassTexture::ScenePassTexture() {
    m_actor->SetMapper(m_mapper);
    m_mapper->ScalarVisibilityOff();
    m_texture->SetInputData(m_image);
    m_texture->InterpolateOff(); // crisp cells, exact palette colours
    m_texture->RepeatOff();
    m_texture->EdgeClampOn();
    m_actor->SetTexture(m_texture);
    m_actor->GetProperty()->LightingOff(); // the same colours as the 2D map and the legend
    // Nothing is drawn in VTK's translucent pass (see SiteSceneRenderer): the surface is forced opaque and
    // its alpha-0 texels still blend away.
    m_actor->ForceOpaqueOn();
    m_actor->SetVisibility(false);
    // Pulled towards the camera in depth more than the ways, so it wins over them and the terrain.
    m_mapper->SetRelativeCoincidentTopologyPolygonOffsetParameters(-3, -6);
}

void ScenePassTexture::build(const PassCountRaster& r, const SceneTerrain& terrain) {
    bool usable = !r.empty() && r.cellSize > 0.0 && std::isfinite(r.cellSize) && std::isfinite(r.originE) &&
                  std::isfinite(r.originN);
    if (usable && static_cast<std::int64_t>(r.cols) * r.rows > kMaxRasterCells) {
        logWarning(kLogCategory, "pass-count raster of " + std::to_string(r.cols) + " x " +
                                     std::to_string(r.rows) +
                                     " cells is too large for the 3D view; not drawn");
        usable = false;
    } else if (!usable && (r.cols > 0 || r.rows > 0)) {
        logWarning(kLogCategory,
                   "pass-count raster ignored: rgba must hold cols*rows*4 bytes and the cell size "
                   "must be positive");
    }
    m_actor->SetVisibility(usable);
    if (!usable) {
        m_geometry = {};
        return;
    }
    const std::array<double, 4> geometry{r.originE, r.originN, r.cellSize,
                                         static_cast<double>(r.cols) * 1e6 + r.rows};
    if (geometry != m_geometry) {
        m_geometry = geometry;
        buildMesh(r, terrain);
    }
    fillTexture(r);
}

void ScenePassTexture::buildMesh(const PassCountRaster& r, const SceneTerrain& terrain) {
    const double e0 = r.originE, n0 = r.originN;
    const double we = r.cols * r.cellSize, wn = r.rows * r.cellSize;
    // Flat ground needs one quad; on terrain the mesh follows it every drape step (at most 128 x 128 quads).
    const int nx =
        terrain.flat() ? 1 : std::clamp(static_cast<int>(std::ceil(we / terrain.drapeStep())), 1, 128);
    const int ny =
        terrain.flat() ? 1 : std::clamp(static_cast<int>(std::ceil(wn / terrain.drapeStep())), 1, 128);
    vtkNew<vtkPoints> pts;
    vtkNew<vtkFloatArray> tcoords;
    tcoords->SetNumberOfComponents(2);
    tcoords->SetName("tcoords");
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) {
            const double s = static_cast<double>(i) / nx, t = static_cast<double>(j) / ny;
            const double e = e0 + s * we, n = n0 + t * wn;
            pts->InsertNextPoint(e, n, terrain.height(e, n) + kLiftPassCount);
            tcoords->InsertNextTuple2(s, t);
        }
    vtkNew<vtkCellArray> quads;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const vtkIdType a = j * (nx + 1) + i;
            const vtkIdType ids[4] = {a, a + 1, a + nx + 2, a + nx + 1};
            quads->InsertNextCell(4, ids);
        }
    vtkNew<vtkPolyData> surface;
    surface->SetPoints(pts);
    surface->SetPolys(quads);
    surface->GetPointData()->SetTCoords(tcoords);
    m_mapper->SetInputData(surface);
}

void ScenePassTexture::fillTexture(const PassCountRaster& r) {
    // Very large rasters are sampled down to what every GL implementation can hold (nearest cell).
    const int step = std::max({1, (r.cols + kMaxTextureSide - 1) / kMaxTextureSide,
                               (r.rows + kMaxTextureSide - 1) / kMaxTextureSide});
    const int tw = (r.cols + step - 1) / step, th = (r.rows + step - 1) / step;
    if (m_image->GetDimensions()[0] != tw || m_image->GetDimensions()[1] != th) {
        m_image->SetDimensions(tw, th, 1);
        m_image->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
    }
    auto* dst = static_cast<std::uint8_t*>(m_image->GetScalarPointer());
    // Row 0 is the south row in both the raster and VTK images (origin bottom-left): a straight copy.
    if (step == 1) {
        std::copy_n(r.rgba.data(), static_cast<std::size_t>(tw) * th * 4, dst);
    } else {
        for (int y = 0; y < th; ++y)
            for (int x = 0; x < tw; ++x)
                std::copy_n(&r.rgba[(static_cast<std::size_t>(y) * step * r.cols + x * step) * 4], 4,
                            &dst[(static_cast<std::size_t>(y) * tw + x) * 4]);
    }
    m_image->Modified();
}

std::array<int, 2> ScenePassTexture::textureSize() const {
    if (!m_actor->GetVisibility() || m_image->GetScalarPointer() == nullptr)
        return {0, 0};
    return {m_image->GetDimensions()[0], m_image->GetDimensions()[1]};
}

std::array<std::uint8_t, 4> ScenePassTexture::texel(int x, int y) const {
    const auto [w, h] = textureSize();
    if (x < 0 || y < 0 || x >= w || y >= h)
        return {0, 0, 0, 0};
    const auto* p = static_cast<const std::uint8_t*>(m_image->GetScalarPointer(x, y, 0));
    return {p[0], p[1], p[2], p[3]};
}

} // namespace ocu::scene3d
