#pragma once
// The dispatch panel: the dispatch table (DispatchModel, one row per haul truck), the assign
// controls (task, destination picked from the areas of the road network or by clicking an area on the 2D
// map, Assign / Re-assign, Reset) and the queues per shovel and per dump. Every command goes through the
// CommandGate (audited); the line under the controls says per target what went on the wire, then the truck's
// own answer (Accepted / Rejected with its detail). Re-assigning a truck that has a task and resetting ask
// for confirmation. Keyboard: see shortcutHelp() (also the panel's tooltip and docs/dispatch-panel.md).
#include "models/DispatchModel.h"

#include <QPointer>
#include <QWidget>

#include <functional>

class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;
class QSplitter;
class QTableView;
class QVBoxLayout;

namespace ocu {

class AutoDispatcher;
class CommandGate;
class FleetSelection;
class SiteMapView;
class OnScreenWatcher;
class RouteOverlay2D;
struct CommandResult;

class DispatchPanel : public QWidget {
    Q_OBJECT
public:
    DispatchPanel(DispatchSource* source, CommandGate* gate, FleetSelection* selection,
                  QWidget* parent = nullptr);
    ~DispatchPanel() override;

    // The 2D map: the selected truck's route is drawn on it, and "Pick on map" takes the clicked area.
    void setMap(SiteMapView* map);
    // Asked before a re-assignment or a reset (title, text); the default is a modal Yes/No box (No default).
    void setConfirm(std::function<bool(const QString&, const QString&)> confirm) {
        m_confirm = std::move(confirm);
    }

    // The automatic dispatcher (optional, not owned): its switch and what it did last show in the panel.
    void setAutoDispatcher(AutoDispatcher* autoDispatcher);
    QPushButton* autoButton() const { return m_auto; }
    QLabel* autoLabel() const { return m_autoLabel; }

    static QString shortcutHelp();

    DispatchModel* model() const { return m_model; }
    DispatchQueueModel* queueModel() const { return m_queues; }
    QTableView* table() const { return m_table; }
    QTableView* queueTable() const { return m_queueTable; }
    QComboBox* taskBox() const { return m_task; }
    QComboBox* destinationBox() const { return m_destination; }
    QPushButton* assignButton() const { return m_assign; }
    QPushButton* resetButton() const { return m_reset; }
    QPushButton* pickButton() const { return m_pick; }
    QLabel* resultLabel() const { return m_result; }
    QLabel* refusalLabel() const { return m_refusal; }
    RouteOverlay2D* routeOverlay() const { return m_overlay; }
    QString currentTruck() const { return m_current; }

    // The route of the current truck changed (link, way ids; empty when none): the 3D view draws it too.
signals:
    void routeChanged(const QString& link, const QVector<qint64>& ways);

public slots:
    void setCurrentTruck(const QString& id);
    void assignCurrent(); // what the Assign button does
    void resetCurrent();  // what the Reset button does
    void selectNextNeedingAssignment();
    void pickOnMap(bool on);
    void pickArea(const QString& featureId); // a map area was clicked

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    // Construction, in the order the panel is laid out.
    QWidget* buildTruckList(QSplitter* split);
    QWidget* buildQueueList(QSplitter* split);
    void buildControls(QVBoxLayout* top);
    void connectControls(DispatchSource* source, FleetSelection* selection);
    void onTrucksUpdated(const QStringList& ids);
    void rebuildDestinations();
    void updateControls();
    void updateRoute();
    void showResult(const QString& what, const CommandResult& r);
    void followAnswer();
    bool confirm(const QString& title, const QString& text);
    std::optional<DispatchArea> currentArea() const;

    QPointer<DispatchSource> m_source;
    QPointer<CommandGate> m_gate;
    QPointer<FleetSelection> m_selection;
    QPointer<SiteMapView> m_map;
    DispatchModel* m_model = nullptr;
    DispatchQueueModel* m_queues = nullptr;
    QTableView* m_table = nullptr;
    QTableView* m_queueTable = nullptr;
    QLabel* m_needs = nullptr;
    QComboBox* m_task = nullptr;
    QComboBox* m_destination = nullptr;
    QPushButton* m_pick = nullptr;
    QPushButton* m_assign = nullptr;
    QPushButton* m_reset = nullptr;
    QLabel* m_refusal = nullptr;
    QLabel* m_result = nullptr;
    RouteOverlay2D* m_overlay = nullptr;
    OnScreenWatcher* m_onScreen = nullptr;
    QString m_current;
    QString m_pickFor; // the truck a map pick is for
    // The last request sent from here, to show the truck's answer when it comes.
    QString m_followTruck, m_followAssignment, m_followText;
    std::function<bool(const QString&, const QString&)> m_confirm;
    bool m_syncing = false;
    int m_needsShown = -1;
    QPointer<AutoDispatcher> m_autoDispatcher;
    QPushButton* m_auto = nullptr;
    QLabel* m_autoLabel = nullptr;
    void updateAuto();
    // The queues beside the trucks where both tables have their columns' widths, else below them (a
    // laptop's side column): neither table then scrolls sideways, their long texts elided.
    QSplitter* m_split = nullptr;
    int m_sideBySideWidth = 0;
};

} // namespace ocu
