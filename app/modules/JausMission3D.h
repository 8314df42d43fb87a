#pragma once
// The mission panel's vehicle in the 3D view, live and in a replay alike: its planned route in the vehicle's
// colour (the 2D map's, MissionPlanLayer::missionColour) and the path it drove in a darker, thinner line
// beside it, each a RouteOverlay3D on the window's 3D view. Nothing without a 3D view in the build or the
// window.
#include "protocols/common/GeoFrame.h"

namespace ocu {

class MainWindow;
class MissionPanel;

void attachMissionRoutes3D(MainWindow& window, MissionPanel* panel, const GeoFrame& frame);

// The overlays' object names (tests find them among the 3D view's children).
inline const char* plannedRoute3DName() {
    return "missionPlannedRoute3D";
}
inline const char* drivenPath3DName() {
    return "missionDrivenPath3D";
}

} // namespace ocu
