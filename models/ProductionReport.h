#pragma once
// One production report of a haul truck as the machine sent it, protocol-neutral for the
// production model: a production state, a payload, a dump or a completed cycle (ISO 23725 §12:
// HaulTruckProductionStateV2, HaulTruckPayloadV1, HaulTruckDumpV1, HaulTruckProductionCycleV1). Every field
// comes from the report; what the report left out stays unknown (nullopt / empty), never a default.
#include <QMetaType>
#include <QString>
#include <QVector>

#include <optional>

namespace ocu {

struct ProductionStatePeriod {
    QString state;          // Driving, Queued, Spotting, Loading, Hauling, Dumping, Stopped, Parked, ...
    qint64 startUnixMs = 0; // 0 = not reported
    std::optional<double> seconds;
};

struct ProductionReport {
    enum class Kind { State, Payload, Dump, Cycle };
    Kind kind = Kind::State;
    QString truckId;   // fleet model id ("iso23725:<guid>")
    QString truckName; // HID
    qint64 unixMs = 0; // when the machine sent it (header time)
    QString assignmentId;
    // State: the production state and the way the truck is on.
    QString state;
    std::optional<qint64> wayId;
    // Payload: tonnes on board and the loader (equipment id) that loaded them.
    // Dump: tonnes dumped at wayId (the dump area or crusher).
    // Cycle: the load and dump areas, the loader, the payload and the states of the cycle with their times.
    std::optional<double> tonnes;
    QString loaderId;
    QString cycleId;
    std::optional<qint64> loadWayId;
    std::optional<qint64> dumpWayId;
    QVector<ProductionStatePeriod> periods;
};

} // namespace ocu

Q_DECLARE_METATYPE(ocu::ProductionReport)
