#pragma once
// 1 px opaque lines written straight into the 32-bit pixels of the map's images: what QPainter's aliased
// cosmetic pen draws, without a span call per pixel (5,000 ways or 1,000 trails are several hundred
// thousand pixels, and QPainter spent ~40 ns on each).
//  * clippedLine: clipped to a rectangle first (the trails, drawn afresh every frame).
//  * MapLineRaster: the pixels of a line do not depend on the clip rectangle, so the static layer can be
//    redrawn in pieces (a pan's exposed strip, a changed pass-count patch) and match a redraw of the whole.
#include <QImage>
#include <QPointF>
#include <QRect>

namespace ocu {

// `clip`: device pixels inside the image.
void clippedLine(uchar* bits, qsizetype bytesPerLine, const QRect& clip, QPointF a, QPointF b, QRgb colour);

class MapLineRaster {
public:
    // `image` must be Format_RGB32 or Format_ARGB32(_Premultiplied) and outlive this; `clip` in device
    // pixels (the image's rectangle when empty). Points are in device pixels.
    MapLineRaster(QImage& image, const QRect& clip);
    // Solid, or dashed like Qt::DashLine on a 1 px pen (4 on, 2 off), the pattern running on along the line.
    void polyline(const QPointF* points, int count, QRgb colour, bool dashed);

private:
    // Returns the pattern position after the segment.
    int segment(QPointF a, QPointF b, QRgb colour, bool dashed, int dashPos);

    uchar* m_bits = nullptr;
    qsizetype m_bpl = 0;
    QRect m_clip;
    QRectF m_reach; // segments are pre-clipped to this fixed rectangle (the image and a wide margin)
};

} // namespace ocu
