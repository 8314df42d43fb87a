#pragma once
// How the mission panel and the map's "Go here" send a mission: typed commands through the command gate
// (audited, with what went on the wire per target). The JAUS module gives the panel an implementation; the
// panel never talks to a stack. `machineId` is the fleet's id of the vehicle ("jaus:<subsystem>").
#include "models/jaus/JausMission.h"

#include <QString>
#include <QVector>

namespace ocu {

class MissionCommands {
public:
    virtual ~MissionCommands() = default;
    virtual void upload(const QString& machineId, const QVector<MissionWaypoint>& waypoints) = 0;
    virtual void start(const QString& machineId, int fromIndex) = 0; // 0-based waypoint to start from
    virtual void pause(const QString& machineId) = 0;
    virtual void resume(const QString& machineId) = 0;
    virtual void abort(const QString& machineId) = 0;
    virtual void goTo(const QString& machineId, const MissionWaypoint& waypoint) = 0;
};

} // namespace ocu
