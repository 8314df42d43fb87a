#pragma once
// The ISO 23725 face of the dispatch panel: IsoBridge's dispatch views as protocol-neutral
// DispatchTrucks, its MapConnectivityV1 areas as DispatchAreas, and each truck's remaining route over the
// AHS's road network (the assignment's own route when it sent one, else the shortest path from the truck's
// reported way), so the panel and the map overlays include no stack header.
#include "models/DispatchSource.h"

#include <QHash>
#include <QPointer>

namespace ocu {

class IsoBridge;
struct IsoDispatchState;

DispatchTruck toDispatchTruck(const IsoDispatchState& s);

class IsoDispatchSource final : public DispatchSource {
    Q_OBJECT
public:
    explicit IsoDispatchSource(IsoBridge* bridge, QObject* parent = nullptr);

    QVector<DispatchTruck> trucks() const override;
    std::optional<DispatchTruck> truck(const QString& id) const override;
    QVector<DispatchArea> areas() const override;
    QString assignRefusal(const QString& id) const override;
    DispatchRoute route(const QString& id) const override;
    DispatchRoute routeTo(const QString& id, const DispatchArea& area) const override;
    Assign assignCommand(const QString& id, const QString& task, const DispatchArea& area,
                         QString* assignmentId = nullptr) const override;

private:
    QPointer<IsoBridge> m_bridge;
};

} // namespace ocu
