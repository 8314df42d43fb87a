#include "app/modules/JausMissionReplay.h"

#include "app/modules/JausMission3D.h"
#include "app/modules/JausMissionHeadless.h"
#include "models/FleetSelection.h"
#include "models/jaus/MissionJson.h"
#include "models/jaus/MissionPlan.h"
#include "models/jaus/MissionReplayBridge.h"
#include "models/recording/ReplayController.h"
#include "widgets/SiteMapView.h"
#include "widgets/jaus/MissionPanel.h"

#include <QCoreApplication>

#include <limits>

namespace ocu {

MissionReplayBridge* makeMissionReplayBridge(recording::ReplayController* controller, QObject* parent) {
    const recording::Recording* rec = controller->recording();
    QVector<MissionReplayBridge::Record> records;
    for (const recording::RecordedDetail& d :
         rec->details(missionRecordKind(), std::numeric_limits<qint64>::min(), rec->endMs()))
        records.push_back({d.t, d.machine, d.data});
    if (records.isEmpty())
        return nullptr;
    auto* vehicles = new MissionReplayBridge(std::move(records), controller->fleet(), parent);
    QObject::connect(controller, &recording::ReplayController::positionChanged, vehicles,
                     &MissionReplayBridge::setTime);
    return vehicles;
}

void populateMissionReplay(const ModuleReplay& r, const QString& panelKey) {
    MissionReplayBridge* vehicles = makeMissionReplayBridge(r.controller, &r.window);
    if (!vehicles)
        return;
    auto* panel = new MissionPanel(vehicles, r.selection);
    panel->setUnavailableText(QCoreApplication::translate(
        "JausModule", "Replay: the missions as the vehicles reported them then; commands are disabled."));
    panel->attachMap(r.map, r.frame);
    r.window.setPanelWidget(panelKey, panel);
    attachMissionRoutes3D(r.window, panel, r.frame); // the route and the path driven in 3D, as live
    // The table shows the mission's waypoints as uploaded, and the first UGV with a mission is in front
    // until the operator selects another.
    QObject::connect(vehicles, &JausVehicleBridge::subsystemUpdated, panel, [panel](const JausVehicle& v) {
        MissionPlan* plan = panel->planFor(v.subsystem);
        if (!v.mission.waypoints.isEmpty() && plan->waypoints() != v.mission.waypoints)
            plan->replace(v.mission.waypoints, QCoreApplication::translate("JausModule", "Recorded mission"));
        if (!panel->vehicle())
            panel->setVehicle(v.subsystem);
    });
    vehicles->setTime(r.controller->position());
}

void registerMissionReplayHeadless(const ModuleHeadlessReplay& r) {
    MissionReplayBridge* vehicles = makeMissionReplayBridge(r.controller, r.owner);
    if (!vehicles)
        return;
    addMissionLines(vehicles, r.commands);
    vehicles->setTime(r.controller->position());
}

} // namespace ocu
