#pragma once
// A dispatch source without a protocol, for tests and benchmarks: trucks, areas and routes are set by hand;
// assignCommand builds the same Assign (one task with its assignment id) as the ISO adapter.
#include "models/DispatchSource.h"

#include <QHash>

namespace ocu {

class FakeDispatchSource final : public DispatchSource {
    Q_OBJECT
public:
    using DispatchSource::DispatchSource;

    // Replaces or adds trucks and announces them (trucksChanged).
    void setTrucks(const QVector<DispatchTruck>& trucks, bool announce = true);
    void removeTruck(const QString& id);
    void setAreas(const QVector<DispatchArea>& areas);
    // Route per truck (route()) and per (truck, area way) (routeTo()).
    QHash<QString, DispatchRoute> routes;
    QHash<QString, DispatchRoute> previews; // key: truck id + '/' + way id
    QHash<QString, QString> refusals;       // truck id -> why an assignment is refused
    mutable int routeCalls = 0;

    QVector<DispatchTruck> trucks() const override;
    std::optional<DispatchTruck> truck(const QString& id) const override;
    QVector<DispatchArea> areas() const override { return m_areas; }
    QString assignRefusal(const QString& id) const override { return refusals.value(id); }
    DispatchRoute route(const QString& id) const override;
    DispatchRoute routeTo(const QString& id, const DispatchArea& area) const override;
    Assign assignCommand(const QString& id, const QString& task, const DispatchArea& area,
                         QString* assignmentId = nullptr) const override;

private:
    QHash<QString, DispatchTruck> m_trucks;
    QVector<DispatchArea> m_areas;
    mutable int m_nextAssignment = 1;
};

} // namespace ocu
