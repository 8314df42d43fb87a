#pragma once
// Routes from other tools as mission waypoints, read through GDAL/OGR: GPX (a route's rtept, else a track's
// trkpt, else the waypoints in file order) and KML (the first LineString placemark, else the points in file
// order), and any other vector file OGR opens the same way. Coordinates are converted to WGS84 when the layer
// has another reference system. Speed and tolerance come out 0 (the plan's defaults fill them).
#include "models/jaus/JausMission.h"

#include <QString>
#include <QVector>

namespace ocu {

// What an import gave: the waypoints, or why not (for the operator: the file and what is wrong with it).
struct MissionFileRead {
    QVector<MissionWaypoint> waypoints;
    QString error; // empty when read
    bool ok() const { return error.isEmpty(); }
};

// Never throws and never crashes on a bad file: the error names the file and what is wrong with it.
MissionFileRead importMissionRoute(const QString& path);

} // namespace ocu
