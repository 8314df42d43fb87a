#include "app/SiteRuntime.h"
#include "app/ShiftReportCommand.h"

#include "app/ConsoleApp.h"
#ifdef OCU_HAVE_COVERAGE
#include "app/CompactionSetup.h"
#endif
#include "app/LogRouting.h"
#include "app/MainWindow.h"
#include "app/ProtocolModule.h"
#ifdef OCU_HAVE_OCU_VIEW3D
#include "app/Site3DFeed.h"
#include "app/TerrainDem.h"
#include "widgets/view3d/Site3DView.h"
#endif

#include "app/HeadlessMonitor.h"
#include "models/AlarmModel.h"
#include "models/CommandGate.h"
#include "models/FleetContext.h"
#include "models/FleetModel.h"
#include "models/FleetSelection.h"
#include "models/OwnPosition.h"
#include "models/history/PgHistory.h"
#include "models/recording/Recorder.h"
#include "sim/SimulatedSite.h"
#include "widgets/EventLogWidget.h"
#include "widgets/FleetListWidget.h"
#include "widgets/PassCountPanel.h"
#include "widgets/SiteMapView.h"
#include "widgets/osyris/CrewMessagesPanel.h"

#include <QApplication>
#include <QDateTime>
#include <QDir>
#include <QDockWidget>
#include <QLabel>
#include <QPointer>
#include <QScrollArea>
#include <QSet>
#include <QStandardPaths>
#include <QStatusBar>
#include <QSysInfo>
#include <QTabWidget>
#include <QTime>
#include <QTimer>
#include <QVBoxLayout>

namespace ocu {

class CompactionSession;

struct SiteRuntime::Impl {
    GeoFrame frame;
    std::unique_ptr<sim::SimulatedSite> sim;
    FleetContext* ctx = nullptr;
    OwnPosition* own = nullptr;
    std::vector<std::unique_ptr<ProtocolModule>> modules = makeProtocolModules();
    recording::Recorder* recorder = nullptr; // the flight recorder of this run
    QStringList startProblems;
    bool stopped = false;
    CompactionSession* compaction = nullptr; // app/CompactionSetup

    // The site map: what the bridges offer (today the ISO 23725 AHS map), in module order.
    SiteMapData mergedMap() const {
        SiteMapData out;
        bool first = true;
        for (const auto& m : modules) {
            FleetBridge* b = m->bridge();
            if (!b)
                continue;
            SiteMapData map = b->siteMap();
            if (map.features.isEmpty() && map.revision == 0)
                continue;
            if (first) {
                out = std::move(map);
                first = false;
            } else {
                out.features += map.features;
                out.revision += map.revision;
            }
        }
        return out;
    }
    // The pass-count layer: the first bridge that offers one (today the OSYRIS station's).
    const PassCountLayer* passLayer() const {
        for (const auto& m : modules)
            if (FleetBridge* b = m->bridge(); b && b->passCountLayer())
                return b->passCountLayer();
        return nullptr;
    }
};

SiteRuntime::SiteRuntime(SiteConfig config, QObject* parent)
    : QObject(parent), m_config(std::move(config)), m_impl(std::make_unique<Impl>()) {}

SiteRuntime::~SiteRuntime() {
    stop();
}

void SiteRuntime::start() {
    Impl& d = *m_impl;
    d.frame = GeoFrame(m_config.origin);
    if (m_config.simulation.enabled) {
        d.sim = std::make_unique<sim::SimulatedSite>();
        const std::string err = d.sim->start(m_config);
        if (!err.empty())
            d.startProblems << tr("Simulated site: %1").arg(QString::fromStdString(err));
    }
    d.ctx = new FleetContext(this);
    d.ctx->fleet()->setStaleAfterMs(static_cast<qint64>(m_config.fleet.staleAfterSeconds * 1000));
    d.ctx->fleet()->setRemoveAfterMs(static_cast<qint64>(m_config.fleet.removeAfterSeconds * 1000));
    if (!m_config.fleet.auditLog.empty())
        d.ctx->gate()->setAuditLogPath(QString::fromStdString(m_config.fleet.auditLog));
    d.ctx->gate()->setConfirmTimeoutMs(int(m_config.fleet.stopConfirmTimeoutSeconds * 1000));
    startRecorder();
    startControlRoomHistory();

    // A stack that cannot start (port taken, bad URL) does not stop the console: its link shows down and the
    // reason is an alarm.
    for (const auto& m : d.modules) {
        const QString e =
            m->start({m_config, d.frame, d.ctx, this, d.recorder ? d.recorder->messageTap() : nullptr});
        if (!e.isEmpty())
            d.startProblems << e;
    }
#ifdef OCU_HAVE_COVERAGE
    d.compaction = startCompaction(m_config, d.frame, d.passLayer(), this, &d.startProblems);
#endif
    d.own = new OwnPosition(d.frame, this);
    const auto& op = m_config.ownPosition;
    if (op.source == "system")
        d.own->startSystemSource();
    else if (op.source == "nmea-file")
        d.own->startNmeaFile(QString::fromStdString(op.path), true);
    else if (op.source == "nmea-serial")
        d.own->startNmeaFile(QString::fromStdString(op.path), false);
    connect(d.own, &OwnPosition::error, this, [this](const QString& msg) {
        m_impl->ctx->alarms()->add(makeEvent(EventSeverity::Warning, EventKind::Info, {},
                                             tr("Own position: %1").arg(msg), QStringLiteral("gui")));
    });
    for (const auto& m : d.modules)
        m->attachOwnPosition(d.own, m_config);
    if (d.recorder) {
        for (const auto& m : d.modules)
            if (FleetBridge* b = m->bridge())
                connect(b, &FleetBridge::siteMapChanged, d.recorder,
                        [this] { m_impl->recorder->recordSiteMap(m_impl->mergedMap()); });
        d.recorder->recordSiteMap(d.mergedMap());
        // The OSYRIS pass counts: the grid now, then its changes (at most once a second).
        if (const PassCountLayer* layer = d.passLayer()) {
            d.recorder->watchPassCounts(layer);
            for (const auto& m : d.modules)
                if (FleetBridge* b = m->bridge())
                    connect(b, &FleetBridge::passCountChanged, d.recorder,
                            &recording::Recorder::passCountsChanged);
        }
    }
    for (const QString& p : std::as_const(d.startProblems)) {
        qCWarning(lcApp).noquote() << p;
        d.ctx->alarms()->add(
            makeEvent(EventSeverity::Alarm, EventKind::LinkLoss, {}, p, QStringLiteral("gui")));
    }
}

// The shared history on PostgreSQL, when the site configuration names one.
void SiteRuntime::startControlRoomHistory() {
    Impl& d = *m_impl;
    if (!m_config.historyPostgres)
        return;
    const auto& h = *m_config.historyPostgres;
    PgHistoryConfig hc{QString::fromStdString(h.conninfo), QString::fromStdString(h.console),
                       QString::fromStdString(h.outbox)};
    if (hc.console.isEmpty())
        hc.console = QSysInfo::machineHostName();
    if (hc.outboxPath.isEmpty()) {
        const QString dir = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
        QDir().mkpath(dir);
        hc.outboxPath = dir + QStringLiteral("/history-outbox-%1.sqlite").arg(hc.console);
    }
    AlarmModel* alarms = d.ctx->alarms();
    alarms->setOperatorName(hc.console);
    auto* history = new PgHistory(hc, this);
    history->attach(alarms);
    history->attachGate(d.ctx->gate());
    connect(history, &PgHistory::connectionChanged, alarms, [alarms](bool up, const QString& why) {
        alarms->add(up ? makeEvent(EventSeverity::Info, EventKind::LinkLoss, {},
                                   tr("control-room history connected"), QStringLiteral("history"))
                       : makeEvent(EventSeverity::Warning, EventKind::LinkLoss, {},
                                   tr("control-room history unavailable (kept locally, back-filled on "
                                      "return): %1")
                                       .arg(why),
                                   QStringLiteral("history")));
    });
    const QString e = history->start();
    if (!e.isEmpty())
        d.startProblems << tr("Control-room history: %1").arg(e);
}

void SiteRuntime::stop() {
    Impl& d = *m_impl;
    if (d.stopped)
        return;
    d.stopped = true;
    // Stacks first (JAUS releases control after zero drive commands), then the simulators.
    for (const auto& m : d.modules)
        m->stop();
    if (d.sim)
        d.sim->stop();
    if (d.recorder)
        d.recorder->stop(); // commits what is queued and closes the file
}

recording::Recorder* SiteRuntime::recorder() const {
    return m_impl->recorder;
}

void SiteRuntime::startRecorder() {
    Impl& d = *m_impl;
    const RecordConfig& rc = m_config.record;
    if (!rc.enabled)
        return;
    // Where: record.dir (or --record); else OCU_RECORD_DIR (tests and CI runs: a temporary folder, never the
    // user's home); else the user's data folder.
    const QString envDir = qEnvironmentVariable("OCU_RECORD_DIR");
    const QString dir = !rc.dir.empty() ? QString::fromStdString(rc.dir)
                        : !envDir.isEmpty()
                            ? envDir
                            : QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation) +
                                  QStringLiteral("/recordings");
    recording::applyRetention(dir, qint64(rc.maxTotalMb * 1024 * 1024), rc.maxAgeDays);
    recording::RecorderOptions o;
    o.path = recording::newRecordingPath(dir);
    o.raw = rc.raw;
    o.messages = rc.messages;
    // A run alone never outgrows the folder's budget, and the folder's older runs give way while it records.
    o.maxFileBytes = recording::effectiveMaxFileBytes(rc.maxFileMb, rc.maxTotalMb);
    o.retentionDir = dir;
    o.maxTotalBytes = qint64(rc.maxTotalMb * 1024 * 1024);
    o.maxAgeDays = rc.maxAgeDays;
    o.siteName = QString::fromStdString(m_config.name);
    o.originLat = m_config.origin.lat;
    o.originLon = m_config.origin.lon;
    o.originAlt = m_config.origin.alt;
    d.recorder = new recording::Recorder(this);
    const QString err = d.recorder->start(o);
    if (!err.isEmpty()) {
        // The console runs without a recorder, loudly.
        d.startProblems << tr("Flight recorder: %1").arg(err);
        delete d.recorder;
        d.recorder = nullptr;
        return;
    }
    d.recorder->attach(d.ctx);
    qCInfo(lcApp).noquote() << "recording to" << o.path;
    d.ctx->alarms()->add(makeEvent(EventSeverity::Info, EventKind::Info, {},
                                   tr("Recording this run to %1").arg(o.path), QStringLiteral("recorder")));
}

static QWidget* notice(const QString& text) {
    auto* l = new QLabel(text);
    l->setAlignment(Qt::AlignCenter);
    l->setWordWrap(true);
    l->setMargin(20);
    return l;
}

static LinkIndicator::State indicatorState(LinkState s) {
    switch (s) {
    case LinkState::Up:
        return LinkIndicator::State::Up;
    case LinkState::Degraded:
    case LinkState::Unknown:
        return LinkIndicator::State::Degraded;
    case LinkState::Down:
        return LinkIndicator::State::Down;
    }
    return LinkIndicator::State::Down;
}

void SiteRuntime::populate(MainWindow& window) {
    Impl& d = *m_impl;
    FleetContext* ctx = d.ctx;

    // One link indicator per protocol of this build, in module order.
    for (const auto& m : d.modules)
        window.addLinkIndicator(m->displayName());

    auto* list = new FleetListWidget(ctx->fleet(), ctx->selection());
    list->setCommandGate(ctx->gate());
    window.setPanelWidget(Panel::Fleet, list);

    auto* map = new SiteMapView;
    map->setFleet(ctx->fleet(), ctx->selection());
    map->setGeoFrame(d.frame);
    map->setSiteMap(d.mergedMap());
    map->setPassCountLayer(d.passLayer());
    window.setPanelWidget(Panel::SiteMap, map);
    connect(list, &FleetListWidget::centerOnMapRequested, map, &SiteMapView::centerOnMachine);
    connect(map, &SiteMapView::contextMenuRequested, list, &FleetListWidget::showContextMenu);
    connect(d.own, &OwnPosition::fixChanged, map, &SiteMapView::setOwnFix);
    // Frame the whole site once the first machines have arrived (unless the operator has taken over).
    QTimer::singleShot(1500, map, [map] { map->refitIfAuto(); });
    // The background raster named by the site (the simulated pit's hillshade by default).
    if (!m_config.background.raster.empty()) {
        connect(map, &SiteMapView::backgroundFailed, this, [this](const QString& msg) {
            qCWarning(lcApp).noquote() << "map background:" << msg;
            m_impl->ctx->alarms()->add(makeEvent(EventSeverity::Warning, EventKind::Info, {},
                                                 tr("Map background not shown: %1").arg(msg),
                                                 QStringLiteral("gui")));
        });
        map->loadBackground(QString::fromStdString(m_config.background.raster));
    }

#ifdef OCU_HAVE_OCU_VIEW3D
    auto* view3d = new Site3DView;
    auto* feed = new Site3DFeed(view3d, ctx->fleet(), ctx->selection(), view3d);
    feed->setPassCountLayer(d.passLayer());
    if (!m_config.terrain.dem.empty()) {
        auto dem = loadTerrainDem(m_config.terrain.dem, d.frame);
        if (dem)
            feed->setTerrain(dem.value());
        else
            ctx->alarms()->add(
                makeEvent(EventSeverity::Warning, EventKind::Diagnostic, {},
                          tr("3D terrain not shown: %1").arg(QString::fromStdString(dem.error())),
                          QStringLiteral("gui")));
    }
    window.setPanelWidget(Panel::Site3D, view3d);
#ifdef OCU_HAVE_COVERAGE
    attachCompaction3D(d.compaction, view3d);
#endif
#else
    QObject* feed = nullptr;
    window.setPanelWidget(Panel::Site3D,
                          notice(tr("This build has no 3D view (configured with OCU_WITH_VTK=OFF).")));
#endif

    auto* passPanel = new PassCountPanel;
    passPanel->setLayer(d.passLayer());
    // Lifts and filters of the layer's source; crew messages beside the pass counts.
    QWidget* passDock = passPanel;
    for (const auto& module : d.modules) {
        FleetBridge* b = module->bridge();
        if (auto* c = dynamic_cast<PassCountControls*>(b); c && b->passCountLayer() == d.passLayer())
            passPanel->setControls(c);
        if (auto* crew = dynamic_cast<CrewMessaging*>(b); crew && passDock == passPanel) {
            auto* crewPanel = new CrewMessagesPanel;
            crewPanel->setCommandGate(ctx->gate());
            crewPanel->setBridge(b, crew);
            auto* tabs = new QTabWidget;
            // The panel (summary, lift, filters, histogram) scrolls inside its tab: beside it the areas panel
            // stays in view in a low dock (1366 x 768).
            auto* passScroll = new QScrollArea;
            passScroll->setFrameShape(QFrame::NoFrame);
            passScroll->setWidgetResizable(true);
            passScroll->setWidget(passPanel);
            tabs->addTab(passScroll, tr("Pass counts"));
            const int crewTab = tabs->addTab(crewPanel, tr("Crew messages"));
            // Unread messages in the tab's title: seen from any tab of the panel.
            connect(crewPanel, &CrewMessagesPanel::unreadChanged, tabs, [tabs, crewTab](int unread) {
                tabs->setTabText(crewTab,
                                 unread > 0 ? tr("Crew messages (%1)").arg(unread) : tr("Crew messages"));
            });
            passDock = tabs;
        }
    }
#ifdef OCU_HAVE_COVERAGE
    window.setPanelWidget(Panel::PassCounts, buildCompactionGui(d.compaction, map, passDock));
#else
    window.setPanelWidget(Panel::PassCounts, passDock);
#endif
    connect(passPanel, &PassCountPanel::paletteChanged, map, &SiteMapView::setPassPalette);
    connect(passPanel, &PassCountPanel::targetChanged, map, &SiteMapView::setPassTarget);
#ifdef OCU_HAVE_OCU_VIEW3D
    // The 3D surface in the 2D map's colours, cell for cell (passCountColor with the same palette and
    // target).
    feed->setPassPalette(map->passPalette());
    feed->setPassTarget(map->passTarget());
    connect(passPanel, &PassCountPanel::paletteChanged, feed, &Site3DFeed::setPassPalette);
    connect(passPanel, &PassCountPanel::targetChanged, feed, &Site3DFeed::setPassTarget);
#endif

    for (const auto& module : d.modules) {
        FleetBridge* b = module->bridge();
        if (!b)
            continue;
#ifdef OCU_HAVE_COVERAGE
        watchCompactionCounts(d.compaction, b); // the areas' statistics follow the counts
#endif
        connect(b, &FleetBridge::siteMapChanged, map, [this, map, feed] {
            const SiteMapData m = m_impl->mergedMap();
            map->setSiteMap(m);
#ifdef OCU_HAVE_OCU_VIEW3D
            static_cast<Site3DFeed*>(feed)->setSiteMap(m);
#endif
            map->refitIfAuto();
        });
        connect(b, &FleetBridge::passCountChanged, map, [map, passPanel, feed] {
            map->passCountChanged();
            passPanel->layerChanged();
#ifdef OCU_HAVE_OCU_VIEW3D
            static_cast<Site3DFeed*>(feed)->passCountChanged();
#endif
        });
        LinkIndicator* ind = window.linkIndicator(module->displayName());
        ind->watchBridge(b); // reject counters per link in its details
        // A standing condition of the stack (e.g. JAUS without its group socket); the stacks started in
        // start(), before the window is filled.
        ind->setNote(b->statusNote());
        connect(b, &FleetBridge::linkChanged, ind, [ind](const LinkStatus& s) {
            ind->setState(indicatorState(s.state),
                          s.link + (s.detail.isEmpty() ? QString() : ": " + s.detail));
            if (s.dataAgeMs >= 0)
                ind->setDataAgeMs(s.dataAgeMs);
        });
    }
    // Data age per protocol from the newest machine data, refreshed every second.
    auto* ages = new QTimer(&window);
    QHash<Protocol, LinkIndicator*> indicators;
    for (const auto& m : d.modules)
        indicators.insert(m->protocol(), window.linkIndicator(m->displayName()));
    connect(ages, &QTimer::timeout, &window, [ctx, indicators] {
        QHash<Protocol, qint64> newest;
        for (const MachineState& m : ctx->fleet()->machinesSnapshot())
            newest[m.protocol] = std::max(newest.value(m.protocol, 0), m.lastDataMs);
        const qint64 now = QDateTime::currentMSecsSinceEpoch();
        for (auto it = newest.begin(); it != newest.end(); ++it)
            if (LinkIndicator* ind = indicators.value(it.key()); ind && it.value() > 0)
                ind->setDataAgeMs(std::max<qint64>(0, now - it.value()));
    });
    ages->start(1000);

    window.setPanelWidget(Panel::EventLog, new EventLogWidget(ctx->alarms()));
    connect(ctx->alarms(), &AlarmModel::unacknowledgedCountChanged, &window,
            &MainWindow::setUnacknowledgedAlarms);
    window.setUnacknowledgedAlarms(ctx->alarms()->unacknowledgedCount());
    connect(&window, &MainWindow::stopAllRequested, ctx->gate(),
            [ctx] { ctx->gate()->stopAll(QStringLiteral("gui")); });
    // A stop that did not reach every target, or that a machine did not confirm, is shown loudly until the
    // operator dismisses it or a later STOP ALL reaches everything.
    QPointer<MainWindow> win(&window);
    connect(ctx->gate(), &CommandGate::stopFinished, &window, [win](const CommandResult& r, const QString&) {
        if (!win)
            return;
        if (r.ok) {
            if (r.action == QLatin1String("stop_all"))
                win->clearStopBanner();
            return;
        }
        const QString when = QTime::currentTime().toString(QStringLiteral("HH:mm:ss"));
        const QString what = r.notSent().isEmpty() ? r.message : r.notSent().join(QStringLiteral("; "));
        win->showStopBanner(r.action == QLatin1String("stop_all")
                                ? MainWindow::tr("%1 STOP ALL did NOT reach: %2").arg(when, what)
                                : MainWindow::tr("%1 STOP did NOT reach: %2").arg(when, what));
    });
    connect(ctx->gate(), &CommandGate::stopUnconfirmed, &window, [win](const QString&, const QString& text) {
        if (!win)
            return;
        const QString line = QTime::currentTime().toString(QStringLiteral("HH:mm:ss ")) + text;
        win->showStopBanner(win->stopBannerVisible() ? win->stopBannerText() + QLatin1Char('\n') + line
                                                     : line);
    });

    // The protocols' own panels; a panel no module of this build fills says so.
    QSet<Panel> filled{Panel::Fleet, Panel::SiteMap, Panel::Site3D, Panel::PassCounts, Panel::EventLog};
    bool dispatchLive = false;
    for (const auto& m : d.modules) {
        if (m->bridge())
            m->populate({window, ctx, m_config});
        else
            for (Panel p : m->panels())
                window.setPanelWidget(p, notice(m->notConfiguredText()));
        for (Panel p : m->panels()) {
            filled.insert(p);
            dispatchLive |= p == Panel::Dispatch && m->bridge();
        }
    }
    // A site with pass counts and no haulage to dispatch shows the pass counts in front of the
    // Dispatch notice that shares their place (a saved layout still wins, it is restored after this).
    if (!dispatchLive && d.passLayer())
        window.dock(Panel::PassCounts)->raise();
    for (Panel p : MainWindow::panels())
        if (!filled.contains(p))
            window.setPanelWidget(
                p,
                notice(tr("This build has no protocol module for the %1 panel.").arg(window.panelTitle(p))));
    for (const QString& p : std::as_const(d.startProblems))
        window.statusBar()->showMessage(p, 15000);
}

HeadlessMonitor* SiteRuntime::attachHeadless(QIODevice* out) {
    Impl& d = *m_impl;
    HeadlessMonitor* mon = HeadlessMonitor::attach(d.ctx, out);
    for (const auto& m : d.modules)
        m->registerHeadless(mon->commands());
#ifdef OCU_HAVE_COVERAGE
    registerCompactionHeadless(mon->commands(), d.compaction);
#endif
    return mon;
}

int SiteRuntime::runHeadless(QApplication& app, double durationSeconds) {
    HeadlessMonitor* mon = attachHeadless();
    mon->setRateLimitMs(static_cast<int>(1000.0 / m_config.fleet.monitorRateHz));
    if (!mon->startStdin() && durationSeconds <= 0) {
        std::fputs("ocu: --headless reads commands from stdin, which is not readable; give --duration\n",
                   stderr);
        return 2;
    }
    if (durationSeconds > 0)
        QTimer::singleShot(static_cast<int>(durationSeconds * 1000), &app, &QApplication::quit);
    else
        connect(mon, &HeadlessMonitor::inputFinished, &app, &QApplication::quit);
    const int rc = execUnlessQuitting(app); // SIGINT/SIGTERM quit as end of input does
    mon->stopStdin();                       // no early stop through the bridges once they are being torn down
    stop();
    return rc;
}

QJsonObject SiteRuntime::writeShiftReport(const QString& pdf, const QString& csv) {
    // The first module with a production model (ProtocolModule::production()).
    for (const auto& m : m_impl->modules)
        if (ProductionModel* model = m->production())
            return ocu::writeShiftReport(model, m->bridge(), m_impl->ctx->fleet(),
                                         {pdf, csv, std::nullopt, QString::fromStdString(m_config.name)});
    return ocu::writeShiftReport(nullptr, nullptr, m_impl->ctx->fleet(), {pdf, csv, std::nullopt, {}});
}

} // namespace ocu
