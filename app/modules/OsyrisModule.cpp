// The OSYRIS module of the console: the OsyrisBridge over the OCU's OSYRIS station, whose pass counts are the
// pass-count layer of the 2D map, the 3D view and the pass-count panel (with the station's lifts and
// filters), the crew messages panel, the compaction job fed by the counts with its areas panel, and the
// "OSYRIS" link indicator.
#include "app/ProtocolModule.h"

#include "models/FleetContext.h"
#include "models/bridges/OsyrisBridge.h"
#include "widgets/PassCountPanel.h"
#include "widgets/osyris/CrewMessagesPanel.h"
#ifdef OCU_HAVE_COVERAGE
#include "app/CompactionSetup.h"
#include "widgets/SiteMapView.h"
#endif

#include <QCoreApplication>
#include <QDockWidget>

namespace ocu {

namespace {

// Their --view names and saved-layout keys.
const QString kCrewPanel = QStringLiteral("crew");
const QString kAreasPanel = QStringLiteral("areas");

QString crewTitle(int unread) {
    return unread > 0 ? QCoreApplication::translate("ocu::SiteRuntime", "Crew messages (%1)").arg(unread)
                      : QCoreApplication::translate("ocu::SiteRuntime", "Crew messages");
}

class OsyrisModule final : public ProtocolModule {
public:
    QString displayName() const override { return QStringLiteral("OSYRIS"); }
    Protocol protocol() const override { return Protocol::Osyris; }
    QString stopAllReach() const override {
        return QCoreApplication::translate("ocu::MainWindow", "the OSYRIS stop message");
    }

    QString start(const ModuleStart& s) override {
        QString error;
        if (s.config.osyris) {
            m_bridge = new OsyrisBridge(*s.config.osyris, s.frame, s.owner);
            m_bridge->setMessageTap(s.tap);
            s.fleet->addBridge(m_bridge);
            error = m_bridge->start();
        }
#ifdef OCU_HAVE_COVERAGE
        // The compaction job (design, areas, the headless coverage report) also on a site whose station is
        // not configured yet: its design and areas are the job's, the counts come once the station does.
        m_compaction = startCompaction(
            s.config, s.frame, m_bridge ? m_bridge->osyrisPassCountLayer() : nullptr, s.owner, s.problems);
#endif
        return error;
    }
    void stop() override {
        if (m_bridge)
            m_bridge->stop();
    }
    FleetBridge* bridge() const override {
        return m_bridge;
    }

    // The compaction job's areas (Ctrl+0) and the crew messages (Ctrl+M).
    QList<PanelSpec> panels() const override {
        QList<PanelSpec> out;
#ifdef OCU_HAVE_COVERAGE
        out << PanelSpec{.key = kAreasPanel,
                         .title = QCoreApplication::translate("ocu::SiteRuntime", "Areas and reports"),
                         .place = PanelPlace::BesidePassCounts,
                         .scrolls = false, // its tables shrink; its buttons stay in view in a low dock
                         .kind = PanelKind::CompactionAreas,
                         .shortcutKey = Qt::Key_0};
#endif
        out << PanelSpec{.key = kCrewPanel,
                         .title = crewTitle(0),
                         .place = PanelPlace::BesidePassCounts,
                         .scrolls = false, // a list and a line to type in: they keep to the dock's width
                         .kind = PanelKind::CrewMessages,
                         .shortcutKey = Qt::Key_M};
        return out;
    }

#ifdef OCU_HAVE_COVERAGE
    // The compaction job's "coverage_report".
    // Crew messages: the site manager, the supervisor and the admin; a station ping changes nothing.
    void addPermissions(CommandPermissions& table) const override {
        using R = OperatorRole;
        table.allow(QStringLiteral("send_text"), {R::SiteManager, R::Supervisor, R::Admin});
        table.allow(QStringLiteral("ping"), QVector<R>(kAllOperatorRoles.begin(), kAllOperatorRoles.end()));
        table.allow(QStringLiteral("coverage_report"), {R::SiteManager, R::Supervisor, R::Admin});
    }
    void registerHeadless(HeadlessCommands& table) override {
        registerCompactionHeadless(table, m_compaction);
    }
#endif

    void populate(const ModulePanels& ui) override {
        // The station's lifts and filters when the panel shows its counts.
        if (ui.passCounts->layer() == m_bridge->passCountLayer())
            ui.passCounts->setControls(m_bridge);
        auto* crew = new CrewMessagesPanel;
        crew->setCommandGate(ui.fleet->gate());
        crew->setBridge(m_bridge, m_bridge);
        ui.window.setPanelWidget(kCrewPanel, crew);
        // Unread messages in the dock's title: its tab when it is behind another panel.
        if (QDockWidget* dock = ui.window.dock(kCrewPanel))
            QObject::connect(crew, &CrewMessagesPanel::unreadChanged, dock,
                             [dock](int unread) { dock->setWindowTitle(crewTitle(unread)); });
#ifdef OCU_HAVE_COVERAGE
        auto* map = qobject_cast<SiteMapView*>(ui.window.panelWidget(Panel::SiteMap));
        ui.window.setPanelWidget(kAreasPanel, buildCompactionPanel(m_compaction, map));
        attachCompaction3D(m_compaction, ui.window.panelWidget(Panel::Site3D));
        watchCompactionCounts(m_compaction, m_bridge); // the areas' statistics follow the counts
#endif
    }

private:
    OsyrisBridge* m_bridge = nullptr;
#ifdef OCU_HAVE_COVERAGE
    CompactionSession* m_compaction = nullptr;
#endif
};

} // namespace

std::unique_ptr<ProtocolModule> makeOsyrisModule() {
    return std::make_unique<OsyrisModule>();
}

} // namespace ocu
