#include "widgets/view3d/RouteOverlay3D.h"

#include "widgets/view3d/Site3DView.h"
#include "widgets/view3d/SiteSceneRenderer.h"

#include <QVector3D>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <cmath>

namespace ocu {

struct RouteOverlay3D::Impl {
    QPointer<Site3DView> view;
    vtkNew<vtkPolyData> poly;
    vtkNew<vtkPolyDataMapper> mapper;
    vtkNew<vtkActor> actor;
    QVector<QVector3D> points;
};

RouteOverlay3D::RouteOverlay3D(Site3DView* view) : QObject(view), m_impl(std::make_unique<Impl>()) {
    m_impl->view = view;
    m_impl->mapper->SetInputData(m_impl->poly);
    m_impl->actor->SetMapper(m_impl->mapper);
    m_impl->actor->GetProperty()->SetColor(0.56, 0.14, 0.67);
    m_impl->actor->GetProperty()->SetLineWidth(6);
    m_impl->actor->GetProperty()->SetRenderLinesAsTubes(true);
    m_impl->actor->GetProperty()->LightingOff();
    m_impl->actor->PickableOff();
    m_impl->actor->VisibilityOff();
    view->sceneRenderer().renderer()->AddActor(m_impl->actor); // the renderer holds it from now on
}

// The renderer is not touched here: as a child of the view this runs after the view's renderer and its window
// are gone (the renderer keeps a reference to the actor and releases it with itself); hiding our own actor
// covers an overlay deleted before its view.
RouteOverlay3D::~RouteOverlay3D() {
    m_impl->actor->VisibilityOff();
}

void RouteOverlay3D::setPath(const QVector<QPointF>& path) {
    m_impl->points.clear();
    if (m_impl->view) {
        const SiteSceneRenderer& scene = m_impl->view->sceneRenderer();
        auto add = [&](QPointF p) {
            m_impl->points << QVector3D(float(p.x()), float(p.y()),
                                        float(scene.terrainHeight(p.x(), p.y()) + kLift));
        };
        for (int i = 0; i < path.size(); ++i) {
            if (i > 0) {
                const QPointF a = path[i - 1], b = path[i];
                const double len = std::hypot(b.x() - a.x(), b.y() - a.y());
                const int steps = int(std::ceil(len / kStep));
                for (int s = 1; s < steps; ++s)
                    add(a + (b - a) * (double(s) / steps));
            }
            add(path[i]);
        }
    }
    vtkNew<vtkPoints> pts;
    vtkNew<vtkCellArray> lines;
    if (m_impl->points.size() >= 2) {
        lines->InsertNextCell(vtkIdType(m_impl->points.size()));
        for (const auto& p : m_impl->points)
            lines->InsertCellPoint(pts->InsertNextPoint(p.x(), p.y(), p.z()));
    }
    m_impl->poly->SetPoints(pts);
    m_impl->poly->SetLines(lines);
    m_impl->poly->Modified();
    m_impl->actor->SetVisibility(m_impl->points.size() >= 2);
    if (m_impl->view)
        m_impl->view->refresh();
}

void RouteOverlay3D::setStyle(double r, double g, double b, float width) {
    m_impl->actor->GetProperty()->SetColor(r, g, b);
    m_impl->actor->GetProperty()->SetLineWidth(width);
    if (m_impl->view)
        m_impl->view->refresh();
}

QVector3D RouteOverlay3D::colour() const {
    double c[3];
    m_impl->actor->GetProperty()->GetColor(c);
    return QVector3D(float(c[0]), float(c[1]), float(c[2]));
}

float RouteOverlay3D::width() const {
    return m_impl->actor->GetProperty()->GetLineWidth();
}

QVector<QVector3D> RouteOverlay3D::drawnPoints() const {
    return m_impl->points;
}

} // namespace ocu
