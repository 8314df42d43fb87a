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

// The route of a FeatureCollection (its first LineString or Point feature), of a Feature, or the geometry
// itself, as positions; with the properties of its feature.
bool findRoute(const QJsonObject& root, QJsonArray& positions, QJsonObject& properties) {
    const QString type = root.value(QLatin1String("type")).toString();
    if (type == QLatin1String("LineString")) {
        positions = root.value(QLatin1String("coordinates")).toArray();
        return true;
    }
    if (type == QLatin1String("Point")) {
        positions = QJsonArray{root.value(QLatin1String("coordinates"))};
        return true;
    }
    if (type == QLatin1String("Feature")) {
        const QJsonObject g = root.value(QLatin1String("geometry")).toObject();
        const QString gt = g.value(QLatin1String("type")).toString();
        if (gt != QLatin1String("LineString") && gt != QLatin1String("Point"))
            return false;
        findRoute(g, positions, properties);
        properties = root.value(QLatin1String("properties")).toObject();
        return true;
    }
    if (type == QLatin1String("FeatureCollection"))
        for (const QJsonValue& f : root.value(QLatin1String("features")).toArray())
            if (findRoute(f.toObject(), positions, properties))
                return true;
    return false;
}

} // namespace

QByteArray writeMissionGeoJson(const QVector<MissionWaypoint>& waypoints) {
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

std::optional<QVector<MissionWaypoint>> readMissionGeoJson(const QByteArray& json, QString* error) {
    auto fail = [error](const QString& why) -> std::optional<QVector<MissionWaypoint>> {
        if (error)
            *error = why;
        return std::nullopt;
    };
    QJsonParseError pe;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &pe);
    if (pe.error != QJsonParseError::NoError)
        return fail(QCoreApplication::translate("ocu::MissionGeoJson", "not JSON (%1 at byte %2)")
                        .arg(pe.errorString())
                        .arg(pe.offset));
    QJsonArray positions;
    QJsonObject properties;
    if (!doc.isObject() || !findRoute(doc.object(), positions, properties))
        return fail(
            QCoreApplication::translate("ocu::MissionGeoJson", "no GeoJSON LineString (the route) in it"));
    if (positions.isEmpty())
        return fail(QCoreApplication::translate("ocu::MissionGeoJson", "the route has no positions"));
    const QJsonValue per = properties.value(QLatin1String("waypoints"));
    if (!per.isUndefined() && (!per.isArray() || per.toArray().size() != positions.size()))
        return fail(QCoreApplication::translate("ocu::MissionGeoJson",
                                                "properties.waypoints must list one {speed, tolerance} per "
                                                "position (%1 positions)")
                        .arg(positions.size()));
    const QJsonArray perArray = per.toArray();
    QVector<MissionWaypoint> out;
    for (int i = 0; i < positions.size(); ++i) {
        const QJsonArray c = positions[i].toArray();
        if (c.size() < 2 || !c[0].isDouble() || !c[1].isDouble())
            return fail(
                QCoreApplication::translate("ocu::MissionGeoJson", "position %1 is not [longitude, latitude]")
                    .arg(i + 1));
        MissionWaypoint w;
        w.lon = c[0].toDouble();
        w.lat = c[1].toDouble();
        if (!(std::abs(w.lat) <= 90 && std::abs(w.lon) <= 180))
            return fail(
                QCoreApplication::translate("ocu::MissionGeoJson",
                                            "position %1 lies outside WGS84 (latitude %2, longitude %3)")
                    .arg(i + 1)
                    .arg(w.lat)
                    .arg(w.lon));
        if (!perArray.isEmpty()) {
            const QJsonObject p = perArray[i].toObject();
            const QJsonValue speed = p.value(QLatin1String("speed")),
                             tol = p.value(QLatin1String("tolerance"));
            w.speed = speed.toDouble();
            w.tolerance = tol.toDouble();
            if ((!speed.isUndefined() && !speed.isDouble()) || (!tol.isUndefined() && !tol.isDouble()) ||
                !(w.speed >= 0) || !(w.tolerance >= 0 && w.tolerance <= kMaxMissionToleranceM))
                return fail(QCoreApplication::translate("ocu::MissionGeoJson",
                                                        "waypoint %1: speed must be a number of 0 or more, "
                                                        "tolerance 0 to 100 m")
                                .arg(i + 1));
        }
        out << w;
    }
    return out;
}

std::optional<QVector<MissionWaypoint>> readMissionGeoJsonFile(const QString& path, QString* error) {
    QFile f(path);
    QString why;
    std::optional<QVector<MissionWaypoint>> out;
    constexpr qint64 kMaxBytes = 64 << 20; // far beyond any route: a wrong file is refused, not read whole
    if (!f.open(QIODevice::ReadOnly))
        why =
            QCoreApplication::translate("ocu::MissionGeoJson", "cannot be opened (%1)").arg(f.errorString());
    else if (f.size() > kMaxBytes)
        why = QCoreApplication::translate("ocu::MissionGeoJson", "too large for a mission file");
    else
        out = readMissionGeoJson(f.readAll(), &why);
    if (!out && error)
        *error = QStringLiteral("%1: %2").arg(path, why);
    return out;
}

bool writeMissionGeoJsonFile(const QString& path, const QVector<MissionWaypoint>& waypoints, QString* error) {
    QString why;
    QSaveFile f(path);
    if (waypoints.isEmpty())
        why = QCoreApplication::translate("ocu::MissionGeoJson", "the plan has no waypoints to save");
    else if (!f.open(QIODevice::WriteOnly) || f.write(writeMissionGeoJson(waypoints)) < 0 || !f.commit())
        why =
            QCoreApplication::translate("ocu::MissionGeoJson", "cannot be written (%1)").arg(f.errorString());
    if (!why.isEmpty() && error)
        *error = QStringLiteral("%1: %2").arg(path, why);
    return why.isEmpty();
}

} // namespace ocu
