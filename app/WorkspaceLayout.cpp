#include "app/WorkspaceLayout.h"

#include <QCoreApplication>

namespace ocu {

WorkspacePlan workspacePlan(Workspace workspace) {
    using K = PanelKind;
    switch (workspace) {
    case Workspace::Dispatch:
        // The dispatch table needs 610 px in German: a little more of the width for the side column.
        return {{K::Map},
                {K::Dispatch, K::Fleet},
                {K::Alarms, K::Production, K::ControlRoom},
                {K::Dispatch, K::Production},
                55,
                64};
    case Workspace::Compaction:
        // The event log is a tab here too: an alarm needs the site manager's action (EEMUA 191).
        return {{K::Map},
                {K::CompactionAreas, K::PassCounts},
                {K::CrewMessages, K::Site3D, K::Alarms},
                {K::PassCounts, K::CompactionAreas, K::CrewMessages}};
    case Workspace::Ugv:
        // The video is the main area, the drive controls in front below the map (both in sight: driving
        // needs them; on a 768-px screen the controls take most of the column's height). Below 1600 px the
        // video gives the side column nearly half the width (it keeps 45 % of the window; its picture is
        // letterboxed anyway), so that the map above the controls is wide and over 200 px high. The event
        // log's controls need more than the side column (the alarm count stays in the status bar).
        return {{K::Video},
                {K::Map},
                {K::Teleop, K::VehicleControl, K::Missions},
                {K::Video, K::Teleop, K::VehicleControl, K::Missions},
                54,
                68,
                35,
                48};
    case Workspace::Monitor:
        return {{K::Map}, {K::Fleet}, {K::Alarms, K::ControlRoom}, {}};
    case Workspace::All:
        break;
    }
    // Every panel: the 3D view below with the tables (as a tab beside the map its tab bar would take the
    // map's height), the side column as wide as for Dispatch.
    return {{K::Map},
            {K::Fleet, K::Dispatch, K::VehicleControl, K::Video, K::Missions},
            {K::Alarms, K::Teleop, K::PassCounts, K::CompactionAreas, K::CrewMessages, K::Production,
             K::Site3D, K::ControlRoom, K::Other},
            {},
            55,
            64};
}

QString workspaceKey(Workspace workspace) {
    switch (workspace) {
    case Workspace::Dispatch:
        return QStringLiteral("dispatch");
    case Workspace::Compaction:
        return QStringLiteral("compaction");
    case Workspace::Ugv:
        return QStringLiteral("ugv");
    case Workspace::Monitor:
        return QStringLiteral("monitor");
    case Workspace::All:
        break;
    }
    return QStringLiteral("all");
}

QString workspaceTitle(Workspace workspace) {
    switch (workspace) {
    case Workspace::Dispatch:
        return QCoreApplication::translate("ocu::WorkspaceBar", "Dispatch");
    case Workspace::Compaction:
        return QCoreApplication::translate("ocu::WorkspaceBar", "Compaction");
    case Workspace::Ugv:
        return QCoreApplication::translate("ocu::WorkspaceBar", "UGV");
    case Workspace::Monitor:
        return QCoreApplication::translate("ocu::WorkspaceBar", "Monitor");
    case Workspace::All:
        break;
    }
    return QCoreApplication::translate("ocu::WorkspaceBar", "All");
}

bool workspaceFromKey(const QString& key, Workspace* workspace) {
    for (Workspace w : kAllWorkspaces)
        if (workspaceKey(w) == key) {
            *workspace = w;
            return true;
        }
    return false;
}

Workspace firstWorkspaceFor(OperatorRole role) {
    switch (role) {
    case OperatorRole::Monitor:
        return Workspace::Monitor;
    case OperatorRole::Dispatcher:
        return Workspace::Dispatch;
    case OperatorRole::SiteManager:
        return Workspace::Compaction;
    case OperatorRole::UgvOperator:
        return Workspace::Ugv;
    case OperatorRole::Supervisor:
    case OperatorRole::Admin:
        break;
    }
    return Workspace::All;
}

} // namespace ocu
