#include "widgets/jaus/MissionPlanEditor.h"

#include "models/FleetSelection.h"
#include "models/jaus/MissionPlan.h"
#include "widgets/SiteMapView.h"
#include "widgets/jaus/MissionPlanLayer.h"

#include <QContextMenuEvent>
#include <QCursor>
#include <QKeyEvent>
#include <QMenu>
#include <QMouseEvent>

#include <cmath>

namespace ocu {

namespace {
constexpr double kClickSlopPx = 3; // a press that moves less is a click (as the map's own panning)
constexpr double kNudgePx = 10;    // Shift+arrow
} // namespace

MissionPlanEditor::MissionPlanEditor(SiteMapView* view, MissionPlanLayer* layer, QObject* parent)
    : QObject(parent), m_view(view), m_layer(layer) {
    if (view)
        view->installEventFilter(this);
}

MissionPlanEditor::~MissionPlanEditor() {
    if (m_view)
        m_view->removeEventFilter(this);
}

void MissionPlanEditor::setEditing(bool on) {
    if (on == m_editing)
        return;
    m_editing = on;
    m_drag = Drag::None;
    m_layer->setEditing(on);
    if (m_view) {
        if (on)
            m_view->setCursor(Qt::CrossCursor);
        else
            m_view->unsetCursor();
    }
    emit editingChanged(on);
}

int MissionPlanEditor::selected() const {
    return m_layer->selected();
}

void MissionPlanEditor::select(int index) {
    MissionPlan* plan = m_layer->plan();
    if (!plan || index < -1 || index >= plan->size())
        return;
    if (index >= 0 && m_view) {
        const QPointF px = m_view->worldToScreen(m_layer->toEN(plan->at(index)));
        if (!m_view->rect().contains(px.toPoint()))
            m_view->setView(m_layer->toEN(plan->at(index)), m_view->scale());
    }
    if (index != m_layer->selected()) {
        m_layer->setSelected(index);
        emit selectedChanged(index);
    }
}

void MissionPlanEditor::addAt(QPointF px, int index) {
    MissionPlan* plan = m_layer->plan();
    if (!plan || !m_view)
        return;
    const auto ll = m_layer->toLatLon(m_view->screenToWorld(px));
    plan->insert(index, plan->makeWaypoint(ll.first, ll.second));
    select(index);
}

void MissionPlanEditor::insertOnLeg(int leg, QPointF en) {
    MissionPlan* plan = m_layer->plan();
    const auto ll = m_layer->toLatLon(en);
    MissionWaypoint w = plan->makeWaypoint(ll.first, ll.second);
    // The new waypoint drives like the leg it splits: the speed of the waypoint the leg led to.
    w.speed = plan->at(leg + 1).speed;
    plan->insert(leg + 1, w);
    select(leg + 1);
}

bool MissionPlanEditor::mousePress(QMouseEvent* e) {
    if (e->button() != Qt::LeftButton)
        return false;
    m_pressPx = m_lastPx = e->position();
    if (const int wp = m_layer->waypointAt(e->position()); wp >= 0) {
        select(wp);
        m_drag = Drag::Waypoint;
        ++m_gesture;
        return true;
    }
    QPointF en;
    if (const int leg = m_layer->legAt(e->position(), &en); leg >= 0) {
        insertOnLeg(leg, en);
        m_drag = Drag::Waypoint;
        ++m_gesture;
        return true;
    }
    m_drag = Drag::Pending;
    return true;
}

bool MissionPlanEditor::mouseMove(QMouseEvent* e) {
    const QPointF px = e->position();
    switch (m_drag) {
    case Drag::None:
        if (m_view)
            m_view->setCursor(m_layer->waypointAt(px) >= 0 ? Qt::SizeAllCursor
                              : m_layer->legAt(px) >= 0    ? Qt::PointingHandCursor
                                                           : Qt::CrossCursor);
        return false; // the map shows the cursor's position and the hover card
    case Drag::Pending:
        if ((px - m_pressPx).manhattanLength() <= kClickSlopPx)
            return true;
        m_drag = Drag::Panning;
        [[fallthrough]];
    case Drag::Panning:
        m_view->panByPixels(px - m_lastPx);
        break;
    case Drag::Waypoint:
        if (MissionPlan* plan = m_layer->plan(); plan && selected() >= 0) {
            const auto ll = m_layer->toLatLon(m_view->screenToWorld(px));
            plan->move(selected(), ll.first, ll.second, m_gesture);
        }
        break;
    }
    m_lastPx = px;
    return true;
}

bool MissionPlanEditor::mouseRelease(QMouseEvent* e) {
    if (e->button() != Qt::LeftButton)
        return false;
    const Drag was = m_drag;
    m_drag = Drag::None;
    if (was != Drag::Pending)
        return true;
    if (const QString id = m_view->machineAt(e->position()); !id.isEmpty()) {
        if (m_selection)
            m_selection->setCurrent(id);
        return true;
    }
    if (MissionPlan* plan = m_layer->plan())
        addAt(e->position(), plan->size());
    return true;
}

bool MissionPlanEditor::isEditKey(QKeyEvent* e) const {
    const auto mods = e->modifiers() & ~Qt::KeypadModifier;
    switch (e->key()) {
    case Qt::Key_Z:
    case Qt::Key_Y:
        return mods & Qt::ControlModifier;
    case Qt::Key_Delete:
    case Qt::Key_Backspace:
    case Qt::Key_Insert:
    case Qt::Key_Return:
    case Qt::Key_Enter:
    case Qt::Key_PageUp:
    case Qt::Key_PageDown:
    case Qt::Key_Escape:
        return mods == Qt::NoModifier;
    case Qt::Key_Left:
    case Qt::Key_Right:
    case Qt::Key_Up:
    case Qt::Key_Down:
        return mods == Qt::ShiftModifier;
    default:
        return false;
    }
}

void MissionPlanEditor::nudge(QPointF deltaPx) {
    MissionPlan* plan = m_layer->plan();
    const int i = selected();
    if (!plan || i < 0)
        return;
    const QPointF px = m_view->worldToScreen(m_layer->toEN(plan->at(i))) + deltaPx;
    const auto ll = m_layer->toLatLon(m_view->screenToWorld(px));
    plan->move(i, ll.first, ll.second);
}

bool MissionPlanEditor::keyPress(QKeyEvent* e) {
    MissionPlan* plan = m_layer->plan();
    if (!plan)
        return false;
    const int i = selected();
    switch (e->key()) {
    case Qt::Key_Z:
        if (e->modifiers() & Qt::ShiftModifier)
            plan->redo();
        else
            plan->undo();
        break;
    case Qt::Key_Y:
        plan->redo();
        break;
    case Qt::Key_Delete:
    case Qt::Key_Backspace:
        if (i >= 0) {
            plan->remove(i);
            select(std::min(i, plan->size() - 1));
        }
        break;
    case Qt::Key_Insert:
    case Qt::Key_Return:
    case Qt::Key_Enter: {
        const QPointF cursor = m_view->mapFromGlobal(QCursor::pos());
        addAt(m_view->rect().contains(cursor.toPoint()) ? cursor : QPointF(m_view->rect().center()),
              i >= 0 ? i + 1 : plan->size());
        break;
    }
    case Qt::Key_PageUp:
        select(i > 0 ? i - 1 : plan->size() - 1);
        break;
    case Qt::Key_PageDown:
        select(plan->isEmpty() ? -1 : (i + 1) % plan->size());
        break;
    case Qt::Key_Left:
        nudge({-kNudgePx, 0});
        break;
    case Qt::Key_Right:
        nudge({kNudgePx, 0});
        break;
    case Qt::Key_Up:
        nudge({0, -kNudgePx});
        break;
    case Qt::Key_Down:
        nudge({0, kNudgePx});
        break;
    case Qt::Key_Escape:
        setEditing(false);
        break;
    default:
        return false;
    }
    return true;
}

void MissionPlanEditor::addContextActions(QMenu* menu, QPointF px) {
    if (!m_view || !m_view->machineAt(px).isEmpty())
        return;
    const QPointF en = m_view->screenToWorld(px);
    if (!m_goHereName.isEmpty()) {
        const auto ll = m_layer->toLatLon(en);
        QAction* go = menu->addAction(tr("Go here (%1)").arg(m_goHereName));
        go->setObjectName(QStringLiteral("mission-go-here"));
        connect(go, &QAction::triggered, this, [this, ll] { emit goHereRequested(ll.first, ll.second); });
    }
    MissionPlan* plan = m_layer->plan();
    if (!m_editing || !plan)
        return;
    const int wp = m_layer->waypointAt(px);
    QPointF onLeg;
    const int leg = wp < 0 ? m_layer->legAt(px, &onLeg) : -1;
    if (wp >= 0) {
        QAction* del = menu->addAction(tr("Delete waypoint %1").arg(wp + 1));
        del->setObjectName(QStringLiteral("mission-delete"));
        connect(del, &QAction::triggered, this, [this, plan, wp] {
            plan->remove(wp);
            select(std::min(wp, plan->size() - 1));
        });
    } else if (leg >= 0) {
        QAction* ins = menu->addAction(tr("Insert waypoint between %1 and %2").arg(leg + 1).arg(leg + 2));
        ins->setObjectName(QStringLiteral("mission-insert"));
        connect(ins, &QAction::triggered, this, [this, leg, onLeg] { insertOnLeg(leg, onLeg); });
    } else {
        QAction* add = menu->addAction(tr("Add waypoint here"));
        add->setObjectName(QStringLiteral("mission-add"));
        connect(add, &QAction::triggered, this, [this, plan, px] { addAt(px, plan->size()); });
    }
}

bool MissionPlanEditor::eventFilter(QObject* watched, QEvent* event) {
    if (watched != m_view)
        return false;
    switch (event->type()) {
    case QEvent::ContextMenu: {
        auto* e = static_cast<QContextMenuEvent*>(event);
        QMenu menu(m_view);
        addContextActions(&menu, e->pos());
        if (menu.isEmpty())
            return false; // a machine's menu, or nothing to offer: the map's own
        menu.exec(e->globalPos());
        return true;
    }
    default:
        break;
    }
    if (!m_editing || !m_layer->plan())
        return false;
    switch (event->type()) {
    case QEvent::MouseButtonPress:
        return mousePress(static_cast<QMouseEvent*>(event));
    case QEvent::MouseButtonDblClick: // the second click of a quick pair adds nothing and does not zoom
        return static_cast<QMouseEvent*>(event)->button() == Qt::LeftButton;
    case QEvent::MouseMove:
        return mouseMove(static_cast<QMouseEvent*>(event));
    case QEvent::MouseButtonRelease:
        return mouseRelease(static_cast<QMouseEvent*>(event));
    case QEvent::ShortcutOverride: // the editor's keys before any window shortcut
        if (isEditKey(static_cast<QKeyEvent*>(event))) {
            event->accept();
            return true;
        }
        return false;
    case QEvent::KeyPress:
        return isEditKey(static_cast<QKeyEvent*>(event)) && keyPress(static_cast<QKeyEvent*>(event));
    default:
        return false;
    }
}

} // namespace ocu
