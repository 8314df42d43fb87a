#include "widgets/coverage/CompactionMapOverlay.h"

#include "models/coverage/CompactionView.h"

#include <QDockWidget>
#include <QKeyEvent>
#include <QLabel>
#include <QMouseEvent>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace ocu {

namespace {
QPolygonF toScreen(const SiteMapView& view, const QPolygonF& w) {
    QPolygonF s;
    s.reserve(w.size());
    for (const QPointF& q : w)
        s << view.worldToScreen(q);
    return s;
}
} // namespace

CompactionMapOverlay::CompactionMapOverlay(SiteMapView* view, CompactionView* session)
    // A child of the session, not of the view: a child of the view would be deleted inside ~QWidget, after
    // SiteMapView's own members (its overlay list) are gone, while the QPointer still says it is alive.
    : QObject(session), m_view(view), m_session(session) {
    view->addOverlay(this);
    view->installEventFilter(this);
    connect(session, &CompactionView::changed, view, qOverload<>(&QWidget::update));
    m_hint = new QLabel(view);
    m_hint->setObjectName(QStringLiteral("compactionDrawingHint"));
    m_hint->setWordWrap(true);
    m_hint->setAttribute(Qt::WA_TransparentForMouseEvents); // clicks on it still add points
    m_hint->hide();
}

CompactionMapOverlay::~CompactionMapOverlay() {
    if (m_view)
        m_view->removeOverlay(this);
}

void CompactionMapOverlay::setHighlightedArea(const QString& name) {
    m_highlight = name;
    if (m_view)
        m_view->update();
}

bool CompactionMapOverlay::zoomToArea(const QString& name) {
    if (!m_view || !m_session)
        return false;
    const auto& g = m_session->mapGeometry();
    QRectF box;
    if (name.isEmpty()) {
        for (const QPolygonF& b : g.boundaries)
            box = box.united(b.boundingRect());
    } else {
        for (const auto& [n, ring] : g.areas)
            if (n == name)
                box = ring.boundingRect();
    }
    return zoomToBox(box);
}

void CompactionMapOverlay::setHighlightedBand(const QPolygonF& siteEN, const QString& label) {
    m_band = siteEN;
    m_bandLabel = label;
    if (m_view)
        m_view->update();
}

bool CompactionMapOverlay::zoomToBand() {
    return m_band.size() >= 3 && zoomToBox(m_band.boundingRect());
}

bool CompactionMapOverlay::zoomToBox(const QRectF& box) {
    if (!m_view || box.isEmpty() || m_view->width() <= 0 || m_view->height() <= 0)
        return false;
    // 10 % margin; at most 50 px/m (an area of a few metres is not blown up to nothing but cells).
    const double s = std::min({0.9 * m_view->width() / std::max(box.width(), 1.0),
                               0.9 * m_view->height() / std::max(box.height(), 1.0), 50.0});
    m_view->panByPixels({0, 0}); // the operator's choice of view: no more auto-fitting, no following
    m_view->setView(box.center(), s);
    return true;
}

void CompactionMapOverlay::startDrawing() {
    m_drawing = true;
    m_points.clear();
    m_haveHover = false;
    if (m_view) {
        // The map may be a tab behind the 3D view or a closed dock: bring it to the front, or the button
        // seems to do nothing.
        for (QWidget* w = m_view->parentWidget(); w; w = w->parentWidget())
            if (auto* dock = qobject_cast<QDockWidget*>(w)) {
                dock->show();
                dock->raise();
                break;
            }
        m_view->setCursor(Qt::CrossCursor);
        m_view->setFocus(Qt::OtherFocusReason); // Esc, Enter and Backspace go to the tool
        m_view->update();
    }
    updateHint();
    emit drawingChanged(true);
}

void CompactionMapOverlay::cancelDrawing() {
    if (!m_drawing)
        return;
    m_drawing = false;
    m_points.clear();
    if (m_view) {
        m_view->unsetCursor();
        m_view->update();
    }
    updateHint();
    emit drawingChanged(false);
}

QString CompactionMapOverlay::drawingHint() const {
    if (!m_drawing)
        return {};
    const int n = int(m_points.size());
    QString head;
    if (n < 3) {
        head = tr("New area: %1 points (3 needed)").arg(n);
    } else {
        double twice = 0; // shoelace
        for (int i = 0; i < n; ++i) {
            const QPointF& a = m_points[i];
            const QPointF& b = m_points[(i + 1) % n];
            twice += a.x() * b.y() - b.x() * a.y();
        }
        head = tr("New area: %1 points, %2 m²").arg(n).arg(std::abs(twice) / 2, 0, 'f', 0);
    }
    return head + QStringLiteral(" · ") +
           tr("click adds a point · Enter, double click or the first point closes · Backspace undoes · Esc "
              "cancels");
}

void CompactionMapOverlay::updateHint() {
    if (!m_hint || !m_view)
        return;
    if (!m_drawing) {
        m_hint->hide();
        return;
    }
    // At the top of the map (the legend, the scale bar and the cursor read-out are at the bottom), in the
    // night palette's colours when it is on.
    const bool night = m_view->isNight();
    m_hint->setStyleSheet(night ? QStringLiteral("QLabel { background: rgba(30,30,34,240); color: #e6e6e0;"
                                                 " border: 1px solid #d00080; padding: 3px 6px; }")
                                : QStringLiteral("QLabel { background: rgba(255,255,230,240); color: black;"
                                                 " border: 1px solid #d00080; padding: 3px 6px; }"));
    m_hint->setText(drawingHint());
    const int maxW = std::max(120, m_view->width() - 80);
    m_hint->setFixedWidth(std::min(maxW, m_hint->fontMetrics().horizontalAdvance(m_hint->text()) + 16));
    m_hint->setFixedHeight(m_hint->heightForWidth(m_hint->width()));
    m_hint->move((m_view->width() - m_hint->width()) / 2, 8);
    m_hint->show();
    m_hint->raise();
}

void CompactionMapOverlay::finish() {
    if (m_points.size() < 3)
        return; // keep drawing: a polygon needs three points (the hint says so)
    const QPolygonF done = m_points;
    cancelDrawing();
    emit polygonFinished(done);
}

bool CompactionMapOverlay::eventFilter(QObject* watched, QEvent* event) {
    if (watched == m_view && event->type() == QEvent::Resize)
        updateHint(); // wrapped and centred to the new width
    if (!m_drawing || watched != m_view)
        return QObject::eventFilter(watched, event);
    switch (event->type()) {
    case QEvent::MouseButtonPress: {
        auto* e = static_cast<QMouseEvent*>(event);
        if (e->button() != Qt::LeftButton)
            return false; // right/middle: the map's own (pan, menu)
        const QPointF px = e->position();
        auto near = [&](const QPointF& world, double r) {
            const QPointF d = m_view->worldToScreen(world) - px;
            return std::hypot(d.x(), d.y()) <= r;
        };
        if (m_points.size() >= 3 && near(m_points.first(), kClosePx)) {
            finish(); // a click on the first point closes the ring
            return true;
        }
        // The second press of a double click (or a shaky second click) lands on the last point: a point
        // twice would be a degenerate edge.
        if (m_points.isEmpty() || !near(m_points.last(), kSamePointPx))
            m_points << m_view->screenToWorld(px);
        updateHint();
        m_view->update();
        return true;
    }
    case QEvent::MouseButtonDblClick:
        if (static_cast<QMouseEvent*>(event)->button() != Qt::LeftButton)
            return false;
        finish();
        return true;
    case QEvent::MouseButtonRelease:
        return static_cast<QMouseEvent*>(event)->button() == Qt::LeftButton;
    case QEvent::MouseMove:
        m_hover = m_view->screenToWorld(static_cast<QMouseEvent*>(event)->position());
        m_haveHover = true;
        m_view->update();
        return false; // the map still shows the cursor position
    case QEvent::KeyPress: {
        auto* k = static_cast<QKeyEvent*>(event);
        if (k->key() == Qt::Key_Escape) {
            cancelDrawing();
            return true;
        }
        if (k->key() == Qt::Key_Return || k->key() == Qt::Key_Enter) {
            finish();
            return true;
        }
        if (k->key() == Qt::Key_Backspace) {
            if (!m_points.isEmpty())
                m_points.removeLast();
            updateHint();
            m_view->update();
            return true;
        }
        return false;
    }
    default:
        return false;
    }
}

void CompactionMapOverlay::paintOverlay(QPainter& p, const SiteMapView& view) {
    if (!m_session)
        return;
    const QRectF screen(QPointF(-50, -50), QSizeF(view.width() + 100, view.height() + 100));
    p.save();
    p.setRenderHint(QPainter::Antialiasing, true);
    p.setBrush(Qt::NoBrush);
    // The night palette: dark boxes and halos with light text, like the map's own labels, so
    // nothing glares white in a dark cab.
    Ink ink;
    ink.night = view.isNight();
    ink.box = ink.night ? QColor(30, 30, 34, 230) : QColor(255, 255, 255, 230);
    ink.halo = ink.night ? QColor(20, 20, 22, 230) : QColor(255, 255, 255, 230);
    ink.station = ink.night ? QColor(0xf0, 0xa8, 0x60) : QColor(0x80, 0x40, 0x00);
    paintDesign(p, view, screen, ink);
    paintAreas(p, view, screen, ink);
    if (m_band.size() >= 3)
        paintBand(p, view, screen, ink);
    if (m_drawing)
        paintDrawing(p, view);
    p.restore();
}

// The design: boundaries, centre lines, station ticks and their labels.
void CompactionMapOverlay::paintDesign(QPainter& p, const SiteMapView& view, const QRectF& screen,
                                       const Ink& ink) const {
    const auto& g = m_session->mapGeometry();
    for (const QPolygonF& b : g.boundaries) {
        const QPolygonF s = toScreen(view, b);
        if (!s.boundingRect().intersects(screen))
            continue;
        p.setPen(QPen(ink.night ? QColor(200, 200, 200, 200) : QColor(40, 40, 40, 200), 1.5, Qt::DashLine));
        p.drawPolygon(s);
    }
    for (const QPolygonF& c : g.centreLines) {
        const QPolygonF s = toScreen(view, c);
        if (!s.boundingRect().intersects(screen))
            continue;
        p.setPen(QPen(centreLineColour(), 2));
        p.drawPolyline(s);
    }
    // Station ticks every 100 m; labels when they are at least 60 px apart (else every 500 m or km).
    if (g.ticks.size() >= 1) {
        const double pxPer100 = view.scale() * CompactionView::kTickSpacing;
        const int labelEvery = pxPer100 >= 60 ? 1 : pxPer100 * 5 >= 60 ? 5 : 10;
        QFont f = p.font();
        f.setPixelSize(11);
        p.setFont(f);
        for (const auto& t : g.ticks) {
            const QPointF a = view.worldToScreen(t.left), b = view.worldToScreen(t.right);
            if (!screen.contains(a))
                continue;
            p.setPen(QPen(centreLineColour(), 2));
            if (pxPer100 >= 8)
                p.drawLine(a, b);
            const long long k = std::llround(t.station / CompactionView::kTickSpacing);
            if (k % labelEvery == 0) {
                const QString text = CompactionView::stationText(t.station, 0);
                const QRectF r = p.fontMetrics().boundingRect(text).adjusted(-2, -1, 2, 1);
                const QPointF at = b + QPointF(4, 4);
                p.fillRect(r.translated(at), ink.box);
                p.setPen(ink.station);
                p.drawText(at, text);
                view.reserveLabelArea(r.translated(at)); // machine labels keep clear of it
            }
        }
    }
}

// Areas: a deep magenta outline (a colour neither the pass-count scales, the design's orange centre line
// nor the machines use) over a white halo, so it reads on pass counts, road and hillshade alike; a light
// fill; the name in a white box. The selected area is wider and filled more.
void CompactionMapOverlay::paintAreas(QPainter& p, const SiteMapView& view, const QRectF& screen,
                                      const Ink& ink) const {
    const auto& g = m_session->mapGeometry();
    const QColor areaColour = CompactionMapOverlay::areaColour();
    for (int i = 0; i < g.areas.size(); ++i) {
        const auto& [name, ring] = g.areas[i];
        const QPolygonF s = toScreen(view, ring);
        if (!s.boundingRect().intersects(screen))
            continue;
        const bool hi = name == m_highlight;
        // A design boundary used as an area (usually the whole job) only gets a thin outline unless selected:
        // the lots drawn on it must stand out.
        const bool design = i < g.areaFromDesign.size() && g.areaFromDesign[i];
        p.setBrush(Qt::NoBrush);
        if (design && !hi) {
            p.setPen(QPen(areaColour, 1.5, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
            p.drawPolygon(s);
        } else {
            p.setPen(QPen(ink.halo, hi ? 8 : 6, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
            p.drawPolygon(s);
            QColor fill = areaColour;
            fill.setAlpha(hi ? 60 : 28);
            p.setBrush(fill);
            p.setPen(QPen(areaColour, hi ? 4 : 2.5, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
            p.drawPolygon(s);
        }
        p.setBrush(Qt::NoBrush);
        QFont f = p.font();
        f.setPixelSize(12);
        f.setBold(true);
        p.setFont(f);
        // The name at the first vertex on screen (a long area's bounding box may be far off).
        QPointF at = s.boundingRect().topLeft();
        for (const QPointF& q : s)
            if (q.x() >= 0 && q.y() >= 14 && q.x() < view.width() - 40 && q.y() < view.height()) {
                at = q + QPointF(4, -6);
                break;
            }
        const QRectF r = p.fontMetrics().boundingRect(name).adjusted(-3, -1, 3, 1);
        p.fillRect(r.translated(at), ink.box);
        p.setPen(QPen(areaColour, 1));
        p.drawRect(r.translated(at));
        p.setPen(ink.night ? areaColour.lighter(190) : areaColour);
        p.drawText(at, name);
        view.reserveLabelArea(r.translated(at)); // machine labels keep clear of it
    }
}

void CompactionMapOverlay::paintBand(QPainter& p, const SiteMapView& view, const QRectF& screen,
                                     const Ink& ink) const {
    // The station range picked in the panel: dashed, in the centre line's orange (it is a piece of the
    // alignment's band), over a white halo; its stationing at its first vertex.
    const QPolygonF s = toScreen(view, m_band);
    if (s.boundingRect().intersects(screen)) {
        p.setBrush(Qt::NoBrush);
        p.setPen(QPen(ink.halo, 6, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        p.drawPolygon(s);
        p.setPen(QPen(centreLineColour(), 3, Qt::DashLine, Qt::RoundCap, Qt::RoundJoin));
        p.drawPolygon(s);
        QFont f = p.font();
        f.setPixelSize(12);
        f.setBold(true);
        p.setFont(f);
        const QRectF r = p.fontMetrics().boundingRect(m_bandLabel).adjusted(-3, -1, 3, 1);
        const QPointF at = s.boundingRect().topLeft() + QPointF(0, -6);
        p.fillRect(r.translated(at), ink.box);
        p.setPen(ink.station);
        p.drawText(at, m_bandLabel);
        view.reserveLabelArea(r.translated(at));
    }
}

// The polygon being drawn, its points, and the ring that closes it.
void CompactionMapOverlay::paintDrawing(QPainter& p, const SiteMapView& view) const {
    QPolygonF s = toScreen(view, m_points);
    if (m_haveHover)
        s << view.worldToScreen(m_hover);
    p.setPen(QPen(QColor(0xd0, 0x00, 0x80), 2, Qt::DashLine));
    p.setBrush(QColor(0xd0, 0x00, 0x80, 40));
    p.drawPolygon(s);
    p.setBrush(QColor(0xd0, 0x00, 0x80));
    for (const QPointF& q : toScreen(view, m_points))
        p.drawEllipse(q, 3.5, 3.5);
    // The first point grows into a ring once a click on it would close the polygon.
    if (m_points.size() >= 3) {
        p.setBrush(Qt::NoBrush);
        p.setPen(QPen(QColor(0xd0, 0x00, 0x80), 2));
        p.drawEllipse(view.worldToScreen(m_points.first()), kClosePx, kClosePx);
    }
}

} // namespace ocu
