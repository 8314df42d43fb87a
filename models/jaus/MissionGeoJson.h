#pragma once
// A mission route as a GeoJSON file (RFC 7946, WGS84): a FeatureCollection with one Feature whose geometry
// is a LineString of [lon, lat] positions (one position: a Point is accepted too), and whose
// properties.waypoints holds one {"speed", "tolerance"} per position (m/s and metres; 0 or missing = the
// vehicle's default). The plan editor saves and opens this format; the headless mission_upload reads it.
#include "models/jaus/JausMission.h"

#include <QByteArray>
#include <QString>
#include <QVector>

#include <optional>

namespace ocu {

// The route read from GeoJSON text; an error text (and nothing) when it is not such a route.
std::optional<QVector<MissionWaypoint>> readMissionGeoJson(const QByteArray& json, QString* error);
std::optional<QVector<MissionWaypoint>> readMissionGeoJsonFile(const QString& path, QString* error);
// The route as GeoJSON text (indented); written back it reads to the same waypoints.
QByteArray writeMissionGeoJson(const QVector<MissionWaypoint>& waypoints);
bool writeMissionGeoJsonFile(const QString& path, const QVector<MissionWaypoint>& waypoints, QString* error);

} // namespace ocu
