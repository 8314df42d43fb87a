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

RouteOverlay3D::RouteOverlay3D(Site3DView* view) : QObject(view), d(std::make_unique<Impl>()) {
    d->view = view;
    d->mapper->SetInputData(d->poly);
    d->actor->SetMapper(d->mapper);
    d->actor->GetProperty()->SetColor(0.56, 0.14, 0.67);
    d->actor->GetProperty()->SetLineWidth(6);
    d->actor->GetProperty()->SetRenderLinesAsTubes(true);
    d->actor->GetProperty()->LightingOff();
    d->actor->PickableOff();
    d->actor->VisibilityOff();
    view->sceneRenderer().renderer()->AddActor(d->actor); // the renderer holds it from now on
}

// The renderer is not touched here: as a child of the view this runs after the view's renderer and its window
// are gone (the renderer keeps a reference to the actor and releases it with itself); hiding our own actor
// covers an overlay deleted before its view.
RouteOverlay3D::~RouteOverlay3D() {
    d->actor->VisibilityOff();
}

void RouteOverlay3D::setPath(const QVector<QPointF>& path) {
    d->points.clear();
    if (d->view) {
        const SiteSceneRenderer& scene = d->view->sceneRenderer();
        auto add = [&](QPointF p) {
            d->points << QVector3D(float(p.x()), float(p.y()),
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
    if (d->points.size() >= 2) {
        lines->InsertNextCell(vtkIdType(d->points.size()));
        for (const auto& p : d->points)
            lines->InsertCellPoint(pts->InsertNextPoint(p.x(), p.y(), p.z()));
    }
    d->poly->SetPoints(pts);
    d->poly->SetLines(lines);
    d->poly->Modified();
    d->actor->SetVisibility(d->points.size() >= 2);
    if (d->view)
        d->view->refresh();
}

void RouteOverlay3D::setStyle(double r, double g, double b, float width) {
    d->actor->GetProperty()->SetColor(r, g, b);
    d->actor->GetProperty()->SetLineWidth(width);
    if (d->view)
        d->view->refresh();
}

QVector<QVector3D> RouteOverlay3D::drawnPoints() const {
    return d->points;
}

} // namespace ocu
