// The ISO 23725 module of the console (the FMS side): the IsoBridge over the FMS stack, whose AHS map is the
// site map, the "ISO 23725" link indicator, and the console's own position sent to the AHS as one of the
// FMS's machines when the site configuration names it (own_position.fms_machine_id).
#include "app/ProtocolModule.h"
#include "app/modules/IsoHeadless.h"
#include "app/modules/IsoProduction.h"

#include <QCoreApplication>

#include "models/AutoDispatcher.h"
#include "models/FleetContext.h"
#include "models/OwnPosition.h"
#include "models/ProductionModel.h"
#include "models/bridges/IsoBridge.h"
#include "models/bridges/IsoDispatchSource.h"
#include "widgets/SiteMapView.h"
#include "widgets/dispatch/DispatchPanel.h"
#include "widgets/dispatch/RouteOverlay2D.h"
#ifdef OCU_HAVE_OCU_VIEW3D
#include "widgets/view3d/RouteOverlay3D.h"
#include "widgets/view3d/Site3DView.h"
#endif

namespace ocu {

namespace {

// Their --view names and saved-layout keys.
const QString kDispatchPanel = QStringLiteral("dispatch");
const QString kProductionPanel = QStringLiteral("production");

class IsoModule final : public ProtocolModule {
public:
    QString displayName() const override { return QStringLiteral("ISO 23725"); }
    Protocol protocol() const override { return Protocol::Iso23725; }

    QString start(const ModuleStart& s) override {
        m_fleet = s.fleet;
        if (!s.config.iso23725)
            return {};
        m_bridge = new IsoBridge(*s.config.iso23725, s.frame, s.owner);
        m_bridge->setMessageTap(s.tap);
        m_production = attachProductionModel(m_bridge);
        m_production->setSiteName(QString::fromStdString(s.config.name));
        s.fleet->addBridge(m_bridge);
        // The automatic dispatcher (off until the operator or a script switches it on), owned by
        // the bridge like its dispatch source; the panel and the headless monitor get it from this module.
        auto* source = new IsoDispatchSource(m_bridge, m_bridge);
        m_autoDispatch = new AutoDispatcher(source, s.fleet->gate(), m_bridge);
        m_autoDispatch->setAlarms(s.fleet->alarms());
        return m_bridge->start();
    }
    void stop() override {
        if (m_bridge)
            m_bridge->stop();
    }
    FleetBridge* bridge() const override { return m_bridge; }
    ProductionModel* production() const override { return m_production; }

    void attachOwnPosition(OwnPosition* own, const SiteConfig& config) override {
        if (!m_bridge || config.ownPosition.fmsMachineId.empty())
            return;
        const QString machine = QString::fromStdString(config.ownPosition.fmsMachineId);
        QObject::connect(
            own, &OwnPosition::fixChanged, m_bridge, [bridge = m_bridge, machine](const OwnFix& f) {
                if (f.valid)
                    bridge->setOwnPosition(machine, f.lat, f.lon, f.alt, f.headingDeg, f.speed * 3.6);
            });
    }

    // The dispatch panel over this bridge; the selected truck's route on the 2D map and in 3D.
    // The dispatcher's table (Ctrl+8) and the production (Ctrl+9).
    QList<PanelSpec> panels() const override {
        return {{kDispatchPanel, QCoreApplication::translate("ocu::MainWindow", "Dispatch"),
                 PanelPlace::BesidePassCounts, 8, true, true,
                 QCoreApplication::translate(
                     "ocu::MainWindow", "Dispatch: F6 next truck needing work, Alt+T task, Alt+D "
                                        "destination, Alt+M pick on map, Ctrl+Enter assign, Alt+R reset"),
                 PanelKind::Dispatch},
                {kProductionPanel,
                 QCoreApplication::translate("ocu::MainWindow", "Production"),
                 PanelPlace::BesidePassCounts,
                 9,
                 false,
                 true,
                 {},
                 PanelKind::Production}};
    }
    QString stopAllReach() const override {
        return QCoreApplication::translate("ocu::MainWindow", "ISO 23725 all-stop to every AHS link");
    }
    void populate(const ModulePanels& ui) override {
        ui.window.setPanelWidget(
            kProductionPanel,
            makeProductionView(ui.fleet, m_bridge, m_production, QString::fromStdString(ui.config.name)));
        auto* panel = new DispatchPanel(m_autoDispatch->source(), ui.fleet->gate(), ui.fleet->selection());
        panel->setAutoDispatcher(m_autoDispatch);
        auto* map = qobject_cast<SiteMapView*>(ui.window.panelWidget(Panel::SiteMap));
        panel->setMap(map);
        ui.window.setPanelWidget(kDispatchPanel, panel);
#ifdef OCU_HAVE_OCU_VIEW3D
        if (auto* view3d = qobject_cast<Site3DView*>(ui.window.panelWidget(Panel::Site3D)); view3d && map) {
            auto* route3d = new RouteOverlay3D(view3d);
            QObject::connect(panel, &DispatchPanel::routeChanged, route3d,
                             [route3d, map](const QString& link, const QVector<qint64>& ways) {
                                 route3d->setPath(routePath(map->siteMap(), link, ways));
                             });
        }
#endif
    }

    // assign, reset_assignment, production, auto_dispatch, shift_report (app/modules/IsoHeadless.h).
    // The all-stop of a link is a stop; its removal, assignments: the dispatcher, the supervisor and the
    // admin. Fetching the map changes nothing: every role.
    void addPermissions(CommandPermissions& table) const override {
        using R = OperatorRole;
        table.addStop(QStringLiteral("all_stop_apply"));
        for (const char* name : {"all_stop_remove", "assign", "reset_assignment"})
            table.allow(QLatin1String(name), {R::Dispatcher, R::Supervisor, R::Admin});
        table.allow(QStringLiteral("fetch_map"),
                    QVector<R>(kAllOperatorRoles.begin(), kAllOperatorRoles.end()));
        // Console-local actions of the headless table: switching auto dispatch dispatches trucks; the shift
        // report is the production record of the people who run the shift.
        table.allow(QStringLiteral("auto_dispatch"), {R::Dispatcher, R::Supervisor, R::Admin});
        table.allow(QStringLiteral("shift_report"), {R::Dispatcher, R::SiteManager, R::Supervisor, R::Admin});
    }
    void registerHeadless(HeadlessCommands& table) override {
        registerIsoHeadless(table,
                            {m_bridge, m_production, m_autoDispatch, m_fleet ? m_fleet->fleet() : nullptr});
    }

private:
    IsoBridge* m_bridge = nullptr;
    FleetContext* m_fleet = nullptr;
    ProductionModel* m_production = nullptr;  // owned by the bridge
    AutoDispatcher* m_autoDispatch = nullptr; // owned by the bridge
};

} // namespace

std::unique_ptr<ProtocolModule> makeIsoModule() {
    return std::make_unique<IsoModule>();
}

} // namespace ocu
