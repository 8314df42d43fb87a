#pragma once
// The compaction pass-count raster in the 3D scene: a texture (one texel per cell, nearest filtering) on a
// mesh draped over the terrain, so a fine grid (1 km² at 0.34 m = 8.6 M cells) costs one texture upload, not
// millions of quads.
#include "widgets/view3d/Scene3D.h"

#include <vtkActor.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPolyDataMapper.h>
#include <vtkTexture.h>

#include <array>
#include <cstdint>

namespace ocu::scene3d {

class SceneTerrain;

class ScenePassTexture {
public:
    ScenePassTexture();

    vtkActor* actor() const { return m_actor; }

    // Shows `raster` (hidden when it is empty or unusable). The draped mesh is rebuilt only when the raster's
    // geometry changed since the last call or after invalidateMesh().
    void build(const PassCountRaster& raster, const SceneTerrain& terrain);
    // The terrain changed: the next build() re-drapes the mesh.
    void invalidateMesh() { m_geometry = {}; }

    std::array<int, 2> textureSize() const; // (0, 0) while hidden
    std::array<std::uint8_t, 4> texel(int x, int y) const;

private:
    void buildMesh(const PassCountRaster& r, const SceneTerrain& terrain);
    void fillTexture(const PassCountRaster& r);

    vtkNew<vtkActor> m_actor;
    vtkNew<vtkPolyDataMapper> m_mapper;
    vtkNew<vtkImageData> m_image;
    vtkNew<vtkTexture> m_texture;
    std::array<double, 4> m_geometry{0, 0, 0, 0}; // origin, cell size, cols/rows of the current mesh
};

} // namespace ocu::scene3d
