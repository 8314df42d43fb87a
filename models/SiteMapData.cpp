#include "models/SiteMapData.h"

#include <QHash>

namespace ocu {

QRectF SiteMapData::bounds() const {
    bool first = true;
    double minX = 0, maxX = 0, minY = 0, maxY = 0;
    for (const MapFeature& f : features) {
        for (const QPointF& p : f.points) {
            if (first) {
                minX = maxX = p.x();
                minY = maxY = p.y();
                first = false;
            } else {
                minX = std::min(minX, p.x());
                maxX = std::max(maxX, p.x());
                minY = std::min(minY, p.y());
                maxY = std::max(maxY, p.y());
            }
        }
    }
    return first ? QRectF() : QRectF(QPointF(minX, minY), QPointF(maxX, maxY));
}

QColor taskColor(const QString& task) {
    const QString t = task.toLower();
    if (t.isEmpty())
        return QColor(0x80, 0x80, 0x80);
    if (t.contains(QLatin1String("haul")) || t.contains(QLatin1String("travel")))
        return QColor(0x8c, 0x6d, 0x46);
    if (t.contains(QLatin1String("load")))
        return QColor(0x2a, 0x9d, 0x8f);
    if (t.contains(QLatin1String("dump")))
        return QColor(0xb5, 0x83, 0x8d);
    if (t.contains(QLatin1String("park")))
        return QColor(0x6d, 0x6d, 0xa8);
    if (t.contains(QLatin1String("fuel")) || t.contains(QLatin1String("service")))
        return QColor(0xc9, 0xa2, 0x27);
    if (t.contains(QLatin1String("compact")) || t.contains(QLatin1String("pave")))
        return QColor(0x5b, 0x5b, 0x5b);
    return QColor::fromHsv(int(qHash(t) % 360), 110, 170);
}

} // namespace ocu
