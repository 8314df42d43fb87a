#include "widgets/dispatch/RouteOverlay2D.h"

#include <QPainter>
#include <QPainterPath>

#include <cmath>
#include <limits>

namespace ocu {

namespace {
double dist2(QPointF a, QPointF b) {
    const QPointF d = a - b;
    return d.x() * d.x() + d.y() * d.y();
}
QPointF centroid(const QVector<QPointF>& pts) {
    QPointF c;
    for (const auto& p : pts)
        c += p;
    return pts.isEmpty() ? c : c / double(pts.size());
}
const MapFeature* featureOf(const SiteMapData& map, const QString& id) {
    for (const auto& f : map.features)
        if (f.id == id)
            return &f;
    return nullptr;
}
} // namespace

QVector<QPointF> routePath(const SiteMapData& map, const QString& link, const QVector<qint64>& ways,
                           QVector<qint64>* missing) {
    // One point list per way: a road's polyline, an area's centroid.
    QHash<QString, const MapFeature*> byId;
    byId.reserve(map.features.size());
    for (const auto& f : map.features)
        byId.insert(f.id, &f);
    QVector<QVector<QPointF>> parts;
    for (qint64 w : ways) {
        const MapFeature* f = byId.value(link + QLatin1Char('/') + QString::number(std::llabs(w)));
        if (!f || f->points.isEmpty()) {
            if (missing)
                *missing << w;
            continue;
        }
        parts << (f->kind == MapFeatureKind::Area ? QVector<QPointF>{centroid(f->points)} : f->points);
    }
    QVector<QPointF> path;
    for (int i = 0; i < parts.size(); ++i) {
        QVector<QPointF> part = parts[i];
        if (part.size() > 1) {
            bool reverse = false;
            if (!path.isEmpty()) {
                // Continue where the path ended.
                reverse = dist2(path.back(), part.back()) < dist2(path.back(), part.front());
            } else if (i + 1 < parts.size()) {
                // The first road: end where the next way is nearest.
                double front = std::numeric_limits<double>::max(), back = front;
                for (const auto& q : {parts[i + 1].front(), parts[i + 1].back()}) {
                    front = std::min(front, dist2(part.front(), q));
                    back = std::min(back, dist2(part.back(), q));
                }
                reverse = front < back;
            }
            if (reverse)
                std::reverse(part.begin(), part.end());
        }
        for (const auto& p : part)
            if (path.isEmpty() || path.back() != p)
                path << p;
    }
    return path;
}

RouteOverlay2D::RouteOverlay2D(SiteMapView* view) : m_view(view) {
    if (view)
        view->addOverlay(this);
}

RouteOverlay2D::~RouteOverlay2D() {
    if (m_view)
        m_view->removeOverlay(this);
}

void RouteOverlay2D::setRoute(const QString& link, const QVector<qint64>& ways, const QString& label,
                              bool preview) {
    const bool lineChanged = link != m_link || ways != m_ways || preview != m_preview;
    if (!lineChanged && label == m_label)
        return;
    m_label = label;
    if (lineChanged) {
        m_preview = preview;
        m_link = link;
        m_ways = ways;
        m_pathValid = false;
    }
    if (!m_view)
        return;
    if (lineChanged)
        m_view->staticOverlayChanged(); // the line is in the view's static layer
    else
        m_view->update(); // the label is drawn every frame (ETA)
}

const QVector<QPointF>& RouteOverlay2D::path() const {
    const quint64 rev = m_view ? m_view->siteMap().revision : 0;
    if (!m_pathValid || rev != m_pathRevision) {
        m_path =
            m_view && !m_ways.isEmpty() ? routePath(m_view->siteMap(), m_link, m_ways) : QVector<QPointF>{};
        const MapFeature* dest = m_view ? featureOf(m_view->siteMap(), destinationFeature()) : nullptr;
        m_destinationArea = dest && dest->kind == MapFeatureKind::Area ? dest->points : QVector<QPointF>{};
        m_pathRevision = rev;
        m_pathValid = true;
    }
    return m_path;
}

QString RouteOverlay2D::destinationFeature() const {
    return m_ways.isEmpty() ? QString()
                            : m_link + QLatin1Char('/') + QString::number(std::llabs(m_ways.back()));
}

void RouteOverlay2D::paintStatic(QPainter& p, const SiteMapView& view) {
    // The line, the destination and the arrow change only with the route and the view: drawn into the
    // view's cached static layer, not again in every 10 Hz frame (two wide antialiased strokes).
    const QVector<QPointF>& world = path();
    if (world.isEmpty())
        return;
    QPolygonF screen;
    screen.reserve(world.size());
    for (const auto& q : world)
        screen << view.worldToScreen(q);
    QPolygonF area;
    for (const auto& q : m_destinationArea)
        area << view.worldToScreen(q);
    // A part of the layer away from the route (a roller's pass-count patch, a pan's strip): nothing to
    // draw there (the margin: half the casing, the arrowhead).
    if (p.hasClipping()) {
        // Per segment: the route's box covers much of the map, its line little of it.
        const QRectF clip = p.clipBoundingRect().adjusted(-16, -16, 16, 16);
        bool near = area.boundingRect().intersects(clip) || clip.contains(screen.front());
        for (qsizetype i = 1; i < screen.size() && !near; ++i)
            near = clip.intersects(QRectF(screen[i - 1], screen[i]).normalized().adjusted(-1, -1, 1, 1));
        if (!near)
            return;
    }
    p.save();
    p.setRenderHint(QPainter::Antialiasing, true);
    if (!area.isEmpty()) { // the destination area, outlined
        p.setPen(QPen(QColor(0x6a, 0x1b, 0x9a), 3, Qt::DashLine));
        p.setBrush(QColor(0x6a, 0x1b, 0x9a, 40));
        p.drawPolygon(area);
    }
    p.setBrush(Qt::NoBrush);
    p.setPen(QPen(QColor(255, 255, 255, 220), 9, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    p.drawPolyline(screen);
    p.setPen(QPen(QColor(0x8e, 0x24, 0xaa), 5, m_preview ? Qt::DashLine : Qt::SolidLine, Qt::RoundCap,
                  Qt::RoundJoin));
    p.drawPolyline(screen);
    // Start dot and an arrowhead at the destination.
    const QPointF end = screen.back();
    p.setBrush(QColor(0x8e, 0x24, 0xaa));
    p.setPen(QPen(Qt::white, 2));
    p.drawEllipse(screen.front(), 5, 5);
    if (screen.size() > 1) {
        QPointF prev = screen[screen.size() - 2];
        for (int i = int(screen.size()) - 2; i >= 0 && dist2(screen[i], end) < 4; --i)
            prev = screen[i];
        const double a = std::atan2(end.y() - prev.y(), end.x() - prev.x());
        const double s = 14;
        QPolygonF head;
        head << end << end - QPointF(std::cos(a - 0.45) * s, std::sin(a - 0.45) * s)
             << end - QPointF(std::cos(a + 0.45) * s, std::sin(a + 0.45) * s);
        p.drawPolygon(head);
    }
    p.restore();
}

void RouteOverlay2D::paintOverlay(QPainter& p, const SiteMapView& view) {
    const QVector<QPointF>& world = path();
    if (world.isEmpty() || m_label.isEmpty())
        return;
    // The label as an image, laid out again only when its text changes (ETA), not in every frame.
    QFont f = p.font();
    f.setBold(true);
    const qreal dpr = p.device() ? p.device()->devicePixelRatioF() : 1.0;
    if (m_labelImage.isNull() || m_labelImageText != m_label || m_labelImageFont != f ||
        m_labelImage.devicePixelRatio() != dpr) {
        const QRectF box = QFontMetricsF(f).boundingRect(m_label).adjusted(-4, -2, 4, 2);
        const QRectF at(QPointF(0, 0), box.size());
        m_labelImage = QImage((at.size() * dpr).toSize() + QSize(1, 1), QImage::Format_ARGB32_Premultiplied);
        m_labelImage.setDevicePixelRatio(dpr);
        m_labelImage.fill(Qt::transparent);
        QPainter lp(&m_labelImage);
        lp.setRenderHint(QPainter::Antialiasing, true);
        lp.setFont(f);
        lp.setPen(Qt::NoPen);
        lp.setBrush(QColor(0x4a, 0x14, 0x8c, 220));
        lp.drawRoundedRect(at, 3, 3);
        lp.setPen(Qt::white);
        lp.drawText(at, Qt::AlignCenter, m_label);
        m_labelImageText = m_label;
        m_labelImageFont = f;
        m_labelSize = at.size();
    }
    // Above and right of the destination, on whole pixels.
    const QPointF end = view.worldToScreen(world.back());
    const QPointF topLeft(std::round(end.x() + 10), std::round(end.y() - 10 - m_labelSize.height()));
    p.drawImage(topLeft, m_labelImage);
    view.reserveLabelArea(QRectF(topLeft, m_labelSize)); // machine labels keep clear of it
}

} // namespace ocu
