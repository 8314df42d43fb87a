#pragma once
// Hands the flight recorder every UGV's mission as it changes (FleetBridge::publishDetail on the JAUS
// bridge, kind missionRecordKind()), so a replay shows the mission's states and the path it drove: a change
// of state, waypoint, ownership, reason or waypoints at once; the distance to go, the ETA and the driven
// path, which change with every pose, at most once per interval (the latest then).
#include "models/jaus/JausMission.h"

#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <QPointer>
#include <QTimer>

namespace ocu {

class JausVehicleBridge;
struct JausVehicle;

class MissionRecordFeed : public QObject {
public:
    explicit MissionRecordFeed(JausVehicleBridge* bridge, int intervalMs = 1000);
    // Publishes what waits for its interval now (tests, the end of a run).
    void flush();

private:
    struct Vehicle {
        JausMission recorded; // what the records so far give
        JausMission latest;
        qint64 recordedAtMs = -1;
        bool pending = false;
    };
    void onVehicle(const JausVehicle& v);
    void record(quint16 subsystem, Vehicle& v);

    QPointer<JausVehicleBridge> m_bridge;
    int m_intervalMs;
    QHash<quint16, Vehicle> m_vehicles;
    QElapsedTimer m_clock;
    QTimer m_timer;
};

} // namespace ocu
