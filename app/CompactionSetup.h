#pragma once
// The compaction job of a started site: the session (design, areas, reports) fed by the OSYRIS
// pass counts, the headless "coverage_report" command, and in the GUI the map overlay and the areas panel.
// The OSYRIS module (app/modules/OsyrisModule.cpp) owns it.
#include "protocols/site/SiteConfig.h"

#include <QObject>
#include <QStringList>

class QWidget;

namespace ocu {

class CompactionSession;
class HeadlessCommands;
class OsyrisPassCountLayer;
class SiteMapView;

// nullptr in a build without the coverage module. Problems (design not readable) are appended to problems.
CompactionSession* startCompaction(const SiteConfig& config, const GeoFrame& frame,
                                   const OsyrisPassCountLayer* layer, QObject* parent, QStringList* problems);
// The headless "coverage_report" command of the session (nothing when session is nullptr).
void registerCompactionHeadless(HeadlessCommands& table, CompactionSession* session);
// The session's countsChanged() follows the bridge's passCountChanged() (the areas table refreshes).
void watchCompactionCounts(CompactionSession* session, QObject* fleetBridge);
// The areas panel (areas, stations, lifts, the coverage report) with its overlay on the map.
QWidget* buildCompactionPanel(CompactionSession* session, SiteMapView* map);
// The design's centre line and boundary and the areas in the 3D view (a build with the 3D view).
void attachCompaction3D(CompactionSession* session, QWidget* site3DView);

} // namespace ocu
