#include "widgets/view3d/SceneCamera.h"

#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ocu::scene3d {

void SceneCamera::reset(const double bounds[6], const Machine3D* selected) {
    vtkCamera* cam = m_renderer->GetActiveCamera();
    double b[6];
    std::copy_n(bounds, 6, b);
    const double ce = (b[0] + b[1]) / 2, cn = (b[2] + b[3]) / 2, cu = (b[4] + b[5]) / 2;
    cam->SetFocalPoint(ce, cn, cu);
    if (m_mode == CameraMode::TopDown) {
        cam->SetPosition(ce, cn, cu + 100.0);
        cam->SetViewUp(0.0, 1.0, 0.0); // north up, like the 2D map
    } else {
        cam->SetPosition(ce, cn - 100.0, cu + 80.0); // looking north, tilted
        cam->SetViewUp(0.0, 0.0, 1.0);
    }
    m_renderer->ResetCamera(b);
    if (m_mode != CameraMode::TopDown)
        cam->Dolly(1.25);
    m_renderer->ResetCameraClippingRange();
    m_followAnchor.reset();
    if (m_mode == CameraMode::FollowSelected)
        follow(selected);
    m_initialised = true;
}

void SceneCamera::frame(const double b[6], const Machine3D* selected) {
    const std::array<double, 4> extent{b[0], b[1], b[2], b[3]};
    if (!m_initialised || extent != m_extent) {
        m_extent = extent;
        reset(b, selected);
    } else {
        m_renderer->ResetCameraClippingRange();
    }
}

void SceneCamera::follow(const Machine3D* m) {
    if (m == nullptr) {
        m_followAnchor.reset();
        return;
    }
    vtkCamera* cam = m_renderer->GetActiveCamera();
    const Vec3 c{m->e, m->n, m->u + m->height / 2.0}; // centre of the machine
    if (!m_followAnchor) {
        const double h = m->headingDeg * kDegToRad;
        const double dist = std::max(40.0, 6.0 * m->length);
        const double fe = std::sin(h), fn = std::cos(h);
        cam->SetFocalPoint(c.x, c.y, c.z);
        cam->SetPosition(c.x - fe * dist * 0.8, c.y - fn * dist * 0.8, c.z + dist * 0.6);
        cam->SetViewUp(0.0, 0.0, 1.0);
    } else {
        double fp[3], pos[3];
        cam->GetFocalPoint(fp);
        cam->GetPosition(pos);
        // Re-centre on the machine exactly (the user may have panned), keeping the view offset.
        const double off[3] = {pos[0] - fp[0], pos[1] - fp[1], pos[2] - fp[2]};
        cam->SetFocalPoint(c.x, c.y, c.z);
        cam->SetPosition(c.x + off[0], c.y + off[1], c.z + off[2]);
    }
    m_followAnchor = c;
    m_renderer->ResetCameraClippingRange();
}

double SceneCamera::viewElevationDeg() const {
    double dir[3];
    m_renderer->GetActiveCamera()->GetDirectionOfProjection(dir);
    return -std::asin(std::clamp(dir[2], -1.0, 1.0)) * 180.0 / std::numbers::pi;
}

void SceneCamera::orbit(double azimuthDeg, double elevationDeg) {
    if (m_mode == CameraMode::TopDown)
        return;
    vtkCamera* cam = m_renderer->GetActiveCamera();
    cam->Azimuth(azimuthDeg);
    // Keep the line of sight between 5 and 89 degrees below the horizon (world z up).
    const double current = viewElevationDeg();
    const double target = std::clamp(current + elevationDeg, 5.0, 89.0);
    cam->Elevation(target - current);
    cam->SetViewUp(0.0, 0.0, 1.0);
    cam->OrthogonalizeViewUp();
    m_renderer->ResetCameraClippingRange();
}

void SceneCamera::zoom(double factor) {
    if (factor <= 0)
        return;
    vtkCamera* cam = m_renderer->GetActiveCamera();
    if (cam->GetParallelProjection())
        cam->SetParallelScale(cam->GetParallelScale() / factor);
    else
        cam->Dolly(factor);
    m_renderer->ResetCameraClippingRange();
}

bool SceneCamera::ray(double x, double y, double out[2][3]) const {
    int w = 0, h = 0;
    if (!windowSize(m_renderer, w, h))
        return false;
    vtkRenderer* r = m_renderer;
    for (int k = 0; k < 2; ++k) {
        r->SetDisplayPoint(x, h - y, k == 0 ? 0.0 : 1.0);
        r->DisplayToWorld();
        double wp[4];
        r->GetWorldPoint(wp);
        if (wp[3] == 0.0)
            return false;
        for (int i = 0; i < 3; ++i)
            out[k][i] = wp[i] / wp[3];
    }
    return true;
}

std::optional<QPointF> SceneCamera::project(double e, double n, double u) const {
    int w = 0, h = 0;
    if (!windowSize(m_renderer, w, h))
        return std::nullopt;
    vtkRenderer* r = m_renderer;
    r->SetWorldPoint(e, n, u, 1.0);
    r->WorldToDisplay();
    double dp[3];
    r->GetDisplayPoint(dp);
    if (dp[2] < 0.0 || dp[2] > 1.0)
        return std::nullopt;
    return QPointF(dp[0], h - dp[1]);
}

} // namespace ocu::scene3d
