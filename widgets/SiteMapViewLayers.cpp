// SiteMapView: what the cached static layer shows (what does not move with the machines: the background
// raster, the site map's areas, roads and lanes, the pass-count overlay) and the night palette that dims it.
// When and where it is redrawn: SiteMapViewStaticCache.cpp.
#include "widgets/MapBackground.h"
#include "widgets/MapLineRaster.h"
#include "widgets/SiteMapView.h"

#include <QApplication>
#include <QEvent>
#include <QPainter>
#include <QPainterPath>
#include <QPointer>
#include <QThreadPool>
#include <cmath>

namespace ocu {

namespace {
// Qt::DashLine on a 1 px pen (4 px on, 2 off, running on along the polyline), cut here rather than by the
// stroker: the stroker restarts the pattern where the view's edge cuts a line, so the strip drawn after a pan
// would not match the rest. Only the dashes within `within` (px) are made (a lane zoomed in is long).
void dashes(const QPolygonF& poly, const QRectF& within, QVector<QLineF>& out) {
    out.clear();
    double at = 0; // px along the polyline
    for (int i = 1; i < poly.size(); ++i) {
        const QPointF a = poly[i - 1], b = poly[i];
        const double len = QLineF(a, b).length();
        // The part of the segment within the rectangle (Liang-Barsky), as distances along it.
        double t0 = 0, t1 = 1;
        const double dx = b.x() - a.x(), dy = b.y() - a.y();
        const double ps[4] = {-dx, dx, -dy, dy};
        const double qs[4] = {a.x() - within.left(), within.right() - a.x(), a.y() - within.top(),
                              within.bottom() - a.y()};
        bool inside = len > 0;
        for (int k = 0; k < 4 && inside; ++k) {
            if (ps[k] == 0) {
                inside = qs[k] >= 0;
                continue;
            }
            const double t = qs[k] / ps[k];
            if (ps[k] < 0)
                t0 = std::max(t0, t);
            else
                t1 = std::min(t1, t);
        }
        if (inside && t0 < t1) {
            const double from = at + t0 * len, to = at + t1 * len;
            for (double d = std::floor(from / 6) * 6; d < to; d += 6) {
                const double on0 = std::max(d, at), on1 = std::min(d + 4, at + len);
                if (on1 > on0)
                    out.push_back(QLineF(a + (b - a) * ((on0 - at) / len), a + (b - a) * ((on1 - at) / len)));
            }
        }
        at += len;
    }
}
} // namespace

int SiteMapView::visibleFeatureCount(const QRectF& world) const {
    int visible = 0;
    for (const QRectF& b : m_featureBounds)
        visible += world.intersects(b) ? 1 : 0;
    return visible;
}

void SiteMapView::drawStatic(QPainter& p, const QSize& size, const QRectF& cull, MapLineRaster* lines) {
    const bool passCounts = (m_layers & LayerPassCount) && m_pass;
    drawBackgroundRaster(p, size);
    if (!(m_layers & LayerMap)) {
        if (passCounts)
            drawPassCount(p, size);
        return;
    }
    const double s = m_scale;
    const double cx = size.width() / 2.0, cy = size.height() / 2.0;
    auto toPx = [&](const QPointF& q) {
        return QPointF(cx + (q.x() - m_center.x()) * s, cy - (q.y() - m_center.y()) * s);
    };
    QPolygonF poly;
    QVector<QLineF> dashLines;
    const QRectF viewPx = QRectF(QPointF(0, 0), QSizeF(size)).adjusted(-8, -8, 8, 8);
    int drawn = 0;
    // Many thin lines: aliased 1 px lines are several times cheaper and look the same at that density;
    // written straight into the pixels (MapLineRaster) they cost a tenth of QPainter's cosmetic stroker.
    // Decided by the whole view (m_staticVisible), so a strip drawn after a pan matches the rest.
    const bool dense = m_staticVisible > kDenseWays;
    const qreal dpr = p.device() ? p.device()->devicePixelRatioF() : 1.0;
    p.setRenderHint(QPainter::Antialiasing, !dense);
    // Areas first, then the pass-count overlay (translucent area fills must not tint it), then roads and
    // lanes on top.
    for (int pass = 0; pass < 2; ++pass) {
        if (pass == 1 && passCounts) {
            drawPassCount(p, size);
            p.setRenderHint(QPainter::Antialiasing, !dense);
        }
        for (int i = 0; i < m_map.features.size(); ++i) {
            const MapFeature& f = m_map.features[i];
            const bool area = f.kind == MapFeatureKind::Area;
            if ((pass == 0) != area || f.points.size() < 2 || !cull.intersects(m_featureBounds[i]))
                continue;
            poly.resize(f.points.size());
            for (int k = 0; k < f.points.size(); ++k)
                poly[k] = toPx(f.points[k]);
            const QColor c = taskColor(f.defaultTask);
            if (area) {
                QColor fill = c;
                fill.setAlpha(70);
                p.setBrush(fill);
                p.setPen(QPen(c.darker(130), 0)); // cosmetic 1 px: the fast stroker path
                p.drawPolygon(poly);
            } else {
                const double wpx = f.width * s;
                if (wpx >= 3.0) {
                    // Zoomed in: the road at its real width, opaque without antialiasing (5x cheaper than
                    // antialiased wide pens; perf-anchors.md §4), then a thin centre line.
                    p.setRenderHint(QPainter::Antialiasing, false);
                    p.setPen(QPen(c.lighter(150), wpx, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
                    p.drawPolyline(poly);
                    p.setRenderHint(QPainter::Antialiasing, !dense);
                }
                const bool lane = f.kind == MapFeatureKind::Lane;
                const QColor line = lane ? c.lighter(120) : c;
                if (dense && lines) {
                    for (QPointF& q : poly)
                        q *= dpr;
                    lines->polyline(poly.constData(), int(poly.size()), line.rgb(), lane);
                } else if (lane) {
                    dashes(poly, viewPx, dashLines);
                    p.setPen(QPen(line, 0));
                    p.drawLines(dashLines);
                } else {
                    p.setPen(QPen(line, 0));
                    p.drawPolyline(poly);
                }
            }
            ++drawn;
        }
        p.setBrush(Qt::NoBrush);
    }
    m_stats.featuresDrawn += drawn;
}

void SiteMapView::setBackground(std::shared_ptr<const MapBackground> background) {
    m_background = std::move(background);
    ++m_backgroundRequest; // a pending load must not replace what was set since
    invalidateStatic();
    update();
}

void SiteMapView::setBackgroundVisible(bool visible) {
    if (m_backgroundVisible == visible)
        return;
    m_backgroundVisible = visible;
    invalidateStatic();
    update();
}

void SiteMapView::loadBackground(const QString& path) {
    const quint64 request = ++m_backgroundRequest;
    QPointer<SiteMapView> self(this);
    const GeoFrame frame = m_frame;
    QThreadPool::globalInstance()->start([self, request, path, frame] {
        MapBackground::LoadResult r = MapBackground::load(path, frame);
        QMetaObject::invokeMethod(
            qApp,
            [self, request, r] {
                if (!self || self->m_backgroundRequest != request)
                    return; // the view is gone, or another background was asked for since
                if (!r.background) {
                    emit self->backgroundFailed(r.error);
                    return;
                }
                self->m_background = r.background;
                self->invalidateStatic();
                self->update();
                emit self->backgroundLoaded(r.background->path());
            },
            Qt::QueuedConnection);
    });
}

void SiteMapView::drawBackgroundRaster(QPainter& p, const QSize& size) {
    if (!m_background || !m_backgroundVisible)
        return;
    m_background->draw(p, m_center, m_scale, QSizeF(size));
}

void SiteMapView::changeEvent(QEvent* e) {
    if (e->type() == QEvent::PaletteChange) {
        const bool night = palette().color(QPalette::Window).lightness() < 110;
        if (night != m_night) {
            m_night = night;
            m_labelImages.clear();
            m_machineLabels.clear(); // keyed by text only: their colours follow the palette
            m_rowLabels.clear();
            invalidateStatic();
            update();
        }
    }
    QWidget::changeEvent(e);
}

void SiteMapView::dimStaticForNight(QPainter& p, const QRectF& region) {
    // Multiplying keeps every hue of the plan, the background raster and the pass-count layer apart while
    // taking the light site-plan ground (#f4f1ea) down to about #5c5a58.
    p.save();
    p.setCompositionMode(QPainter::CompositionMode_Multiply);
    p.fillRect(region, QColor(0x60, 0x60, 0x64));
    p.restore();
}

} // namespace ocu
