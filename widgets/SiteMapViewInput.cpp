// SiteMapView: the view transform (centre and scale, world <-> screen), zoom, pan, follow and fit, navigation
// (zoom to fleet / selection / area), hit tests, and the mouse and keyboard input that drives them.
#include "models/FleetModel.h"
#include "models/FleetSelection.h"
#include "widgets/SiteMapView.h"

#include <QContextMenuEvent>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainterPath>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>

namespace ocu {

namespace {
constexpr double kMinScale = 0.005; // px/m: 200 km across 1000 px
constexpr double kMaxScale = 200.0; // px/m: 5 m across 1000 px
} // namespace

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
    update();
}

void SiteMapView::zoomBy(double factor, QPointF anchorPx) {
    const QPointF before = screenToWorld(anchorPx);
    m_scale = std::clamp(m_scale * factor, kMinScale, kMaxScale);
    const QPointF after = screenToWorld(anchorPx);
    if (!m_follow)
        m_center += before - after; // keep the point under the cursor fixed
    update();
}

void SiteMapView::panByPixels(QPointF delta) {
    userTookOver();
    if (m_follow)
        setFollow(false); // a manual pan ends following
    m_center += QPointF(-delta.x() / m_scale, delta.y() / m_scale);
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
    }
}

static void fitRect(SiteMapView& v, QRectF r, QSize view, double minHalfM) {
    if (r.isNull() || !r.isValid())
        return;
    const QPointF c = r.center();
    const double hw = std::max(r.width() / 2, minHalfM), hh = std::max(r.height() / 2, minHalfM);
    const double s = 0.9 * std::min(view.width() / (2 * hw), view.height() / (2 * hh));
    v.setView(c, s);
}

void SiteMapView::zoomToFleet() {
    userTookOver();
    setFollow(false);
    QRectF r;
    if (m_fleet)
        for (int i = 0; i < m_fleet->rowCount(); ++i) {
            const MachineState& m = m_fleet->machineAt(i);
            if (!m.hasPosition || std::abs(m.e) > 50000 || std::abs(m.n) > 50000)
                continue;
            const QRectF one(m.e - 5, m.n - 5, 10, 10);
            r = r.isNull() ? one : r.united(one);
        }
    if (r.isNull()) {
        fitToContent();
        return;
    }
    fitRect(*this, r, m_viewSize, 40);
}

void SiteMapView::zoomToSelection() {
    userTookOver();
    QRectF r;
    if (m_fleet && m_selection)
        for (const QString& id : m_selection->selectedIds()) {
            const MachineState* m = m_fleet->machine(id);
            if (!m || !m->hasPosition)
                continue;
            const QRectF one(m->e - 5, m->n - 5, 10, 10);
            r = r.isNull() ? one : r.united(one);
        }
    if (r.isNull()) {
        zoomToFleet();
        return;
    }
    fitRect(*this, r, m_viewSize, 40); // one machine: 80 m across
}

bool SiteMapView::zoomToArea(const QString& featureId) {
    for (int i = 0; i < m_map.features.size(); ++i)
        if (m_map.features[i].id == featureId && i < m_featureBounds.size()) {
            userTookOver();
            setFollow(false);
            fitRect(*this, m_featureBounds[i], m_viewSize, 20);
            return true;
        }
    return false;
}

QString SiteMapView::areaAt(QPointF px) const {
    const QPointF w = screenToWorld(px);
    QString best;
    double bestArea = 1e300;
    for (int i = 0; i < m_map.features.size(); ++i) {
        const MapFeature& f = m_map.features[i];
        if (f.kind != MapFeatureKind::Area || i >= m_featureBounds.size() || !m_featureBounds[i].contains(w))
            continue;
        if (!QPolygonF(f.points).containsPoint(w, Qt::OddEvenFill))
            continue;
        const double a = m_featureBounds[i].width() * m_featureBounds[i].height();
        if (a < bestArea) { // the innermost (smallest) area
            bestArea = a;
            best = f.id;
        }
    }
    return best;
}

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

void SiteMapView::setAreaPicking(bool on) {
    m_areaPicking = on;
    if (on)
        setCursor(Qt::CrossCursor);
    else
        unsetCursor();
}

bool SiteMapView::clickEdgeIndicator(QPointF px) {
    for (const EdgeIndicator& ind : std::as_const(m_edges))
        if (std::hypot(ind.pos.x() - px.x(), ind.pos.y() - px.y()) <= 14) {
            centerOnMachine(ind.firstId);
            return true;
        }
    return false;
}

} // namespace ocu
