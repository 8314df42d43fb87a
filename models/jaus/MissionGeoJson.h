#pragma once
// A mission route as a GeoJSON file (RFC 7946, WGS84): a FeatureCollection with one Feature whose geometry is
// a LineString of [lon, lat] positions (one position: a Point is accepted too), and whose
// properties.waypoints holds one {"speed", "tolerance"} per position (m/s and metres; 0 or missing = the
// vehicle's default). The plan editor saves and opens this format; the headless mission_upload reads it.
// Doubles are written in their shortest exact form, so a route written and read again gives the same
// waypoints bit for bit.
#include "models/jaus/JausMission.h"

#include <QByteArray>
#include <QString>
#include <QVector>

#include <optional>

namespace ocu {

// The widest waypoint tolerance a file may carry: the wire's tolerance field spans 0 to 100 m.
constexpr double kMaxMissionToleranceM = 100;

// The route read from GeoJSON text (also a bare Feature or LineString geometry); nothing, with the reason in
// `error` (for the operator: which point or property is wrong), when it is not such a route.
std::optional<QVector<MissionWaypoint>> readMissionGeoJson(const QByteArray& json, QString* error);
// The same from a file; the error names the file.
std::optional<QVector<MissionWaypoint>> readMissionGeoJsonFile(const QString& path, QString* error);
// The route as GeoJSON text (indented).
QByteArray writeMissionGeoJson(const QVector<MissionWaypoint>& waypoints);
// Written atomically (QSaveFile); false with the reason naming the file (also for an empty route).
bool writeMissionGeoJsonFile(const QString& path, const QVector<MissionWaypoint>& waypoints, QString* error);

} // namespace ocu
