#include "widgets/jaus/MissionPlanLayer.h"

#include "models/jaus/MissionPlan.h"

#include <QPainter>
#include <QPainterPath>

#include <cmath>

namespace ocu {

namespace {

double dist2(QPointF a, QPointF b) {
    const QPointF d = a - b;
    return d.x() * d.x() + d.y() * d.y();
}

// Nearest point to p on the segment a-b, and its parameter along it.
QPointF nearestOnSegment(QPointF p, QPointF a, QPointF b, double* t = nullptr) {
    const QPointF ab = b - a;
    const double len2 = ab.x() * ab.x() + ab.y() * ab.y();
    double u = len2 > 0 ? ((p.x() - a.x()) * ab.x() + (p.y() - a.y()) * ab.y()) / len2 : 0;
    u = std::clamp(u, 0.0, 1.0);
    if (t)
        *t = u;
    return a + ab * u;
}

constexpr double kMarkerPx = 14;      // waypoint disc diameter
constexpr int kMaxNumbered = 200;     // waypoints on screen beyond which their numbers are left out
constexpr double kMinCirclePx = 6;    // tolerance circles smaller than this are not drawn
constexpr int kMaxCircles = 400;      // nor more than this many
constexpr double kNumberSpacing = 18; // px between waypoints below which numbers would overlap

} // namespace

MissionPlanLayer::MissionPlanLayer(SiteMapView* view, const GeoFrame& frame) : m_view(view), m_frame(frame) {
    if (view)
        view->addOverlay(this);
}

MissionPlanLayer::~MissionPlanLayer() {
    QObject::disconnect(m_planConnection);
    if (m_view)
        m_view->removeOverlay(this);
}

QColor MissionPlanLayer::missionColour(quint16 subsystem) {
    // Blue, teal, brown, cyan, deep pink, olive, indigo-blue, slate: apart from the dispatch route's purple
    // (#8e24aa) and the status colours.
    static const QColor palette[] = {QColor(0x15, 0x65, 0xc0), QColor(0x00, 0x89, 0x7b),
                                     QColor(0x8d, 0x5b, 0x2c), QColor(0x00, 0x97, 0xa7),
                                     QColor(0xc2, 0x18, 0x5b), QColor(0x82, 0x77, 0x17),
                                     QColor(0x28, 0x35, 0x93), QColor(0x45, 0x5a, 0x64)};
    return palette[subsystem % (sizeof(palette) / sizeof(palette[0]))];
}

void MissionPlanLayer::setPlan(MissionPlan* plan, const QColor& colour) {
    QObject::disconnect(m_planConnection);
    m_plan = plan;
    m_colour = colour;
    m_selected = -1;
    if (plan)
        m_planConnection =
            QObject::connect(plan, &MissionPlan::changed, plan, [this](int i) { planChanged(i); });
    planChanged(-1);
}

void MissionPlanLayer::planChanged(int index) {
    const int n = m_plan ? m_plan->size() : 0;
    if (index >= 0 && index < n && m_planEN.size() == n) {
        m_planEN[index] = toEN(m_plan->at(index));
    } else {
        m_planEN.resize(n);
        for (int i = 0; i < n; ++i)
            m_planEN[i] = toEN(m_plan->at(i));
    }
    if (m_selected >= n)
        m_selected = n - 1;
    if (m_view)
        m_view->update();
}

void MissionPlanLayer::setSelected(int index) {
    if (index == m_selected)
        return;
    m_selected = index;
    if (m_view)
        m_view->update();
}

void MissionPlanLayer::setEditing(bool on) {
    m_editing = on;
    if (m_view)
        m_view->update();
}

void MissionPlanLayer::setPlanLabel(const QString& label) {
    if (label == m_label)
        return;
    m_label = label;
    if (m_view)
        m_view->update();
}

void MissionPlanLayer::setMissions(const QVector<VehicleMission>& missions) {
    m_missions = missions;
    m_missionEN.resize(missions.size());
    m_drivenEN.resize(missions.size());
    for (int i = 0; i < missions.size(); ++i) {
        m_missionEN[i].clear();
        for (const MissionWaypoint& w : missions[i].mission.waypoints)
            m_missionEN[i] << toEN(w);
        m_drivenEN[i].clear();
        for (const auto& ll : missions[i].mission.drivenPath)
            m_drivenEN[i] << toEN(MissionWaypoint{ll.first, ll.second, 0, 0});
    }
    if (m_view)
        m_view->update();
}

QPointF MissionPlanLayer::toEN(const MissionWaypoint& w) const {
    const EnuPoint e = m_frame.toLocal({w.lat, w.lon, 0});
    return {e.e, e.n};
}

QPair<double, double> MissionPlanLayer::toLatLon(QPointF en) const {
    const GeoPoint g = m_frame.toGeodetic({en.x(), en.y(), 0});
    return {g.lat, g.lon};
}

int MissionPlanLayer::waypointAt(QPointF px, double radius) const {
    if (!m_view)
        return -1;
    int best = -1;
    double bestD = radius * radius;
    for (int i = int(m_planEN.size()) - 1; i >= 0; --i) { // the last drawn is on top
        const double d = dist2(m_view->worldToScreen(m_planEN[i]), px);
        if (d <= bestD) {
            bestD = d;
            best = i;
        }
    }
    return best;
}

int MissionPlanLayer::legAt(QPointF px, QPointF* onLegEN, double radius) const {
    if (!m_view)
        return -1;
    int best = -1;
    double bestD = radius * radius;
    QPointF bestPx;
    for (int i = 0; i + 1 < m_planEN.size(); ++i) {
        const QPointF a = m_view->worldToScreen(m_planEN[i]), b = m_view->worldToScreen(m_planEN[i + 1]);
        const QPointF q = nearestOnSegment(px, a, b);
        if (const double d = dist2(q, px); d <= bestD) {
            bestD = d;
            best = i;
            bestPx = q;
        }
    }
    if (best >= 0 && onLegEN)
        *onLegEN = m_view->screenToWorld(bestPx);
    return best;
}

const QImage& MissionPlanLayer::marker(const QColor& colour, bool selected, qreal dpr) {
    const QString key =
        colour.name() + (selected ? QLatin1Char('s') : QLatin1Char('n')) + QString::number(dpr);
    auto it = m_markers.find(key);
    if (it != m_markers.end())
        return *it;
    const double side = kMarkerPx + 8;
    QImage img(int(std::ceil(side * dpr)), int(std::ceil(side * dpr)), QImage::Format_ARGB32_Premultiplied);
    img.setDevicePixelRatio(dpr);
    img.fill(Qt::transparent);
    QPainter ip(&img);
    ip.setRenderHint(QPainter::Antialiasing);
    const QPointF c(side / 2, side / 2);
    if (selected) {
        ip.setPen(QPen(QColor(0xff, 0xd7, 0x00), 3));
        ip.setBrush(Qt::NoBrush);
        ip.drawEllipse(c, kMarkerPx / 2 + 2.5, kMarkerPx / 2 + 2.5);
    }
    ip.setPen(QPen(Qt::white, 2));
    ip.setBrush(colour);
    ip.drawEllipse(c, kMarkerPx / 2, kMarkerPx / 2);
    ip.end();
    return *m_markers.insert(key, img);
}

void MissionPlanLayer::paintOverlay(QPainter& p, const SiteMapView& view) {
    if (m_missions.isEmpty() && m_planEN.isEmpty())
        return;
    p.save();
    p.setRenderHint(QPainter::Antialiasing, true);
    for (int i = 0; i < m_missions.size(); ++i)
        drawMission(p, view, m_missions[i]);
    drawPlan(p, view);
    p.restore();
}

void MissionPlanLayer::drawMission(QPainter& p, const SiteMapView& view, const VehicleMission& m) {
    const int i = int(&m - m_missions.constData());
    const QVector<QPointF>& route = m_missionEN[i];
    const QVector<QPointF>& driven = m_drivenEN[i];
    QPolygonF screen;
    screen.reserve(std::max(route.size(), driven.size()));
    // The uploaded route, dashed: what the vehicle was given.
    for (const QPointF& q : route)
        screen << view.worldToScreen(q);
    if (screen.size() >= 2) {
        p.setBrush(Qt::NoBrush);
        p.setPen(QPen(m.colour, 2, Qt::DashLine, Qt::FlatCap, Qt::RoundJoin));
        p.drawPolyline(screen);
    }
    // The waypoint the vehicle reports active, ringed.
    if (m.mission.activeIndex >= 0 && m.mission.activeIndex < screen.size()) {
        p.setPen(QPen(m.colour, 3));
        p.drawEllipse(screen[m.mission.activeIndex], 9, 9);
    }
    // The driven path: a solid line in a darker tone beside the route.
    screen.clear();
    for (const QPointF& q : driven)
        screen << view.worldToScreen(q);
    if (screen.size() >= 2) {
        p.setPen(QPen(QColor(255, 255, 255, 200), 5, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        p.drawPolyline(screen);
        p.setPen(QPen(m.colour.darker(140), 3, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        p.drawPolyline(screen);
    }
}

void MissionPlanLayer::drawPlan(QPainter& p, const SiteMapView& view) {
    const int n = int(m_planEN.size());
    if (n == 0)
        return;
    QPolygonF screen(n);
    for (int i = 0; i < n; ++i)
        screen[i] = view.worldToScreen(m_planEN[i]);
    const QRectF visible = QRectF(QPointF(0, 0), QSizeF(p.device()->width(), p.device()->height()) /
                                                     p.device()->devicePixelRatioF())
                               .adjusted(-kMarkerPx, -kMarkerPx, kMarkerPx, kMarkerPx);
    // The cased line: a white casing under the vehicle's colour, distinct from the dispatch route's purple.
    if (n >= 2) {
        p.setBrush(Qt::NoBrush);
        p.setPen(QPen(QColor(255, 255, 255, 220), 7, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        p.drawPolyline(screen);
        p.setPen(
            QPen(m_colour, 3.5, m_editing ? Qt::SolidLine : Qt::DashDotLine, Qt::RoundCap, Qt::RoundJoin));
        p.drawPolyline(screen);
    }
    // Which waypoints are on screen; numbers only when they do not crowd each other.
    QVector<int> shown;
    shown.reserve(n);
    for (int i = 0; i < n; ++i)
        if (visible.contains(screen[i]))
            shown << i;
    const double scale = view.scale();
    if (m_plan && shown.size() <= kMaxCircles) {
        p.setBrush(QColor(m_colour.red(), m_colour.green(), m_colour.blue(), 30));
        p.setPen(QPen(QColor(m_colour.red(), m_colour.green(), m_colour.blue(), 140), 1));
        for (int i : shown)
            if (const double r = m_plan->at(i).tolerance * scale; r >= kMinCirclePx)
                p.drawEllipse(screen[i], r, r);
    }
    const qreal dpr = p.device()->devicePixelRatioF();
    const QImage normal = marker(m_colour, false, dpr); // copies: a second insert may rehash
    const QImage chosen = marker(m_colour, true, dpr);
    const QPointF half(normal.width() / dpr / 2, normal.height() / dpr / 2);
    for (int i : shown)
        p.drawImage(screen[i] - half, i == m_selected ? chosen : normal);
    bool numbered = shown.size() <= kMaxNumbered;
    for (int k = 1; numbered && k < shown.size(); ++k)
        if (shown[k] == shown[k - 1] + 1 &&
            dist2(screen[shown[k]], screen[shown[k - 1]]) < kNumberSpacing * kNumberSpacing)
            numbered = false;
    if (numbered) {
        QFont f = p.font();
        f.setPixelSize(9);
        f.setBold(true);
        p.setFont(f);
        p.setPen(Qt::white);
        for (int i : shown)
            p.drawText(
                QRectF(screen[i] - QPointF(kMarkerPx / 2, kMarkerPx / 2), QSizeF(kMarkerPx, kMarkerPx)),
                Qt::AlignCenter, QString::number(i + 1));
    }
    if (!m_label.isEmpty()) {
        QFont f = p.font();
        f.setPixelSize(12);
        f.setBold(true);
        p.setFont(f);
        const QRectF box = QFontMetricsF(f).boundingRect(m_label).adjusted(-5, -3, 5, 3);
        const QRectF at = box.translated(screen.back() + QPointF(14, -14) - box.bottomLeft());
        p.setPen(Qt::NoPen);
        p.setBrush(m_colour.darker(130));
        p.drawRoundedRect(at, 3, 3);
        p.setPen(Qt::white);
        p.drawText(at, Qt::AlignCenter, m_label);
        view.reserveLabelArea(at);
    }
}

} // namespace ocu
