#include "models/jaus/MissionRecordFeed.h"

#include "models/jaus/JausVehicleBridge.h"
#include "models/jaus/MissionJson.h"

#include <algorithm>

namespace ocu {

MissionRecordFeed::MissionRecordFeed(JausVehicleBridge* bridge, int intervalMs)
    : QObject(bridge), m_bridge(bridge), m_intervalMs(intervalMs) {
    m_clock.start();
    m_timer.setInterval(std::max(10, intervalMs / 2));
    connect(&m_timer, &QTimer::timeout, this, [this] {
        bool waiting = false;
        for (auto it = m_vehicles.begin(); it != m_vehicles.end(); ++it) {
            if (it->pending && m_clock.elapsed() - it->recordedAtMs >= m_intervalMs)
                record(it.key(), *it);
            waiting = waiting || it->pending;
        }
        if (!waiting)
            m_timer.stop();
    });
    if (bridge)
        connect(bridge, &JausVehicleBridge::subsystemUpdated, this, &MissionRecordFeed::onVehicle);
}

void MissionRecordFeed::onVehicle(const JausVehicle& vehicle) {
    Vehicle& v = m_vehicles[vehicle.subsystem];
    v.latest = vehicle.mission;
    if (v.latest == v.recorded) {
        v.pending = false;
        return;
    }
    if (!onlyProgressDiffers(v.latest, v.recorded) || v.recordedAtMs < 0 ||
        m_clock.elapsed() - v.recordedAtMs >= m_intervalMs) {
        record(vehicle.subsystem, v);
        return;
    }
    v.pending = true;
    if (!m_timer.isActive())
        m_timer.start();
}

void MissionRecordFeed::record(quint16 subsystem, Vehicle& v) {
    v.pending = false;
    if (!m_bridge || v.latest == v.recorded)
        return;
    m_bridge->publishDetail(JausVehicleBridge::machineId(subsystem), missionRecordKind(),
                            encodeMissionRecord(v.recorded, v.latest));
    v.recorded = v.latest;
    v.recordedAtMs = m_clock.elapsed();
}

void MissionRecordFeed::flush() {
    for (auto it = m_vehicles.begin(); it != m_vehicles.end(); ++it)
        if (it->pending)
            record(it.key(), *it);
}

} // namespace ocu
