#pragma once
// The mission panel of the selected UGV: its plan (a table of waypoints, editable, and the plan editor on the
// 2D map), the route's length and ETA, the plan's files (open and save GeoJSON, import GPX and KML), the
// commands Upload / Start / Pause / Resume / Abort, and the mission's state as the vehicle reports it
// (JausVehicle::mission: never what was asked). One plan per vehicle; the panel shows the plan of the
// current JAUS vehicle of the fleet selection and keeps it while a machine of another protocol or nothing is
// selected. Sending goes through MissionCommands (the JAUS module's); without it the plan can be edited,
// saved and drawn, and the panel says that sending is not available.
#include "models/FleetSelection.h"
#include "models/jaus/JausMission.h"
#include "models/jaus/JausVehicle.h"
#include "models/jaus/JausVehicleBridge.h"

#include <QHash>
#include <QPointer>
#include <QWidget>

class QLabel;
class QPushButton;
class QSpinBox;
class QTableView;
class QTimer;

namespace ocu {

class FleetSelection;
class GeoFrame;
class JausVehicleBridge;
class MissionCommands;
class CommandGate;
class MissionPlan;
class MissionPlanEditor;
class MissionPlanLayer;
class MissionPlanTableModel;
class SiteMapView;

class MissionPanel : public QWidget {
    Q_OBJECT
public:
    MissionPanel(JausVehicleBridge* bridge, FleetSelection* selection, QWidget* parent = nullptr);
    ~MissionPanel() override;

    // Not owned (must outlive the panel or be reset); nullptr: sending is not available.
    void setCommands(MissionCommands* commands);
    // The operator's role decides too: a mission command the gate would refuse is greyed, its tooltip naming
    // the role needed (null: no role check here).
    void setCommandGate(CommandGate* gate);
    // What the panel says while it has no commands (default: this build cannot send missions).
    void setUnavailableText(const QString& text);
    // The plan editor and the missions' drawing on this map (site frame for WGS84 <-> map metres).
    void attachMap(SiteMapView* map, const GeoFrame& frame);
    MissionPlanLayer* layer() const { return m_layer; }
    MissionPlanEditor* editor() const { return m_editor; }

    // The vehicle whose plan is shown (0: none) and its plan (created on first use).
    quint16 vehicle() const { return m_vehicle; }
    void setVehicle(quint16 subsystem);
    MissionPlan* plan() const;
    MissionPlan* planFor(quint16 subsystem);

    // Files; each returns the error shown to the operator (empty when done).
    QString openFile(const QString& path);
    QString importFile(const QString& path);
    QString saveFile(const QString& path);

    // The mission state in words, as the panel shows it (for the vehicle's reported mission and a plan of
    // `planned` waypoints).
    static QString describe(const JausMission& mission, int planned);
    QString stateText() const;
    QString summaryText() const; // waypoints, length, ETA
    QString messageText() const; // the last file or sending message
    QTableView* table() const { return m_table; }
    enum class Action {
        Edit,
        Open,
        Import,
        Save,
        Clear,
        Delete,
        Undo,
        Redo,
        Upload,
        Start,
        Pause,
        Resume,
        Abort
    };
    QPushButton* button(Action a) const;

signals:
    // The plan drawn on the map changed (for the 3D view; at most every 100 ms while dragging): WGS84
    // waypoints and the vehicle's colour.
    void planRouteChanged(const QVector<ocu::MissionWaypoint>& waypoints, const QColor& colour);
    // The path the panel's vehicle drove, as it reports it (for the 3D view; at most every 100 ms): WGS84
    // (lat, lon) points, empty when none, and the vehicle's colour.
    void drivenPathChanged(const QVector<QPair<double, double>>& path, const QColor& colour);

private:
    void build();
    void connectButtons();
    QPushButton* addButton(Action a, const QString& text, const QString& tip);
    void onSelection(const QString& id);
    void onVehicle(const JausVehicle& v);
    void onPlanChanged();
    void refreshState();
    void refreshButtons();
    void refreshMissions();
    void showMessage(const QString& text, bool error);
    void chooseFile(Action a);
    void deleteSelected();
    void goHere(double lat, double lon);
    QString machineId() const;
    QString vehicleName(quint16 subsystem) const;
    int selectedRow() const;

    QPointer<JausVehicleBridge> m_bridge;
    QPointer<FleetSelection> m_selection;
    QPointer<CommandGate> m_gate;
    MissionCommands* m_commands = nullptr;
    MissionPlanLayer* m_layer = nullptr;
    MissionPlanEditor* m_editor = nullptr;
    QHash<quint16, MissionPlan*> m_plans;
    QHash<quint16, JausMission> m_reported; // the missions drawn on the map, as last reported
    quint16 m_vehicle = 0;
    QMetaObject::Connection m_planConnection;

    QLabel* m_title;
    QLabel* m_state;
    QLabel* m_summary;
    QLabel* m_message;
    QLabel* m_unavailable;
    QTableView* m_table;
    MissionPlanTableModel* m_model;
    QSpinBox* m_from;
    QTimer* m_routeTimer;
    QVector<QPair<double, double>> m_pathSent; // the driven path last sent to the 3D view
    quint16 m_pathSentFor = 0;
    QHash<int, QPushButton*> m_buttons;
};

} // namespace ocu
