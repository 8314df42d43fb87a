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

QString text(const char* source) {
    return QCoreApplication::translate("MissionGeoJson", source);
}

// The one route Feature of a FeatureCollection (or a bare Feature).
std::optional<QJsonObject> routeFeature(const QJsonObject& root, QString* why) {
    const QString type = root.value(QStringLiteral("type")).toString();
    if (type == QLatin1String("Feature"))
        return root;
    if (type != QLatin1String("FeatureCollection")) {
        *why = text("not a GeoJSON FeatureCollection");
        return std::nullopt;
    }
    for (const QJsonValue& f : root.value(QStringLiteral("features")).toArray()) {
        const QString g = f.toObject()
                              .value(QStringLiteral("geometry"))
                              .toObject()
                              .value(QStringLiteral("type"))
                              .toString();
        if (g == QLatin1String("LineString") || g == QLatin1String("Point"))
            return f.toObject();
    }
    *why = text("no LineString feature (the route) in the file");
    return std::nullopt;
}

} // namespace

std::optional<QVector<MissionWaypoint>> readMissionGeoJson(const QByteArray& json, QString* error) {
    QString why;
    auto fail = [&](const QString& w) -> std::optional<QVector<MissionWaypoint>> {
        if (error)
            *error = w;
        return std::nullopt;
    };
    QJsonParseError pe;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &pe);
    if (!doc.isObject())
        return fail(text("not JSON: %1").arg(pe.errorString()));
    const auto feature = routeFeature(doc.object(), &why);
    if (!feature)
        return fail(why);
    const QJsonObject geometry = feature->value(QStringLiteral("geometry")).toObject();
    QJsonArray positions;
    if (geometry.value(QStringLiteral("type")).toString() == QLatin1String("Point"))
        positions << geometry.value(QStringLiteral("coordinates"));
    else
        positions = geometry.value(QStringLiteral("coordinates")).toArray();
    if (positions.isEmpty())
        return fail(text("the route has no positions"));
    const QJsonArray props =
        feature->value(QStringLiteral("properties")).toObject().value(QStringLiteral("waypoints")).toArray();
    QVector<MissionWaypoint> out;
    for (int i = 0; i < positions.size(); ++i) {
        const QJsonArray p = positions[i].toArray();
        if (p.size() < 2 || !p[0].isDouble() || !p[1].isDouble())
            return fail(text("position %1 is not [longitude, latitude]").arg(i + 1));
        MissionWaypoint w;
        w.lon = p[0].toDouble();
        w.lat = p[1].toDouble();
        if (!(std::fabs(w.lat) <= 90 && std::fabs(w.lon) <= 180))
            return fail(text("position %1 lies outside ±90° latitude / ±180° longitude").arg(i + 1));
        if (i < props.size()) {
            const QJsonObject o = props[i].toObject();
            w.speed = o.value(QStringLiteral("speed")).toDouble(0);
            w.tolerance = o.value(QStringLiteral("tolerance")).toDouble(0);
            if (!(w.speed >= 0) || !(w.tolerance >= 0 && w.tolerance <= 100))
                return fail(text("waypoint %1: speed must be 0 or more, tolerance 0 to 100 m").arg(i + 1));
        }
        out << w;
    }
    return out;
}

std::optional<QVector<MissionWaypoint>> readMissionGeoJsonFile(const QString& path, QString* error) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        if (error)
            *error = text("cannot open %1: %2").arg(path, f.errorString());
        return std::nullopt;
    }
    return readMissionGeoJson(f.readAll(), error);
}

QByteArray writeMissionGeoJson(const QVector<MissionWaypoint>& waypoints) {
    QJsonArray coords, props;
    for (const MissionWaypoint& w : waypoints) {
        coords << QJsonArray{w.lon, w.lat};
        props << QJsonObject{{QStringLiteral("speed"), w.speed}, {QStringLiteral("tolerance"), w.tolerance}};
    }
    QJsonObject feature{
        {QStringLiteral("type"), QStringLiteral("Feature")},
        {QStringLiteral("geometry"), QJsonObject{{QStringLiteral("type"), QStringLiteral("LineString")},
                                                 {QStringLiteral("coordinates"), coords}}},
        {QStringLiteral("properties"), QJsonObject{{QStringLiteral("waypoints"), props}}}};
    QJsonObject root{{QStringLiteral("type"), QStringLiteral("FeatureCollection")},
                     {QStringLiteral("features"), QJsonArray{feature}}};
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

bool writeMissionGeoJsonFile(const QString& path, const QVector<MissionWaypoint>& waypoints, QString* error) {
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(writeMissionGeoJson(waypoints)) < 0 || !f.commit()) {
        if (error)
            *error = text("cannot write %1: %2").arg(path, f.errorString());
        return false;
    }
    return true;
}

} // namespace ocu
