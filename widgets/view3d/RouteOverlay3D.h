#pragma once
// The selected truck's route in the 3D view: a thick line a little above the terrain along the
// route's path (site ENU metres, computed from the map like the 2D overlay). It adds one actor to the view's
// renderer and asks the view to redraw; nothing else of the 3D scene is touched. VTK stays in the .cpp.
#include <QObject>
#include <QPointF>
#include <QPointer>
#include <QVector3D>
#include <QVector>

#include <memory>

namespace ocu {

class Site3DView;

class RouteOverlay3D : public QObject {
    Q_OBJECT
public:
    explicit RouteOverlay3D(Site3DView* view); // a child of the view
    ~RouteOverlay3D() override;

    // Empty: nothing drawn.
    void setPath(const QVector<QPointF>& pathEN);
    // Line colour (0..1) and width (px).
    void setStyle(double r, double g, double b, float width);
    // The line's colour (r, g, b in 0..1) and width (px), for tests.
    QVector3D colour() const;
    float width() const;
    // The drawn polyline in ENU (x = E, y = N, z = height on the terrain + kLift), for tests.
    QVector<QVector3D> drawnPoints() const;
    static constexpr double kLift = 1.5;  // m above the terrain, so the line is not buried in it
    static constexpr double kStep = 10.0; // m: long segments are split to follow the terrain

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace ocu
