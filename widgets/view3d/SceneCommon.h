#pragma once
// What the parts of the 3D scene (terrain, ways, pass texture, machines, labels, camera) share: the draping
// lifts, finiteness checks of the input values, colour arrays and the window size of the renderer. Private to
// ocu_view3d: VTK headers are fine here, SiteSceneRenderer.h stays VTK-free.
#include "widgets/view3d/Scene3D.h"

#include <vtkMapper.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>

#include <cmath>
#include <numbers>

namespace ocu::scene3d {

constexpr double kDegToRad = std::numbers::pi / 180.0;
// Draping lifts above the terrain (metres): enough to avoid z-fighting at site scale, small enough to look
// flat.
constexpr double kLiftArea = 0.08;
constexpr double kLiftRoad = 0.15;
constexpr double kLiftLane = 0.22;
constexpr double kLiftPassCount = 0.30;
constexpr const char* kLogCategory = "ocu.view3d";

inline bool finite(const Enu& p) {
    return std::isfinite(p.e) && std::isfinite(p.n) && std::isfinite(p.u);
}

inline bool finite(const Machine3D& m) {
    return std::isfinite(m.e) && std::isfinite(m.n) && std::isfinite(m.u) && std::isfinite(m.headingDeg) &&
           std::isfinite(m.length) && std::isfinite(m.width) && std::isfinite(m.height);
}

struct Vec3 {
    double x, y, z;
};

inline vtkSmartPointer<vtkUnsignedCharArray> makeColours(int components, const char* name) {
    auto a = vtkSmartPointer<vtkUnsignedCharArray>::New();
    a->SetNumberOfComponents(components);
    a->SetName(name);
    return a;
}

inline void configureDirectColours(vtkMapper* mapper, bool cellData) {
    mapper->SetColorModeToDirectScalars();
    mapper->ScalarVisibilityOn();
    if (cellData)
        mapper->SetScalarModeToUseCellData();
    else
        mapper->SetScalarModeToUsePointData();
}

// Size of the window the renderer draws into (device pixels); false while it has none or it is empty.
inline bool windowSize(vtkRenderer* renderer, int& w, int& h) {
    if (renderer->GetRenderWindow() == nullptr)
        return false;
    const int* s = renderer->GetSize();
    w = s[0];
    h = s[1];
    return w > 0 && h > 0;
}

} // namespace ocu::scene3d
