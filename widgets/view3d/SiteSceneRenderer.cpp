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

SiteSceneRenderer::SiteSceneRenderer() : d(std::make_unique<Impl>()) {}
SiteSceneRenderer::~SiteSceneRenderer() = default;

vtkRenderer* SiteSceneRenderer::renderer() const {
    return d->renderer;
}

void SiteSceneRenderer::setScene(const Scene3D& scene) {
    const std::vector<Machine3D> machines = scene.machines;
    d->scene = scene;
    d->scene.machines = {};
    d->machines.forgetIds();
    d->renderer->SetBackground(scene.background.r / 255.0, scene.background.g / 255.0,
                               scene.background.b / 255.0);
    d->terrain.build(d->scene.terrain);
    d->ways.build(d->scene.ways, d->terrain);
    d->passTexture.invalidateMesh(); // the terrain may have changed: re-drape the raster mesh
    d->passTexture.build(d->scene.passCount, d->terrain);
    d->applyMachines(machines);
    ++d->buildCount;
    double b[6];
    d->terrain.bounds(d->scene.terrain, b);
    d->camera.frame(b, d->machines.find(d->selected));
}

void SiteSceneRenderer::updateMachines(const std::vector<Machine3D>& machines) {
    d->applyMachines(machines);
    d->renderer->ResetCameraClippingRange();
}

void SiteSceneRenderer::setPassCount(const PassCountRaster& raster, const std::vector<LegendEntry>& legend) {
    d->scene.passCount = raster;
    d->scene.legend = legend;
    d->passTexture.build(d->scene.passCount, d->terrain);
}

void SiteSceneRenderer::setSelectedMachine(const QString& id) {
    if (id != d->selected)
        d->camera.forgetFollow();
    d->selected = id;
    for (Machine3D& m : d->scene.machines)
        m.selected = (m.id == id);
    d->updateSelection();
}

QString SiteSceneRenderer::selectedMachine() const {
    return d->selected;
}

void SiteSceneRenderer::setCameraMode(CameraMode mode) {
    if (mode == d->camera.mode())
        return;
    d->camera.setMode(mode);
    d->resetCamera();
}

CameraMode SiteSceneRenderer::cameraMode() const {
    return d->camera.mode();
}

void SiteSceneRenderer::resetCamera() {
    d->resetCamera();
}

double SiteSceneRenderer::viewElevationDeg() const {
    return d->camera.viewElevationDeg();
}

void SiteSceneRenderer::orbit(double azimuthDeg, double elevationDeg) {
    d->camera.orbit(azimuthDeg, elevationDeg);
}

void SiteSceneRenderer::zoom(double factor) {
    d->camera.zoom(factor);
}

double SiteSceneRenderer::terrainHeight(double e, double n) const {
    return d->terrain.height(e, n);
}

QString SiteSceneRenderer::pick(double x, double y) const {
    double ray[2][3];
    if (!d->camera.ray(x, y, ray))
        return {};
    return d->machines.pick(ray);
}

std::optional<QPointF> SiteSceneRenderer::project(double e, double n, double u) const {
    return d->camera.project(e, n, u);
}

const Scene3D& SiteSceneRenderer::scene() const {
    return d->scene;
}

std::optional<Machine3D> SiteSceneRenderer::machine(const QString& id) const {
    const Machine3D* m = d->machines.find(id);
    if (m == nullptr)
        return std::nullopt;
    return *m;
}

std::uint64_t SiteSceneRenderer::sceneBuildCount() const {
    return d->buildCount;
}

std::uint64_t SiteSceneRenderer::machineLayoutCount() const {
    return d->machines.layoutCount();
}

std::vector<QRectF> SiteSceneRenderer::nameLabelRects() const {
    return d->labels.rects();
}

std::uint64_t SiteSceneRenderer::renderCount() const {
    return d->renders;
}

std::array<int, 2> SiteSceneRenderer::passTextureSize() const {
    return d->passTexture.textureSize();
}

std::array<std::uint8_t, 4> SiteSceneRenderer::passTexel(int x, int y) const {
    return d->passTexture.texel(x, y);
}

} // namespace ocu
