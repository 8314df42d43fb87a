#include "widgets/view3d/SiteSceneRenderer.h"

#include "protocols/common/Log.h"

#include <vtkActor.h>
#include <vtkAppendPolyData.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkCoordinate.h>
#include <vtkCubeSource.h>
#include <vtkCylinderSource.h>
#include <vtkDelaunay2D.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkGlyph3DMapper.h>
#include <vtkImageData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTexture.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>
#include <vtkTriangleFilter.h>
#include <vtkUnsignedCharArray.h>

#include <QHash>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace ocu {

namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;
// Draping lifts above the terrain (metres): enough to avoid z-fighting at site scale, small enough to look
// flat.
constexpr double kLiftArea = 0.08;
constexpr double kLiftRoad = 0.15;
constexpr double kLiftLane = 0.22;
constexpr double kLiftPassCount = 0.30;
constexpr std::int64_t kMaxRasterCells = 64'000'000; // beyond this the raster is refused (256 MB of RGBA)
constexpr int kMaxTextureSide = 8192;                // larger rasters are sampled down for the texture
constexpr const char* kLogCategory = "ocu.view3d";

bool finite(const Enu& p) {
    return std::isfinite(p.e) && std::isfinite(p.n) && std::isfinite(p.u);
}

bool finite(const Machine3D& m) {
    return std::isfinite(m.e) && std::isfinite(m.n) && std::isfinite(m.u) && std::isfinite(m.headingDeg) &&
           std::isfinite(m.length) && std::isfinite(m.width) && std::isfinite(m.height);
}

struct Vec3 {
    double x, y, z;
};

// Uniform bucket grid over the terrain triangles for height look-ups.
class TriangleIndex {
public:
    void build(std::vector<Enu> pts, std::vector<std::array<int, 3>> tris) {
        m_pts = std::move(pts);
        m_tris = std::move(tris);
        m_buckets.clear();
        if (m_pts.empty() || m_tris.empty())
            return;
        m_minE = m_maxE = m_pts[0].e;
        m_minN = m_maxN = m_pts[0].n;
        double sumU = 0.0;
        for (const Enu& p : m_pts) {
            m_minE = std::min(m_minE, p.e);
            m_maxE = std::max(m_maxE, p.e);
            m_minN = std::min(m_minN, p.n);
            m_maxN = std::max(m_maxN, p.n);
            sumU += p.u;
        }
        m_meanU = sumU / static_cast<double>(m_pts.size());
        const int n = static_cast<int>(std::clamp(std::sqrt(static_cast<double>(m_tris.size())), 1.0, 256.0));
        m_nx = m_ny = n;
        m_cellE = std::max((m_maxE - m_minE) / n, 1e-6);
        m_cellN = std::max((m_maxN - m_minN) / n, 1e-6);
        m_buckets.assign(static_cast<std::size_t>(m_nx * m_ny), {});
        for (int t = 0; t < static_cast<int>(m_tris.size()); ++t) {
            double e0 = 1e300, e1 = -1e300, n0 = 1e300, n1 = -1e300;
            for (int k : m_tris[t]) {
                e0 = std::min(e0, m_pts[k].e);
                e1 = std::max(e1, m_pts[k].e);
                n0 = std::min(n0, m_pts[k].n);
                n1 = std::max(n1, m_pts[k].n);
            }
            for (int j = cellY(n0); j <= cellY(n1); ++j)
                for (int i = cellX(e0); i <= cellX(e1); ++i)
                    m_buckets[static_cast<std::size_t>(j * m_nx + i)].push_back(t);
        }
    }

    bool valid() const { return !m_buckets.empty(); }
    double minE() const { return m_minE; }
    double maxE() const { return m_maxE; }
    double minN() const { return m_minN; }
    double maxN() const { return m_maxN; }

    double height(double e, double n) const {
        // Outside the hull: clamp into the bounding box, then fall back to the nearest vertex of the bucket.
        const double ce = std::clamp(e, m_minE, m_maxE);
        const double cn = std::clamp(n, m_minN, m_maxN);
        const auto& bucket = m_buckets[static_cast<std::size_t>(cellY(cn) * m_nx + cellX(ce))];
        for (int t : bucket) {
            const Enu& a = m_pts[m_tris[t][0]];
            const Enu& b = m_pts[m_tris[t][1]];
            const Enu& c = m_pts[m_tris[t][2]];
            const double det = (b.n - c.n) * (a.e - c.e) + (c.e - b.e) * (a.n - c.n);
            if (std::abs(det) < 1e-12)
                continue;
            const double l1 = ((b.n - c.n) * (ce - c.e) + (c.e - b.e) * (cn - c.n)) / det;
            const double l2 = ((c.n - a.n) * (ce - c.e) + (a.e - c.e) * (cn - c.n)) / det;
            const double l3 = 1.0 - l1 - l2;
            constexpr double eps = -1e-9;
            if (l1 >= eps && l2 >= eps && l3 >= eps)
                return l1 * a.u + l2 * b.u + l3 * c.u;
        }
        double best = std::numeric_limits<double>::max();
        double u = m_meanU;
        for (int t : bucket)
            for (int k : m_tris[t]) {
                const double d2 =
                    (m_pts[k].e - ce) * (m_pts[k].e - ce) + (m_pts[k].n - cn) * (m_pts[k].n - cn);
                if (d2 < best) {
                    best = d2;
                    u = m_pts[k].u;
                }
            }
        return u;
    }

private:
    int cellX(double e) const { return std::clamp(static_cast<int>((e - m_minE) / m_cellE), 0, m_nx - 1); }
    int cellY(double n) const { return std::clamp(static_cast<int>((n - m_minN) / m_cellN), 0, m_ny - 1); }

    std::vector<Enu> m_pts;
    std::vector<std::array<int, 3>> m_tris;
    std::vector<std::vector<int>> m_buckets;
    double m_minE = 0, m_maxE = 0, m_minN = 0, m_maxN = 0, m_cellE = 1, m_cellN = 1, m_meanU = 0;
    int m_nx = 1, m_ny = 1;
};

vtkSmartPointer<vtkUnsignedCharArray> makeColours(int components, const char* name) {
    auto a = vtkSmartPointer<vtkUnsignedCharArray>::New();
    a->SetNumberOfComponents(components);
    a->SetName(name);
    return a;
}

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
constexpr int kMaxLabels = 40; // name labels drawn at once (nearest first, never overlapping)

void configureDirectColours(vtkMapper* mapper, bool cellData) {
    mapper->SetColorModeToDirectScalars();
    mapper->ScalarVisibilityOn();
    if (cellData)
        mapper->SetScalarModeToUseCellData();
    else
        mapper->SetScalarModeToUsePointData();
}

} // namespace

struct SiteSceneRenderer::Impl {
    vtkNew<vtkRenderer> renderer;

    // Terrain
    vtkNew<vtkActor> terrainActor;
    vtkNew<vtkPolyDataMapper> terrainMapper;
    TriangleIndex terrainIndex;
    bool flatTerrain = true;
    double drapeStep = 2.0;                       // resampling distance of draped layers (m)
    double flatU = 0.0;                           // plane height when flat
    std::array<double, 4> flatExtent{0, 0, 0, 0}; // minE, maxE, minN, maxN of the plane

    // Ways
    vtkNew<vtkActor> ribbonActor;
    vtkNew<vtkPolyDataMapper> ribbonMapper;
    vtkNew<vtkActor> areaActor;
    vtkNew<vtkPolyDataMapper> areaMapper;
    vtkNew<vtkTriangleFilter> areaTriangles;

    // Pass count
    vtkNew<vtkActor> passActor;
    vtkNew<vtkPolyDataMapper> passMapper;
    vtkNew<vtkImageData> passImage;
    vtkNew<vtkTexture> passTexture;
    std::array<double, 4> passGeometry{0, 0, 0, 0}; // origin, cell size, cols/rows of the current mesh

    // Machines: one instanced glyph mapper (one draw call for all boxes), arrays updated in place.
    vtkNew<vtkCubeSource> box;
    vtkNew<vtkPolyData> machineData;
    vtkNew<vtkPoints> machinePoints;
    vtkNew<vtkDoubleArray> machineScale;
    vtkNew<vtkDoubleArray> machineRotation;
    vtkNew<vtkIntArray> machineShape;
    vtkSmartPointer<vtkUnsignedCharArray> machineColour = makeColours(3, "colour");
    vtkNew<vtkGlyph3DMapper> machineMapper;
    vtkNew<vtkActor> machineActor;
    QHash<QString, int> machineIndex;

    // Selection
    vtkNew<vtkCubeSource> selectionBox;
    vtkNew<vtkPolyDataMapper> selectionMapper;
    vtkNew<vtkActor> selectionActor;
    vtkNew<vtkTextActor> label; // 2D overlay anchored to a world point (no translucent pass)
    std::vector<vtkSmartPointer<vtkTextActor>> nameLabels; // placed before every frame (placeLabels)
    std::uint64_t labelsPlaced = 0;
    std::vector<QRectF> labelRects; // where the name labels of the last frame are (display pixels, y up)
    vtkNew<vtkCoordinate> labelAnchor;

    Scene3D scene;
    QString selected;
    CameraMode cameraMode = CameraMode::FreeOrbit;
    bool cameraInitialised = false;
    std::array<double, 4> cameraExtent{0, 0, 0, 0};
    std::optional<Vec3> followAnchor; // last machine centre the follow camera was aligned to
    std::uint64_t buildCount = 0;
    std::uint64_t layoutCount = 0;
    std::size_t lastBadMachines = 0;
    std::uint64_t renders = 0;
    vtkNew<vtkCallbackCommand> renderObserver;

    Impl() {
        renderObserver->SetClientData(this);
        renderObserver->SetCallback(
            [](vtkObject*, unsigned long, void* self, void*) { static_cast<Impl*>(self)->beforeFrame(); });
        renderer->AddObserver(vtkCommand::StartEvent, renderObserver);
        for (int i = 0; i < kMaxLabels; ++i) {
            auto t = vtkSmartPointer<vtkTextActor>::New();
            t->GetTextProperty()->SetFontSize(12);
            t->GetTextProperty()->SetColor(1.0, 1.0, 1.0);
            t->GetTextProperty()->SetBackgroundColor(0.12, 0.12, 0.12);
            t->GetTextProperty()->SetBackgroundOpacity(0.6);
            t->GetTextProperty()->SetJustificationToCentered();
            t->GetTextProperty()->SetVerticalJustificationToBottom();
            t->GetPositionCoordinate()->SetCoordinateSystemToDisplay();
            t->SetVisibility(false);
            renderer->AddActor2D(t);
            nameLabels.push_back(t);
        }
        renderer->SetBackground(0.78, 0.84, 0.92);
        // Nothing is drawn in VTK's translucent pass: in 9.1 that pass always runs order-independent
        // transparency (extra full-screen passes, several ms per frame on llvmpipe). The pass-count surface
        // is forced opaque (its no-data texels still blend away) and the label is a 2D overlay.
        renderer->UseDepthPeelingOff();
        renderer->AddActor(terrainActor);
        renderer->AddActor(areaActor);
        renderer->AddActor(ribbonActor);
        renderer->AddActor(passActor);
        renderer->AddActor(machineActor);
        renderer->AddActor(selectionActor);
        renderer->AddActor(label);

        terrainActor->SetMapper(terrainMapper);
        terrainActor->GetProperty()->SetAmbient(0.35);
        terrainActor->GetProperty()->SetDiffuse(0.65);
        configureDirectColours(terrainMapper, false);

        ribbonActor->SetMapper(ribbonMapper);
        configureDirectColours(ribbonMapper, true);
        areaTriangles->PassLinesOff();
        areaTriangles->PassVertsOff();
        areaActor->SetMapper(areaMapper);
        configureDirectColours(areaMapper, true);
        passActor->SetMapper(passMapper);
        passMapper->ScalarVisibilityOff();
        passTexture->SetInputData(passImage);
        passTexture->InterpolateOff(); // crisp cells, exact palette colours
        passTexture->RepeatOff();
        passTexture->EdgeClampOn();
        passActor->SetTexture(passTexture);
        passActor->GetProperty()->LightingOff(); // the same colours as the 2D map and the legend
        passActor->ForceOpaqueOn();              // see UseDepthPeelingOff above; alpha-0 texels blend away
        passActor->SetVisibility(false);
        // Draped layers are pulled towards the camera in depth so that they win over the terrain at any
        // distance.
        areaMapper->SetRelativeCoincidentTopologyPolygonOffsetParameters(-1, -2);
        ribbonMapper->SetRelativeCoincidentTopologyPolygonOffsetParameters(-2, -4);
        passMapper->SetRelativeCoincidentTopologyPolygonOffsetParameters(-3, -6);
        for (vtkActor* a : {ribbonActor.Get(), areaActor.Get()}) {
            a->GetProperty()->SetAmbient(0.5);
            a->GetProperty()->SetDiffuse(0.5);
        }

        // Unit box sitting on z = 0: x = width, y = length (forward = +y = north at heading 0), z = height.
        box->SetCenter(0.0, 0.0, 0.5);
        box->SetXLength(1.0);
        box->SetYLength(1.0);
        box->SetZLength(1.0);
        machineScale->SetName("scale");
        machineScale->SetNumberOfComponents(3);
        machineRotation->SetName("rotation");
        machineRotation->SetNumberOfComponents(3);
        machineData->SetPoints(machinePoints);
        machineData->GetPointData()->AddArray(machineScale);
        machineData->GetPointData()->AddArray(machineRotation);
        machineShape->SetName("shape");
        machineData->GetPointData()->AddArray(machineShape);
        for (int i = 0; i < kShapeCount; ++i)
            machineMapper->SetSourceData(i, shapeOf(static_cast<MachineShape>(i)));
        machineMapper->SetSourceIndexArray("shape");
        machineMapper->SourceIndexingOn();
        machineData->GetPointData()->SetScalars(machineColour);
        machineMapper->SetInputData(machineData);
        machineMapper->SetScaleArray("scale");
        machineMapper->SetScaleModeToScaleByVectorComponents();
        machineMapper->SetOrientationArray("rotation");
        machineMapper->SetOrientationModeToRotation();
        machineMapper->SetColorModeToDirectScalars();
        machineMapper->SetScalarModeToUsePointData();
        machineMapper->ScalarVisibilityOn();
        machineActor->SetMapper(machineMapper);
        machineActor->GetProperty()->SetAmbient(0.35);
        machineActor->GetProperty()->SetDiffuse(0.65);

        selectionBox->SetCenter(0.0, 0.0, 0.5);
        selectionMapper->SetInputConnection(selectionBox->GetOutputPort());
        selectionActor->SetMapper(selectionMapper);
        selectionActor->GetProperty()->SetRepresentationToWireframe();
        selectionActor->GetProperty()->SetColor(1.0, 0.9, 0.0);
        selectionActor->GetProperty()->SetLineWidth(3.0);
        selectionActor->GetProperty()->LightingOff();
        selectionActor->SetVisibility(false);

        label->GetTextProperty()->SetFontSize(16);
        label->GetTextProperty()->SetBold(true);
        label->GetTextProperty()->SetColor(1.0, 1.0, 1.0);
        label->GetTextProperty()->SetBackgroundColor(0.1, 0.1, 0.1);
        label->GetTextProperty()->SetBackgroundOpacity(0.7);
        label->GetTextProperty()->SetJustificationToCentered();
        // Text sits above its anchor so it never hides the machine it names.
        label->GetTextProperty()->SetVerticalJustificationToBottom();
        // Anchored 1.5 m above the machine roof, then lifted 14 px on screen.
        labelAnchor->SetCoordinateSystemToWorld();
        label->GetPositionCoordinate()->SetCoordinateSystemToDisplay();
        label->GetPositionCoordinate()->SetReferenceCoordinate(labelAnchor);
        label->GetPositionCoordinate()->SetValue(0.0, 14.0);
        label->SetVisibility(false);
    }

    void beforeFrame() {
        ++renders;
        applyMinimumSize();
        placeLabels();
    }

    // Like the 2D map's symbols: true size when near, but never smaller on screen than
    // kMinMachinePx across, so a 15 m truck stays a visible shape when the whole pit is in view.
    static constexpr double kMinMachinePx = 12.0;
    void applyMinimumSize() {
        int w = 0, h = 0;
        if (!windowSize(w, h) || h <= 0 || scene.machines.empty())
            return;
        vtkCamera* cam = renderer->GetActiveCamera();
        double eye[3];
        cam->GetPosition(eye);
        // Metres per pixel at distance 1 (perspective) or everywhere (parallel projection).
        const double perPx = cam->GetParallelProjection()
                                 ? 2.0 * cam->GetParallelScale() / h
                                 : 2.0 * std::tan(cam->GetViewAngle() * kDegToRad / 2.0) / h;
        bool changed = false;
        for (std::size_t i = 0; i < scene.machines.size(); ++i) {
            const Machine3D& m = scene.machines[i];
            if (!finite(m))
                continue;
            const double d =
                cam->GetParallelProjection() ? 1.0 : std::hypot(m.e - eye[0], m.n - eye[1], m.u - eye[2]);
            const double size = std::max({m.width, m.length, 0.1});
            const double k = std::max(1.0, kMinMachinePx * perPx * d / size);
            double cur[3];
            machineScale->GetTuple(static_cast<vtkIdType>(i), cur);
            const double want[3] = {std::max(m.width, 0.1) * k, std::max(m.length, 0.1) * k,
                                    std::max(m.height, 0.1) * k};
            if (std::abs(cur[0] - want[0]) > 1e-3 * want[0] || std::abs(cur[2] - want[2]) > 1e-3 * want[2]) {
                machineScale->SetTuple3(static_cast<vtkIdType>(i), want[0], want[1], want[2]);
                changed = true;
            }
        }
        if (changed) {
            machineScale->Modified();
            machineData->Modified();
        }
    }

    // Name labels above the machines, nearest to the camera first, none overlapping another or the selected
    // machine's label; at most kMaxLabels. Done before every frame because the camera may have moved.
    void placeLabels() {
        labelRects.clear();
        int w = 0, h = 0;
        std::size_t used = 0;
        if (windowSize(w, h) && machineActor->GetVisibility()) {
            vtkCamera* cam = renderer->GetActiveCamera();
            double eye[3];
            cam->GetPosition(eye);
            auto project = [&](const Machine3D& m, double& x, double& y) {
                renderer->SetWorldPoint(m.e, m.n, m.u + m.height + 1.0, 1.0);
                renderer->WorldToDisplay();
                double dp[3];
                renderer->GetDisplayPoint(dp);
                x = dp[0];
                y = dp[1];
                return dp[2] >= 0.0 && dp[2] <= 1.0 && x >= 0 && x < w && y >= 0 && y < h;
            };
            auto rectFor = [](const QString& text, double x, double y, int fontPx) {
                const double tw = text.size() * fontPx * 0.6 + 8.0, th = fontPx + 6.0;
                return QRectF(x - tw / 2.0, y + 6.0, tw, th);
            };
            if (const Machine3D* sel = find(selected)) {
                double x = 0, y = 0;
                if (project(*sel, x, y))
                    labelRects.push_back(
                        rectFor(sel->label.isEmpty() ? sel->id : sel->label, x, y + 8.0, 16));
            }
            std::vector<std::pair<double, std::size_t>> order;
            order.reserve(scene.machines.size());
            for (std::size_t i = 0; i < scene.machines.size(); ++i) {
                const Machine3D& m = scene.machines[i];
                if (!finite(m) || m.id == selected)
                    continue;
                const double d2 = (m.e - eye[0]) * (m.e - eye[0]) + (m.n - eye[1]) * (m.n - eye[1]) +
                                  (m.u - eye[2]) * (m.u - eye[2]);
                order.emplace_back(d2, i);
            }
            std::sort(order.begin(), order.end());
            const std::size_t first = labelRects.size();
            for (const auto& [d2, i] : order) {
                if (used == nameLabels.size())
                    break;
                const Machine3D& m = scene.machines[i];
                double x = 0, y = 0;
                if (!project(m, x, y))
                    continue;
                const QString text = m.label.isEmpty() ? m.id : m.label;
                const QRectF r = rectFor(text, x, y, 12);
                if (std::any_of(labelRects.begin(), labelRects.end(),
                                [&](const QRectF& o) { return o.intersects(r); }))
                    continue;
                labelRects.push_back(r);
                vtkTextActor* t = nameLabels[used++];
                t->SetInput(text.toUtf8().constData());
                t->SetPosition(x, y + 6.0);
                t->SetVisibility(true);
            }
            // Only the name labels are reported (the selected machine's label is drawn by `label`).
            labelRects.erase(labelRects.begin(), labelRects.begin() + static_cast<std::ptrdiff_t>(first));
        }
        for (std::size_t k = used; k < nameLabels.size(); ++k)
            nameLabels[k]->SetVisibility(false);
        labelsPlaced = used;
    }

    double height(double e, double n) const {
        if (!flatTerrain && terrainIndex.valid())
            return terrainIndex.height(e, n);
        return flatU;
    }

    // A DEM grid: two triangles per cell, coloured by height (low = darker, like a pit floor in shadow).
    vtkSmartPointer<vtkPolyData> buildGridTerrain(const Terrain3D& t) {
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
                for (const std::array<int, 3>& tri :
                     {std::array<int, 3>{a, b, e}, std::array<int, 3>{a, e, d}}) {
                    tris.push_back(tri);
                    const vtkIdType ids[3] = {tri[0], tri[1], tri[2]};
                    cells->InsertNextCell(3, ids);
                }
            }
        terrainIndex.build(verts, std::move(tris));
        flatTerrain = !terrainIndex.valid();
        drapeStep = std::clamp(g.step / 2.0, 1.0, 25.0);
        auto surface = vtkSmartPointer<vtkPolyData>::New();
        surface->SetPoints(pts);
        surface->SetPolys(cells);
        surface->GetPointData()->SetScalars(colours);
        return surface;
    }

    void buildTerrain() {
        const Terrain3D& t = scene.terrain;
        flatTerrain = true;
        vtkSmartPointer<vtkPolyData> surface;
        const auto bad =
            std::count_if(t.points.begin(), t.points.end(), [](const Enu& p) { return !finite(p); });
        if (bad > 0) {
            logWarning(kLogCategory,
                       "terrain: " + std::to_string(bad) + " point(s) with non-finite coordinates ignored");
            scene.terrain.points.erase(std::remove_if(scene.terrain.points.begin(),
                                                      scene.terrain.points.end(),
                                                      [](const Enu& p) { return !finite(p); }),
                                       scene.terrain.points.end());
        }
        if (t.grid.valid()) {
            surface = buildGridTerrain(t);
        } else if (t.points.size() >= 3) {
            vtkNew<vtkPoints> pts;
            for (const Enu& p : t.points)
                pts->InsertNextPoint(p.e, p.n, p.u);
            vtkNew<vtkPolyData> cloud;
            cloud->SetPoints(pts);
            vtkNew<vtkDelaunay2D> delaunay;
            delaunay->SetInputData(cloud);
            delaunay->Update();
            vtkPolyData* out = delaunay->GetOutput();
            if (out->GetNumberOfPolys() > 0) {
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
                        tris.push_back(
                            {static_cast<int>(ids[0]), static_cast<int>(ids[1]), static_cast<int>(ids[2])});
                terrainIndex.build(verts, std::move(tris));
                flatTerrain = !terrainIndex.valid();
                // Draped layers are resampled at half the mean terrain point spacing: finer adds triangles
                // (llvmpipe pays per triangle) without following the piecewise-linear surface any better.
                const double area = std::max(1.0, (terrainIndex.maxE() - terrainIndex.minE()) *
                                                      (terrainIndex.maxN() - terrainIndex.minN()));
                drapeStep = std::clamp(std::sqrt(area / static_cast<double>(verts.size())) / 2.0, 1.0, 25.0);
                surface = vtkSmartPointer<vtkPolyData>::New();
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
                    colours->InsertNextTuple3(std::min(255.0, t.colour.r * f),
                                              std::min(255.0, t.colour.g * f),
                                              std::min(255.0, t.colour.b * f));
                }
                surface->GetPointData()->SetScalars(colours);
            }
        }
        if (flatTerrain) {
            // No usable elevations: the given plane, or (points too few or collinear) a plane through their
            // mean height covering their extent plus a margin.
            flatU = t.planeU;
            flatExtent = {std::min(t.minE, t.maxE), std::max(t.minE, t.maxE), std::min(t.minN, t.maxN),
                          std::max(t.minN, t.maxN)};
            if (!t.points.empty()) {
                double sumU = 0.0;
                flatExtent = {t.points[0].e, t.points[0].e, t.points[0].n, t.points[0].n};
                for (const Enu& p : t.points) {
                    sumU += p.u;
                    flatExtent[0] = std::min(flatExtent[0], p.e - 50.0);
                    flatExtent[1] = std::max(flatExtent[1], p.e + 50.0);
                    flatExtent[2] = std::min(flatExtent[2], p.n - 50.0);
                    flatExtent[3] = std::max(flatExtent[3], p.n + 50.0);
                }
                flatU = sumU / static_cast<double>(t.points.size());
            }
            if (flatExtent[1] - flatExtent[0] < 1.0)
                flatExtent[1] = flatExtent[0] + 1.0;
            if (flatExtent[3] - flatExtent[2] < 1.0)
                flatExtent[3] = flatExtent[2] + 1.0;
            surface = vtkSmartPointer<vtkPolyData>::New();
            vtkNew<vtkPoints> pts;
            pts->InsertNextPoint(flatExtent[0], flatExtent[2], flatU);
            pts->InsertNextPoint(flatExtent[1], flatExtent[2], flatU);
            pts->InsertNextPoint(flatExtent[1], flatExtent[3], flatU);
            pts->InsertNextPoint(flatExtent[0], flatExtent[3], flatU);
            vtkNew<vtkCellArray> quad;
            const vtkIdType ids[4] = {0, 1, 2, 3};
            quad->InsertNextCell(4, ids);
            surface->SetPoints(pts);
            surface->SetPolys(quad);
            auto colours = makeColours(3, "colour");
            for (int i = 0; i < 4; ++i)
                colours->InsertNextTuple3(t.colour.r, t.colour.g, t.colour.b);
            surface->GetPointData()->SetScalars(colours);
        }
        terrainMapper->SetInputData(surface);
    }

    // Draped ribbon: the centre line is resampled every `step` metres so the ribbon follows the terrain.
    void addRibbon(const Way3D& w, double lift, vtkPoints* pts, vtkCellArray* tris,
                   vtkUnsignedCharArray* colours) {
        if (w.points.size() < 2 || !(w.width > 0.0) || !std::isfinite(w.width))
            return;
        const double step = flatTerrain ? 1e9 : drapeStep;
        std::vector<std::pair<double, double>> line;
        for (std::size_t i = 0; i + 1 < w.points.size(); ++i) {
            const Enu& a = w.points[i];
            const Enu& b = w.points[i + 1];
            const double len = std::hypot(b.e - a.e, b.n - a.n);
            const int n = std::max(1, static_cast<int>(std::ceil(len / step)));
            for (int k = 0; k < n; ++k)
                line.emplace_back(a.e + (b.e - a.e) * k / n, a.n + (b.n - a.n) * k / n);
        }
        line.emplace_back(w.points.back().e, w.points.back().n);
        // Drop repeated points (zero-length segments have no direction).
        line.erase(std::unique(line.begin(), line.end(),
                               [](const auto& p, const auto& q) {
                                   return std::abs(p.first - q.first) < 1e-6 &&
                                          std::abs(p.second - q.second) < 1e-6;
                               }),
                   line.end());
        if (line.size() < 2)
            return;
        const double half = w.width / 2.0;
        const vtkIdType base = pts->GetNumberOfPoints();
        for (std::size_t i = 0; i < line.size(); ++i) {
            const auto& prev = line[i == 0 ? 0 : i - 1];
            const auto& next = line[std::min(i + 1, line.size() - 1)];
            double de = next.first - prev.first, dn = next.second - prev.second;
            const double len = std::hypot(de, dn);
            de /= len;
            dn /= len;
            // Left normal of the direction (de, dn) is (-dn, de).
            const double le = line[i].first - dn * half, ln = line[i].second + de * half;
            const double re = line[i].first + dn * half, rn = line[i].second - de * half;
            pts->InsertNextPoint(le, ln, height(le, ln) + lift);
            pts->InsertNextPoint(re, rn, height(re, rn) + lift);
        }
        for (std::size_t i = 0; i + 1 < line.size(); ++i) {
            const vtkIdType l0 = base + 2 * static_cast<vtkIdType>(i), r0 = l0 + 1, l1 = l0 + 2, r1 = l0 + 3;
            const vtkIdType t1[3] = {l0, r0, r1};
            const vtkIdType t2[3] = {l0, r1, l1};
            tris->InsertNextCell(3, t1);
            tris->InsertNextCell(3, t2);
            colours->InsertNextTuple3(w.colour.r, w.colour.g, w.colour.b);
            colours->InsertNextTuple3(w.colour.r, w.colour.g, w.colour.b);
        }
    }

    void buildWays() {
        vtkNew<vtkPoints> rPts;
        vtkNew<vtkCellArray> rTris;
        auto rColours = makeColours(3, "colour");
        vtkNew<vtkPoints> aPts;
        vtkNew<vtkCellArray> aPolys;
        auto aColours = makeColours(3, "colour");
        // Areas first, roads, then lanes on top.
        for (WayKind kind : {WayKind::Road, WayKind::Lane})
            for (const Way3D& w : scene.ways)
                if (w.kind == kind)
                    addRibbon(w, kind == WayKind::Road ? kLiftRoad : kLiftLane, rPts, rTris, rColours);
        // Areas: triangulate the outline in 2D (concave outlines allowed), then subdivide every triangle so
        // the surface follows the terrain instead of cutting through it.
        vtkNew<vtkPoints> outlinePts;
        vtkNew<vtkCellArray> outlines;
        auto outlineColours = makeColours(3, "colour");
        for (const Way3D& w : scene.ways) {
            if (w.kind != WayKind::Area || w.points.size() < 3)
                continue;
            std::vector<vtkIdType> ids;
            for (const Enu& p : w.points)
                ids.push_back(outlinePts->InsertNextPoint(p.e, p.n, 0.0));
            outlines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
            outlineColours->InsertNextTuple3(w.colour.r, w.colour.g, w.colour.b);
        }
        vtkNew<vtkPolyData> outlineData;
        outlineData->SetPoints(outlinePts);
        outlineData->SetPolys(outlines);
        outlineData->GetCellData()->SetScalars(outlineColours);
        areaTriangles->SetInputData(outlineData);
        areaTriangles->Update();
        vtkPolyData* tri = areaTriangles->GetOutput();
        vtkDataArray* triColours = tri->GetCellData()->GetScalars();
        const double step = flatTerrain ? 1e9 : drapeStep;
        vtkIdType npts = 0;
        const vtkIdType* ids = nullptr;
        vtkIdType cell = 0;
        vtkCellArray* polys = tri->GetPolys();
        for (polys->InitTraversal(); polys->GetNextCell(npts, ids); ++cell) {
            if (npts != 3)
                continue;
            double a[3], b[3], c[3];
            tri->GetPoint(ids[0], a);
            tri->GetPoint(ids[1], b);
            tri->GetPoint(ids[2], c);
            const double longest =
                std::max({std::hypot(b[0] - a[0], b[1] - a[1]), std::hypot(c[0] - b[0], c[1] - b[1]),
                          std::hypot(a[0] - c[0], a[1] - c[1])});
            const int k = std::clamp(static_cast<int>(std::ceil(longest / step)), 1, 64);
            double rgb[3] = {128, 128, 128};
            if (triColours != nullptr)
                triColours->GetTuple(cell, rgb);
            // Uniform barycentric subdivision into k*k triangles.
            auto vertex = [&](int i, int j) {
                const double u = static_cast<double>(i) / k, v = static_cast<double>(j) / k, w0 = 1.0 - u - v;
                const double e = w0 * a[0] + u * b[0] + v * c[0], n = w0 * a[1] + u * b[1] + v * c[1];
                return aPts->InsertNextPoint(e, n, height(e, n) + kLiftArea);
            };
            for (int i = 0; i < k; ++i)
                for (int j = 0; j + i < k; ++j) {
                    const vtkIdType t1[3] = {vertex(i, j), vertex(i + 1, j), vertex(i, j + 1)};
                    aPolys->InsertNextCell(3, t1);
                    aColours->InsertNextTuple(rgb);
                    if (i + j + 1 < k) {
                        const vtkIdType t2[3] = {vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j + 1)};
                        aPolys->InsertNextCell(3, t2);
                        aColours->InsertNextTuple(rgb);
                    }
                }
        }
        vtkNew<vtkPolyData> ribbons;
        ribbons->SetPoints(rPts);
        ribbons->SetPolys(rTris);
        ribbons->GetCellData()->SetScalars(rColours);
        ribbonMapper->SetInputData(ribbons);
        vtkNew<vtkPolyData> areas;
        areas->SetPoints(aPts);
        areas->SetPolys(aPolys);
        areas->GetCellData()->SetScalars(aColours);
        areaMapper->SetInputData(areas);
    }

    // The raster is a texture (one texel per cell, nearest filtering) on a mesh draped over the terrain, so a
    // fine grid (1 km² at 0.34 m = 8.6 M cells) costs one texture upload, not millions of quads.
    void buildPassCount() {
        const PassCountRaster& r = scene.passCount;
        bool usable = !r.empty() && r.cellSize > 0.0 && std::isfinite(r.cellSize) &&
                      std::isfinite(r.originE) && std::isfinite(r.originN);
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
        passActor->SetVisibility(usable);
        if (!usable) {
            passGeometry = {};
            return;
        }
        const std::array<double, 4> geometry{r.originE, r.originN, r.cellSize,
                                             static_cast<double>(r.cols) * 1e6 + r.rows};
        if (geometry != passGeometry) {
            passGeometry = geometry;
            buildPassMesh();
        }
        fillPassTexture();
    }

    void buildPassMesh() {
        const PassCountRaster& r = scene.passCount;
        const double e0 = r.originE, n0 = r.originN;
        const double we = r.cols * r.cellSize, wn = r.rows * r.cellSize;
        // Flat ground needs one quad; on terrain the mesh follows it every drapeStep (at most 128 x 128
        // quads).
        const int nx = flatTerrain ? 1 : std::clamp(static_cast<int>(std::ceil(we / drapeStep)), 1, 128);
        const int ny = flatTerrain ? 1 : std::clamp(static_cast<int>(std::ceil(wn / drapeStep)), 1, 128);
        vtkNew<vtkPoints> pts;
        vtkNew<vtkFloatArray> tcoords;
        tcoords->SetNumberOfComponents(2);
        tcoords->SetName("tcoords");
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i <= nx; ++i) {
                const double s = static_cast<double>(i) / nx, t = static_cast<double>(j) / ny;
                const double e = e0 + s * we, n = n0 + t * wn;
                pts->InsertNextPoint(e, n, height(e, n) + kLiftPassCount);
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
        passMapper->SetInputData(surface);
    }

    void fillPassTexture() {
        const PassCountRaster& r = scene.passCount;
        // Very large rasters are sampled down to what every GL implementation can hold (nearest cell).
        const int step = std::max({1, (r.cols + kMaxTextureSide - 1) / kMaxTextureSide,
                                   (r.rows + kMaxTextureSide - 1) / kMaxTextureSide});
        const int tw = (r.cols + step - 1) / step, th = (r.rows + step - 1) / step;
        if (passImage->GetDimensions()[0] != tw || passImage->GetDimensions()[1] != th) {
            passImage->SetDimensions(tw, th, 1);
            passImage->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
        }
        auto* dst = static_cast<std::uint8_t*>(passImage->GetScalarPointer());
        // Row 0 is the south row in both the raster and VTK images (origin bottom-left): a straight copy.
        if (step == 1) {
            std::copy_n(r.rgba.data(), static_cast<std::size_t>(tw) * th * 4, dst);
        } else {
            for (int y = 0; y < th; ++y)
                for (int x = 0; x < tw; ++x)
                    std::copy_n(&r.rgba[(static_cast<std::size_t>(y) * step * r.cols + x * step) * 4], 4,
                                &dst[(static_cast<std::size_t>(y) * tw + x) * 4]);
        }
        passImage->Modified();
    }

    void layoutMachines() {
        const auto n = static_cast<vtkIdType>(scene.machines.size());
        machinePoints->SetNumberOfPoints(n);
        machineScale->SetNumberOfTuples(n);
        machineRotation->SetNumberOfTuples(n);
        machineColour->SetNumberOfTuples(n);
        machineShape->SetNumberOfTuples(n);
        machineIndex.clear();
        for (vtkIdType i = 0; i < n; ++i)
            machineIndex.insert(scene.machines[static_cast<std::size_t>(i)].id, static_cast<int>(i));
        ++layoutCount;
    }

    void writeMachine(vtkIdType i, const Machine3D& m) {
        if (!finite(m)) {
            // Hidden (zero-size box) rather than dropped, so indices stay stable and the next good update
            // shows it.
            machinePoints->SetPoint(i, 0.0, 0.0, 0.0);
            machineScale->SetTuple3(i, 0.0, 0.0, 0.0);
            machineRotation->SetTuple3(i, 0.0, 0.0, 0.0);
            machineColour->SetTuple3(i, 0, 0, 0);
            machineShape->SetValue(i, 0);
            return;
        }
        machineShape->SetValue(i, std::clamp(static_cast<int>(m.shape), 0, kShapeCount - 1));
        machinePoints->SetPoint(i, m.e, m.n, m.u);
        machineScale->SetTuple3(i, std::max(m.width, 0.1), std::max(m.length, 0.1), std::max(m.height, 0.1));
        machineRotation->SetTuple3(i, 0.0, 0.0,
                                   -m.headingDeg); // VTK rotates counter-clockwise; heading is clockwise
        machineColour->SetTuple3(i, m.colour.r, m.colour.g, m.colour.b);
    }

    void applyMachines(const std::vector<Machine3D>& machines) {
        bool sameSet = machines.size() == scene.machines.size();
        for (std::size_t i = 0; sameSet && i < machines.size(); ++i)
            sameSet = machines[i].id == scene.machines[i].id;
        scene.machines = machines;
        if (scene.clampMachinesToTerrain)
            for (Machine3D& m : scene.machines)
                if (std::isfinite(m.e) && std::isfinite(m.n))
                    m.u = height(m.e, m.n);
        if (!sameSet)
            layoutMachines();
        std::size_t bad = 0;
        for (std::size_t i = 0; i < scene.machines.size(); ++i) {
            const Machine3D& m = scene.machines[i];
            writeMachine(static_cast<vtkIdType>(i), m);
            bad += finite(m) ? 0 : 1;
            if (m.selected)
                selected = m.id;
        }
        if (bad != lastBadMachines) // only on change: updates come at 10 Hz
            logWarning(kLogCategory,
                       std::to_string(bad) + " machine(s) with non-finite pose or size are hidden");
        lastBadMachines = bad;
        machinePoints->Modified();
        machineScale->Modified();
        machineRotation->Modified();
        machineColour->Modified();
        machineShape->Modified();
        machineData->Modified();
        machineActor->SetVisibility(!machines.empty());
        updateSelection();
    }

    // The machine with that id, if it is known and drawable.
    const Machine3D* find(const QString& id) const {
        const auto it = machineIndex.constFind(id);
        if (id.isEmpty() || it == machineIndex.constEnd())
            return nullptr;
        const Machine3D* m = &scene.machines[static_cast<std::size_t>(*it)];
        return finite(*m) ? m : nullptr;
    }

    void updateSelection() {
        const Machine3D* m = find(selected);
        selectionActor->SetVisibility(m != nullptr);
        label->SetVisibility(m != nullptr);
        if (m != nullptr) {
            selectionActor->SetPosition(m->e, m->n, m->u);
            selectionActor->SetOrientation(0.0, 0.0, -m->headingDeg);
            selectionActor->SetScale(m->width + 0.6, m->length + 0.6, m->height + 0.3);
            labelAnchor->SetValue(m->e, m->n, m->u + m->height + 1.5);
            label->Modified();
            const QString text = m->label.isEmpty() ? m->id : m->label;
            label->SetInput(text.toUtf8().constData());
        }
        if (cameraMode == CameraMode::FollowSelected)
            follow();
    }

    Vec3 centreOf(const Machine3D& m) const { return {m.e, m.n, m.u + m.height / 2.0}; }

    // Follow: the first time (or after a selection change) the camera is put behind the machine; afterwards
    // it is translated by the machine's movement, which keeps the machine centred and keeps the user's orbit.
    void follow() {
        const Machine3D* m = find(selected);
        if (m == nullptr) {
            followAnchor.reset();
            return;
        }
        vtkCamera* cam = renderer->GetActiveCamera();
        const Vec3 c = centreOf(*m);
        if (!followAnchor) {
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
        followAnchor = c;
        renderer->ResetCameraClippingRange();
    }

    void siteBounds(double b[6]) const {
        if (flatTerrain) {
            b[0] = flatExtent[0];
            b[1] = flatExtent[1];
            b[2] = flatExtent[2];
            b[3] = flatExtent[3];
            b[4] = flatU;
            b[5] = flatU + 5.0;
            return;
        }
        const TerrainGrid3D& g = scene.terrain.grid;
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
        const auto& pts = scene.terrain.points;
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

    void resetCamera() {
        vtkCamera* cam = renderer->GetActiveCamera();
        double b[6];
        siteBounds(b);
        const double ce = (b[0] + b[1]) / 2, cn = (b[2] + b[3]) / 2, cu = (b[4] + b[5]) / 2;
        cam->SetFocalPoint(ce, cn, cu);
        if (cameraMode == CameraMode::TopDown) {
            cam->SetPosition(ce, cn, cu + 100.0);
            cam->SetViewUp(0.0, 1.0, 0.0); // north up, like the 2D map
        } else {
            cam->SetPosition(ce, cn - 100.0, cu + 80.0); // looking north, tilted
            cam->SetViewUp(0.0, 0.0, 1.0);
        }
        renderer->ResetCamera(b);
        if (cameraMode != CameraMode::TopDown)
            cam->Dolly(1.25);
        renderer->ResetCameraClippingRange();
        followAnchor.reset();
        if (cameraMode == CameraMode::FollowSelected)
            follow();
        cameraInitialised = true;
    }

    bool windowSize(int& w, int& h) const {
        vtkRenderWindow* rw = renderer->GetRenderWindow();
        if (rw == nullptr)
            return false;
        const int* s = renderer->GetSize();
        w = s[0];
        h = s[1];
        return w > 0 && h > 0;
    }
};

SiteSceneRenderer::SiteSceneRenderer() : d(std::make_unique<Impl>()) {}
SiteSceneRenderer::~SiteSceneRenderer() = default;

vtkRenderer* SiteSceneRenderer::renderer() const {
    return d->renderer;
}

void SiteSceneRenderer::setScene(const Scene3D& scene) {
    const std::vector<Machine3D> machines = scene.machines;
    const Terrain3D old = d->scene.terrain;
    d->scene = scene;
    d->scene.machines = {};
    d->machineIndex.clear();
    d->renderer->SetBackground(scene.background.r / 255.0, scene.background.g / 255.0,
                               scene.background.b / 255.0);
    d->buildTerrain();
    d->buildWays();
    d->passGeometry = {}; // the terrain may have changed: re-drape the raster mesh
    d->buildPassCount();
    d->applyMachines(machines);
    ++d->buildCount;
    double b[6];
    d->siteBounds(b);
    const std::array<double, 4> extent{b[0], b[1], b[2], b[3]};
    if (!d->cameraInitialised || extent != d->cameraExtent) {
        d->cameraExtent = extent;
        d->resetCamera();
    } else {
        d->renderer->ResetCameraClippingRange();
    }
}

void SiteSceneRenderer::updateMachines(const std::vector<Machine3D>& machines) {
    d->applyMachines(machines);
    d->renderer->ResetCameraClippingRange();
}

void SiteSceneRenderer::setPassCount(const PassCountRaster& raster, const std::vector<LegendEntry>& legend) {
    d->scene.passCount = raster;
    d->scene.legend = legend;
    d->buildPassCount();
}

void SiteSceneRenderer::setSelectedMachine(const QString& id) {
    if (id != d->selected)
        d->followAnchor.reset();
    d->selected = id;
    for (Machine3D& m : d->scene.machines)
        m.selected = (m.id == id);
    d->updateSelection();
}

QString SiteSceneRenderer::selectedMachine() const {
    return d->selected;
}

void SiteSceneRenderer::setCameraMode(CameraMode mode) {
    if (mode == d->cameraMode)
        return;
    d->cameraMode = mode;
    d->resetCamera();
}

CameraMode SiteSceneRenderer::cameraMode() const {
    return d->cameraMode;
}

void SiteSceneRenderer::resetCamera() {
    d->resetCamera();
}

double SiteSceneRenderer::viewElevationDeg() const {
    double dir[3];
    d->renderer->GetActiveCamera()->GetDirectionOfProjection(dir);
    return -std::asin(std::clamp(dir[2], -1.0, 1.0)) * 180.0 / std::numbers::pi;
}

void SiteSceneRenderer::orbit(double azimuthDeg, double elevationDeg) {
    if (d->cameraMode == CameraMode::TopDown)
        return;
    vtkCamera* cam = d->renderer->GetActiveCamera();
    cam->Azimuth(azimuthDeg);
    // Keep the line of sight between 5 and 89 degrees below the horizon (world z up).
    const double current = viewElevationDeg();
    const double target = std::clamp(current + elevationDeg, 5.0, 89.0);
    cam->Elevation(target - current);
    cam->SetViewUp(0.0, 0.0, 1.0);
    cam->OrthogonalizeViewUp();
    d->renderer->ResetCameraClippingRange();
}

void SiteSceneRenderer::zoom(double factor) {
    if (factor <= 0)
        return;
    vtkCamera* cam = d->renderer->GetActiveCamera();
    if (cam->GetParallelProjection())
        cam->SetParallelScale(cam->GetParallelScale() / factor);
    else
        cam->Dolly(factor);
    d->renderer->ResetCameraClippingRange();
}

double SiteSceneRenderer::terrainHeight(double e, double n) const {
    return d->height(e, n);
}

QString SiteSceneRenderer::pick(double x, double y) const {
    int w = 0, h = 0;
    if (!d->windowSize(w, h))
        return {};
    vtkRenderer* r = d->renderer;
    double ray[2][3];
    for (int k = 0; k < 2; ++k) {
        r->SetDisplayPoint(x, h - y, k == 0 ? 0.0 : 1.0);
        r->DisplayToWorld();
        double wp[4];
        r->GetWorldPoint(wp);
        if (wp[3] == 0.0)
            return {};
        for (int i = 0; i < 3; ++i)
            ray[k][i] = wp[i] / wp[3];
    }
    const double dir[3] = {ray[1][0] - ray[0][0], ray[1][1] - ray[0][1], ray[1][2] - ray[0][2]};
    QString best;
    double bestT = std::numeric_limits<double>::max();
    for (const Machine3D& m : d->scene.machines) {
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

std::optional<QPointF> SiteSceneRenderer::project(double e, double n, double u) const {
    int w = 0, h = 0;
    if (!d->windowSize(w, h))
        return std::nullopt;
    vtkRenderer* r = d->renderer;
    r->SetWorldPoint(e, n, u, 1.0);
    r->WorldToDisplay();
    double dp[3];
    r->GetDisplayPoint(dp);
    if (dp[2] < 0.0 || dp[2] > 1.0)
        return std::nullopt;
    return QPointF(dp[0], h - dp[1]);
}

const Scene3D& SiteSceneRenderer::scene() const {
    return d->scene;
}

std::optional<Machine3D> SiteSceneRenderer::machine(const QString& id) const {
    const Machine3D* m = d->find(id);
    if (m == nullptr)
        return std::nullopt;
    return *m;
}

std::uint64_t SiteSceneRenderer::sceneBuildCount() const {
    return d->buildCount;
}
std::uint64_t SiteSceneRenderer::machineLayoutCount() const {
    return d->layoutCount;
}
std::vector<QRectF> SiteSceneRenderer::nameLabelRects() const {
    return d->labelRects;
}

std::uint64_t SiteSceneRenderer::renderCount() const {
    return d->renders;
}

std::array<int, 2> SiteSceneRenderer::passTextureSize() const {
    if (!d->passActor->GetVisibility() || d->passImage->GetScalarPointer() == nullptr)
        return {0, 0};
    return {d->passImage->GetDimensions()[0], d->passImage->GetDimensions()[1]};
}

std::array<std::uint8_t, 4> SiteSceneRenderer::passTexel(int x, int y) const {
    const auto [w, h] = passTextureSize();
    if (x < 0 || y < 0 || x >= w || y >= h)
        return {0, 0, 0, 0};
    const auto* p = static_cast<const std::uint8_t*>(d->passImage->GetScalarPointer(x, y, 0));
    return {p[0], p[1], p[2], p[3]};
}

} // namespace ocu
