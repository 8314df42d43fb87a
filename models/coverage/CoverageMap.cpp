// The coverage report's map snapshot: pass-count cells, the design, the areas, legend, scale bar and north
// arrow, north-up in the worksite frame.
#include "models/coverage/CoverageReportCommon.h"

#include "models/PassCountLayer.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

namespace ocu {

using coverage::areaRing;
using coverage::findArea;
using coverage::ReportText;
using osyris::LocalPoint;
using osyris::PassCountSnapshot;

namespace {

// Worksite metres to image pixels (north up).
struct MapView {
    QSize size;
    double scale = 1; // px per m
    double ox = 0, oy = 0;
    QPointF toPx(double x, double y) const { return QPointF(ox + scale * x, oy - scale * y); }
};

// The extent: the chosen area, else the covered cells (at least 40 m), with a margin; nullopt when there is
// nothing to show.
std::optional<MapView> mapView(const CoverageJob& job, const CoverageFrames& frames, int l,
                               const QString& area, QSize size) {
    const PassCountSnapshot& snap = *job.snapshot;
    const double cs = snap.cellSize();
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool have = false;
    if (const CompactionArea* a = area.isEmpty() ? nullptr : findArea(job, area)) {
        for (const LocalPoint& p : areaRing(frames, *a)) {
            x0 = have ? std::min(x0, p.x) : p.x;
            x1 = have ? std::max(x1, p.x) : p.x;
            y0 = have ? std::min(y0, p.y) : p.y;
            y1 = have ? std::max(y1, p.y) : p.y;
            have = true;
        }
    }
    if (!have && !snap.empty()) {
        const osyris::GridRect b = snap.bounds();
        // Tighter than whole tiles: the covered cells themselves.
        std::int32_t cx0 = INT32_MAX, cy0 = INT32_MAX, cx1 = INT32_MIN, cy1 = INT32_MIN;
        snap.forEachCell(l, [&](std::int32_t cx, std::int32_t cy, int, bool) {
            cx0 = std::min(cx0, cx);
            cy0 = std::min(cy0, cy);
            cx1 = std::max(cx1, cx);
            cy1 = std::max(cy1, cy);
        });
        if (cx1 >= cx0) {
            x0 = cx0 * cs;
            y0 = cy0 * cs;
            x1 = (cx1 + 1) * cs;
            y1 = (cy1 + 1) * cs;
        } else {
            x0 = b.xMin, y0 = b.yMin, x1 = b.xMax, y1 = b.yMax;
        }
        have = true;
    }
    if (!have)
        return std::nullopt;
    const double minSpan = 40;
    if (x1 - x0 < minSpan) {
        const double c = (x0 + x1) / 2;
        x0 = c - minSpan / 2;
        x1 = c + minSpan / 2;
    }
    if (y1 - y0 < minSpan) {
        const double c = (y0 + y1) / 2;
        y0 = c - minSpan / 2;
        y1 = c + minSpan / 2;
    }
    const double margin = 0.08 * std::max(x1 - x0, y1 - y0);
    x0 -= margin;
    x1 += margin;
    y0 -= margin;
    y1 += margin;
    MapView v;
    v.size = size;
    v.scale = std::min(size.width() / (x1 - x0), size.height() / (y1 - y0));
    v.ox = size.width() / 2.0 - v.scale * (x0 + x1) / 2;
    v.oy = size.height() / 2.0 + v.scale * (y0 + y1) / 2;
    return v;
}

// Cells: a rectangle each, or the largest count per pixel when cells are smaller than pixels.
void drawCells(QPainter& p, QImage& img, const PassCountSnapshot& snap, int l, const MapView& v) {
    const double cs = snap.cellSize();
    const PassTarget target{snap.targetMin(), snap.targetMax()};
    const QSize size = v.size;
    const QRectF view(0, 0, size.width(), size.height());
    if (v.scale * cs >= 1.5) {
        snap.forEachCell(l, [&](std::int32_t cx, std::int32_t cy, int c, bool inc) {
            const QPointF a = v.toPx(cx * cs, (cy + 1) * cs);
            const QRectF r(a, QSizeF(v.scale * cs + 0.5, v.scale * cs + 0.5));
            if (!view.intersects(r))
                return;
            if (c > 0)
                p.fillRect(r, passCountColor(c, PassPalette::Discrete, target));
            else if (inc)
                p.fillRect(r, QColor(0x80, 0x80, 0x80, 120));
        });
        return;
    }
    std::vector<std::uint16_t> px(std::size_t(size.width()) * std::size_t(size.height()), 0);
    snap.forEachCell(l, [&](std::int32_t cx, std::int32_t cy, int c, bool) {
        const QPointF a = v.toPx((cx + 0.5) * cs, (cy + 0.5) * cs);
        const int ix = int(a.x()), iy = int(a.y());
        if (ix < 0 || iy < 0 || ix >= size.width() || iy >= size.height())
            return;
        auto& val = px[std::size_t(iy) * std::size_t(size.width()) + std::size_t(ix)];
        val = std::max<std::uint16_t>(val, std::uint16_t(c));
    });
    for (int y = 0; y < size.height(); ++y) {
        auto* line = reinterpret_cast<QRgb*>(img.scanLine(y));
        for (int x = 0; x < size.width(); ++x)
            if (int c = px[std::size_t(y) * std::size_t(size.width()) + std::size_t(x)])
                line[x] = passCountColor(c, PassPalette::Discrete, target).rgba();
    }
}

// Design: boundary, centre line with station ticks every 100 m.
void drawDesign(QPainter& p, const CoverageJob& job, const CoverageFrames& frames, const MapView& v) {
    if (!job.design || !frames.hasDesignCrs())
        return;
    const QRectF view(0, 0, v.size.width(), v.size.height());
    p.setPen(QPen(QColor(0x30, 0x30, 0x30), 1.5, Qt::DashLine));
    for (const auto& b : job.design->boundaries) {
        QPolygonF poly;
        for (const auto& q : b.points) {
            LocalPoint lp;
            if (frames.designToLocal(q, lp))
                poly << v.toPx(lp.x, lp.y);
        }
        p.drawPolygon(poly);
    }
    for (const auto& al : job.design->alignments) {
        QPolygonF line;
        for (const auto& q : al.polyline(std::max(1.0, 2 / v.scale))) {
            LocalPoint lp;
            if (frames.designToLocal(q, lp))
                line << v.toPx(lp.x, lp.y);
        }
        p.setPen(QPen(QColor(0xd0, 0x60, 0x00), 2));
        p.drawPolyline(line);
        QFont f = p.font();
        f.setPixelSize(std::max(11, v.size.height() / 70));
        p.setFont(f);
        const double first = std::ceil(al.staStart / 100) * 100;
        for (double s = first; s <= al.staEnd() + 1e-6; s += 100) {
            auto c = al.pointAt(s), r = al.pointAt(s, 3), lft = al.pointAt(s, -3);
            LocalPoint lc, lr, ll;
            if (!c || !frames.designToLocal(*c, lc) || !frames.designToLocal(*r, lr) ||
                !frames.designToLocal(*lft, ll))
                continue;
            const QPointF pc = v.toPx(lc.x, lc.y);
            if (!view.contains(pc))
                continue;
            p.drawLine(v.toPx(ll.x, ll.y), v.toPx(lr.x, lr.y));
            p.drawText(v.toPx(lr.x, lr.y) + QPointF(4, 4),
                       QString::fromStdString(landxml::formatStation(s, 0)));
        }
    }
}

void drawAreas(QPainter& p, const CoverageJob& job, const CoverageFrames& frames, const QString& area,
               const MapView& v) {
    for (const CompactionArea& a : job.areas) {
        QPolygonF poly;
        for (const LocalPoint& q : areaRing(frames, a))
            poly << v.toPx(q.x, q.y);
        const bool chosen = a.name == area;
        p.setPen(QPen(chosen ? QColor(0x10, 0x40, 0xc0) : QColor(0x40, 0x40, 0xa0), chosen ? 3 : 1.5));
        p.setBrush(Qt::NoBrush);
        p.drawPolygon(poly);
        if (!poly.isEmpty())
            p.drawText(poly.boundingRect().topLeft() + QPointF(4, -4), a.name);
    }
}

// Legend (top right); sets the font the scale bar uses too.
void drawLegend(QPainter& p, QSize size, const PassTarget& target) {
    QFont f = p.font();
    f.setPixelSize(std::max(12, size.height() / 38));
    p.setFont(f);
    const int lh = p.fontMetrics().height();
    const QStringList labels{QStringLiteral("1"), QStringLiteral("2"), QStringLiteral("3"),
                             QStringLiteral("4"), QStringLiteral("5"), QStringLiteral("6"),
                             QStringLiteral("7"), QStringLiteral("8"), QStringLiteral("9+")};
    const int lw = lh * 7;
    QRect legend(size.width() - lw - 10, 10, lw, lh * (labels.size() + 3));
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(255, 255, 255, 225));
    p.drawRect(legend);
    p.setBrush(Qt::NoBrush);
    p.setPen(Qt::black);
    p.drawText(QRect(legend.left() + 6, legend.top() + 2, lw, lh), Qt::AlignLeft | Qt::AlignVCenter,
               ReportText::tr("Passes"));
    for (int i = 0; i < labels.size(); ++i) {
        const QRect sw(legend.left() + 6, legend.top() + lh * (i + 1) + 4, lh - 2, lh - 4);
        p.fillRect(sw, passCountColor(i + 1, PassPalette::Discrete, target));
        p.drawRect(sw);
        p.drawText(QRect(sw.right() + 6, sw.top() - 2, lw, lh), Qt::AlignLeft | Qt::AlignVCenter,
                   labels[i] + ((i + 1 >= target.min && i + 1 <= target.max) ? ReportText::tr(" (target)")
                                                                             : QString()));
    }
    const QRect inc(legend.left() + 6, legend.top() + lh * (labels.size() + 1) + 6, lh - 2, lh - 4);
    p.fillRect(inc, QColor(0x80, 0x80, 0x80, 120));
    p.drawRect(inc);
    p.drawText(QRect(inc.right() + 6, inc.top() - 2, lw, lh), Qt::AlignLeft | Qt::AlignVCenter,
               ReportText::tr("incomplete"));
}

// Scale bar (bottom left): a round length about a fifth of the width; then the north arrow (the worksite
// frame is north-up).
void drawScaleBar(QPainter& p, const MapView& v) {
    const QSize size = v.size;
    const int lh = p.fontMetrics().height();
    const double target_m = size.width() / 5.0 / v.scale;
    const double pow10 = std::pow(10, std::floor(std::log10(target_m)));
    double len = pow10;
    for (double m : {1.0, 2.0, 5.0})
        if (m * pow10 <= target_m)
            len = m * pow10;
    const int bx = 20, by = size.height() - 24, bw = int(len * v.scale);
    p.fillRect(QRect(bx - 6, by - lh - 6, bw + 12 + lh * 3, lh + 16), QColor(255, 255, 255, 225));
    p.setPen(QPen(Qt::black, 3));
    p.drawLine(bx, by, bx + bw, by);
    p.drawLine(bx, by - 6, bx, by + 4);
    p.drawLine(bx + bw, by - 6, bx + bw, by + 4);
    p.setPen(Qt::black);
    p.drawText(QPoint(bx, by - 8),
               len >= 1000 ? QStringLiteral("%1 km").arg(len / 1000) : QStringLiteral("%1 m").arg(len));
    p.drawText(QPoint(size.width() - 30, size.height() - 12), QStringLiteral("N↑"));
}

} // namespace

QImage renderCoverageMap(const CoverageJob& job, const CoverageFrames& frames, int lift, const QString& area,
                         QSize size) {
    QImage img(size, QImage::Format_ARGB32_Premultiplied);
    img.fill(QColor(0xf4, 0xf4, 0xf0));
    if (!job.snapshot)
        return img;
    const PassCountSnapshot& snap = *job.snapshot;
    const int l = lift == kAllLifts ? -1 : lift;
    const std::optional<MapView> v = mapView(job, frames, l, area, size);
    if (!v)
        return img;
    QPainter p(&img);
    p.setRenderHint(QPainter::Antialiasing);
    drawCells(p, img, snap, l, *v);
    drawDesign(p, job, frames, *v);
    drawAreas(p, job, frames, area, *v);
    drawLegend(p, size, PassTarget{snap.targetMin(), snap.targetMax()});
    drawScaleBar(p, *v);
    return img;
}

} // namespace ocu
