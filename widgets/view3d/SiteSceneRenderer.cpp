#include "widgets/view3d/SiteSceneRenderer.h"

#include "widgets/view3d/SceneCamera.h"
#include "widgets/view3d/SceneLabels.h"
#include "widgets/view3d/SceneMachines.h"
#include "widgets/view3d/ScenePassTexture.h"
#include "widgets/view3d/SceneTerrain.h"
#include "widgets/view3d/SceneWays.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkNew.h>
#include <vtkRenderer.h>

#include <cmath>

namespace ocu {

using namespace scene3d;

struct SiteSceneRenderer::Impl {
    vtkNew<vtkRenderer> renderer;
    Scene3D scene; // machines as last updated
    QString selected;
    SceneTerrain terrain;
    SceneWays ways;
    ScenePassTexture passTexture;
    SceneMachines machines{scene.machines};
    SceneLabels labels;
    SceneCamera camera{renderer.Get()};
    std::uint64_t buildCount = 0;
    std::uint64_t renders = 0;
    vtkNew<vtkCallbackCommand> renderObserver;

    Impl() {
        renderObserver->SetClientData(this);
        renderObserver->SetCallback(
            [](vtkObject*, unsigned long, void* self, void*) { static_cast<Impl*>(self)->beforeFrame(); });
        renderer->AddObserver(vtkCommand::StartEvent, renderObserver);
        for (const auto& t : labels.nameLabels())
            renderer->AddActor2D(t);
        renderer->SetBackground(0.78, 0.84, 0.92);
        // Nothing is drawn in VTK's translucent pass: in 9.1 that pass always runs order-independent
        // transparency (extra full-screen passes, several ms per frame on llvmpipe). The pass-count surface
        // is forced opaque (its no-data texels still blend away) and the labels are 2D overlays.
        renderer->UseDepthPeelingOff();
        renderer->AddActor(terrain.actor());
        renderer->AddActor(ways.areaActor());
        renderer->AddActor(ways.ribbonActor());
        renderer->AddActor(passTexture.actor());
        renderer->AddActor(machines.glyphActor());
        renderer->AddActor(machines.selectionActor());
        renderer->AddActor(labels.selectedLabel());
    }

    // Before every frame (the camera may have moved): minimum machine size and the name labels.
    void beforeFrame() {
        ++renders;
        machines.applyMinimumSize(renderer);
        labels.place(renderer, scene.machines, machines.find(selected), selected, machines.visible());
    }

    void applyMachines(const std::vector<Machine3D>& incoming) {
        bool sameSet = incoming.size() == scene.machines.size();
        for (std::size_t i = 0; sameSet && i < incoming.size(); ++i)
            sameSet = incoming[i].id == scene.machines[i].id;
        scene.machines = incoming;
        if (scene.clampMachinesToTerrain)
            for (Machine3D& m : scene.machines)
                if (std::isfinite(m.e) && std::isfinite(m.n))
                    m.u = terrain.height(m.e, m.n);
        machines.update(sameSet);
        for (const Machine3D& m : scene.machines)
            if (m.selected)
                selected = m.id;
        updateSelection();
    }

    void updateSelection() {
        const Machine3D* m = machines.find(selected);
        machines.showSelection(m);
        labels.showSelected(m);
        if (camera.mode() == CameraMode::FollowSelected)
            camera.follow(m);
    }

    void resetCamera() {
        double b[6];
        terrain.bounds(scene.terrain, b);
        camera.reset(b, machines.find(selected));
    }
};

SiteSceneRenderer::SiteSceneRenderer() : m_impl(std::make_unique<Impl>()) {}
SiteSceneRenderer::~SiteSceneRenderer() = default;

vtkRenderer* SiteSceneRenderer::renderer() const {
    return m_impl->renderer;
}

void SiteSceneRenderer::setScene(const Scene3D& scene) {
    const std::vector<Machine3D> machines = scene.machines;
    m_impl->scene = scene;
    m_impl->scene.machines = {};
    m_impl->machines.forgetIds();
    m_impl->renderer->SetBackground(scene.background.r / 255.0, scene.background.g / 255.0,
                                    scene.background.b / 255.0);
    m_impl->terrain.build(m_impl->scene.terrain);
    m_impl->ways.build(m_impl->scene.ways, m_impl->terrain);
    m_impl->passTexture.invalidateMesh(); // the terrain may have changed: re-drape the raster mesh
    m_impl->passTexture.build(m_impl->scene.passCount, m_impl->terrain);
    m_impl->applyMachines(machines);
    ++m_impl->buildCount;
    double b[6];
    m_impl->terrain.bounds(m_impl->scene.terrain, b);
    m_impl->camera.frame(b, m_impl->machines.find(m_impl->selected));
}

void SiteSceneRenderer::updateMachines(const std::vector<Machine3D>& machines) {
    m_impl->applyMachines(machines);
    m_impl->renderer->ResetCameraClippingRange();
}

void SiteSceneRenderer::setPassCount(const PassCountRaster& raster, const std::vector<LegendEntry>& legend) {
    m_impl->scene.passCount = raster;
    m_impl->scene.legend = legend;
    m_impl->passTexture.build(m_impl->scene.passCount, m_impl->terrain);
}

void SiteSceneRenderer::setSelectedMachine(const QString& id) {
    if (id != m_impl->selected)
        m_impl->camera.forgetFollow();
    m_impl->selected = id;
    for (Machine3D& m : m_impl->scene.machines)
        m.selected = (m.id == id);
    m_impl->updateSelection();
}

QString SiteSceneRenderer::selectedMachine() const {
    return m_impl->selected;
}

void SiteSceneRenderer::setCameraMode(CameraMode mode) {
    if (mode == m_impl->camera.mode())
        return;
    m_impl->camera.setMode(mode);
    m_impl->resetCamera();
}

CameraMode SiteSceneRenderer::cameraMode() const {
    return m_impl->camera.mode();
}

void SiteSceneRenderer::resetCamera() {
    m_impl->resetCamera();
}

double SiteSceneRenderer::viewElevationDeg() const {
    return m_impl->camera.viewElevationDeg();
}

void SiteSceneRenderer::orbit(double azimuthDeg, double elevationDeg) {
    m_impl->camera.orbit(azimuthDeg, elevationDeg);
}

void SiteSceneRenderer::zoom(double factor) {
    m_impl->camera.zoom(factor);
}

double SiteSceneRenderer::terrainHeight(double e, double n) const {
    return m_impl->terrain.height(e, n);
}

QString SiteSceneRenderer::pick(double x, double y) const {
    double ray[2][3];
    if (!m_impl->camera.ray(x, y, ray))
        return {};
    return m_impl->machines.pick(ray);
}

std::optional<QPointF> SiteSceneRenderer::project(double e, double n, double u) const {
    return m_impl->camera.project(e, n, u);
}

const Scene3D& SiteSceneRenderer::scene() const {
    return m_impl->scene;
}

std::optional<Machine3D> SiteSceneRenderer::machine(const QString& id) const {
    const Machine3D* m = m_impl->machines.find(id);
    if (m == nullptr)
        return std::nullopt;
    return *m;
}

std::uint64_t SiteSceneRenderer::sceneBuildCount() const {
    return m_impl->buildCount;
}

std::uint64_t SiteSceneRenderer::machineLayoutCount() const {
    return m_impl->machines.layoutCount();
}

std::vector<QRectF> SiteSceneRenderer::nameLabelRects() const {
    return m_impl->labels.rects();
}

std::uint64_t SiteSceneRenderer::renderCount() const {
    return m_impl->renders;
}

std::array<int, 2> SiteSceneRenderer::passTextureSize() const {
    return m_impl->passTexture.textureSize();
}

std::array<std::uint8_t, 4> SiteSceneRenderer::passTexel(int x, int y) const {
    return m_impl->passTexture.texel(x, y);
}

} // namespace ocu
