// SiteMapView: the cached static layer (what does not move with the machines: the background raster, the
// site map's areas, roads and lanes, the pass-count overlay) and the night palette that dims it.
#include "widgets/MapBackground.h"
#include "widgets/SiteMapView.h"

#include <QApplication>
#include <QEvent>
#include <QPainter>
#include <QPainterPath>
#include <QPointer>
#include <QThreadPool>
#include <cmath>

namespace ocu {

void SiteMapView::ensureStaticLayer(const QSize& size, qreal dpr) {
    const QSize px = (QSizeF(size) * dpr).toSize();
    if (m_pass && (m_pass->revision() != m_passImageRevision || m_palette != m_passImagePalette ||
                   m_target.min != m_passImageTarget.min || m_target.max != m_passImageTarget.max))
        m_staticValid = false;
    if (m_passOverlayPending)
        m_staticValid = false; // owed pass-count tiles: this frame renders more of them
    if (m_staticValid && m_static.size() == px && m_staticCenter == m_center && m_staticScale == m_scale)
        return;
    if (m_static.size() != px)
        m_static = QImage(px, QImage::Format_RGB32); // opaque: the per-frame blit is a copy, not a blend
    m_static.setDevicePixelRatio(dpr);
    m_static.fill(QColor(0xf4, 0xf1, 0xea)); // light site-plan background
    QPainter sp(&m_static);
    m_passOverlayPending = false; // drawPassCount says again if tiles are still owed
    drawStatic(sp, size);
    // Screenshots (app/Screenshot.cpp) wait while tiles are owed, like for a video view's first frame.
    setProperty("screenshotPending", m_passOverlayPending);
    if (m_night)
        dimStaticForNight(sp, size);
    sp.end();
    m_staticValid = true;
    m_staticCenter = m_center;
    m_staticScale = m_scale;
    m_stats.staticRebuilt = true;
}

void SiteMapView::drawStatic(QPainter& p, const QSize& size) {
    const QRectF world = visibleWorld(size);
    const bool passCounts = (m_layers & LayerPassCount) && m_pass;
    m_mapLabels.clear();
    drawBackgroundRaster(p, size);
    if (!(m_layers & LayerMap)) {
        if (passCounts)
            drawPassCount(p, size);
        return;
    }
    p.setRenderHint(QPainter::Antialiasing, true);
    const double s = m_scale;
    const double cx = size.width() / 2.0, cy = size.height() / 2.0;
    auto toPx = [&](const QPointF& q) {
        return QPointF(cx + (q.x() - m_center.x()) * s, cy - (q.y() - m_center.y()) * s);
    };
    QPolygonF poly;
    int drawn = 0;
    int visible = 0;
    for (int i = 0; i < m_featureBounds.size(); ++i)
        visible += world.intersects(m_featureBounds[i]) ? 1 : 0;
    // Many thin lines: aliased 1 px lines are several times cheaper and look the same at that density.
    const bool dense = visible > 1000;
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
            if ((pass == 0) != area || f.points.size() < 2 || !world.intersects(m_featureBounds[i]))
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
                p.setPen(QPen(f.kind == MapFeatureKind::Lane ? c.lighter(120) : c, 0,
                              f.kind == MapFeatureKind::Lane ? Qt::DashLine : Qt::SolidLine));
                p.drawPolyline(poly);
            }
            ++drawn;
        }
        p.setBrush(Qt::NoBrush);
    }
    m_stats.featuresDrawn = drawn;
    // Names only when they can be read (not with thousands of features on screen); placed per frame
    // together with the machine labels so that none overlaps another (SiteMapViewSymbols.cpp).
    if ((m_layers & LayerMapNames) && visible <= 400)
        collectMapLabels(size);
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
            invalidateStatic();
            update();
        }
    }
    QWidget::changeEvent(e);
}

void SiteMapView::dimStaticForNight(QPainter& p, const QSize& size) {
    // Multiplying keeps every hue of the plan, the background raster and the pass-count layer apart while
    // taking the light site-plan ground (#f4f1ea) down to about #5c5a58.
    p.save();
    p.setCompositionMode(QPainter::CompositionMode_Multiply);
    p.fillRect(QRect(QPoint(0, 0), size), QColor(0x60, 0x60, 0x64));
    p.restore();
}

} // namespace ocu
