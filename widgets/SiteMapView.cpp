// SiteMapView: the view's data (fleet, site map, pass counts, own position, layer switches) and the order in
// which a frame is drawn. The parts of the frame are in SiteMapViewLayers.cpp (static layer: background
// raster, site map features, night dimming), SiteMapViewSymbols.cpp (machines, trails, own position, labels,
// hover card), SiteMapViewOverlays.cpp (pass counts, legend, scale bar, north arrow, cursor, feature
// overlays); the view transform and input in SiteMapViewInput.cpp; load handling in SiteMapViewPerf.cpp.
#include "widgets/SiteMapView.h"

#include "models/FleetModel.h"
#include "models/FleetSelection.h"

#include <QPainter>
#include <cmath>

namespace ocu {

SiteMapView::SiteMapView(QWidget* parent) : QWidget(parent) {
    setMouseTracking(true);
    setFocusPolicy(Qt::StrongFocus);
    setAttribute(Qt::WA_OpaquePaintEvent);
    setMinimumSize(200, 150);
    m_viewSize = size();
    m_trails.setCapacity(120);
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
    requestDataRepaint(); // the static layer redraws the changed cells' patch (ensureStaticLayer)
}

void SiteMapView::setOwnFix(const OwnFix& fix) {
    m_own = fix;
    requestDataRepaint();
}

void SiteMapView::setLayerVisible(Layer layer, bool visible) {
    const unsigned before = m_layers;
    m_layers = visible ? (m_layers | layer) : (m_layers & ~unsigned(layer));
    if (before != m_layers) {
        if ((before ^ m_layers) & (LayerMap | LayerMapNames | LayerPassCount))
            invalidateStatic(); // what the cached static layer shows
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

void SiteMapView::onMachinesChanged(const QStringList& ids) {
    // 10,000 positions a second: one row lookup per machine serves the trail and the start-up fit.
    const bool fit = m_autoFit && !m_follow && m_fleet;
    QRectF inner;
    if (fit) {
        // Start-up: keep every machine in view until the operator takes over.
        const QRectF world = visibleWorld(m_viewSize);
        inner = world.adjusted(world.width() * 0.03, world.height() * 0.03, -world.width() * 0.03,
                               -world.height() * 0.03);
    }
    bool refit = false;
    if (m_fleet && (m_trails.capacity() > 0 || fit)) {
        for (const QString& id : ids) {
            const int row = m_fleet->rowOf(id);
            if (row < 0)
                continue;
            const MachineState& m = m_fleet->machineAt(row);
            if (!m.hasPosition)
                continue;
            // One point per metre travelled keeps trails short to draw.
            m_trails.appendIfMoved(id, QPointF(m.e, m.n), 1.0);
            if (fit && !refit && std::abs(m.e) < kFitRadius && std::abs(m.n) < kFitRadius &&
                !inner.contains(m.e, m.n))
                refit = true;
        }
    }
    followCurrent();
    if (refit)
        fitToContent();
    requestDataRepaint();
}

void SiteMapView::onMachineRemoved(const QString& id) {
    m_trails.remove(id);
    requestDataRepaint();
}

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
    // Hundreds of trails: aliased 1 px lines written into the pixels (SiteMapViewPerf.cpp).
    const bool manyTrails = (m_layers & LayerTrails) && m_trails.size() >= 200;
    QVector<QRect> clip;
    QImage* direct = manyTrails ? painterImage(p, clip) : nullptr;
    const bool trailsInBase = manyTrails && !direct && drawTrailsIntoBase(world, dpr);
    p.drawImage(QPointF(0, 0), trailsInBase ? m_frameBase : m_static);
    if (direct) {
        rasterTrails(*direct, clip, p.deviceTransform(), world);
        m_stats.trailsIntoTarget = true;
    }
    p.setRenderHint(QPainter::Antialiasing, true);
    if ((m_layers & LayerTrails) && !trailsInBase && !direct)
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

} // namespace ocu
