// SiteMapView under load: data-driven repaints coalesced to a capped rate, and the per-frame caches
// that keep a frame with 1,000 machines free of string building and allocation. SiteMapView.cpp lists where
// the rest of the view is.
#include "widgets/SiteMapView.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace ocu {

void SiteMapView::setMaxDataFrameRate(double hz) {
    m_maxDataHz = std::isfinite(hz) && hz > 0 ? hz : 0.0;
    if (m_maxDataHz == 0 && m_dataRepaint.isActive()) {
        m_dataRepaint.stop();
        update();
    }
}

void SiteMapView::requestDataRepaint() {
    // New positions arrive in several batches per data period (one per protocol bridge and coalescer
    // drain); painting each would redraw 1,000 machines many times a second for no visible gain.
    if (m_dataRepaint.isActive())
        return; // a repaint is already due and will show this change too
    const qint64 intervalMs = m_maxDataHz > 0 ? qint64(std::ceil(1000.0 / m_maxDataHz)) : 0;
    const qint64 since = m_lastPaint.isValid() ? m_lastPaint.elapsed() : intervalMs;
    if (since >= intervalMs) {
        update();
        return;
    }
    m_dataRepaint.start(int(intervalMs - since));
}

const QImage& SiteMapView::machineLabelImage(const QString& text, qreal dpr) {
    // Keyed by the text alone (the colour and kind are fixed for machine labels): no key string is built per
    // label and frame.
    if (dpr != m_machineLabelsDpr || m_machineLabels.size() > 8000) {
        m_machineLabels.clear();
        m_machineLabelsDpr = dpr;
    }
    auto it = m_machineLabels.constFind(text);
    if (it == m_machineLabels.constEnd())
        it = m_machineLabels.insert(text, labelImage(text, MapLabelLayout::Kind::Machine, Qt::black, dpr));
    return *it;
}

namespace {
// A 1 px opaque line into 32-bit pixels: clipped to the image (Liang-Barsky), then Bresenham. What
// QPainter's aliased cosmetic pen draws, without a span call per pixel (1,000 trails are ~100,000 pixels).
void rasterLine(uchar* bits, qsizetype bpl, int w, int h, QPointF a, QPointF b, QRgb colour) {
    const double maxX = w - 0.001, maxY = h - 0.001;
    const double dx = b.x() - a.x(), dy = b.y() - a.y();
    double t0 = 0, t1 = 1;
    auto clip = [&](double p, double q) {
        if (p == 0)
            return q >= 0;
        const double r = q / p;
        if (p < 0) {
            if (r > t1)
                return false;
            t0 = std::max(t0, r);
        } else {
            if (r < t0)
                return false;
            t1 = std::min(t1, r);
        }
        return true;
    };
    if (!clip(-dx, a.x()) || !clip(dx, maxX - a.x()) || !clip(-dy, a.y()) || !clip(dy, maxY - a.y()))
        return;
    int x0 = int(a.x() + t0 * dx), y0 = int(a.y() + t0 * dy);
    const int x1 = int(a.x() + t1 * dx), y1 = int(a.y() + t1 * dy);
    const int sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
    const int ax = std::abs(x1 - x0), ay = -std::abs(y1 - y0);
    int err = ax + ay;
    for (;;) {
        reinterpret_cast<QRgb*>(bits + y0 * bpl)[x0] = colour;
        if (x0 == x1 && y0 == y1)
            break;
        const int e2 = 2 * err;
        if (e2 >= ay) {
            err += ay;
            x0 += sx;
        }
        if (e2 <= ax) {
            err += ax;
            y0 += sy;
        }
    }
}
} // namespace

bool SiteMapView::drawTrailsIntoBase(const QRectF& world, qreal dpr) {
    // Few trails are drawn antialiased by drawTrails(); hundreds aliased, which is what this does faster.
    if (m_trails.size() < 200 || m_static.format() != QImage::Format_RGB32 || m_static.isNull())
        return false;
    if (m_frameBase.size() != m_static.size() || m_frameBase.format() != m_static.format())
        m_frameBase = QImage(m_static.size(), m_static.format());
    m_frameBase.setDevicePixelRatio(m_static.devicePixelRatio());
    std::memcpy(m_frameBase.bits(), m_static.constBits(), size_t(m_static.sizeInBytes()));
    uchar* bits = m_frameBase.bits();
    const qsizetype bpl = m_frameBase.bytesPerLine();
    const int w = m_frameBase.width(), h = m_frameBase.height();
    const double s = m_scale * dpr;
    const double cx = m_viewSize.width() / 2.0 * dpr, cy = m_viewSize.height() / 2.0 * dpr;
    const QRgb colour = qRgb(0x55, 0x55, 0x88); // drawTrails' pen
    const QRectF grown = world.adjusted(-50, -50, 50, 50);
    // As drawTrails: zoomed out, every step-th point (segments of ~4 px), the newest always.
    const int step = std::max(1, int(std::ceil(4.0 / m_scale)));
    for (auto it = m_trails.cbegin(); it != m_trails.cend(); ++it) {
        const auto& t = it.value();
        const int n = int(t.size());
        if (n < 2 || !grown.contains(t.back()))
            continue;
        QPointF prev;
        bool first = true;
        for (int k = (n - 1) % step; k < n; k += step) {
            const QPointF& q = t[size_t(k)];
            const QPointF px(cx + (q.x() - m_center.x()) * s, cy - (q.y() - m_center.y()) * s);
            if (!first)
                rasterLine(bits, bpl, w, h, prev, px, colour);
            prev = px;
            first = false;
        }
    }
    return true;
}

} // namespace ocu
