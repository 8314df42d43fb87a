#include "app/modules/JausMission3D.h"

#include "app/MainWindow.h"
#include "widgets/jaus/MissionPanel.h"
#ifdef OCU_HAVE_OCU_VIEW3D
#include "widgets/view3d/RouteOverlay3D.h"
#include "widgets/view3d/Site3DView.h"
#endif

namespace ocu {

#ifdef OCU_HAVE_OCU_VIEW3D
namespace {

constexpr float kRouteWidth = 5, kPathWidth = 3;
constexpr int kPathDarker = 160; // QColor::darker: the driven path's tone, as on the 2D map but deeper

QPointF toEN(const GeoFrame& frame, double lat, double lon) {
    const EnuPoint e = frame.toLocal({lat, lon, 0});
    return {e.e, e.n};
}

} // namespace

void attachMissionRoutes3D(MainWindow& window, MissionPanel* panel, const GeoFrame& frame) {
    auto* view3d = qobject_cast<Site3DView*>(window.panelWidget(Panel::Site3D));
    if (!view3d || !panel)
        return;
    auto* route = new RouteOverlay3D(view3d);
    route->setObjectName(QLatin1String(plannedRoute3DName()));
    auto* path = new RouteOverlay3D(view3d);
    path->setObjectName(QLatin1String(drivenPath3DName()));
    QObject::connect(panel, &MissionPanel::planRouteChanged, route,
                     [route, frame](const QVector<MissionWaypoint>& plan, const QColor& c) {
                         QVector<QPointF> en;
                         for (const MissionWaypoint& w : plan)
                             en << toEN(frame, w.lat, w.lon);
                         route->setStyle(c.redF(), c.greenF(), c.blueF(), kRouteWidth);
                         route->setPath(en);
                     });
    QObject::connect(panel, &MissionPanel::drivenPathChanged, path,
                     [path, frame](const QVector<QPair<double, double>>& driven, const QColor& c) {
                         QVector<QPointF> en;
                         en.reserve(driven.size());
                         for (const auto& p : driven)
                             en << toEN(frame, p.first, p.second);
                         const QColor d = c.darker(kPathDarker);
                         path->setStyle(d.redF(), d.greenF(), d.blueF(), kPathWidth);
                         path->setPath(en);
                     });
}

#else

void attachMissionRoutes3D(MainWindow&, MissionPanel*, const GeoFrame&) {}

#endif

} // namespace ocu
