#include "widgets/SiteMapView.h"

#include "models/FleetModel.h"
#include "models/FleetSelection.h"

#include <QContextMenuEvent>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QWheelEvent>
#include <cmath>
#include <numbers>

namespace ocu {

namespace {
constexpr double kMinScale = 0.005; // px/m: 200 km across 1000 px
constexpr double kMaxScale = 200.0; // px/m: 5 m across 1000 px
constexpr double kDefaultLength = 4.0;
constexpr double kDefaultWidth = 2.0;
constexpr double kFitRadius = 50000.0; // m from the site origin: machines beyond are not fitted

double niceLength(double metres) {
    const double p = std::pow(10.0, std::floor(std::log10(metres)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * p >= metres)
            return m * p;
    return 10 * p;
}
} // namespace

SiteMapView::SiteMapView(QWidget* parent) : QWidget(parent) {
    setMouseTracking(true);
    setFocusPolicy(Qt::StrongFocus);
    setAttribute(Qt::WA_OpaquePaintEvent);
    setMinimumSize(200, 150);
    m_viewSize = size();
    m_dataRepaint.setSingleShot(true);
    connect(&m_dataRepaint, &QTimer::timeout, this, [this] { update(); });
}

SiteMapView::~SiteMapView() = default;

void SiteMapView::setFleet(FleetModel* fleet, FleetSelection* selection) {
    if (m_fleet)
        disconnect(m_fleet, nullptr, this, nullptr);
    if (m_selection)
        disconnect(m_selection, nullptr, this, nullptr);
    m_fleet = fleet;
    m_selection = selection;
    m_trails.clear();
    if (fleet) {
        connect(fleet, &FleetModel::machinesChanged, this, &SiteMapView::onMachinesChanged);
        connect(fleet, &FleetModel::machineRemoved, this, &SiteMapView::onMachineRemoved);
        connect(fleet, &FleetModel::machineStaleChanged, this, [this] { requestDataRepaint(); });
    }
    if (selection) {
        connect(selection, &FleetSelection::selectionChanged, this, [this] { update(); });
        connect(selection, &FleetSelection::currentMachineChanged, this, [this](const QString& id) {
            if (id.isEmpty() && m_follow)
                setFollow(false);
            followCurrent();
            update();
        });
    }
    update();
}

void SiteMapView::setSiteMap(const SiteMapData& map) {
    m_map = map;
    m_featureBounds.clear();
    m_featureBounds.reserve(m_map.features.size());
    for (const MapFeature& f : m_map.features) {
        double minX = 0, maxX = 0, minY = 0, maxY = 0;
        for (int i = 0; i < f.points.size(); ++i) {
            const QPointF& q = f.points[i];
            if (i == 0) {
                minX = maxX = q.x();
                minY = maxY = q.y();
            } else {
                minX = std::min(minX, q.x());
                maxX = std::max(maxX, q.x());
                minY = std::min(minY, q.y());
                maxY = std::max(maxY, q.y());
            }
        }
        const double pad = f.width / 2;
        m_featureBounds.push_back(QRectF(QPointF(minX - pad, minY - pad), QPointF(maxX + pad, maxY + pad)));
    }
    invalidateStatic();
    if (!m_autoFitted && !m_map.features.isEmpty()) {
        m_autoFitted = true;
        fitToContent();
    }
    update();
}

void SiteMapView::setPassCountLayer(const PassCountLayer* layer) {
    m_pass = layer;
    m_passOverlay.clear();
    m_passImageRevision = 0;
    invalidateStatic();
    update();
}

void SiteMapView::passCountChanged() {
    invalidateStatic();
    requestDataRepaint();
}

void SiteMapView::setOwnFix(const OwnFix& fix) {
    m_own = fix;
    requestDataRepaint();
}

void SiteMapView::setLayerVisible(Layer layer, bool visible) {
    const unsigned before = m_layers;
    m_layers = visible ? (m_layers | layer) : (m_layers & ~unsigned(layer));
    if (before != m_layers) {
        invalidateStatic();
        update();
    }
}

void SiteMapView::setPassPalette(PassPalette palette) {
    m_palette = palette;
    invalidateStatic();
    update();
}

void SiteMapView::setPassTarget(PassTarget target) {
    m_target = target;
    invalidateStatic();
    update();
}

// ---- view transform ----

QPointF SiteMapView::worldToScreen(QPointF en) const {
    return {m_viewSize.width() / 2.0 + (en.x() - m_center.x()) * m_scale,
            m_viewSize.height() / 2.0 - (en.y() - m_center.y()) * m_scale};
}

QPointF SiteMapView::screenToWorld(QPointF px) const {
    return {m_center.x() + (px.x() - m_viewSize.width() / 2.0) / m_scale,
            m_center.y() - (px.y() - m_viewSize.height() / 2.0) / m_scale};
}

QRectF SiteMapView::visibleWorld(const QSize& size) const {
    const double hw = size.width() / 2.0 / m_scale, hh = size.height() / 2.0 / m_scale;
    return QRectF(m_center.x() - hw, m_center.y() - hh, 2 * hw, 2 * hh);
}

void SiteMapView::setView(QPointF centerEN, double pixelsPerMetre) {
    m_center = centerEN;
    m_scale = std::clamp(pixelsPerMetre, kMinScale, kMaxScale);
    invalidateStatic();
    update();
}

void SiteMapView::zoomBy(double factor, QPointF anchorPx) {
    const QPointF before = screenToWorld(anchorPx);
    m_scale = std::clamp(m_scale * factor, kMinScale, kMaxScale);
    const QPointF after = screenToWorld(anchorPx);
    if (!m_follow)
        m_center += before - after; // keep the point under the cursor fixed
    invalidateStatic();
    update();
}

void SiteMapView::panByPixels(QPointF delta) {
    userTookOver();
    if (m_follow)
        setFollow(false); // a manual pan ends following
    m_center += QPointF(-delta.x() / m_scale, delta.y() / m_scale);
    invalidateStatic();
    update();
}

void SiteMapView::centerOnMachine(const QString& id) {
    const MachineState* m = m_fleet ? m_fleet->machine(id) : nullptr;
    if (!m || !m->hasPosition)
        return;
    userTookOver();
    setView({m->e, m->n}, m_scale);
}

void SiteMapView::fitToContent() {
    QRectF r = m_map.bounds();
    if (m_fleet) {
        for (int i = 0; i < m_fleet->rowCount(); ++i) {
            const MachineState& m = m_fleet->machineAt(i);
            // A machine reporting a position far off the site (no fix yet: 0°/0°) must not shrink the site
            // to a dot.
            if (m.hasPosition && std::abs(m.e) < kFitRadius && std::abs(m.n) < kFitRadius)
                r = r.isNull() ? QRectF(m.e - 5, m.n - 5, 10, 10)
                               : r.united(QRectF(m.e - 5, m.n - 5, 10, 10));
        }
    }
    if (m_pass && m_pass->columns() > 0)
        r = r.united(QRectF(m_pass->origin(), QSizeF(m_pass->columns() * m_pass->cellSize(),
                                                     m_pass->rows() * m_pass->cellSize())));
    if (r.isNull() || r.width() <= 0 || r.height() <= 0) {
        setView({0, 0}, 1.0);
        return;
    }
    const double s = 0.9 * std::min(m_viewSize.width() / r.width(), m_viewSize.height() / r.height());
    setView(r.center(), s);
}

void SiteMapView::setFollow(bool follow) {
    if (m_follow == follow)
        return;
    m_follow = follow;
    if (follow)
        userTookOver();
    emit followChanged(follow);
    followCurrent();
}

void SiteMapView::followCurrent() {
    if (!m_follow || !m_selection)
        return;
    const MachineState* m = m_fleet ? m_fleet->machine(m_selection->currentId()) : nullptr;
    if (m && m->hasPosition && (m->e != m_center.x() || m->n != m_center.y())) {
        m_center = {m->e, m->n};
        invalidateStatic();
    }
}

// ---- data ----

void SiteMapView::onMachinesChanged(const QStringList& ids) {
    if (m_trailMax > 0 && m_fleet) {
        for (const QString& id : ids) {
            const MachineState* m = m_fleet->machine(id);
            if (!m || !m->hasPosition)
                continue;
            auto& trail = m_trails[id];
            const QPointF p(m->e, m->n);
            // One point per metre travelled keeps trails short to draw.
            if (trail.empty() || std::hypot(trail.back().x() - p.x(), trail.back().y() - p.y()) >= 1.0) {
                trail.push_back(p);
                while (int(trail.size()) > m_trailMax)
                    trail.pop_front();
            }
        }
    }
    followCurrent();
    if (m_autoFit && !m_follow && m_fleet) {
        // Start-up: keep every machine in view until the operator takes over.
        const QRectF world = visibleWorld(m_viewSize);
        const QRectF inner = world.adjusted(world.width() * 0.03, world.height() * 0.03,
                                            -world.width() * 0.03, -world.height() * 0.03);
        for (const QString& id : ids) {
            const MachineState* m = m_fleet->machine(id);
            if (m && m->hasPosition && std::abs(m->e) < kFitRadius && std::abs(m->n) < kFitRadius &&
                !inner.contains(m->e, m->n)) {
                fitToContent();
                break;
            }
        }
    }
    requestDataRepaint();
}

void SiteMapView::onMachineRemoved(const QString& id) {
    m_trails.remove(id);
    requestDataRepaint();
}

// ---- painting ----

void SiteMapView::paintEvent(QPaintEvent*) {
    ++m_framesPainted;
    m_lastPaint.start();
    QPainter p(this);
    m_inPaintEvent = true;
    paintScene(p, size());
    m_inPaintEvent = false;
}

void SiteMapView::resizeEvent(QResizeEvent*) {
    m_viewSize = size(); // the static layer notices the new size itself
}

void SiteMapView::paintScene(QPainter& p, const QSize& size) {
    m_stats = {};
    m_viewSize = size;
    const qreal dpr = p.device() ? p.device()->devicePixelRatioF() : 1.0;
    ensureStaticLayer(size, dpr);
    const QRectF world = visibleWorld(size);
    const bool trailsInBase = (m_layers & LayerTrails) && drawTrailsIntoBase(world, dpr);
    p.drawImage(QPointF(0, 0), trailsInBase ? m_frameBase : m_static);
    p.setRenderHint(QPainter::Antialiasing, true);
    if ((m_layers & LayerTrails) && !trailsInBase)
        drawTrails(p, world);
    m_reservedLabels.clear();
    for (SiteMapOverlay* o : std::as_const(m_overlays))
        o->paintOverlay(p, *this);
    m_edges.clear();
    if (m_layers & LayerMachines)
        drawMachines(p, world);
    else {
        m_labels.reset(QRectF(QPointF(0, 0), QSizeF(size)));
        QVector<MachineLabel> none;
        layoutAndDrawLabels(p, size, none); // road and area names
    }
    if (m_layers & LayerMachines)
        drawEdgeIndicators(p);
    if (m_layers & LayerOwnPosition)
        drawOwnPosition(p);
    if ((m_layers & LayerLegend) && (m_layers & LayerPassCount) && m_pass)
        drawLegend(p, size);
    if (m_layers & LayerScaleBar)
        drawScaleBar(p, size);
    if (m_layers & LayerNorthArrow)
        drawNorthArrow(p, size);
    if (m_layers & LayerCursor)
        drawCursor(p, size);
    drawHoverCard(p, size);
}

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

void SiteMapView::drawPassCount(QPainter& p, const QSize& size) {
    // A tile pyramid of cached images (PassCountOverlay), any zoom, only changed tiles redrawn.
    m_passOverlay.draw(p, *m_pass, m_palette, m_target, visibleWorld(size),
                       QRectF(QPointF(0, 0), QSizeF(size)), m_inPaintEvent ? m_passBudgetMs : 0);
    m_passOverlayPending = m_passOverlay.stats().pending > 0;
    if (m_passOverlayPending && !m_passMoreQueued) {
        // The next frame at once (not behind the data-rate cap): the operator waits for these tiles.
        m_passMoreQueued = true;
        QTimer::singleShot(0, this, [this] {
            m_passMoreQueued = false;
            update();
        });
    }
    m_passImageRevision = m_pass->revision(); // what the static layer shows (ensureStaticLayer)
    m_passImagePalette = m_palette;
    m_passImageTarget = m_target;
}

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
    for (auto it = m_trails.cbegin(); it != m_trails.cend(); ++it) {
        const auto& t = it.value();
        const int n = int(t.size());
        if (n < 2 || !grown.contains(t.back()))
            continue;
        poly.resize(0);
        poly.reserve(n / step + 2);
        for (int k = (n - 1) % step; k < n; k += step) {
            const QPointF& q = t[size_t(k)];
            poly.push_back(QPointF(cx + (q.x() - m_center.x()) * s, cy - (q.y() - m_center.y()) * s));
        }
        if (poly.size() >= 2)
            p.drawPolyline(poly);
    }
    p.setRenderHint(QPainter::Antialiasing, true);
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

void SiteMapView::drawLegend(QPainter& p, const QSize& size) {
    QStringList labels;
    QVector<QColor> colours;
    if (m_palette == PassPalette::Discrete) {
        for (int c = 1; c <= 9; ++c) {
            labels << (c == 9 ? QStringLiteral("9+") : QString::number(c));
            colours << passCountDiscreteColor(c);
        }
    } else {
        labels << tr("below (<%1)").arg(m_target.min)
               << tr("within %1–%2").arg(m_target.min).arg(m_target.max)
               << tr("above (>%1)").arg(m_target.max);
        const PassTarget t{2, 3}; // representative counts for the three classes
        colours << passCountSummaryColor(1, t) << passCountSummaryColor(2, t) << passCountSummaryColor(4, t);
    }
    QFont font = p.font();
    font.setPointSizeF(8);
    font.setBold(false);
    p.setFont(font);
    const QFontMetrics fm(font);
    const int lh = fm.height() + 2;
    const QString title = tr("Passes · target %1–%2").arg(m_target.min).arg(m_target.max);
    int w = fm.horizontalAdvance(title) + 12;
    for (const QString& l : labels)
        w = std::max(w, fm.horizontalAdvance(l) + 34);
    const int h = lh * (int(labels.size()) + 1) + 8;
    const QRect box(8, size.height() - h - 30, w, h);
    p.setRenderHint(QPainter::Antialiasing, false);
    // Night palette: a dark box with light text like the machine labels (a white box glared at night).
    p.fillRect(box, m_night ? QColor(30, 30, 34, 235) : QColor(255, 255, 255, 230));
    p.setPen(QPen(m_night ? QColor(0x90, 0x90, 0x90) : QColor(Qt::gray), 0));
    p.drawRect(box);
    p.setPen(m_night ? QColor(0xe6, 0xe6, 0xe0) : QColor(Qt::black));
    p.drawText(box.left() + 6, box.top() + 4 + fm.ascent(), title);
    for (int i = 0; i < labels.size(); ++i) {
        const int y = box.top() + 4 + lh * (i + 1);
        p.fillRect(QRect(box.left() + 6, y + 1, 18, lh - 4), colours[i]);
        p.drawText(box.left() + 30, y + fm.ascent(), labels[i]);
    }
    p.setRenderHint(QPainter::Antialiasing, true);
}

void SiteMapView::drawScaleBar(QPainter& p, const QSize& size) {
    const double metres = niceLength(120.0 / m_scale);
    const double px = metres * m_scale;
    const QPointF end(size.width() - 16, size.height() - 30);
    const QPointF start = end - QPointF(px, 0);
    p.setPen(QPen(m_night ? QColor(0xe6, 0xe6, 0xe0) : QColor(Qt::black), 2)); // legible on the dimmed ground
    p.drawLine(start, end);
    p.drawLine(start, start - QPointF(0, 6));
    p.drawLine(end, end - QPointF(0, 6));
    const QString text =
        metres >= 1000 ? QStringLiteral("%1 km").arg(metres / 1000) : QStringLiteral("%1 m").arg(metres);
    p.drawText(QRectF(start.x(), end.y() - 22, px, 16), Qt::AlignCenter, text);
}

void SiteMapView::drawNorthArrow(QPainter& p, const QSize& size) {
    const QPointF c(size.width() - 28, 34);
    QPolygonF arrow;
    arrow << c + QPointF(0, -18) << c + QPointF(8, 10) << c + QPointF(0, 4) << c + QPointF(-8, 10);
    p.setPen(QPen(m_night ? QColor(0xe6, 0xe6, 0xe0) : QColor(Qt::black), 0));
    p.setBrush(m_night ? QColor(0xc8, 0xc8, 0xc4) : QColor(0x30, 0x30, 0x30));
    p.drawPolygon(arrow);
    p.setBrush(Qt::NoBrush);
    p.drawText(QRectF(c.x() - 8, c.y() + 10, 16, 16), Qt::AlignCenter, QStringLiteral("N"));
}

void SiteMapView::drawCursor(QPainter& p, const QSize& size) {
    if (m_cursorPx.x() < 0)
        return;
    const QPointF w = screenToWorld(m_cursorPx);
    const GeoPoint g = m_frame.toGeodetic({w.x(), w.y(), 0});
    const QString text = QStringLiteral("E %1 m  N %2 m   %3°  %4°")
                             .arg(w.x(), 0, 'f', 1)
                             .arg(w.y(), 0, 'f', 1)
                             .arg(g.lat, 0, 'f', 7)
                             .arg(g.lon, 0, 'f', 7);
    const QFontMetrics fm(p.font());
    const QRect box(0, size.height() - fm.height() - 6, fm.horizontalAdvance(text) + 12, fm.height() + 6);
    p.fillRect(box, m_night ? QColor(30, 30, 34, 220) : QColor(255, 255, 255, 210));
    p.setPen(m_night ? QColor(0xe6, 0xe6, 0xe0) : QColor(Qt::black));
    p.drawText(box.adjusted(6, 3, 0, 0), Qt::AlignLeft | Qt::AlignTop, text);
}

// ---- interaction ----

QString SiteMapView::machineAt(QPointF px) const {
    if (!m_fleet)
        return {};
    QString best;
    double bestD = 8.0;
    for (int i = 0; i < m_fleet->rowCount(); ++i) {
        const MachineState& m = m_fleet->machineAt(i);
        if (!m.hasPosition)
            continue;
        const QPointF c = worldToScreen({m.e, m.n});
        const QSizeF fp = MapSymbolCache::footprintPx(m.length > 0 ? m.length : kDefaultLength,
                                                      m.width > 0 ? m.width : kDefaultWidth, m_scale);
        const double half = std::max(fp.width(), fp.height()) / 2;
        const double d = std::max(0.0, std::hypot(c.x() - px.x(), c.y() - px.y()) - half);
        if (d <= bestD) {
            bestD = d;
            best = m.id;
        }
    }
    return best;
}

void SiteMapView::mousePressEvent(QMouseEvent* e) {
    if (e->button() == Qt::LeftButton || e->button() == Qt::MiddleButton) {
        m_dragging = true;
        m_dragMoved = false;
        m_dragLast = e->position();
    }
}

void SiteMapView::mouseMoveEvent(QMouseEvent* e) {
    m_cursorPx = e->position();
    if (m_dragging) {
        const QPointF d = e->position() - m_dragLast;
        if (m_dragMoved || d.manhattanLength() > 3) {
            m_dragMoved = true;
            panByPixels(d);
            m_dragLast = e->position();
        }
    }
    const QPointF w = screenToWorld(m_cursorPx);
    const GeoPoint g = m_frame.toGeodetic({w.x(), w.y(), 0});
    emit cursorMoved(w, g.lat, g.lon);
    const QString hover = m_dragging ? QString() : machineAt(m_cursorPx);
    const bool hoverChanged = hover != m_hoverId;
    m_hoverId = hover;
    if ((m_layers & LayerCursor) || hoverChanged || !m_hoverId.isEmpty())
        update();
}

void SiteMapView::mouseReleaseEvent(QMouseEvent* e) {
    const bool click = m_dragging && !m_dragMoved && e->button() == Qt::LeftButton;
    m_dragging = false;
    if (click && m_areaPicking) {
        if (const QString area = areaAt(e->position()); !area.isEmpty())
            emit areaClicked(area);
        return;
    }
    if (click && clickEdgeIndicator(e->position()))
        return;
    if (!click || !m_selection)
        return;
    const QString id = machineAt(e->position());
    if (e->modifiers() & Qt::ControlModifier) {
        if (!id.isEmpty())
            m_selection->toggle(id);
    } else {
        m_selection->setCurrent(id); // empty = clear
    }
}

void SiteMapView::addOverlay(SiteMapOverlay* overlay) {
    if (overlay && !m_overlays.contains(overlay))
        m_overlays.push_back(overlay);
    update();
}

void SiteMapView::removeOverlay(SiteMapOverlay* overlay) {
    m_overlays.removeAll(overlay);
    update();
}

void SiteMapView::setAreaPicking(bool on) {
    m_areaPicking = on;
    if (on)
        setCursor(Qt::CrossCursor);
    else
        unsetCursor();
}

void SiteMapView::mouseDoubleClickEvent(QMouseEvent* e) {
    const QString id = machineAt(e->position());
    userTookOver();
    if (id.isEmpty()) {
        zoomBy(2.0, e->position());
        return;
    }
    if (m_selection)
        m_selection->setCurrent(id);
    centerOnMachine(id);
    emit machineActivated(id);
}

void SiteMapView::wheelEvent(QWheelEvent* e) {
    const double steps = e->angleDelta().y() / 120.0;
    if (steps != 0) {
        userTookOver();
        zoomBy(std::pow(1.25, steps), e->position());
    }
    e->accept();
}

void SiteMapView::keyPressEvent(QKeyEvent* e) {
    const double step = 80.0;
    switch (e->key()) { // every key here is an operator taking over the view
    case Qt::Key_S:
        zoomToSelection();
        break;
    case Qt::Key_A:
        if (!zoomToArea(areaAt(m_cursorPx.x() >= 0
                                   ? m_cursorPx
                                   : QPointF(m_viewSize.width() / 2.0, m_viewSize.height() / 2.0))))
            QWidget::keyPressEvent(e);
        break;
    case Qt::Key_Left:
        panByPixels({step, 0});
        break;
    case Qt::Key_Right:
        panByPixels({-step, 0});
        break;
    case Qt::Key_Up:
        panByPixels({0, step});
        break;
    case Qt::Key_Down:
        panByPixels({0, -step});
        break;
    case Qt::Key_Plus:
    case Qt::Key_Equal:
        userTookOver();
        zoomBy(1.5, QPointF(m_viewSize.width() / 2.0, m_viewSize.height() / 2.0));
        break;
    case Qt::Key_Minus:
        userTookOver();
        zoomBy(1 / 1.5, QPointF(m_viewSize.width() / 2.0, m_viewSize.height() / 2.0));
        break;
    case Qt::Key_Home:
        setFollow(false);
        userTookOver();
        if (e->modifiers() & Qt::ShiftModifier)
            zoomToFleet();
        else
            fitToContent();
        break;
    case Qt::Key_F:
        setFollow(!m_follow);
        break;
    case Qt::Key_C:
        if (m_selection)
            centerOnMachine(m_selection->currentId());
        break;
    case Qt::Key_Escape:
        if (m_selection)
            m_selection->clear();
        break;
    default:
        QWidget::keyPressEvent(e);
        return;
    }
    e->accept();
}

void SiteMapView::contextMenuEvent(QContextMenuEvent* e) {
    const QString id = machineAt(e->pos());
    if (!id.isEmpty() && m_selection && !m_selection->isSelected(id))
        m_selection->setCurrent(id);
    emit contextMenuRequested(id, e->globalPos());
}

void SiteMapView::leaveEvent(QEvent*) {
    m_cursorPx = {-1, -1};
    m_hoverId.clear();
    update();
}

} // namespace ocu
