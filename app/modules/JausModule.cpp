// The JAUS module of the console: the JausBridge over the JAUS stack, the access-control and teleop panels
// (with the SDL2 joystick mapped as the site configuration says), the "JAUS" link indicator and the headless
// commands request_control, release_control, drive and the waypoint missions (mission_upload, mission_start,
// mission_pause, mission_resume, mission_abort, goto).
#include "app/HeadlessCommands.h"
#include "app/ProtocolModule.h"
#include "app/modules/JausMission3D.h"
#include "app/modules/JausMissionHeadless.h"
#include "app/modules/JausMissionReplay.h"
#include "app/modules/JausVideoHeadless.h"

#include "models/FleetContext.h"
#include "models/bridges/JausBridge.h"
#include "models/jaus/JausSubsystemModel.h"
#include "models/jaus/MissionGeoJson.h"
#include "models/jaus/MissionJson.h"
#include "models/jaus/MissionRecordFeed.h"
#include "widgets/SiteMapView.h"
#include "widgets/jaus/HandoffBanner.h"
#include "widgets/jaus/JausControlPanel.h"
#include "widgets/jaus/MissionGateCommands.h"
#include "widgets/jaus/MissionPanel.h"
#include "widgets/jaus/TeleopPanel.h"
#include "widgets/jaus/TeleopVideoPane.h"
#include "widgets/teleop/SdlJoystickInput.h"

#include <QCoreApplication>

namespace ocu {

namespace {

// Their --view names and saved-layout keys.
const QString kControlPanel = QStringLiteral("jaus");
const QString kTeleopPanel = QStringLiteral("teleop");
const QString kVideoPanel = QStringLiteral("video");
const QString kMissionPanel = QStringLiteral("mission");

// mission_upload: inline "waypoints", or "file": a GeoJSON route read into them (the result echoes the file).
HeadlessCommands::GateRequest readMissionUpload(const QJsonObject& cmd) {
    const QString name = QStringLiteral("mission_upload");
    const QString path = cmd.value(QStringLiteral("file")).toString();
    if (path.isEmpty())
        return HeadlessCommands::read(name, cmd);
    QString why;
    const auto waypoints = readMissionGeoJsonFile(path, &why);
    if (!waypoints) {
        HeadlessCommands::GateRequest r;
        r.refusal = QCoreApplication::translate("JausModule", "mission_upload: %1; nothing sent").arg(why);
        r.refusalTarget = cmd.value(QStringLiteral("id")).toString();
        return r;
    }
    QJsonObject withPoints = cmd;
    withPoints.remove(QStringLiteral("file"));
    QJsonArray list;
    for (const MissionWaypoint& w : *waypoints)
        list << waypointToJson(w);
    withPoints[QStringLiteral("waypoints")] = list;
    HeadlessCommands::GateRequest r = HeadlessCommands::read(name, withPoints);
    r.echo[QStringLiteral("file")] = path;
    return r;
}

class JausModule final : public ProtocolModule {
public:
    QString displayName() const override { return QStringLiteral("JAUS"); }
    Protocol protocol() const override { return Protocol::Jaus; }

    QString start(const ModuleStart& s) override {
        if (!s.config.jaus)
            return {};
        jaus::JausConfig cfg = *s.config.jaus;
        if (s.roleAuthority >= 0) { // the operator's role decides (AEP-4818 §4.3.2 bands)
            cfg.authority = std::uint8_t(s.roleAuthority);
            cfg.role = s.roleAuthority == 0    ? jaus::Role::Monitor
                       : s.roleAuthority < 240 ? jaus::Role::PrimaryOperator
                                               : jaus::Role::SafetyCritical;
        }
        m_frame = s.frame;
        m_bridge = new JausBridge(cfg, s.frame, s.owner);
        m_bridge->setMessageTap(s.tap);
        new MissionRecordFeed(m_bridge); // the missions into the flight recorder (the bridge owns it)
        s.fleet->addBridge(m_bridge);
        return m_bridge->start();
    }
    void stop() override {
        if (m_bridge)
            m_bridge->stop(); // releases control after zero drive commands
    }
    FleetBridge* bridge() const override { return m_bridge; }
    QStringList controllerAddresses() const override {
        if (!m_bridge)
            return {};
        return {JausSubsystemModel::roomAddress(m_bridge->identity().ownId)};
    }

    // The access-control column right of the map, teleop as its second tab (Ctrl+4, Ctrl+5), the teleop
    // video in a panel of its own (the UGV workspace's main area; Ctrl+I) and the mission panel in the UGV
    // workspace's lower group (Ctrl+U: every Ctrl+digit is taken). The video comes after teleop: its dock is
    // created, and destroyed, after the teleop panel's that drives from it.
    QList<PanelSpec> panels() const override {
        return {
            {kControlPanel,
             QCoreApplication::translate("ocu::MainWindow", "JAUS control"),
             PanelPlace::SideColumn,
             4,
             true,
             true,
             {},
             PanelKind::VehicleControl},
            {kTeleopPanel, QCoreApplication::translate("ocu::MainWindow", "Teleop"), PanelPlace::SideColumn,
             5, false, true,
             QCoreApplication::translate("ocu::MainWindow", "Teleop panel: W/A/S/D or arrows with the "
                                                            "dead-man key held; Space or Esc: emergency "
                                                            "stop"),
             PanelKind::Teleop},
            {.key = kVideoPanel,
             .title = QCoreApplication::translate("ocu::MainWindow", "Video"),
             .scrolls = false,
             .keyboardHelp = QCoreApplication::translate(
                 "ocu::MainWindow",
                 "Video panel (Ctrl+I): camera, full screen (Esc returns), resume driving"),
             .kind = PanelKind::Video,
             .shortcutKey = Qt::Key_I},
            {kMissionPanel, QCoreApplication::translate("ocu::MainWindow", "Mission"), PanelPlace::SideColumn,
             0, false, true,
             QCoreApplication::translate(
                 "ocu::MainWindow",
                 "Mission panel (Ctrl+U): Alt+E edit on the map, Alt+O open, Alt+I import GPX/KML, Alt+S "
                 "save, Alt+L upload, Alt+P pause, Alt+B abort. Editing on the map: click adds a waypoint, "
                 "drag moves it, click a leg inserts one; Insert or Enter adds at the cursor, Delete removes "
                 "the selected one, Page Up/Down select, Shift+arrows move it, Ctrl+Z / Ctrl+Shift+Z undo / "
                 "redo, Esc ends editing; right-click on the ground: Go here"),
             PanelKind::Missions, Qt::Key_U}};
    }
    void populateReplay(const ModuleReplay& replay) override { populateMissionReplay(replay, kMissionPanel); }
    QString stopAllReach() const override {
        return QCoreApplication::translate("ocu::MainWindow",
                                           "JAUS emergency stop to every discovered vehicle");
    }
    QString aboutName() const override { return QStringLiteral("JAUS (AS5669A/AS5710A, AEP-4818 IOP)"); }

    void populate(const ModulePanels& ui) override {
        auto* control = new JausControlPanel(m_bridge, ui.fleet->gate(), ui.fleet->selection());
        control->model()->setControlRoom(ui.controlRoom);
        control->handoff()->setControlRoom(ui.controlRoom);
        ui.window.setPanelWidget(kControlPanel, control);
        auto* joystick = new SdlJoystickInput(&ui.window);
        const TeleopInputConfig& t = ui.config.teleop;
        AxisMapping mapping;
        mapping.forwardAxis = t.forwardAxis;
        mapping.turnAxis = t.turnAxis;
        mapping.invertForward = t.invertForward;
        mapping.invertTurn = t.invertTurn;
        mapping.deadZone = t.deadZone;
        joystick->setMapping(mapping);
        auto* teleop = new TeleopPanel(m_bridge, ui.fleet->gate(), ui.fleet->selection(), joystick);
        teleop->video()->watchdog().setLimitMs(static_cast<int>(t.videoWatchdogS * 1000));
        ui.window.setPanelWidget(kTeleopPanel, teleop);
        ui.window.setPanelWidget(kVideoPanel, teleop->detachVideo());
        populateMission(ui);
    }

    // Control, management and driving: the UGV operator, the supervisor and the admin. Ending a drive
    // session sends zeros: a stop.
    void addPermissions(CommandPermissions& table) const override {
        using R = OperatorRole;
        table.addStop(QStringLiteral("drive_stop"));
        for (const char* name : {"request_control", "release_control", "release_all", "drive", "drive_start",
                                 "resume", "standby", "reset"})
            table.allow(QLatin1String(name), {R::UgvOperator, R::Supervisor, R::Admin});
        table.allow(QStringLiteral("shutdown"), {R::Supervisor, R::Admin});
        // Missions move the vehicle: whoever may drive may run them (mission_abort stops one, but it is
        // no emergency stop: STOP ALL is for everyone).
        for (const char* name :
             {"mission_upload", "mission_start", "mission_pause", "mission_resume", "mission_abort", "goto"})
            table.allow(QLatin1String(name), {R::UgvOperator, R::Supervisor, R::Admin});
        // The platform services (mode, state, lights, trip odometer) are the vehicle driver's too.
        for (const char* name : {"platform_mode", "platform_state", "lights", "odometry"})
            table.allow(QLatin1String(name), {R::UgvOperator, R::Supervisor, R::Admin});
        // Hand-off between consoles (AEP-4818 §6.3): asking for a vehicle and giving one away are control
        // commands, for whoever may take control.
        for (const char* name : {"handoff_request", "handoff_answer"})
            table.allow(QLatin1String(name), {R::UgvOperator, R::Supervisor, R::Admin});
    }

    // To the bridge of the machine named by "id" (asked for when missing); video_status, video_play and
    // video_stop when the site has JAUS vehicles.
    void registerHeadless(HeadlessCommands& table) override {
        for (const char* name :
             {"request_control", "release_control", "drive", "drive_start", "drive_stop", "mission_start",
              "mission_pause", "mission_resume", "mission_abort", "goto", "platform_mode", "platform_state",
              "lights", "odometry", "handoff_request", "handoff_answer"})
            table.addGateCommand(QLatin1String(name));
        // Inline waypoints, or "file": a GeoJSON route (models/jaus/MissionGeoJson) read here, at the edge.
        table.addGateCommand(QStringLiteral("mission_upload"), readMissionUpload);
        if (m_bridge)
            (new JausVideoHeadless(m_bridge, m_bridge))->registerIn(table);
        // Each UGV's mission in its machine line and in "list": state, waypoint k of n, distance, ETA.
        addMissionLines(m_bridge, table);
    }
    void registerHeadlessReplay(const ModuleHeadlessReplay& replay) override {
        registerMissionReplayHeadless(replay);
    }

private:
    // The mission panel, its editor and drawing on the 2D map, the planned route and the driven path in 3D.
    void populateMission(const ModulePanels& ui) {
        auto* mission = new MissionPanel(m_bridge, ui.fleet->selection());
        mission->setCommands(new MissionGateCommands(ui.fleet->gate(), mission));
        mission->setCommandGate(ui.fleet->gate());
        auto* map = qobject_cast<SiteMapView*>(ui.window.panelWidget(Panel::SiteMap));
        mission->attachMap(map, m_frame);
        ui.window.setPanelWidget(kMissionPanel, mission);
        attachMissionRoutes3D(ui.window, mission, m_frame); // the route and the path driven in 3D
    }

    JausBridge* m_bridge = nullptr;
    GeoFrame m_frame;
};

} // namespace

std::unique_ptr<ProtocolModule> makeJausModule() {
    return std::make_unique<JausModule>();
}

} // namespace ocu
