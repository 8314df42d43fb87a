#pragma once
// A workspace per job (like QGroundControl's Fly/Plan views): which panels each workspace shows and where. A
// panel declares what it shows (its PanelKind, in its PanelSpec); a workspace lists kinds, never panels or
// protocols, so a module's new panel falls into place by its kind, and a panel of a protocol the site does
// not run is simply not there. Pure data: MainWindow lays the docks out from it.
#include "protocols/common/OperatorRoles.h"

#include <QList>
#include <QString>

namespace ocu {

// What a panel shows, for the workspaces.
enum class PanelKind {
    Other,           // shown in "All" only
    Map,             // the 2D site map
    Site3D,          // the 3D view (the compacted surface)
    Fleet,           // the list of machines
    Alarms,          // the event log and its alarms
    PassCounts,      // pass counts, lifts and filters
    CompactionAreas, // areas, stations, coverage reports
    CrewMessages,    // text messages with the crews
    Dispatch,        // assignments of haul trucks
    Production,      // tonnes and loads
    Video,           // a vehicle's camera
    Teleop,          // a vehicle's drive controls (stick, speed, emergency stop)
    VehicleControl,  // control of vehicles and their details
    Missions,        // a vehicle's missions (plans of waypoints)
    ControlRoom,     // who is at which console of the control room (with the shared history only)
};

enum class Workspace { Dispatch, Compaction, Ugv, Monitor, All };
inline constexpr Workspace kAllWorkspaces[] = {Workspace::Dispatch, Workspace::Compaction, Workspace::Ugv,
                                               Workspace::Monitor, Workspace::All};

// Where a workspace puts its panels: the large area on the left (the map, or the video), and a column on the
// right with a top and a bottom group. A group's panels are tabs; the first one present is in front.
struct WorkspacePlan {
    QList<PanelKind> main;
    QList<PanelKind> sideTop;
    QList<PanelKind> sideBottom;
    // The kinds that make the workspace worth offering: it is offered when one of them is present (none:
    // always offered).
    QList<PanelKind> needs;
    int mainPercentSmall = 58; // share of the window's width for the main area below 1600 px
    int mainPercentLarge = 64; // and from 1600 px
    int topPercent = 50;       // the side column's top group's share of its height
    int topPercentLarge = 0;   // and from 1600 px (0: the same)
};

WorkspacePlan workspacePlan(Workspace workspace);

// The stable name (settings, --workspace) and the title on the workspace bar.
QString workspaceKey(Workspace workspace);
QString workspaceTitle(Workspace workspace);
bool workspaceFromKey(const QString& key, Workspace* workspace);

// The workspace a role starts in: the dispatcher's Dispatch, the site manager's Compaction, the UGV
// operator's UGV, the monitor's Monitor; the supervisor and the admin see All.
Workspace firstWorkspaceFor(OperatorRole role);

} // namespace ocu
