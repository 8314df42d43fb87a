#pragma once
// Mission files: a plan saved and opened as GeoJSON (RFC 7946: WGS84, longitude first), a FeatureCollection
// with one LineString Feature whose properties.waypoints holds {"speed": m/s, "tolerance": m} per point, in
// the order of the coordinates. Doubles are written in their shortest exact form, so a file saved and
// opened again gives the same waypoints bit for bit.
#include "models/jaus/JausMission.h"

#include <QByteArray>
#include <QString>
#include <QVector>

namespace ocu {

// What reading a mission file gave: the waypoints, or why not (for the operator, naming what is wrong).
struct MissionFileRead {
    QVector<MissionWaypoint> waypoints;
    QString error; // empty when read
    bool ok() const { return error.isEmpty(); }
};

QByteArray missionToGeoJson(const QVector<MissionWaypoint>& waypoints);
// Also takes a bare LineString Feature or geometry; missing properties leave speed and tolerance 0 (the
// vehicle's default).
MissionFileRead missionFromGeoJson(const QByteArray& json);

// Files: the error text names the file; empty when written.
QString saveMissionGeoJson(const QString& path, const QVector<MissionWaypoint>& waypoints);
MissionFileRead readMissionGeoJson(const QString& path);

} // namespace ocu
