#include "app/modules/JausMissionReplay.h"

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

void populateMissionReplay(const ModuleReplay& r, const QString& panelKey) {
    const recording::Recording* rec = r.controller->recording();
    QVector<MissionReplayBridge::Record> records;
    for (const recording::RecordedDetail& d :
         rec->details(missionRecordKind(), std::numeric_limits<qint64>::min(), rec->endMs()))
        records.push_back({d.t, d.machine, d.data});
    if (records.isEmpty())
        return;
    auto* vehicles = new MissionReplayBridge(std::move(records), r.controller->fleet(), &r.window);
    auto* panel = new MissionPanel(vehicles, r.selection);
    panel->setUnavailableText(QCoreApplication::translate(
        "JausModule", "Replay: the missions as the vehicles reported them then; commands are disabled."));
    panel->attachMap(r.map, r.frame);
    r.window.setPanelWidget(panelKey, panel);
    // The table shows the mission's waypoints as uploaded, and the first UGV with a mission is in front
    // until the operator selects another.
    QObject::connect(vehicles, &JausVehicleBridge::subsystemUpdated, panel, [panel](const JausVehicle& v) {
        MissionPlan* plan = panel->planFor(v.subsystem);
        if (!v.mission.waypoints.isEmpty() && plan->waypoints() != v.mission.waypoints)
            plan->replace(v.mission.waypoints, QCoreApplication::translate("JausModule", "Recorded mission"));
        if (!panel->vehicle())
            panel->setVehicle(v.subsystem);
    });
    QObject::connect(r.controller, &recording::ReplayController::positionChanged, vehicles,
                     &MissionReplayBridge::setTime);
    vehicles->setTime(r.controller->position());
}

} // namespace ocu
