#include "app/modules/JausMissionHeadless.h"

#include "app/HeadlessCommands.h"
#include "models/jaus/JausVehicleBridge.h"
#include "models/jaus/MissionJson.h"

#include <QHash>

#include <memory>

namespace ocu {

void addMissionLines(JausVehicleBridge* bridge, HeadlessCommands& table) {
    if (!bridge)
        return;
    table.addMachineFields(
        [bridge = QPointer<JausVehicleBridge>(bridge)](const QString& id, QJsonObject& line) {
            const auto sub = JausVehicleBridge::subsystemOf(id);
            const auto v = sub && bridge ? bridge->subsystem(*sub) : std::nullopt;
            if (v && (v->mission.state != MissionState::None || !v->mission.drivenPath.isEmpty()))
                line[QStringLiteral("mission")] = missionJson(v->mission);
        });
    // The machine state need not change with the mission (a vehicle standing at a waypoint, a replay's
    // mission record between two recorded states): its line goes out for the mission's sake.
    auto seen = std::make_shared<QHash<quint16, JausMission>>();
    QObject::connect(bridge, &JausVehicleBridge::subsystemUpdated, &table,
                     [seen, table = &table](const JausVehicle& v) {
                         JausMission& before = (*seen)[v.subsystem];
                         if (before == v.mission)
                             return;
                         const bool atOnce = !onlyProgressDiffers(before, v.mission);
                         before = v.mission;
                         table->machineFieldsChanged(JausVehicleBridge::machineId(v.subsystem), atOnce);
                     });
}

} // namespace ocu
