#include "models/jaus/MissionPlan.h"

#include "models/jaus/MissionGeoJson.h"

#include <QUndoCommand>
#include <QUndoStack>

#include <cmath>

namespace ocu {

namespace {

// One edit: the waypoints before and after. A drag's moves of one waypoint merge into one step.
class PlanEdit final : public QUndoCommand {
public:
    PlanEdit(MissionPlan* plan, QVector<MissionWaypoint> before, QVector<MissionWaypoint> after,
             const QString& text, int changedIndex, int mergeId)
        : QUndoCommand(text), m_plan(plan), m_before(std::move(before)), m_after(std::move(after)),
          m_index(changedIndex), m_mergeId(mergeId) {}
    void undo() override { m_plan->applyPoints(m_before, m_index); }
    void redo() override { m_plan->applyPoints(m_after, m_index); }
    int id() const override { return m_mergeId >= 0 ? 1 : -1; }
    bool mergeWith(const QUndoCommand* other) override {
        const auto* o = static_cast<const PlanEdit*>(other);
        if (o->m_mergeId != m_mergeId || o->m_index != m_index)
            return false;
        m_after = o->m_after;
        return true;
    }

private:
    MissionPlan* m_plan;
    QVector<MissionWaypoint> m_before, m_after;
    int m_index;
    int m_mergeId; // (gesture << 20) | index for a drag's moves, -1: never merged
};

constexpr double kPi = 3.14159265358979323846;

} // namespace

MissionPlan::Defaults MissionPlan::defaultsFor(const std::optional<JausPlatform>& platform) {
    Defaults d;
    if (!platform)
        return d;
    if (platform->maxForwardSpeed && *platform->maxForwardSpeed > 0)
        d.speed = *platform->maxForwardSpeed / 2;
    if (platform->front || platform->back)
        d.tolerance =
            std::clamp(platform->front.value_or(0) + platform->back.value_or(0), 1.0, kMaxMissionToleranceM);
    return d;
}

MissionPlan::MissionPlan(QObject* parent) : QObject(parent), m_undo(new QUndoStack(this)) {}

MissionPlan::~MissionPlan() = default;

MissionWaypoint MissionPlan::makeWaypoint(double lat, double lon) const {
    return MissionWaypoint{lat, lon, m_defaults.speed, m_defaults.tolerance};
}

void MissionPlan::applyPoints(const QVector<MissionWaypoint>& points, int changedIndex) {
    const bool inPlace = changedIndex >= 0 && points.size() == m_points.size();
    m_points = points;
    emit changed(inPlace ? changedIndex : -1);
}

void MissionPlan::push(QVector<MissionWaypoint> after, const QString& what, int changedIndex, int mergeId) {
    m_undo->push(new PlanEdit(this, m_points, std::move(after), what, changedIndex, mergeId));
}

void MissionPlan::insert(int index, const MissionWaypoint& waypoint) {
    if (index < 0 || index > size())
        return;
    QVector<MissionWaypoint> after = m_points;
    after.insert(index, waypoint);
    push(std::move(after),
         index == size() ? tr("Add waypoint %1").arg(index + 1) : tr("Insert waypoint %1").arg(index + 1),
         -1);
}

void MissionPlan::move(int index, double lat, double lon, int gesture) {
    if (index < 0 || index >= size() || (m_points[index].lat == lat && m_points[index].lon == lon))
        return;
    QVector<MissionWaypoint> after = m_points;
    after[index].lat = lat;
    after[index].lon = lon;
    push(std::move(after), tr("Move waypoint %1").arg(index + 1), index,
         gesture > 0 ? (gesture << 20) | index : -1);
}

void MissionPlan::remove(int index) {
    if (index < 0 || index >= size())
        return;
    QVector<MissionWaypoint> after = m_points;
    after.remove(index);
    push(std::move(after), tr("Delete waypoint %1").arg(index + 1), -1);
}

void MissionPlan::setSpeed(int index, double speed) {
    if (index < 0 || index >= size() || speed < 0 || m_points[index].speed == speed)
        return;
    QVector<MissionWaypoint> after = m_points;
    after[index].speed = speed;
    push(std::move(after), tr("Speed of waypoint %1").arg(index + 1), index);
}

void MissionPlan::setTolerance(int index, double tolerance) {
    if (index < 0 || index >= size() || !(tolerance >= 0 && tolerance <= kMaxMissionToleranceM) ||
        m_points[index].tolerance == tolerance)
        return;
    QVector<MissionWaypoint> after = m_points;
    after[index].tolerance = tolerance;
    push(std::move(after), tr("Tolerance of waypoint %1").arg(index + 1), index);
}

void MissionPlan::replace(const QVector<MissionWaypoint>& waypoints, const QString& what) {
    if (waypoints == m_points)
        return;
    push(waypoints, what, -1);
}

void MissionPlan::fillDefaults() {
    QVector<MissionWaypoint> after = m_points;
    for (MissionWaypoint& w : after) {
        if (w.speed <= 0)
            w.speed = m_defaults.speed;
        if (w.tolerance <= 0)
            w.tolerance = m_defaults.tolerance;
    }
    if (after != m_points)
        push(std::move(after), tr("Default speeds and tolerances"), -1);
}

void MissionPlan::undo() {
    m_undo->undo();
}

void MissionPlan::redo() {
    m_undo->redo();
}

double MissionPlan::distanceM(double lat1, double lon1, double lat2, double lon2) {
    // WGS84: meridional (M) and prime-vertical (N) radii of curvature at the mean latitude.
    constexpr double a = 6378137.0, e2 = 6.69437999014e-3;
    const double phi = (lat1 + lat2) / 2 * kPi / 180;
    const double s = std::sin(phi);
    const double w = std::sqrt(1 - e2 * s * s);
    const double n = a / w, m = a * (1 - e2) / (w * w * w);
    double dLon = lon2 - lon1;
    if (dLon > 180)
        dLon -= 360;
    else if (dLon < -180)
        dLon += 360;
    const double dn = (lat2 - lat1) * kPi / 180 * m;
    const double de = dLon * kPi / 180 * n * std::cos(phi);
    return std::hypot(dn, de);
}

double MissionPlan::lengthM(std::optional<QPair<double, double>> from) const {
    double total = 0;
    if (from && !m_points.isEmpty())
        total += distanceM(from->first, from->second, m_points[0].lat, m_points[0].lon);
    for (int i = 1; i < size(); ++i)
        total += distanceM(m_points[i - 1].lat, m_points[i - 1].lon, m_points[i].lat, m_points[i].lon);
    return total;
}

double MissionPlan::etaS(std::optional<QPair<double, double>> from) const {
    auto speedOf = [this](int i) { return m_points[i].speed > 0 ? m_points[i].speed : m_defaults.speed; };
    double total = 0;
    if (from && !m_points.isEmpty())
        total += distanceM(from->first, from->second, m_points[0].lat, m_points[0].lon) / speedOf(0);
    for (int i = 1; i < size(); ++i)
        total += distanceM(m_points[i - 1].lat, m_points[i - 1].lon, m_points[i].lat, m_points[i].lon) /
                 speedOf(i);
    return total;
}

} // namespace ocu
