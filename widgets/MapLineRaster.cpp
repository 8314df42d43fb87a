// 1 px opaque lines into 32-bit pixels (see MapLineRaster.h).
#include "widgets/MapLineRaster.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace ocu {

void clippedLine(uchar* bits, qsizetype bpl, const QRect& clipRect, QPointF a, QPointF b, QRgb colour) {
    // Clipped to the rectangle (Liang-Barsky), then Bresenham.
    if (clipRect.isEmpty())
        return;
    const QPoint o = clipRect.topLeft();
    bits += o.y() * bpl + o.x() * 4;
    a -= QPointF(o);
    b -= QPointF(o);
    const double maxX = clipRect.width() - 0.001, maxY = clipRect.height() - 0.001;
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

namespace {
// Beyond this many pixels from the image a segment is cut first, so that the integer arithmetic below cannot
// overflow when zoomed in far (only lines reaching that far can differ between two clip rectangles).
constexpr double kReach = 1 << 20;
} // namespace

MapLineRaster::MapLineRaster(QImage& image, const QRect& clip)
    : m_bits(image.bits()), m_bpl(image.bytesPerLine()),
      m_clip(clip.isEmpty() ? image.rect() : clip.intersected(image.rect())),
      m_reach(QRectF(image.rect()).adjusted(-kReach, -kReach, kReach, kReach)) {}

void MapLineRaster::polyline(const QPointF* points, int count, QRgb colour, bool dashed) {
    if (m_clip.isEmpty())
        return;
    int dashPos = 0;
    for (int i = 1; i < count; ++i)
        dashPos = segment(points[i - 1], points[i], colour, dashed, dashPos);
}

int MapLineRaster::segment(QPointF a, QPointF b, QRgb colour, bool dashed, int dashPos) {
    if (!m_reach.contains(a) || !m_reach.contains(b)) {
        // Far outside: cut to the reach rectangle (rare: zoomed in on a long segment).
        const QLineF l(a, b);
        const QRectF r = m_reach;
        double t0 = 0, t1 = 1;
        const double dx = b.x() - a.x(), dy = b.y() - a.y();
        const double ps[4] = {-dx, dx, -dy, dy};
        const double qs[4] = {a.x() - r.left(), r.right() - a.x(), a.y() - r.top(), r.bottom() - a.y()};
        for (int k = 0; k < 4; ++k) {
            if (ps[k] == 0) {
                if (qs[k] < 0)
                    return dashPos;
                continue;
            }
            const double t = qs[k] / ps[k];
            if (ps[k] < 0)
                t0 = std::max(t0, t);
            else
                t1 = std::min(t1, t);
        }
        if (t0 > t1 || !std::isfinite(t0) || !std::isfinite(t1))
            return dashPos;
        a = l.pointAt(t0);
        b = l.pointAt(t1);
    }
    const std::int64_t x0 = std::int64_t(std::floor(a.x())), y0 = std::int64_t(std::floor(a.y()));
    const std::int64_t x1 = std::int64_t(std::floor(b.x())), y1 = std::int64_t(std::floor(b.y()));
    const std::int64_t adx = std::abs(x1 - x0), ady = std::abs(y1 - y0);
    const bool xMajor = adx >= ady;
    const std::int64_t major = xMajor ? adx : ady, minor = xMajor ? ady : adx;
    const int sMaj = (xMajor ? x1 - x0 : y1 - y0) < 0 ? -1 : 1;
    const int sMin = (xMajor ? y1 - y0 : x1 - x0) < 0 ? -1 : 1;
    const std::int64_t maj0 = xMajor ? x0 : y0, min0 = xMajor ? y0 : x0;
    const std::int64_t majLo = xMajor ? m_clip.left() : m_clip.top();
    const std::int64_t majHi = xMajor ? m_clip.right() : m_clip.bottom();
    const std::int64_t minLo = xMajor ? m_clip.top() : m_clip.left();
    const std::int64_t minHi = xMajor ? m_clip.bottom() : m_clip.right();
    // Steps k along the major axis inside the clip: the pixels themselves do not depend on the clip.
    std::int64_t k0 = sMaj > 0 ? majLo - maj0 : maj0 - majHi;
    std::int64_t k1 = sMaj > 0 ? majHi - maj0 : maj0 - majLo;
    k0 = std::max<std::int64_t>(k0, 0);
    k1 = std::min(k1, major);
    if (k0 <= k1) {
        // Minor offset at step k: floor((2 k minor + major) / (2 major)) (midpoint rounding), kept
        // incrementally as quotient and remainder.
        const std::int64_t den = 2 * std::max<std::int64_t>(major, 1);
        const std::int64_t num = 2 * k0 * minor + major;
        std::int64_t q = num / den, r = num % den;
        // Walk a pixel offset: one step along the major axis per pixel, one along the minor axis when the
        // remainder carries (branch-free: the carry is unpredictable).
        const qsizetype stepMaj = xMajor ? sMaj * 4 : sMaj * m_bpl;
        const qsizetype stepMin = xMajor ? sMin * m_bpl : sMin * 4;
        std::int64_t m = min0 + sMin * q;
        const std::int64_t maj = maj0 + sMaj * k0;
        // An offset, not a pointer: it may point outside the image while the minor axis is outside the clip.
        std::int64_t px = xMajor ? m * m_bpl + maj * 4 : maj * m_bpl + m * 4;
        const std::int64_t twoMinor = 2 * minor;
        int dash = int((dashPos + k0) % 6);
        for (std::int64_t k = k0; k <= k1; ++k) {
            if (m >= minLo && m <= minHi && (!dashed || dash < 4))
                *reinterpret_cast<QRgb*>(m_bits + px) = colour;
            px += stepMaj;
            dash = dash == 5 ? 0 : dash + 1;
            r += twoMinor;
            const bool carry = r >= den;
            r -= carry ? den : 0;
            m += carry ? sMin : 0;
            px += carry ? stepMin : 0;
        }
    }
    return int((dashPos + major) % 6);
}

} // namespace ocu
