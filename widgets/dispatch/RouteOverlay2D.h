#pragma once
// The selected truck's route on the 2D site map: the ways of its route (way ids from its
// assignment or the console's router) looked up in the map by feature id ("<link>/<way id>"), chained into
// one path (each road turned so it continues where the previous one ended; areas by their centroid), drawn as
// a cased line with an arrow at the destination and the destination area outlined. A hook of SiteMapView
// (SiteMapOverlay); the geometry is a pure function, shared with the 3D view's route.
#include "widgets/SiteMapView.h"

#include <QFont>
#include <QImage>
#include <QPointF>
#include <QPointer>
#include <QString>
#include <QVector>

namespace ocu {

// The path of a route over the map in site ENU metres (empty when none of its ways is in the map); `missing`
// (optional) gets the way ids the map does not have.
QVector<QPointF> routePath(const SiteMapData& map, const QString& link, const QVector<qint64>& ways,
                           QVector<qint64>* missing = nullptr);

class RouteOverlay2D final : public SiteMapOverlay {
public:
    explicit RouteOverlay2D(SiteMapView* view); // adds itself to the view
    ~RouteOverlay2D() override;                 // and removes itself
    RouteOverlay2D(const RouteOverlay2D&) = delete;
    RouteOverlay2D& operator=(const RouteOverlay2D&) = delete;

    // Empty ways: nothing drawn. `label` is written at the destination (e.g. the truck and the ETA).
    // `preview`: a route not (yet) assigned, drawn dashed.
    void setRoute(const QString& link, const QVector<qint64>& ways, const QString& label = {},
                  bool preview = false);
    bool isPreview() const { return m_preview; }
    void clear() { setRoute({}, {}); }
    // The path as drawn (ENU metres), recomputed when the route or the map revision changes.
    const QVector<QPointF>& path() const;
    QString destinationFeature() const;

    void paintStatic(QPainter& p, const SiteMapView& view) override;  // line, destination, arrow
    void paintOverlay(QPainter& p, const SiteMapView& view) override; // the label
    // The view is being destroyed (its destroyed signal): forget it without touching it.
    void forgetView() { m_view = nullptr; }

private:
    QPointer<SiteMapView> m_view;
    QString m_link;
    QVector<qint64> m_ways;
    QString m_label;
    bool m_preview = false;
    mutable QVector<QPointF> m_path;
    QImage m_labelImage; // the label drawn, for the frames until its text changes
    QString m_labelImageText;
    QFont m_labelImageFont;
    QSizeF m_labelSize;
    mutable QVector<QPointF> m_destinationArea; // outline of the destination when it is an area
    mutable quint64 m_pathRevision = ~quint64(0);
    mutable bool m_pathValid = false;
};

} // namespace ocu
