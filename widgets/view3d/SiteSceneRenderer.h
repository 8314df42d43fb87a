#pragma once
// Builds and updates the VTK scene of the 3D site view from a Scene3D. VTK stays behind the pimpl;
// only a forward declaration of vtkRenderer is visible here. The renderer is attached to a window by
// VtkOpenGLWidget (GUI) or EglOffscreenRenderer (headless); both call only renderer().
// It composes the parts of the scene, one class and file each: SceneTerrain (the ground and its heights),
// SceneWays (roads, lanes, areas), ScenePassTexture (the pass-count raster), SceneMachines (machine glyphs,
// selection box, picking), SceneLabels (name labels) and SceneCamera (framing, follow, orbit, projection).
#include "widgets/view3d/Scene3D.h"

#include <QPointF>
#include <QRectF>
#include <QString>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

class vtkRenderer;

namespace ocu {

class SiteSceneRenderer {
public:
    SiteSceneRenderer();
    ~SiteSceneRenderer();
    SiteSceneRenderer(const SiteSceneRenderer&) = delete;
    SiteSceneRenderer& operator=(const SiteSceneRenderer&) = delete;

    vtkRenderer* renderer() const;

    // Full rebuild: terrain, ways, pass-count surface, then the machines. Resets the camera the first time
    // (and whenever the terrain extent changes).
    void setScene(const Scene3D& scene);
    // Fast path: moves/recolours the machine boxes in place. Terrain, ways and raster are not touched; the
    // machine arrays are only resized when the set of ids changes. A machine with selected == true selects
    // it.
    void updateMachines(const std::vector<Machine3D>& machines);
    // Replaces only the pass-count surface and its legend.
    void setPassCount(const PassCountRaster& raster, const std::vector<LegendEntry>& legend);

    void setSelectedMachine(const QString& id); // empty = none
    QString selectedMachine() const;

    void setCameraMode(CameraMode mode);
    CameraMode cameraMode() const;
    void resetCamera(); // re-frames the whole site for the current mode
    // Camera moves for a view without a VTK interactor (the headless image view), like the GL widget's
    // trackball: orbit turns about the focal point (degrees; not in TopDown, which stays north-up), zoom > 1
    // moves closer. Elevation stops short of the poles so the view never flips over.
    void orbit(double azimuthDeg, double elevationDeg);
    void zoom(double factor);
    // Elevation of the line of sight below the horizon, degrees (90 = straight down).
    double viewElevationDeg() const;

    // Terrain height at (e, n) (barycentric on the Delaunay surface, plane height otherwise).
    double terrainHeight(double e, double n) const;

    // Both use window pixel coordinates with the origin at the top-left (Qt convention), in device pixels
    // of the render window the renderer is attached to. They need that window (size > 0).
    QString pick(double x, double y) const; // machine id under the pixel, or empty
    std::optional<QPointF> project(double e, double n, double u) const; // world -> pixel; nullopt when behind

    const Scene3D& scene() const; // last scene, machines as last updated
    std::optional<Machine3D> machine(const QString& id) const;
    std::uint64_t sceneBuildCount() const;    // number of full rebuilds (setScene calls)
    std::uint64_t machineLayoutCount() const; // number of times the machine arrays were re-laid out
    // Frames drawn by any window this renderer is attached to (VTK StartEvent of the renderer): a hidden
    // view must not move it.
    std::uint64_t renderCount() const;
    // Where the machines' name labels were drawn in the last frame (display pixels, origin bottom-left):
    // nearest machines first, at most 40, never overlapping each other or the selected machine's label.
    std::vector<QRectF> nameLabelRects() const;
    // The pass-count texture as handed to VTK (one texel per cell, row 0 = south; a raster wider than the
    // GL limit is sampled down). Size (0, 0) when no pass counts are drawn; texel RGBA, zeros outside.
    std::array<int, 2> passTextureSize() const;
    std::array<std::uint8_t, 4> passTexel(int x, int y) const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace ocu
