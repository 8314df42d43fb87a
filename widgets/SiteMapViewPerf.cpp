// SiteMapView under load: data-driven repaints coalesced to a capped rate, and the per-frame caches
// that keep a frame with 1,000 machines free of string building and allocation. SiteMapView.cpp lists where
// the rest of the view is.
#include "widgets/MapLineRaster.h"
#include "widgets/SiteMapView.h"

#include <QPaintEngine>
#include <QPainter>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <numeric>

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

const QImage& SiteMapView::machineLabelImage(int row, const QString& text, qreal dpr) {
    // Keyed by the text alone (the colour and kind are fixed for machine labels), and remembered per fleet
    // row: a label whose text did not change costs a string compare, not a hash of it.
    if (dpr != m_machineLabelsDpr || m_machineLabels.size() > 8000) {
        m_machineLabels.clear();
        m_rowLabels.clear();
        m_machineLabelsDpr = dpr;
    }
    if (row >= m_rowLabels.size())
        m_rowLabels.resize(row + 1);
    RowLabel& memo = m_rowLabels[row];
    if (!memo.image.isNull() && memo.text == text)
        return memo.image;
    auto it = m_machineLabels.constFind(text);
    if (it == m_machineLabels.constEnd())
        it = m_machineLabels.insert(text, labelImage(text, MapLabelLayout::Kind::Machine, Qt::black, dpr));
    memo.text = text;
    memo.image = *it;
    return memo.image;
}

QImage* SiteMapView::painterImage(QPainter& p, QVector<QRect>& clip) const {
    // The image the painter writes into (a widget's backing store, an offscreen target), when trails can be
    // written into it directly: 32 bits, only translated and scaled, not shared, no clip of the caller's.
    QPaintEngine* engine = p.paintEngine();
    QPaintDevice* device = engine ? engine->paintDevice() : nullptr;
    if (!device || device->devType() != QInternal::Image || p.hasClipping())
        return nullptr;
    auto* img = static_cast<QImage*>(device);
    const QImage::Format f = img->format();
    if ((f != QImage::Format_RGB32 && f != QImage::Format_ARGB32_Premultiplied) || !img->isDetached())
        return nullptr;
    const QTransform t = p.deviceTransform();
    if (t.type() > QTransform::TxScale || t.m11() != t.m22() || t.m11() <= 0)
        return nullptr;
    const QRect view = t.mapRect(QRectF(QPointF(0, 0), QSizeF(m_viewSize))).toAlignedRect() & img->rect();
    const QRegion system = engine->systemClip(); // a widget's exposed region, device px; empty: all of it
    clip.clear();
    if (system.isEmpty())
        clip.push_back(view);
    else
        for (const QRect& r : system)
            if (const QRect c = r & view; !c.isEmpty())
                clip.push_back(c);
    return img;
}

void SiteMapView::rasterTrails(QImage& img, const QVector<QRect>& clip, const QTransform& toDevice,
                               const QRectF& world) {
    uchar* bits = const_cast<uchar*>(img.constBits()); // the painter's own buffer: no detach
    const qsizetype bpl = img.bytesPerLine();
    const double k = toDevice.m11();
    const double s = m_scale * k;
    const double cx = toDevice.dx() + m_viewSize.width() / 2.0 * k;
    const double cy = toDevice.dy() + m_viewSize.height() / 2.0 * k;
    const QRgb colour = qRgb(0x55, 0x55, 0x88); // drawTrails' pen
    const QRectF grown = world.adjusted(-50, -50, 50, 50);
    // As drawTrails: zoomed out, every step-th point (segments of ~4 px), the newest always.
    const int step = std::max(1, int(std::ceil(4.0 / m_scale)));
    const QRect bounds = std::accumulate(clip.begin(), clip.end(), QRect(), std::bit_or<QRect>());
    const bool one = clip.size() == 1;
    m_trails.forEach([&](const MapTrails::Span& t) {
        const int n = t.n;
        if (n < 2 || !grown.contains(t.back()))
            return;
        QPointF prev;
        bool first = true;
        for (int i = (n - 1) % step; i < n; i += step) {
            const QPointF px(cx + (t.xy[2 * i] - m_center.x()) * s,
                             cy - (t.xy[2 * i + 1] - m_center.y()) * s);
            if (!first) {
                if (one)
                    clippedLine(bits, bpl, bounds, prev, px, colour);
                else if (QRectF(prev, px).normalized().adjusted(-1, -1, 1, 1).intersects(QRectF(bounds)))
                    for (const QRect& c : clip) // a widget's exposed region: only its own rectangles
                        clippedLine(bits, bpl, c, prev, px, colour);
            }
            prev = px;
            first = false;
        }
    });
}

bool SiteMapView::drawTrailsIntoBase(const QRectF& world, qreal dpr) {
    // A painter without an image of its own (a QPixmap, a printer): trails into a copy of the static layer.
    if (m_static.format() != QImage::Format_RGB32 || m_static.isNull())
        return false;
    if (m_frameBase.size() != m_static.size() || m_frameBase.format() != m_static.format())
        m_frameBase = QImage(m_static.size(), m_static.format());
    m_frameBase.setDevicePixelRatio(m_static.devicePixelRatio());
    std::memcpy(m_frameBase.bits(), m_static.constBits(), size_t(m_static.sizeInBytes()));
    rasterTrails(m_frameBase, {m_frameBase.rect()}, QTransform::fromScale(dpr, dpr), world);
    return true;
}

} // namespace ocu
