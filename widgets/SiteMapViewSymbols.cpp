// SiteMapView: machine symbols and trails, the own position, edge indicators for machines outside the view,
// the decluttered labels (machine names, road and area names) and the hover card.
#include "models/DisplayText.h"
#include "models/FleetModel.h"
#include "models/FleetSelection.h"
#include "widgets/SiteMapView.h"

#include <QDateTime>
#include <QPainter>
#include <QPainterPath>
#include <QSet>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace ocu {

namespace {
constexpr double kEdgeMargin = 14.0; // px from the view's edge to an edge indicator's tip
constexpr double kEdgeBin = 32.0;    // px of edge per indicator group

// Label priority: lower wins a contested place.
int labelPriority(const MachineState& m, StatusCategory status, bool current, bool selected) {
    if (current)
        return 0;
    if (selected)
        return 1;
    if (status == StatusCategory::FaultOrStopped)
        return 2;
    if (m.control == ControlState::ControlledByMe)
        return 3;
    if (status == StatusCategory::Warning)
        return 4;
    if (status == StatusCategory::Stale)
        return 6;
    return 5;
}

int severityRank(StatusCategory c) {
    switch (c) {
    case StatusCategory::FaultOrStopped:
        return 4;
    case StatusCategory::Warning:
        return 3;
    case StatusCategory::Stale:
        return 2;
    case StatusCategory::Autonomous:
        return 1;
    case StatusCategory::Ok:
        break;
    }
    return 0;
}

QRectF rotatedBounds(QPointF centre, QSizeF size, double angleDeg) {
    const double a = angleDeg * M_PI / 180.0;
    const double c = std::abs(std::cos(a)), s = std::abs(std::sin(a));
    const double w = size.width() * c + size.height() * s, h = size.width() * s + size.height() * c;
    return QRectF(centre.x() - w / 2, centre.y() - h / 2, w, h);
}
} // namespace

void SiteMapView::drawTrails(QPainter& p, const QRectF& world) {
    if (m_trails.isEmpty())
        return;
    const double s = m_scale;
    const double cx = m_viewSize.width() / 2.0, cy = m_viewSize.height() / 2.0;
    p.setPen(QPen(QColor(0x55, 0x55, 0x88), 0)); // 1 px cosmetic opaque pen: the fast path
    QPolygonF poly;
    const QRectF grown = world.adjusted(-50, -50, 50, 50);
    // Trail points are ~1 m apart; zoomed out, segments shorter than ~4 px add cost but no information, so
    // only every step-th point is drawn (the newest always).
    const int step = std::max(1, int(std::ceil(4.0 / s)));
    // Hundreds of trails: aliased 1 px lines (about 3x cheaper, perf-anchors.md §4); a few: antialiased.
    p.setRenderHint(QPainter::Antialiasing, m_trails.size() < 200);
    m_trails.forEach([&](const MapTrails::Span& t) {
        const int n = t.n;
        if (n < 2 || !grown.contains(t.back()))
            return;
        poly.resize(0);
        poly.reserve(n / step + 2);
        for (int k = (n - 1) % step; k < n; k += step)
            poly.push_back(
                QPointF(cx + (t.xy[2 * k] - m_center.x()) * s, cy - (t.xy[2 * k + 1] - m_center.y()) * s));
        if (poly.size() >= 2)
            p.drawPolyline(poly);
    });
    p.setRenderHint(QPainter::Antialiasing, true);
}

void SiteMapView::drawMachines(QPainter& p, const QRectF& world) {
    m_labels.reset(QRectF(QPointF(0, 0), QSizeF(m_viewSize)));
    if (!m_fleet)
        return;
    const int n = m_fleet->rowCount();
    const double s = m_scale;
    const double cx = m_viewSize.width() / 2.0, cy = m_viewSize.height() / 2.0;
    const QString current = m_selection ? m_selection->currentId() : QString();
    const qreal dpr = p.device() ? p.device()->devicePixelRatioF() : 1.0;
    const QRectF viewPx(QPointF(0, 0), QSizeF(m_viewSize));
    const QRectF inner = viewPx.adjusted(kEdgeMargin, kEdgeMargin, -kEdgeMargin, -kEdgeMargin);
    int drawn = 0;
    QVector<int> highlighted;
    QVector<MachineLabel> labels;
    labels.reserve(std::min(n, 2048));
    QHash<int, int> edgeBins; // perimeter bin -> index in m_edges
    p.setRenderHint(QPainter::SmoothPixmapTransform, false);
    // The selected rows, once per frame (usually none or a few), instead of an id lookup per machine.
    QSet<int> selectedRows;
    if (m_selection)
        for (const QString& id : m_selection->selectedIds())
            if (const int row = m_fleet->rowOf(id); row >= 0)
                selectedRows.insert(row);
    const int currentRow = current.isEmpty() ? -1 : m_fleet->rowOf(current);
    for (int i = 0; i < n; ++i) {
        const MachineState& m = m_fleet->machineAt(i);
        if (!m.hasPosition)
            continue;
        const StatusCategory status = m_fleet->statusAt(i);
        const QPointF c(cx + (m.e - m_center.x()) * s, cy - (m.n - m_center.y()) * s);
        const QSizeF fp = MapSymbolCache::footprintPx(m.length > 0 ? m.length : kDefaultLength,
                                                      m.width > 0 ? m.width : kDefaultWidth, s);
        const double radius = std::max(fp.width(), fp.height()) / 2;
        if (!viewPx.adjusted(-radius, -radius, radius, radius).contains(c)) {
            // Outside: an arrow at the edge, where the line from the view centre to the machine leaves it.
            const QPointF d = c - QPointF(cx, cy);
            const double hx = inner.width() / 2, hy = inner.height() / 2;
            const double t =
                std::min(d.x() != 0 ? hx / std::abs(d.x()) : 1e18, d.y() != 0 ? hy / std::abs(d.y()) : 1e18);
            const QPointF at = QPointF(cx, cy) + d * t;
            // Bin along the perimeter (0..4 sides, each cut into kEdgeBin pieces).
            int side = 0;
            double along = 0;
            if (std::abs(at.y() - inner.top()) < 0.5) {
                side = 0;
                along = at.x();
            } else if (std::abs(at.x() - inner.right()) < 0.5) {
                side = 1;
                along = at.y();
            } else if (std::abs(at.y() - inner.bottom()) < 0.5) {
                side = 2;
                along = at.x();
            } else {
                side = 3;
                along = at.y();
            }
            const int key = side * 100000 + int(along / kEdgeBin);
            auto it = edgeBins.find(key);
            if (it == edgeBins.end()) {
                EdgeIndicator ind;
                ind.pos = at;
                ind.angleDeg = std::atan2(d.y(), d.x()) * 180.0 / M_PI;
                ind.count = 1;
                ind.worst = status;
                ind.firstId = m.id;
                edgeBins.insert(key, int(m_edges.size()));
                m_edges.push_back(ind);
            } else {
                EdgeIndicator& ind = m_edges[*it];
                ++ind.count;
                if (severityRank(status) > severityRank(ind.worst)) {
                    ind.worst = status;
                    ind.firstId = m.id;
                }
            }
            continue;
        }
        (void)world;
        ++drawn;
        const bool isCurrent = i == currentRow;
        const bool selected = isCurrent || (!selectedRows.isEmpty() && selectedRows.contains(i));
        if (selected)
            highlighted.push_back(i);
        SymbolStyle style;
        style.symbol = m_symbols.symbolFor(m.type);
        style.status = status;
        style.stale = status == StatusCategory::Stale;
        style.ring = m.stop == StopState::Stopped                ? SymbolRing::Stopped
                     : m.control == ControlState::ControlledByMe ? SymbolRing::ControlledByMe
                                                                 : SymbolRing::None;
        m_symbols.draw(p, c, fp, m.headingDeg, style, dpr);
        // The label keeps clear of the state ring and of the selection ring.
        const double clear = selected ? std::hypot(fp.width(), fp.height()) / 2 + 9
                                      : radius + (style.ring != SymbolRing::None ? 4 : 0);
        labels.push_back({c, clear, labelPriority(m, status, isCurrent, selected), i});
    }
    // Selection highlight on top of the symbols: a yellow (current) or white ring with a dark edge.
    p.setRenderHint(QPainter::Antialiasing, true);
    p.setBrush(Qt::NoBrush);
    for (int i : highlighted) {
        const MachineState& m = m_fleet->machineAt(i);
        const QPointF c = worldToScreen({m.e, m.n});
        const QSizeF fp = MapSymbolCache::footprintPx(m.length > 0 ? m.length : kDefaultLength,
                                                      m.width > 0 ? m.width : kDefaultWidth, s);
        const double rad = std::hypot(fp.width(), fp.height()) / 2 + 7;
        p.setPen(QPen(QColor(0x10, 0x10, 0x10), 5));
        p.drawEllipse(c, rad, rad);
        p.setPen(QPen(m.id == current ? QColor(0xff, 0xd7, 0x00) : QColor(0xff, 0xff, 0xff), 3));
        p.drawEllipse(c, rad, rad);
    }
    m_stats.machinesDrawn = drawn;
    layoutAndDrawLabels(p, m_viewSize, labels);
}

void SiteMapView::drawOwnPosition(QPainter& p) {
    if (!m_own.valid)
        return;
    const QPointF c = worldToScreen({m_own.e, m_own.n});
    const QColor col(0xc0, 0x00, 0xc0);
    p.setPen(QPen(col, 2));
    p.setBrush(Qt::white);
    p.drawEllipse(c, 7, 7);
    p.drawLine(c + QPointF(-11, 0), c + QPointF(11, 0));
    p.drawLine(c + QPointF(0, -11), c + QPointF(0, 11));
    if (m_own.hasHeading) {
        const double h = m_own.headingDeg * std::numbers::pi / 180.0;
        p.drawLine(c, c + QPointF(std::sin(h), -std::cos(h)) * 20);
    }
    p.setBrush(Qt::NoBrush);
}

void SiteMapView::drawEdgeIndicators(QPainter& p) {
    if (m_edges.isEmpty())
        return;
    p.setRenderHint(QPainter::Antialiasing, true);
    QFont font = this->font();
    font.setPointSizeF(7.5);
    font.setBold(true);
    p.setFont(font);
    const QFontMetricsF fm(font);
    const QString current = m_selection ? m_selection->currentId() : QString();
    for (const EdgeIndicator& ind : std::as_const(m_edges)) {
        p.save();
        p.translate(ind.pos);
        p.rotate(ind.angleDeg);
        QPolygonF arrow;
        arrow << QPointF(10, 0) << QPointF(-4, -8) << QPointF(-1, 0) << QPointF(-4, 8);
        const bool cur = !current.isEmpty() && ind.firstId == current;
        p.setPen(QPen(cur ? QColor(0xff, 0xd7, 0x00) : QColor(0x20, 0x20, 0x20), cur ? 2.5 : 1.2));
        p.setBrush(statusColor(ind.worst));
        p.drawPolygon(arrow);
        p.restore();
        if (ind.count > 1) {
            const QString t = QString::number(ind.count);
            // The count on the inner side of the arrow.
            const double a = ind.angleDeg * M_PI / 180.0;
            const QPointF at = ind.pos - QPointF(std::cos(a), std::sin(a)) * 16;
            const QRectF box(at.x() - fm.horizontalAdvance(t) / 2 - 3, at.y() - fm.height() / 2,
                             fm.horizontalAdvance(t) + 6, fm.height());
            p.setPen(Qt::NoPen);
            p.setBrush(QColor(255, 255, 255, 220));
            p.drawRoundedRect(box, 3, 3);
            p.setPen(QColor(0x10, 0x10, 0x10));
            p.drawText(box, Qt::AlignCenter, t);
        }
    }
    p.setBrush(Qt::NoBrush);
}

QImage SiteMapView::labelImage(const QString& text, MapLabelLayout::Kind kind, const QColor& colour,
                               qreal dpr) {
    const QString key = QString::number(int(kind)) + colour.name() + QString::number(dpr) +
                        (m_night ? QLatin1Char('n') : QLatin1Char('d')) + text;
    auto it = m_labelImages.constFind(key);
    if (it != m_labelImages.constEnd())
        return *it;
    if (m_labelImages.size() > 8000)
        m_labelImages.clear();
    QFont font = this->font();
    font.setPointSizeF(kind == MapLabelLayout::Kind::Machine ? 8.5 : 8);
    font.setBold(kind != MapLabelLayout::Kind::Road);
    font.setItalic(kind == MapLabelLayout::Kind::Road);
    const QFontMetricsF fm(font);
    const double pad = kind == MapLabelLayout::Kind::Machine ? 3 : 2;
    const QSizeF sz(std::ceil(fm.horizontalAdvance(text) + 2 * pad), std::ceil(fm.height() + 2 * pad - 2));
    QImage img((sz * dpr).toSize(), QImage::Format_ARGB32_Premultiplied);
    img.setDevicePixelRatio(dpr);
    img.fill(Qt::transparent);
    QPainter ip(&img);
    ip.setRenderHint(QPainter::Antialiasing, true);
    ip.setRenderHint(QPainter::TextAntialiasing, true);
    ip.setFont(font);
    const QPointF base(pad, pad - 1 + fm.ascent());
    if (kind == MapLabelLayout::Kind::Machine) {
        ip.setPen(QPen(m_night ? QColor(0x90, 0x90, 0x90) : QColor(0x60, 0x60, 0x60), 1));
        ip.setBrush(m_night ? QColor(30, 30, 34, 230) : QColor(255, 255, 255, 225));
        ip.drawRoundedRect(QRectF(QPointF(0.5, 0.5), sz - QSizeF(1, 1)), 3, 3);
        ip.setPen(m_night ? QColor(0xe6, 0xe6, 0xe0) : QColor(0x10, 0x10, 0x10));
        ip.drawText(base, text);
    } else {
        // A white halo keeps road and area names readable over roads and the background raster.
        QPainterPath path;
        path.addText(base, font, text);
        // At night: a dark halo and the colour lifted to a light tone of the same hue (contrast >= 4.5:1).
        ip.setPen(QPen(m_night ? QColor(20, 20, 22, 230) : QColor(255, 255, 255, 230), 3, Qt::SolidLine,
                       Qt::RoundCap, Qt::RoundJoin));
        ip.setBrush(Qt::NoBrush);
        ip.drawPath(path);
        ip.setPen(Qt::NoPen);
        ip.setBrush(m_night ? QColor::fromHsl(colour.hslHue() < 0 ? 0 : colour.hslHue(),
                                              std::min(colour.hslSaturation(), 120), 200)
                            : colour);
        ip.drawPath(path);
    }
    ip.end();
    m_labelImages.insert(key, img);
    return img;
}

void SiteMapView::collectMapLabels(const QSize& size) {
    const QFontMetricsF fm([this] {
        QFont f = font();
        f.setPointSizeF(8);
        f.setBold(true);
        return f;
    }());
    const QRectF world = visibleWorld(size);
    for (int i = 0; i < m_map.features.size(); ++i) {
        const MapFeature& f = m_map.features[i];
        if (f.name.isEmpty() || f.points.size() < 2 || !world.intersects(m_featureBounds[i]))
            continue;
        const double textW = fm.horizontalAdvance(f.name) + 8;
        MapLabelCandidate cand;
        cand.text = f.name;
        const QColor task = taskColor(f.defaultTask);
        if (f.kind == MapFeatureKind::Area) {
            const QRectF& b = m_featureBounds[i];
            const double wPx = b.width() * m_scale, hPx = b.height() * m_scale;
            if (wPx < textW || hPx < fm.height() * 1.5)
                continue; // too small on screen to carry its name
            cand.kind = MapLabelLayout::Kind::Area;
            cand.colour = task.darker(220);
            cand.priority = 0;
            // The area's centre, else just below or above it (a machine label may hold the centre).
            const QPointF c = worldToScreen(b.center());
            const double step = fm.height() + 2;
            cand.spots = {{c, 0.0}, {c + QPointF(0, step), 0.0}, {c - QPointF(0, step), 0.0}};
            // Large areas (an operating zone) also near their top edge, where fewer machines are.
            if (hPx > 6 * step)
                cand.spots.push_back({worldToScreen({b.center().x(), b.bottom()}) + QPointF(0, step), 0.0});
        } else {
            // Roads and lanes: along the polyline, upright, at the middle or further along the way.
            QVector<QPointF> px;
            QVector<double> acc;
            px.reserve(f.points.size());
            double len = 0;
            for (const QPointF& q : f.points) {
                const QPointF s = worldToScreen(q);
                if (!px.isEmpty())
                    len += std::hypot(s.x() - px.back().x(), s.y() - px.back().y());
                px.push_back(s);
                acc.push_back(len);
            }
            if (len < textW + 16)
                continue;
            auto at = [&](double d) {
                d = std::clamp(d, 0.0, len);
                const int k = int(std::upper_bound(acc.begin(), acc.end(), d) - acc.begin());
                if (k <= 0)
                    return px.front();
                if (k >= px.size())
                    return px.back();
                const double seg = acc[k] - acc[k - 1];
                const double t = seg > 0 ? (d - acc[k - 1]) / seg : 0;
                return px[k - 1] + (px[k] - px[k - 1]) * t;
            };
            cand.kind = MapLabelLayout::Kind::Road;
            cand.colour = (f.kind == MapFeatureKind::Lane ? task.darker(250) : task.darker(200));
            cand.priority = 1 + int(1e6 / std::max(1.0, len)); // longer roads first
            for (double t : {0.5, 0.35, 0.65, 0.22, 0.78, 0.1, 0.9}) {
                const double d = t * len;
                if (d < textW / 2 || d > len - textW / 2)
                    continue;
                const QPointF a = at(d - textW / 2), b = at(d + textW / 2), mid = at(d);
                // Only where the way is nearly straight under the text (the chord is close to the arc).
                if (std::hypot(b.x() - a.x(), b.y() - a.y()) < 0.92 * textW)
                    continue;
                double ang = std::atan2(b.y() - a.y(), b.x() - a.x()) * 180.0 / M_PI;
                if (ang > 90)
                    ang -= 180;
                else if (ang <= -90)
                    ang += 180;
                cand.spots.push_back({mid, ang});
            }
            if (cand.spots.isEmpty())
                continue;
        }
        m_mapLabels.push_back(cand);
    }
    std::stable_sort(
        m_mapLabels.begin(), m_mapLabels.end(),
        [](const MapLabelCandidate& a, const MapLabelCandidate& b) { return a.priority < b.priority; });
}

void SiteMapView::layoutAndDrawLabels(QPainter& p, const QSize& size, QVector<MachineLabel>& machines) {
    const qreal dpr = p.device() ? p.device()->devicePixelRatioF() : 1.0;
    // Overlays drawn later keep their place free.
    if ((m_layers & LayerLegend) && (m_layers & LayerPassCount) && m_pass)
        m_labels.block(legendRect(size));
    if (m_layers & LayerNorthArrow)
        m_labels.block(QRectF(size.width() - 52, 8, 48, 56));
    if (m_layers & LayerScaleBar)
        m_labels.block(QRectF(size.width() - 170, size.height() - 58, 166, 40));
    for (const QRectF& r : std::as_const(m_reservedLabels)) // text drawn by overlays this frame
        m_labels.block(r);
    if (m_layers & LayerLabels) {
        std::stable_sort(machines.begin(), machines.end(), [](const MachineLabel& a, const MachineLabel& b) {
            return a.priority < b.priority;
        });
        for (const MachineLabel& ml : machines) {
            const MachineState& m = m_fleet->machineAt(ml.row);
            const QString text = m.name.isEmpty() ? m.id : m.name;
            const QImage& img = machineLabelImage(ml.row, text, dpr);
            const QSizeF sz = QSizeF(img.size()) / dpr;
            const double r = ml.radius + 2;
            const QPointF c = ml.centre;
            const QRectF spots[] = {
                QRectF(QPointF(c.x() + r, c.y() - sz.height() / 2), sz),              // right
                QRectF(QPointF(c.x() - r - sz.width(), c.y() - sz.height() / 2), sz), // left
                QRectF(QPointF(c.x() - sz.width() / 2, c.y() - r - sz.height()), sz), // above
                QRectF(QPointF(c.x() - sz.width() / 2, c.y() + r), sz),               // below
                QRectF(QPointF(c.x() + r * 0.7, c.y() - r * 0.7 - sz.height()), sz),  // upper right
                QRectF(QPointF(c.x() + r * 0.7, c.y() + r * 0.7), sz),                // lower right
            };
            for (const QRectF& spot : spots) {
                const QRectF aligned(std::round(spot.x()), std::round(spot.y()), sz.width(), sz.height());
                if (m_labels.fits(aligned)) {
                    m_labels.place(aligned, MapLabelLayout::Kind::Machine, text, ml.priority);
                    p.drawImage(aligned.topLeft(), img);
                    break;
                }
            }
        }
    }
    // Road and area names are drawn after the machines: they also keep off the machine symbols (in
    // the load screenshots "Dumproad 2" was written across a truck).
    for (const MachineLabel& ml : std::as_const(machines))
        m_labels.block(
            QRectF(ml.centre - QPointF(ml.radius, ml.radius), QSizeF(2 * ml.radius, 2 * ml.radius)));
    // Road and area names yield to machine labels and to each other.
    for (const MapLabelCandidate& cand : std::as_const(m_mapLabels)) {
        const QImage img = labelImage(cand.text, cand.kind, cand.colour, dpr);
        const QSizeF sz = QSizeF(img.size()) / dpr;
        for (const auto& [centre, angle] : cand.spots) {
            const QRectF box = rotatedBounds(centre, sz, angle);
            if (!m_labels.fits(box))
                continue;
            m_labels.place(box, cand.kind, cand.text, 100 + cand.priority, angle);
            if (angle == 0) {
                p.drawImage(QPointF(std::round(centre.x() - sz.width() / 2),
                                    std::round(centre.y() - sz.height() / 2)),
                            img);
            } else {
                p.save();
                p.setRenderHint(QPainter::SmoothPixmapTransform, true);
                p.translate(centre);
                p.rotate(angle);
                p.drawImage(QPointF(-sz.width() / 2, -sz.height() / 2), img);
                p.restore();
            }
            break;
        }
    }
}

void SiteMapView::drawHoverCard(QPainter& p, const QSize& size) {
    if (m_hoverId.isEmpty() || m_cursorPx.x() < 0 || !m_fleet)
        return;
    const int row = m_fleet->rowOf(m_hoverId);
    if (row < 0)
        return;
    const MachineState& m = m_fleet->machineAt(row);
    const StatusCategory status = m_fleet->statusAt(row);
    QStringList lines;
    lines << (m.type.isEmpty() ? tr("type unknown") : m.type) + QStringLiteral(" · ") + toText(m.protocol);
    lines << tr("Status: %1").arg(DisplayText::status(status));
    if (!m.modeText.isEmpty())
        lines << tr("Mode: %1").arg(m.modeText);
    lines << tr("Speed: %1 km/h · heading %2°").arg(m.speed * 3.6, 0, 'f', 1).arg(m.headingDeg, 0, 'f', 0);
    if (m.stop == StopState::Stopped)
        lines << tr("Stopped: %1").arg(m.stopText.isEmpty() ? tr("yes") : m.stopText);
    if (m.health != HealthLevel::Unknown)
        lines << tr("Health: %1").arg(m.healthText.isEmpty() ? DisplayText::health(m.health) : m.healthText);
    if (m.control != ControlState::None)
        lines << tr("Control: %1").arg(DisplayText::control(m.control));
    if (!m.workText.isEmpty())
        lines << m.workText.left(80);
    const qint64 age = m_fleet->ageMsAt(row);
    lines << tr("Link: %1 · data %2 s ago").arg(DisplayText::link(m.link)).arg(age / 1000.0, 0, 'f', 1);
    QFont bold = font();
    bold.setPointSizeF(9);
    bold.setBold(true);
    QFont normal = bold;
    normal.setBold(false);
    normal.setPointSizeF(8.5);
    const QFontMetricsF fb(bold), fn(normal);
    const QString title = m.name.isEmpty() ? m.id : m.name;
    double w = fb.horizontalAdvance(title);
    for (const QString& l : lines)
        w = std::max(w, fn.horizontalAdvance(l));
    const double h = fb.height() + lines.size() * fn.height() + 10;
    w += 16;
    QPointF at = m_cursorPx + QPointF(18, 18);
    if (at.x() + w > size.width() - 4)
        at.setX(m_cursorPx.x() - 18 - w);
    if (at.y() + h > size.height() - 4)
        at.setY(m_cursorPx.y() - 18 - h);
    at.setX(std::max(4.0, at.x()));
    at.setY(std::max(4.0, at.y()));
    const QRectF box(at, QSizeF(w, h));
    p.setRenderHint(QPainter::Antialiasing, true);
    p.setPen(QPen(statusColor(status), 2));
    p.setBrush(QColor(255, 255, 255, 240));
    p.drawRoundedRect(box, 4, 4);
    p.setBrush(Qt::NoBrush);
    p.setPen(QColor(0x10, 0x10, 0x10));
    p.setFont(bold);
    double y = box.top() + 5 + fb.ascent();
    p.drawText(QPointF(box.left() + 8, y), title);
    y += fb.height() - fb.ascent() + fn.ascent();
    p.setFont(normal);
    for (const QString& l : lines) {
        p.drawText(QPointF(box.left() + 8, y), l);
        y += fn.height();
    }
}

} // namespace ocu
