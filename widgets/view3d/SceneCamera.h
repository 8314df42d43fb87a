#pragma once
// The camera of the 3D scene: framing the site for the camera mode (free orbit, follow the selected machine,
// top-down north up), the follow camera, orbit and zoom for views without a VTK interactor, and the
// conversions between window pixels and the world.
#include "widgets/view3d/Scene3D.h"
#include "widgets/view3d/SceneCommon.h"

#include <QPointF>

#include <array>
#include <optional>

class vtkRenderer;

namespace ocu::scene3d {

class SceneCamera {
public:
    explicit SceneCamera(vtkRenderer* renderer) : m_renderer(renderer) {}

    CameraMode mode() const { return m_mode; }
    void setMode(CameraMode mode) { m_mode = mode; } // then reset()

    // Re-frames the site bounds (minE, maxE, minN, maxN, minU, maxU) for the current mode; in
    // FollowSelected, then puts the camera behind `selected`.
    void reset(const double bounds[6], const Machine3D* selected);
    // After a rebuild: frames the site the first time and whenever its extent changed, else keeps the view.
    void frame(const double bounds[6], const Machine3D* selected);
    // Follow: the first time (or after forgetFollow()) the camera is put behind the machine; afterwards it is
    // translated by the machine's movement, which keeps the machine centred and keeps the user's orbit.
    void follow(const Machine3D* selected);
    void forgetFollow() { m_followAnchor.reset(); }

    void orbit(double azimuthDeg, double elevationDeg);
    void zoom(double factor);
    double viewElevationDeg() const;

    // The line of sight through window pixel (x, y) (origin top-left) from the near to the far plane.
    bool ray(double x, double y, double out[2][3]) const;
    std::optional<QPointF> project(double e, double n, double u) const;

private:
    vtkRenderer* m_renderer;
    CameraMode m_mode = CameraMode::FreeOrbit;
    bool m_initialised = false;
    std::array<double, 4> m_extent{0, 0, 0, 0};
    std::optional<Vec3> m_followAnchor; // last machine centre the follow camera was aligned to
};

} // namespace ocu::scene3d
