#pragma once
// Site map content in the local ENU frame (metres), neutral for the 2D map and the 3D view.
// ISO 23725 map elements (roads, lanes, areas) are converted to this by the ISO bridge; other sources
// (a site plan) may fill it too.
#include <QColor>
#include <QPointF>
#include <QRectF>
#include <QString>
#include <QVector>

namespace ocu {

enum class MapFeatureKind { Road, Lane, Area };

struct MapFeature {
    QString id;
    QString name;
    MapFeatureKind kind = MapFeatureKind::Road;
    QString defaultTask;     // e.g. "haul", "load", "dump", "park", "fuel"; colours the feature
    bool autonomous = false; // autonomous operation allowed
    QVector<QPointF> points; // (E, N); closed polygon for areas, polyline for roads/lanes
    double width = 0;        // road width (m) when known
};

struct SiteMapData {
    QVector<MapFeature> features;
    quint64 revision = 0; // bumped by whoever edits the data, so caches know when to rebuild

    QRectF bounds() const;
};

// Stable colour per default task (known tasks get fixed colours, others a hash-derived hue).
QColor taskColor(const QString& task);

} // namespace ocu
