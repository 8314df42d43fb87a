// The site map as the recording stores it (RecordSchema.h): compact JSON and back.
#include "models/recording/RecordSchema.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>

namespace ocu::recording {

QByteArray siteMapToJson(const SiteMapData& map) {
    QJsonArray features;
    for (const MapFeature& f : map.features) {
        QJsonArray pts;
        for (const QPointF& p : f.points) {
            pts.append(p.x());
            pts.append(p.y());
        }
        features.append(QJsonObject{{QStringLiteral("id"), f.id},
                                    {QStringLiteral("name"), f.name},
                                    {QStringLiteral("kind"), int(f.kind)},
                                    {QStringLiteral("task"), f.defaultTask},
                                    {QStringLiteral("auto"), f.autonomous},
                                    {QStringLiteral("width"), f.width},
                                    {QStringLiteral("points"), pts}});
    }
    return QJsonDocument(QJsonObject{{QStringLiteral("revision"), double(map.revision)},
                                     {QStringLiteral("features"), features}})
        .toJson(QJsonDocument::Compact);
}

SiteMapData siteMapFromJson(const QByteArray& json) {
    SiteMapData map;
    const QJsonObject o = QJsonDocument::fromJson(json).object();
    map.revision = quint64(o.value(QStringLiteral("revision")).toDouble());
    for (const QJsonValue& v : o.value(QStringLiteral("features")).toArray()) {
        const QJsonObject fo = v.toObject();
        MapFeature f;
        f.id = fo.value(QStringLiteral("id")).toString();
        f.name = fo.value(QStringLiteral("name")).toString();
        f.kind = MapFeatureKind(
            std::clamp(fo.value(QStringLiteral("kind")).toInt(), 0, int(MapFeatureKind::Area)));
        f.defaultTask = fo.value(QStringLiteral("task")).toString();
        f.autonomous = fo.value(QStringLiteral("auto")).toBool();
        f.width = fo.value(QStringLiteral("width")).toDouble();
        const QJsonArray pts = fo.value(QStringLiteral("points")).toArray();
        for (qsizetype i = 0; i + 1 < pts.size(); i += 2)
            f.points.push_back(QPointF(pts[i].toDouble(), pts[i + 1].toDouble()));
        map.features.push_back(std::move(f));
    }
    return map;
}

} // namespace ocu::recording
