#pragma once
// The mission the operator is planning for one UGV: its waypoints in WGS84 with a speed and a tolerance each,
// the route's length and ETA, and every edit (add, insert, move, delete, speed, tolerance, open, import) as
// one step of an undo stack. The plan editor on the map and the mission panel's table both edit it; the JAUS
// bridge uploads a copy of waypoints().
#include "models/jaus/JausMission.h"
#include "models/jaus/JausVehicle.h"

#include <QObject>
#include <QVector>

#include <optional>

class QUndoStack;

namespace ocu {

class MissionPlan : public QObject {
    Q_OBJECT
public:
    // What a new waypoint gets when the operator sets nothing (MissionPlan::defaultsFor).
    struct Defaults {
        double speed = 1.0;     // m/s
        double tolerance = 2.0; // m
        bool operator==(const Defaults&) const = default;
    };
    // The defaults from the vehicle's platform specifications (ReportPlatformSpecifications):
    //  - speed: half the vehicle's maximum forward speed (room for the list driver to slow into turns and
    //    for the operator to raise it per waypoint), 1 m/s when the vehicle reports none;
    //  - tolerance: one vehicle length (front + back of the reference point), at least 1 m, so a waypoint is
    //    reached when the vehicle is over it; 2 m when the vehicle reports no size.
    static Defaults defaultsFor(const std::optional<JausPlatform>& platform);

    explicit MissionPlan(QObject* parent = nullptr);
    ~MissionPlan() override;

    const QVector<MissionWaypoint>& waypoints() const { return m_points; }
    int size() const { return int(m_points.size()); }
    bool isEmpty() const { return m_points.isEmpty(); }
    const MissionWaypoint& at(int index) const { return m_points[index]; }

    void setDefaults(const Defaults& d) { m_defaults = d; }
    const Defaults& defaults() const { return m_defaults; }
    // A waypoint at (lat, lon) with the defaults.
    MissionWaypoint makeWaypoint(double lat, double lon) const;

    // Edits, each one undo step (indexes out of range, negative speeds and tolerances outside 0 to 100 m are
    // ignored). `gesture` merges the moves of one drag
    // (same waypoint, same non-zero gesture) into one step.
    void insert(int index, const MissionWaypoint& waypoint);
    void append(const MissionWaypoint& waypoint) { insert(size(), waypoint); }
    void move(int index, double lat, double lon, int gesture = 0);
    void remove(int index);
    void setSpeed(int index, double speed);
    void setTolerance(int index, double tolerance);
    // The whole plan at once (open, import, clear); `what` names the step in the undo history.
    void replace(const QVector<MissionWaypoint>& waypoints, const QString& what);
    // Zero speeds and tolerances (the file left them to the vehicle) become the defaults, as one step.
    void fillDefaults();

    QUndoStack* undoStack() const { return m_undo; }
    void undo();
    void redo();

    // Route length along the waypoints (m), and the time to drive it (s): each leg at the speed of the
    // waypoint it leads to (the default where that is 0). `from`: the vehicle's position (lat, lon), the
    // first leg then runs from there to the first waypoint.
    double lengthM(std::optional<QPair<double, double>> from = std::nullopt) const;
    double etaS(std::optional<QPair<double, double>> from = std::nullopt) const;
    // Ground distance between two WGS84 points (m): the ellipsoid's radii of curvature at the mean latitude,
    // within millimetres over a leg of a few kilometres.
    static double distanceM(double lat1, double lon1, double lat2, double lon2);

    // The edits' own entry point (the undo commands call it; not an undo step itself).
    void applyPoints(const QVector<MissionWaypoint>& points, int changedIndex);

signals:
    // Any change; `index` is the one waypoint that changed in place, or -1 (added, removed, replaced).
    void changed(int index);

private:
    void push(QVector<MissionWaypoint> after, const QString& what, int changedIndex, int mergeId = -1);

    QVector<MissionWaypoint> m_points;
    Defaults m_defaults;
    QUndoStack* m_undo;
};

} // namespace ocu
