#pragma once
// Editing a mission plan on the 2D site map with the mouse and the keyboard. An event filter on the
// SiteMapView (the map itself is not changed): while editing, a left click on the ground adds a waypoint at
// the end, a press on a waypoint drags it, a press on a leg inserts a waypoint there and drags it, a drag on
// the ground pans the map, a click on a machine selects it. Keys with the map focused: Insert or Enter adds a
// waypoint at the cursor (the view's centre when the cursor is elsewhere) after the selected one, Delete or
// Backspace deletes the selected one, Page Up / Page Down select the previous / next one (and bring it into
// view), Shift+arrows move the selected one by 10 px, Ctrl+Z undo, Ctrl+Shift+Z or Ctrl+Y redo, Esc stops
// editing. The map's context menu on the ground gets "Go here" (a single waypoint for the planned vehicle)
// and, while editing, add / insert / delete.
#include "models/FleetSelection.h"
#include "widgets/SiteMapView.h"

#include <QObject>
#include <QPointF>
#include <QPointer>

class QAction;
class QMenu;
class QMouseEvent;
class QKeyEvent;

namespace ocu {

class SiteMapView;
class MissionPlanLayer;
class FleetSelection;

class MissionPlanEditor : public QObject {
    Q_OBJECT
public:
    // Filters `view`'s events; edits the layer's plan.
    MissionPlanEditor(SiteMapView* view, MissionPlanLayer* layer, QObject* parent = nullptr);
    ~MissionPlanEditor() override;

    void setEditing(bool on);
    bool isEditing() const { return m_editing; }
    // A click on a machine while editing selects it here.
    void setSelection(FleetSelection* selection) { m_selection = selection; }
    // The vehicle "Go here" is for, as the menu names it (empty: no "Go here").
    void setGoHereTarget(const QString& vehicleName) { m_goHereName = vehicleName; }

    int selected() const;
    void select(int index); // also brings it into view when it is outside

    // The context menu's entries for the ground at `px` (view pixels); empty over a machine. Children of
    // `menu`.
    void addContextActions(QMenu* menu, QPointF px);

signals:
    void editingChanged(bool on);
    void selectedChanged(int index);
    void goHereRequested(double lat, double lon);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    bool mousePress(QMouseEvent* e);
    bool mouseMove(QMouseEvent* e);
    bool mouseRelease(QMouseEvent* e);
    bool keyPress(QKeyEvent* e);
    bool isEditKey(QKeyEvent* e) const;
    void addAt(QPointF px, int index);
    void insertOnLeg(int leg, QPointF en);
    void nudge(QPointF deltaPx);

    enum class Drag { None, Pending, Panning, Waypoint };
    QPointer<SiteMapView> m_view;
    MissionPlanLayer* m_layer;
    QPointer<FleetSelection> m_selection;
    QString m_goHereName;
    bool m_editing = false;
    Drag m_drag = Drag::None;
    QPointF m_pressPx, m_lastPx;
    int m_gesture = 0; // merges one drag's moves into one undo step
};

} // namespace ocu
