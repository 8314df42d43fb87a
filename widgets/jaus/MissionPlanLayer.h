#pragma once
// The UGV missions on the 2D site map (a SiteMapOverlay): the plan being edited (numbered waypoints on a
// cased line, the selected one ringed, tolerance circles when they are big enough to see), and for every
// vehicle with a mission the uploaded route (dashed) with its active waypoint and the path it drove (a thin
// solid line beside the route). Each vehicle has its own colour (missionColour), none of them the dispatch
// route's purple. Coordinates stay WGS84 in the models; the layer keeps their site ENU (through the site's
// GeoFrame) and updates one point when one waypoint moves, so a drag of a 1,000-point route stays cheap.
#include "models/jaus/JausMission.h"
#include "models/jaus/MissionPlan.h"
#include "protocols/common/GeoFrame.h"
#include "widgets/SiteMapView.h"

#include <QColor>
#include <QImage>
#include <QPointer>
#include <QVector>

namespace ocu {

class MissionPlan;

class MissionPlanLayer final : public SiteMapOverlay {
public:
    MissionPlanLayer(SiteMapView* view, const GeoFrame& frame); // adds itself to the view
    ~MissionPlanLayer() override;                               // and removes itself
    MissionPlanLayer(const MissionPlanLayer&) = delete;
    MissionPlanLayer& operator=(const MissionPlanLayer&) = delete;

    // The colour of a vehicle's missions: a fixed palette by subsystem ID, apart from the dispatch route's
    // purple and the status colours' green, amber and red.
    static QColor missionColour(quint16 subsystem);

    // The plan being edited (not owned; nullptr: none), drawn in `colour`.
    void setPlan(MissionPlan* plan, const QColor& colour);
    MissionPlan* plan() const { return m_plan; }
    // The plan's waypoint shown selected (-1: none).
    void setSelected(int index);
    int selected() const { return m_selected; }
    void setEditing(bool on);
    // Written at the plan's last waypoint (e.g. the vehicle, the length and the ETA).
    void setPlanLabel(const QString& label);

    // The vehicles' missions as they report them.
    struct VehicleMission {
        quint16 subsystem = 0;
        QColor colour;
        JausMission mission;
    };
    void setMissions(const QVector<VehicleMission>& missions);
    const QVector<VehicleMission>& missions() const { return m_missions; }

    // Hit tests in screen pixels: the plan's waypoint within `radius` (topmost), the leg (k = between
    // waypoints k and k+1) within `radius` with the nearest point on it (ENU), or -1.
    int waypointAt(QPointF px, double radius = 9) const;
    int legAt(QPointF px, QPointF* onLegEN = nullptr, double radius = 6) const;
    // The plan's waypoint in site ENU metres, and back.
    QPointF toEN(const MissionWaypoint& w) const;
    QPair<double, double> toLatLon(QPointF en) const;
    const GeoFrame& frame() const { return m_frame; }

    void paintOverlay(QPainter& p, const SiteMapView& view) override;
    // The view is being destroyed: forget it without touching it.
    void forgetView() { m_view = nullptr; }

private:
    void planChanged(int index);
    void drawPlan(QPainter& p, const SiteMapView& view);
    void drawMission(QPainter& p, const SiteMapView& view, const VehicleMission& m);
    const QImage& marker(const QColor& colour, bool selected, qreal dpr);

    QPointer<SiteMapView> m_view;
    GeoFrame m_frame;
    QPointer<MissionPlan> m_plan;
    QMetaObject::Connection m_planConnection;
    QColor m_colour;
    int m_selected = -1;
    bool m_editing = false;
    QString m_label;
    QVector<QPointF> m_planEN; // the plan's waypoints in ENU, kept in step with the plan
    QVector<VehicleMission> m_missions;
    QVector<QVector<QPointF>> m_missionEN, m_drivenEN; // per mission: route and driven path in ENU
    QHash<QString, QImage> m_markers;                  // waypoint marker per colour, state and dpr
};

} // namespace ocu
