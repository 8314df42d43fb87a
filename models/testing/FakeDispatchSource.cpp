#include "models/testing/FakeDispatchSource.h"

#include <QJsonArray>

#include <algorithm>

namespace ocu {

void FakeDispatchSource::setTrucks(const QVector<DispatchTruck>& trucks, bool announce) {
    QStringList ids;
    for (const auto& t : trucks) {
        m_trucks.insert(t.id, t);
        ids << t.id;
    }
    if (announce)
        emit trucksChanged(ids);
}

void FakeDispatchSource::removeTruck(const QString& id) {
    m_trucks.remove(id);
    emit trucksChanged({id});
}

void FakeDispatchSource::setAreas(const QVector<DispatchArea>& areas) {
    m_areas = areas;
    emit areasChanged();
}

QVector<DispatchTruck> FakeDispatchSource::trucks() const {
    QVector<DispatchTruck> out;
    for (const auto& t : m_trucks)
        out << t;
    std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
    return out;
}

std::optional<DispatchTruck> FakeDispatchSource::truck(const QString& id) const {
    auto it = m_trucks.constFind(id);
    if (it == m_trucks.constEnd())
        return std::nullopt;
    return *it;
}

DispatchRoute FakeDispatchSource::route(const QString& id) const {
    ++routeCalls;
    if (auto it = routes.constFind(id); it != routes.constEnd())
        return *it;
    DispatchRoute r;
    r.error = QStringLiteral("no active assignment");
    return r;
}

DispatchRoute FakeDispatchSource::routeTo(const QString& id, const DispatchArea& area) const {
    return previews.value(id + QLatin1Char('/') + QString::number(area.wayId));
}

Assign FakeDispatchSource::assignCommand(const QString& id, const QString& task, const DispatchArea& area,
                                         QString* assignmentId) const {
    const QString aid = QStringLiteral("assignment-%1").arg(m_nextAssignment++);
    if (assignmentId)
        *assignmentId = aid;
    AssignTask t;
    t.assignmentId = aid;
    t.task = task;
    t.destinationId = area.wayId;
    return Assign{id, {t}};
}

} // namespace ocu
