#include "widgets/view3d/SceneMachines.h"

#include "protocols/common/Log.h"
#include "widgets/view3d/SceneCommon.h"

#include <vtkAppendPolyData.h>
#include <vtkCamera.h>
#include <vtkCylinderSource.h>
#include <vtkPointData.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace ocu::scene3d {

namespace {

// Machine shapes in the unit frame the glyphs are scaled from: x = width [-0.5, 0.5], y = length (forward
// = +y) [-0.5, 0.5], z = height [0, 1]. Made of a few boxes (and a drum) so the type and the front read at a
// glance; index = int(MachineShape).
vtkSmartPointer<vtkPolyData> shapeOf(MachineShape shape) {
    vtkNew<vtkAppendPolyData> all;
    auto box = [&](double x0, double x1, double y0, double y1, double z0, double z1) {
        vtkNew<vtkCubeSource> c;
        c->SetBounds(x0, x1, y0, y1, z0, z1);
        c->Update();
        all->AddInputData(c->GetOutput());
    };
    auto drum = [&](double y, double radius) { // a cylinder across the machine (axis = x)
        vtkNew<vtkCylinderSource> c;
        c->SetResolution(16);
        c->SetRadius(radius);
        c->SetHeight(1.0);
        vtkNew<vtkTransform> t;
        t->Translate(0.0, y, radius);
        t->RotateZ(90.0);
        vtkNew<vtkTransformPolyDataFilter> f;
        f->SetTransform(t);
        f->SetInputConnection(c->GetOutputPort());
        f->Update();
        all->AddInputData(f->GetOutput());
    };
    switch (shape) {
    case MachineShape::HaulTruck: // low chassis, raised dump body at the rear with a canopy over the cab
        box(-0.45, 0.45, -0.5, 0.5, 0.0, 0.35);
        box(-0.5, 0.5, -0.5, 0.2, 0.35, 1.0);
        box(-0.45, 0.05, 0.25, 0.5, 0.35, 0.8);
        box(-0.5, 0.5, 0.2, 0.5, 0.85, 0.95);
        break;
    case MachineShape::Ugv: // flat body, a mast, a low bumper in front
        box(-0.5, 0.5, -0.5, 0.4, 0.15, 0.6);
        box(-0.4, 0.4, 0.4, 0.5, 0.05, 0.35);
        box(-0.08, 0.08, 0.05, 0.25, 0.6, 1.0);
        break;
    case MachineShape::Roller: // the drum in front, engine body and cab behind
        drum(0.3, 0.28);
        box(-0.45, 0.45, -0.5, 0.05, 0.1, 0.55);
        box(-0.35, 0.35, -0.4, 0.0, 0.55, 1.0);
        break;
    case MachineShape::Paver: // hopper in front, wide screed behind, canopy
        box(-0.45, 0.45, -0.3, 0.3, 0.0, 0.6);
        box(-0.5, 0.5, 0.3, 0.5, 0.2, 0.7);
        box(-0.5, 0.5, -0.5, -0.3, 0.0, 0.25);
        box(-0.4, 0.4, -0.25, 0.1, 0.9, 1.0);
        box(-0.4, -0.35, -0.25, 0.1, 0.6, 0.9);
        box(0.35, 0.4, -0.25, 0.1, 0.6, 0.9);
        break;
    case MachineShape::Loader: // body and cab, arms and the bucket in front
        box(-0.45, 0.45, -0.5, 0.15, 0.0, 0.6);
        box(-0.3, 0.3, -0.25, 0.15, 0.6, 1.0);
        box(-0.35, 0.35, 0.15, 0.35, 0.2, 0.45);
        box(-0.5, 0.5, 0.35, 0.5, 0.0, 0.4);
        break;
    case MachineShape::LightVehicle: // body and a cabin set back
        box(-0.5, 0.5, -0.5, 0.5, 0.0, 0.5);
        box(-0.45, 0.45, -0.35, 0.2, 0.5, 1.0);
        break;
    case MachineShape::Unknown:
        box(-0.5, 0.5, -0.5, 0.5, 0.0, 1.0);
        break;
    }
    all->Update();
    auto out = vtkSmartPointer<vtkPolyData>::New();
    out->DeepCopy(all->GetOutput());
    return out;
}

constexpr int kShapeCount = static_cast<int>(MachineShape::LightVehicle) + 1;
constexpr double kMinMachinePx = 12.0; // smallest drawn size across, pixels

} // namespace

SceneMachines::SceneMachines(const std::vector<Machine3D>& machines)
    : m_machines(machines), m_colour(makeColours(3, "colour")) {
    m_scale->SetName("scale");
    m_scale->SetNumberOfComponents(3);
    m_rotation->SetName("rotation");
    m_rotation->SetNumberOfComponents(3);
    m_data->SetPoints(m_points);
    m_data->GetPointData()->AddArray(m_scale);
    m_data->GetPointData()->AddArray(m_rotation);
    m_shape->SetName("shape");
    m_data->GetPointData()->AddArray(m_shape);
    for (int i = 0; i < kShapeCount; ++i)
        m_mapper->SetSourceData(i, shapeOf(static_cast<MachineShape>(i)));
    m_mapper->SetSourceIndexArray("shape");
    m_mapper->SourceIndexingOn();
    m_data->GetPointData()->SetScalars(m_colour);
    m_mapper->SetInputData(m_data);
    m_mapper->SetScaleArray("scale");
    m_mapper->SetScaleModeToScaleByVectorComponents();
    m_mapper->SetOrientationArray("rotation");
    m_mapper->SetOrientationModeToRotation();
    m_mapper->SetColorModeToDirectScalars();
    m_mapper->SetScalarModeToUsePointData();
    m_mapper->ScalarVisibilityOn();
    m_actor->SetMapper(m_mapper);
    m_actor->GetProperty()->SetAmbient(0.35);
    m_actor->GetProperty()->SetDiffuse(0.65);

    m_selectionBox->SetCenter(0.0, 0.0, 0.5);
    m_selectionMapper->SetInputConnection(m_selectionBox->GetOutputPort());
    m_selectionActor->SetMapper(m_selectionMapper);
    m_selectionActor->GetProperty()->SetRepresentationToWireframe();
    m_selectionActor->GetProperty()->SetColor(1.0, 0.9, 0.0);
    m_selectionActor->GetProperty()->SetLineWidth(3.0);
    m_selectionActor->GetProperty()->LightingOff();
    m_selectionActor->SetVisibility(false);
}

void SceneMachines::layout() {
    const auto n = static_cast<vtkIdType>(m_machines.size());
    m_points->SetNumberOfPoints(n);
    m_scale->SetNumberOfTuples(n);
    m_rotation->SetNumberOfTuples(n);
    m_colour->SetNumberOfTuples(n);
    m_shape->SetNumberOfTuples(n);
    m_index.clear();
    for (vtkIdType i = 0; i < n; ++i)
        m_index.insert(m_machines[static_cast<std::size_t>(i)].id, static_cast<int>(i));
    ++m_layoutCount;
}

void SceneMachines::write(vtkIdType i, const Machine3D& m) {
    if (!finite(m)) {
        // Hidden (zero-size box) rather than dropped, so indices stay stable and the next good update
        // shows it.
        m_points->SetPoint(i, 0.0, 0.0, 0.0);
        m_scale->SetTuple3(i, 0.0, 0.0, 0.0);
        m_rotation->SetTuple3(i, 0.0, 0.0, 0.0);
        m_colour->SetTuple3(i, 0, 0, 0);
        m_shape->SetValue(i, 0);
        return;
    }
    m_shape->SetValue(i, std::clamp(static_cast<int>(m.shape), 0, kShapeCount - 1));
    m_points->SetPoint(i, m.e, m.n, m.u);
    m_scale->SetTuple3(i, std::max(m.width, 0.1), std::max(m.length, 0.1), std::max(m.height, 0.1));
    m_rotation->SetTuple3(i, 0.0, 0.0,
                          -m.headingDeg); // VTK rotates counter-clockwise; heading is clockwise
    m_colour->SetTuple3(i, m.colour.r, m.colour.g, m.colour.b);
}

void SceneMachines::update(bool sameSet) {
    if (!sameSet)
        layout();
    std::size_t bad = 0;
    for (std::size_t i = 0; i < m_machines.size(); ++i) {
        const Machine3D& m = m_machines[i];
        write(static_cast<vtkIdType>(i), m);
        bad += finite(m) ? 0 : 1;
    }
    if (bad != m_lastBad) // only on change: updates come at 10 Hz
        logWarning(kLogCategory, std::to_string(bad) + " machine(s) with non-finite pose or size are hidden");
    m_lastBad = bad;
    m_points->Modified();
    m_scale->Modified();
    m_rotation->Modified();
    m_colour->Modified();
    m_shape->Modified();
    m_data->Modified();
    m_actor->SetVisibility(!m_machines.empty());
}

const Machine3D* SceneMachines::find(const QString& id) const {
    const auto it = m_index.constFind(id);
    if (id.isEmpty() || it == m_index.constEnd())
        return nullptr;
    const Machine3D* m = &m_machines[static_cast<std::size_t>(*it)];
    return finite(*m) ? m : nullptr;
}

void SceneMachines::showSelection(const Machine3D* m) {
    m_selectionActor->SetVisibility(m != nullptr);
    if (m == nullptr)
        return;
    m_selectionActor->SetPosition(m->e, m->n, m->u);
    m_selectionActor->SetOrientation(0.0, 0.0, -m->headingDeg);
    m_selectionActor->SetScale(m->width + 0.6, m->length + 0.6, m->height + 0.3);
}

void SceneMachines::applyMinimumSize(vtkRenderer* renderer) {
    int w = 0, h = 0;
    if (!windowSize(renderer, w, h) || h <= 0 || m_machines.empty())
        return;
    vtkCamera* cam = renderer->GetActiveCamera();
    double eye[3];
    cam->GetPosition(eye);
    // Metres per pixel at distance 1 (perspective) or everywhere (parallel projection).
    const double perPx = cam->GetParallelProjection()
                             ? 2.0 * cam->GetParallelScale() / h
                             : 2.0 * std::tan(cam->GetViewAngle() * kDegToRad / 2.0) / h;
    bool changed = false;
    for (std::size_t i = 0; i < m_machines.size(); ++i) {
        const Machine3D& m = m_machines[i];
        if (!finite(m))
            continue;
        const double d =
            cam->GetParallelProjection() ? 1.0 : std::hypot(m.e - eye[0], m.n - eye[1], m.u - eye[2]);
        const double size = std::max({m.width, m.length, 0.1});
        const double k = std::max(1.0, kMinMachinePx * perPx * d / size);
        double cur[3];
        m_scale->GetTuple(static_cast<vtkIdType>(i), cur);
        const double want[3] = {std::max(m.width, 0.1) * k, std::max(m.length, 0.1) * k,
                                std::max(m.height, 0.1) * k};
        if (std::abs(cur[0] - want[0]) > 1e-3 * want[0] || std::abs(cur[2] - want[2]) > 1e-3 * want[2]) {
            m_scale->SetTuple3(static_cast<vtkIdType>(i), want[0], want[1], want[2]);
            changed = true;
        }
    }
    if (changed) {
        m_scale->Modified();
        m_data->Modified();
    }
}

QString SceneMachines::pick(const double ray[2][3]) const {
    const double dir[3] = {ray[1][0] - ray[0][0], ray[1][1] - ray[0][1], ray[1][2] - ray[0][2]};
    QString best;
    double bestT = std::numeric_limits<double>::max();
    for (const Machine3D& m : m_machines) {
        if (!finite(m))
            continue;
        // Ray into the box frame: x = right, y = forward, z = up from the ground point.
        const double hr = m.headingDeg * kDegToRad;
        const double fe = std::sin(hr), fn = std::cos(hr);  // forward
        const double re = std::cos(hr), rn = -std::sin(hr); // right
        const double oe = ray[0][0] - m.e, on = ray[0][1] - m.n, ou = ray[0][2] - m.u;
        const double o[3] = {oe * re + on * rn, oe * fe + on * fn, ou};
        const double v[3] = {dir[0] * re + dir[1] * rn, dir[0] * fe + dir[1] * fn, dir[2]};
        const double lo[3] = {-m.width / 2, -m.length / 2, 0.0};
        const double hi[3] = {m.width / 2, m.length / 2, m.height};
        double t0 = 0.0, t1 = 1.0;
        bool hit = true;
        for (int i = 0; i < 3 && hit; ++i) {
            if (std::abs(v[i]) < 1e-12) {
                hit = o[i] >= lo[i] && o[i] <= hi[i];
                continue;
            }
            double a = (lo[i] - o[i]) / v[i], b = (hi[i] - o[i]) / v[i];
            if (a > b)
                std::swap(a, b);
            t0 = std::max(t0, a);
            t1 = std::min(t1, b);
            hit = t0 <= t1;
        }
        if (hit && t0 < bestT) {
            bestT = t0;
            best = m.id;
        }
    }
    return best;
}

} // namespace ocu::scene3d
