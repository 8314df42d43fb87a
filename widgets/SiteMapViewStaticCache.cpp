// SiteMapView: the cached static layer and what of it is redrawn. The image is kept per scale, size and
// content (site map, background, pass counts, layer switches, palette, night palette); a pan by whole device
// pixels shifts it in place and draws only the exposed strips, a pass-count change redraws only the patch of
// the changed cells. Each part is drawn clipped, from the ground up, so it equals a redraw of the whole.
// What is drawn into it is in SiteMapViewLayers.cpp, then the overlays' static parts (paintStatic).
#include "widgets/MapLineRaster.h"
#include "widgets/SiteMapView.h"

#include <QPainter>
#include <cmath>
#include <cstring>

namespace ocu {

namespace {
const QColor kGround(0xf4, 0xf1, 0xea); // light site-plan background

// Moves the pixels of a 32-bit image by `d` (device px); what moves in from outside is left as it was.
void shiftPixels(QImage& img, QPoint d) {
    const int w = img.width(), h = img.height();
    const int cols = w - std::abs(d.x());
    if (cols <= 0 || std::abs(d.y()) >= h)
        return;
    const int srcX = std::max(0, -d.x()), dstX = std::max(0, d.x());
    const qsizetype bpl = img.bytesPerLine();
    uchar* bits = img.bits();
    auto moveRow = [&](int y) {
        const int from = y - d.y();
        std::memmove(bits + y * bpl + dstX * 4, bits + from * bpl + srcX * 4, size_t(cols) * 4);
    };
    if (d.y() > 0)
        for (int y = h - 1; y >= d.y(); --y) // downwards: bottom rows first
            moveRow(y);
    else
        for (int y = 0; y < h + d.y(); ++y)
            moveRow(y);
}
} // namespace

void SiteMapView::ensureStaticLayer(const QSize& size, qreal dpr) {
    const QSize px = (QSizeF(size) * dpr).toSize();
    const bool passShown = (m_layers & LayerPassCount) && m_pass;
    bool whole = !m_staticValid || m_static.size() != px || m_static.devicePixelRatio() != dpr ||
                 m_staticScale != m_scale || m_static.format() != QImage::Format_RGB32;
    // Owed pass-count tiles: this frame renders more of them.
    whole = whole || m_passOverlayPending;
    whole =
        whole || (passShown && (m_palette != m_passImagePalette || m_target.min != m_passImageTarget.min ||
                                m_target.max != m_passImageTarget.max));
    // A pan by whole pixels shifts the image (integer device pixel ratios only: a strip's edge must fall on
    // a logical pixel edge for the painter's clip). The drift (logical px) is what fractions added up to.
    QPoint shift; // device px
    QPointF drift;
    if (!whole && m_staticCenter != m_center) {
        const QPointF d((m_staticCenter.x() - m_center.x()) * m_scale,
                        (m_center.y() - m_staticCenter.y()) * m_scale);
        const QPoint logical(int(std::lround(d.x())), int(std::lround(d.y())));
        drift = m_staticDrift + d - QPointF(logical);
        shift = logical * int(std::lround(dpr));
        whole = std::abs(drift.x()) > 0.01 || std::abs(drift.y()) > 0.01 ||
                std::abs(shift.x()) >= px.width() || std::abs(shift.y()) >= px.height() ||
                dpr != std::round(dpr);
    }
    // Thousands of ways on screen are drawn differently (SiteMapViewLayers.cpp): the layer must not mix both.
    const int visible = whole || shift.isNull() ? -1 : visibleFeatureCount(visibleWorld(size));
    if (visible >= 0 && (visible > kDenseWays) != (m_staticVisible > kDenseWays))
        whole = true;
    const QRect patch = !whole && passShown && m_pass->revision() != m_passImageRevision
                            ? passCountPatch(size, dpr).intersected(QRect(QPoint(), px))
                            : QRect();
    const bool viewChanged = whole || !shift.isNull();
    if (viewChanged) {
        m_staticCenter = m_center;
        m_staticScale = m_scale;
        m_staticVisible = visible >= 0 ? visible : visibleFeatureCount(visibleWorld(size));
        // Names only when they can be read (not with hundreds of features on screen); placed per frame
        // together with the machine labels so that none overlaps another (SiteMapViewSymbols.cpp).
        m_mapLabels.clear();
        if ((m_layers & LayerMap) && (m_layers & LayerMapNames) && m_staticVisible <= 400)
            collectMapLabels(size);
    }
    if (whole) {
        if (m_static.size() != px || m_static.format() != QImage::Format_RGB32)
            m_static = QImage(px, QImage::Format_RGB32); // opaque: the per-frame blit is a copy, not a blend
        m_static.setDevicePixelRatio(dpr);
        m_staticDrift = {};
        m_passOverlayPending = false; // drawPassCount says again if tiles are still owed
        renderStaticRegion(size, QRect(QPoint(), px));
        m_stats.staticRebuilt = true;
    } else {
        if (!shift.isNull()) {
            shiftPixels(m_static, shift);
            m_staticDrift = drift;
            // The exposed strips: columns on the side the image moved away from, then rows.
            const int sx = shift.x(), sy = shift.y();
            if (sx != 0)
                renderStaticRegion(size, sx > 0 ? QRect(0, 0, sx, px.height())
                                                : QRect(px.width() + sx, 0, -sx, px.height()));
            if (sy != 0) {
                const int x0 = std::max(0, sx), x1 = px.width() + std::min(0, sx);
                renderStaticRegion(size, sy > 0 ? QRect(x0, 0, x1 - x0, sy)
                                                : QRect(x0, px.height() + sy, x1 - x0, -sy));
            }
        }
        if (!patch.isEmpty())
            renderStaticRegion(size, patch);
        m_stats.staticUpdated = !shift.isNull() || !patch.isEmpty();
    }
    // Screenshots (app/Screenshot.cpp) wait while tiles are owed, like for a video view's first frame.
    setProperty("screenshotPending", m_passOverlayPending);
    m_staticValid = true;
}

void SiteMapView::renderStaticRegion(const QSize& size, const QRect& devicePx) {
    if (devicePx.isEmpty())
        return;
    const qreal dpr = m_static.devicePixelRatio();
    const bool whole = devicePx == m_static.rect();
    // Dense ways are written into the pixels, not through the painter: set up before it starts.
    MapLineRaster lines(m_static, devicePx);
    const QRectF region(QPointF(devicePx.topLeft()) / dpr, QSizeF(devicePx.size()) / dpr);
    QPainter sp(&m_static);
    if (!whole)
        sp.setClipRect(region);
    sp.fillRect(region, kGround);
    // The clip's world rectangle, with a margin for antialiased edges and 1 px lines.
    const QPointF tl = screenToWorld(region.topLeft() - QPointF(2, 2));
    const QPointF br = screenToWorld(region.bottomRight() + QPointF(2, 2));
    drawStatic(sp, size, QRectF(tl, br).normalized(), &lines);
    if (m_night)
        dimStaticForNight(sp, region);
    // Overlays' unchanging parts (a route) as before in the frame: after the dimming, not dimmed.
    for (SiteMapOverlay* o : std::as_const(m_overlays))
        o->paintStatic(sp, *this);
}

QRect SiteMapView::passCountPatch(const QSize& size, qreal dpr) const {
    const QRect cells = m_pass->changedCellsSince(m_passImageRevision)
                            .intersected(QRect(0, 0, m_pass->columns(), m_pass->rows()));
    if (cells.isEmpty())
        return {};
    const double c = m_pass->cellSize();
    const QPointF o = m_pass->origin();
    // Cell rows grow northwards; the screen's y grows southwards.
    const QPointF a = worldToScreen({o.x() + cells.left() * c, o.y() + (cells.bottom() + 1) * c});
    const QPointF b = worldToScreen({o.x() + (cells.right() + 1) * c, o.y() + cells.top() * c});
    // A coarser pyramid level's pixel (up to 2 screen pixels) covers more than the changed cells, and its
    // nearest-neighbour scaling rounds: a margin of 4 px takes all of it. Whole logical pixels (the clip).
    const QRect r = QRectF(a, b).normalized().adjusted(-4, -4, 4, 4).toAlignedRect();
    const int k = int(std::lround(dpr));
    return k == dpr ? QRect(r.topLeft() * k, r.size() * k) : QRect(QPoint(), (QSizeF(size) * dpr).toSize());
}

} // namespace ocu
