#include "models/jaus/MissionGeoJson.h"

#include <QCoreApplication>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>

#include <cmath>

namespace ocu {

namespace {

// The LineString of a FeatureCollection (its first line feature), of a Feature, or the geometry itself; with
// the properties of its feature.
bool findLine(const QJsonObject& root, QJsonArray& coordinates, QJsonObject& properties) {
    const QString type = root.value(QLatin1String("type")).toString();
    if (type == QLatin1String("LineString")) {
        coordinates = root.value(QLatin1String("coordinates")).toArray();
        return true;
    }
    if (type == QLatin1String("Feature")) {
        const QJsonObject g = root.value(QLatin1String("geometry")).toObject();
        if (g.value(QLatin1String("type")).toString() != QLatin1String("LineString"))
            return false;
        coordinates = g.value(QLatin1String("coordinates")).toArray();
        properties = root.value(QLatin1String("properties")).toObject();
        return true;
    }
    if (type == QLatin1String("FeatureCollection"))
        for (const QJsonValue& f : root.value(QLatin1String("features")).toArray())
            if (findLine(f.toObject(), coordinates, properties))
                return true;
    return false;
}

} // namespace

QByteArray missionToGeoJson(const QVector<MissionWaypoint>& waypoints) {
    QJsonArray coordinates, perPoint;
    for (const MissionWaypoint& w : waypoints) {
        coordinates.append(QJsonArray{w.lon, w.lat});
        perPoint.append(
            QJsonObject{{QStringLiteral("speed"), w.speed}, {QStringLiteral("tolerance"), w.tolerance}});
    }
    const QJsonObject feature{
        {QStringLiteral("type"), QStringLiteral("Feature")},
        {QStringLiteral("geometry"), QJsonObject{{QStringLiteral("type"), QStringLiteral("LineString")},
                                                 {QStringLiteral("coordinates"), coordinates}}},
        {QStringLiteral("properties"), QJsonObject{{QStringLiteral("waypoints"), perPoint}}}};
    const QJsonObject root{{QStringLiteral("type"), QStringLiteral("FeatureCollection")},
                           {QStringLiteral("features"), QJsonArray{feature}}};
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

MissionFileRead missionFromGeoJson(const QByteArray& json) {
    MissionFileRead r;
    QJsonParseError pe;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &pe);
    if (pe.error != QJsonParseError::NoError) {
        r.error = QCoreApplication::translate("ocu::MissionGeoJson", "not JSON (%1 at byte %2)")
                      .arg(pe.errorString())
                      .arg(pe.offset);
        return r;
    }
    QJsonArray coordinates;
    QJsonObject properties;
    if (!doc.isObject() || !findLine(doc.object(), coordinates, properties)) {
        r.error = QCoreApplication::translate("ocu::MissionGeoJson", "no GeoJSON LineString in it");
        return r;
    }
    if (coordinates.isEmpty()) {
        r.error = QCoreApplication::translate("ocu::MissionGeoJson", "the LineString has no points");
        return r;
    }
    const QJsonValue per = properties.value(QLatin1String("waypoints"));
    if (!per.isUndefined() && (!per.isArray() || per.toArray().size() != coordinates.size())) {
        r.error = QCoreApplication::translate(
                      "ocu::MissionGeoJson",
                      "properties.waypoints must list one {speed, tolerance} per point (%1 points)")
                      .arg(coordinates.size());
        return r;
    }
    const QJsonArray perArray = per.toArray();
    for (int i = 0; i < coordinates.size(); ++i) {
        const QJsonArray c = coordinates[i].toArray();
        if (c.size() < 2 || !c[0].isDouble() || !c[1].isDouble()) {
            r.error =
                QCoreApplication::translate("ocu::MissionGeoJson", "point %1 is not [longitude, latitude]")
                    .arg(i + 1);
            return {{}, r.error};
        }
        MissionWaypoint w;
        w.lon = c[0].toDouble();
        w.lat = c[1].toDouble();
        if (!std::isfinite(w.lat) || !std::isfinite(w.lon) || std::abs(w.lat) > 90 || std::abs(w.lon) > 180) {
            r.error = QCoreApplication::translate("ocu::MissionGeoJson",
                                                  "point %1 is outside WGS84 (latitude %2, longitude %3)")
                          .arg(i + 1)
                          .arg(w.lat)
                          .arg(w.lon);
            return {{}, r.error};
        }
        if (!perArray.isEmpty()) {
            const QJsonObject p = perArray[i].toObject();
            const QJsonValue speed = p.value(QLatin1String("speed")),
                             tol = p.value(QLatin1String("tolerance"));
            if ((!speed.isUndefined() && (!speed.isDouble() || speed.toDouble() < 0)) ||
                (!tol.isUndefined() && (!tol.isDouble() || tol.toDouble() < 0))) {
                r.error = QCoreApplication::translate(
                              "ocu::MissionGeoJson",
                              "waypoint %1: speed and tolerance must be numbers of 0 or more")
                              .arg(i + 1);
                return {{}, r.error};
            }
            w.speed = speed.toDouble();
            w.tolerance = tol.toDouble();
        }
        r.waypoints << w;
    }
    return r;
}

QString saveMissionGeoJson(const QString& path, const QVector<MissionWaypoint>& waypoints) {
    if (waypoints.isEmpty())
        return QCoreApplication::translate("ocu::MissionGeoJson", "%1: the plan has no waypoints to save")
            .arg(path);
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly))
        return QCoreApplication::translate("ocu::MissionGeoJson", "%1: cannot be written (%2)")
            .arg(path, f.errorString());
    f.write(missionToGeoJson(waypoints));
    if (!f.commit())
        return QCoreApplication::translate("ocu::MissionGeoJson", "%1: cannot be written (%2)")
            .arg(path, f.errorString());
    return {};
}

MissionFileRead readMissionGeoJson(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {{},
                QCoreApplication::translate("ocu::MissionGeoJson", "%1: cannot be opened (%2)")
                    .arg(path, f.errorString())};
    constexpr qint64 kMaxBytes = 64 << 20; // far beyond any route; a wrong file is refused, not read whole
    if (f.size() > kMaxBytes)
        return {
            {},
            QCoreApplication::translate("ocu::MissionGeoJson", "%1: too large for a mission file").arg(path)};
    MissionFileRead r = missionFromGeoJson(f.readAll());
    if (!r.ok())
        r.error = QStringLiteral("%1: %2").arg(path, r.error);
    return r;
}

} // namespace ocu
