#include "app/SiteRuntime.h"
#include "app/ShiftReportCommand.h"

#include "app/ConsoleApp.h"
#include "app/LogRouting.h"
#include "app/MainWindow.h"
#include "app/OperatorUi.h"
#include "app/ProtocolModule.h"
#ifdef OCU_HAVE_OCU_VIEW3D
#include "app/Site3DFeed.h"
#include "app/TerrainDem.h"
#include "widgets/view3d/Site3DView.h"
#endif

#include "app/EarlyStopPress.h"
#include "app/HardwareStopButton.h"
#include "app/HeadlessMonitor.h"
#include "app/HeadlessSocket.h"
#include "models/AlarmModel.h"
#include "models/CommandGate.h"
#include "models/ControlRoomModel.h"
#include "models/FleetContext.h"
#include "models/FleetModel.h"
#include "models/FleetSelection.h"
#include "models/OperatorSession.h"
#include "models/OwnPosition.h"
#include "models/history/PgHistory.h"
#include "models/recording/Recorder.h"
#include "protocols/site/PamAuthenticator.h"
#include "sim/SimulatedSite.h"
#include "widgets/ControlRoomPanel.h"
#include "widgets/EventLogWidget.h"
#include "widgets/FleetListWidget.h"
#include "widgets/PassCountPanel.h"
#include "widgets/SiteMapView.h"

#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QLabel>
#include <QPointer>
#include <QStandardPaths>
#include <QStatusBar>
#include <QSysInfo>
#include <QTime>
#include <QTimer>
#include <QVBoxLayout>

namespace ocu {

struct SiteRuntime::Impl {
    GeoFrame frame;
    std::unique_ptr<sim::SimulatedSite> sim;
    FleetContext* ctx = nullptr;
    OwnPosition* own = nullptr;
    OperatorSession* session = nullptr;
    std::vector<std::unique_ptr<ProtocolModule>> modules = makeProtocolModules();
    recording::Recorder* recorder = nullptr;        // the flight recorder of this run
    PgHistory* history = nullptr;                   // the shared control-room history, when configured
    ControlRoomModel* room = nullptr;               // who is where, read from it
    std::unique_ptr<HardwareStopButton> stopButton; // site configuration `stop_button`
    QPointer<EarlyStopPress> earlyPress;            // the window's STOP ALL press, off the GUI thread
    QStringList startProblems;
    bool stopped = false;

    // The site map: what the bridges offer, in module order.
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
    // The pass-count layer: the first bridge that offers one.
    const PassCountLayer* passLayer() const {
        for (const auto& m : modules)
            if (FleetBridge* b = m->bridge(); b && b->passCountLayer())
                return b->passCountLayer();
        return nullptr;
    }

    // populate(), in its steps.
    void addModulePanels(MainWindow& window) const;
    SiteMapView* populateFleetAndMap(MainWindow& window, const SiteConfig& config, SiteRuntime* q) const;
    QObject* populate3D(MainWindow& window, const SiteConfig& config) const;
    void populateModules(MainWindow& window, const SiteConfig& config, PassCountPanel* passCounts) const;
    void connectPassCounts(PassCountPanel* panel, SiteMapView* map, QObject* feed) const;
    void connectBridges(MainWindow& window, SiteMapView* map, PassCountPanel* passPanel, QObject* feed,
                        SiteRuntime* q) const;
    void connectAlarmsAndStops(MainWindow& window) const;
    void addControlRoomPanel(MainWindow& window) const;
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
    for (const auto& m : d.modules)
        m->addPermissions(d.ctx->gate()->permissions());
    const OperatorIdentity who = identityOf(QString::fromStdString(currentOsUser().name));
    d.session = new OperatorSession(
        d.ctx->gate(), d.ctx->fleet(), d.ctx->alarms(),
        [](const QString& user, const QString& password) {
            return QString::fromStdString(
                PamAuthenticator().authenticate(user.toStdString(), password.toStdString()));
        },
        [this](const QString& user) { return identityOf(user); }, this);
    d.session->setOperator(who);
    d.session->setIdleLockMs(int(m_config.roles.lockAfterIdleS * 1000));
    startRecorder();
    startControlRoomHistory();
    // After the recorder and the history start, so that both keep who opened the console.
    d.ctx->gate()->auditSession(QStringLiteral("sign_in"), who, true, tr("console started"));

    // A stack that cannot start (port taken, bad URL) does not stop the console: its link shows down and the
    // reason is an alarm.
    for (const auto& m : d.modules) {
        const QString e = m->start({m_config, d.frame, d.ctx, this,
                                    d.recorder ? d.recorder->messageTap() : nullptr, &d.startProblems,
                                    m_config.roles.configured ? m_config.roles.authorityOf(who.role) : -1});
        if (!e.isEmpty())
            d.startProblems << e;
    }
    if (d.history) { // who is here, and the addresses the stacks just started control machines with
        QStringList addresses;
        for (const auto& m : d.modules)
            addresses << m->controllerAddresses();
        d.history->attachSession(d.session, addresses);
    }
    // After the stacks: the button's first press may come at once (a latched button).
    if (m_config.stopButton)
        d.stopButton = std::make_unique<HardwareStopButton>(
            m_config.stopButton->device, m_config.stopButton->button, d.ctx->gate(), d.ctx->alarms());
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
        // The pass counts: the grid now, then its changes (at most once a second).
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
    if (!e.isEmpty()) {
        d.startProblems << tr("Control-room history: %1").arg(e);
        return;
    }
    d.history = history;
    d.room = new ControlRoomModel(this);
    d.room->setThisConsole(hc.console);
    connect(history, &PgHistory::roomChanged, d.room, &ControlRoomModel::setRoom);
}

// The console's name in audit lines and the shared history: the history's console name, else the host's.
static QString consoleName(const SiteConfig& config) {
    if (config.historyPostgres && !config.historyPostgres->console.empty())
        return QString::fromStdString(config.historyPostgres->console);
    return QSysInfo::machineHostName();
}

OperatorIdentity SiteRuntime::identityOf(const QString& user) const {
    const std::string name = user.toStdString();
    return {user, m_config.roles.roleOf(name, groupsOfUser(name)), consoleName(m_config)};
}

OperatorIdentity SiteRuntime::operatorIdentity() const {
    return m_impl->ctx ? m_impl->ctx->gate()->operatorIdentity() : OperatorIdentity{};
}

OperatorSession* SiteRuntime::operatorSession() const {
    return m_impl->session;
}

void SiteRuntime::stop() {
    Impl& d = *m_impl;
    if (d.stopped)
        return;
    d.stopped = true;
    if (d.ctx) // after the last command of this run could be given, before the recorder and the history stop
        d.ctx->gate()->auditSession(QStringLiteral("sign_out"), d.ctx->gate()->operatorIdentity(), true,
                                    tr("console closed"));
    d.stopButton.reset(); // its thread calls the bridges: gone before they are
    delete d.earlyPress;  // likewise
    // Stacks first (a stack may still send, e.g. release its control), then the simulators.
    for (const auto& m : d.modules)
        m->stop();
    if (d.sim)
        d.sim->stop();
    if (d.recorder)
        d.recorder->stop(); // commits what is queued and closes the file
    if (d.history)
        d.history->stop(); // leaves the room (a clean exit) and sends the sign-out
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

[[maybe_unused]] static QWidget* notice(const QString& text) { // a build without the 3D view
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
    d.addModulePanels(window);
    SiteMapView* map = d.populateFleetAndMap(window, m_config, this);
    QObject* feed = d.populate3D(window, m_config);

    auto* passPanel = new PassCountPanel;
    passPanel->setLayer(d.passLayer());
    d.addControlRoomPanel(window);
    d.populateModules(window, m_config, passPanel);
    if (d.passLayer()) {
        window.setPanelWidget(Panel::PassCounts, passPanel);
    } else { // no protocol of this site counts passes: no pass-count panel anywhere
        window.removePanel(MainWindow::panelKey(Panel::PassCounts));
        passPanel->setParent(&window);
        passPanel->hide();
    }
    d.connectPassCounts(passPanel, map, feed);
    d.connectBridges(window, map, passPanel, feed, this);
    d.connectAlarmsAndStops(window);
    d.earlyPress = new EarlyStopPress(window, d.ctx->gate());
    if (d.session)
        new OperatorUi(window, d.session);
    for (const QString& p : std::as_const(d.startProblems))
        window.statusBar()->showMessage(p, 15000);
}

// The panels and the link indicator of each protocol the site runs (in module order), what STOP ALL reaches
// and the protocols of this build for Help › About. A protocol the site does not run shows nothing.
void SiteRuntime::Impl::addModulePanels(MainWindow& window) const {
    QStringList reach, about;
    for (const auto& m : modules) {
        about << m->aboutName();
        if (!m->bridge())
            continue;
        window.addPanels(m->panels());
        window.addLinkIndicator(m->displayName());
        if (const QString r = m->stopAllReach(); !r.isEmpty())
            reach << r;
    }
    window.setStopAllReach(reach);
    window.setAboutProtocols(about);
}

SiteMapView* SiteRuntime::Impl::populateFleetAndMap(MainWindow& window, const SiteConfig& config,
                                                    SiteRuntime* q) const {
    auto* list = new FleetListWidget(ctx->fleet(), ctx->selection());
    list->setCommandGate(ctx->gate());
    window.setPanelWidget(Panel::Fleet, list);

    auto* map = new SiteMapView;
    map->setFleet(ctx->fleet(), ctx->selection());
    map->setGeoFrame(frame);
    map->setSiteMap(mergedMap());
    map->setPassCountLayer(passLayer());
    window.setPanelWidget(Panel::SiteMap, map);
    connect(list, &FleetListWidget::centerOnMapRequested, map, &SiteMapView::centerOnMachine);
    connect(map, &SiteMapView::contextMenuRequested, list, &FleetListWidget::showContextMenu);
    connect(own, &OwnPosition::fixChanged, map, &SiteMapView::setOwnFix);
    // Frame the whole site once the first machines have arrived (unless the operator has taken over).
    QTimer::singleShot(1500, map, [map] { map->refitIfAuto(); });
    // The background raster named by the site (the simulated pit's hillshade by default).
    if (!config.background.raster.empty()) {
        AlarmModel* alarms = ctx->alarms();
        connect(map, &SiteMapView::backgroundFailed, q, [alarms](const QString& msg) {
            qCWarning(lcApp).noquote() << "map background:" << msg;
            alarms->add(makeEvent(EventSeverity::Warning, EventKind::Info, {},
                                  tr("Map background not shown: %1").arg(msg), QStringLiteral("gui")));
        });
        map->loadBackground(QString::fromStdString(config.background.raster));
    }
    return map;
}

// The 3D view and its feed (nullptr without the 3D view).
QObject* SiteRuntime::Impl::populate3D(MainWindow& window, const SiteConfig& config) const {
#ifdef OCU_HAVE_OCU_VIEW3D
    auto* view3d = new Site3DView;
    auto* feed = new Site3DFeed(view3d, ctx->fleet(), ctx->selection(), view3d);
    feed->setPassCountLayer(passLayer());
    if (!config.terrain.dem.empty()) {
        auto dem = loadTerrainDem(config.terrain.dem, frame);
        if (dem)
            feed->setTerrain(dem.value());
        else
            ctx->alarms()->add(
                makeEvent(EventSeverity::Warning, EventKind::Diagnostic, {},
                          tr("3D terrain not shown: %1").arg(QString::fromStdString(dem.error())),
                          QStringLiteral("gui")));
    }
    window.setPanelWidget(Panel::Site3D, view3d);
    return feed;
#else
    (void)config;
    window.setPanelWidget(Panel::Site3D,
                          notice(tr("This build has no 3D view (configured with OCU_WITH_VTK=OFF).")));
    return nullptr;
#endif
}

// The panels of the protocols the site runs.
void SiteRuntime::Impl::populateModules(MainWindow& window, const SiteConfig& config,
                                        PassCountPanel* passCounts) const {
    for (const auto& m : modules)
        if (m->bridge())
            m->populate({window, ctx, config, passCounts, room});
}

// The control room (who is at which console), with the shared history only.
void SiteRuntime::Impl::addControlRoomPanel(MainWindow& window) const {
    if (!room)
        return;
    const PanelSpec spec = controlRoomPanel();
    window.addPanels({spec});
    auto* panel = new ControlRoomPanel(room);
    if (history->isConnected()) // else "waiting" until it says
        panel->setConnected(true);
    connect(history, &PgHistory::connectionChanged, panel, &ControlRoomPanel::setConnected);
    window.setPanelWidget(spec.key, panel);
}

PanelSpec SiteRuntime::controlRoomPanel() {
    PanelSpec spec;
    spec.key = QStringLiteral("room");
    spec.title = QCoreApplication::translate("ocu::MainWindow", "Control room");
    spec.scrolls = false; // a table: it elides
    spec.kind = PanelKind::ControlRoom;
    return spec;
}

// The pass-count panel's palette and target on the 2D map, and on the 3D surface cell for cell.
void SiteRuntime::Impl::connectPassCounts(PassCountPanel* panel, SiteMapView* map, QObject* feed) const {
    connect(panel, &PassCountPanel::paletteChanged, map, &SiteMapView::setPassPalette);
    connect(panel, &PassCountPanel::targetChanged, map, &SiteMapView::setPassTarget);
#ifdef OCU_HAVE_OCU_VIEW3D
    auto* f = static_cast<Site3DFeed*>(feed);
    f->setPassPalette(map->passPalette());
    f->setPassTarget(map->passTarget());
    connect(panel, &PassCountPanel::paletteChanged, f, &Site3DFeed::setPassPalette);
    connect(panel, &PassCountPanel::targetChanged, f, &Site3DFeed::setPassTarget);
#else
    (void)feed;
#endif
}

// Each bridge's site map and pass counts into the views, its link into its indicator; data age per protocol.
void SiteRuntime::Impl::connectBridges(MainWindow& window, SiteMapView* map, PassCountPanel* passPanel,
                                       QObject* feed, SiteRuntime* q) const {
    for (const auto& module : modules) {
        FleetBridge* b = module->bridge();
        if (!b)
            continue;
        connect(b, &FleetBridge::siteMapChanged, map, [q, map, feed] {
            const SiteMapData m = q->m_impl->mergedMap();
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
        if (!ind)
            continue;
        ind->watchBridge(b); // reject counters per link in its details
        // A standing condition of the stack (e.g. a missing group socket); the stacks started in start(),
        // before the window is filled.
        ind->setNote(b->statusNote());
        connect(b, &FleetBridge::linkChanged, ind, [ind](const LinkStatus& s) {
            ind->setState(indicatorState(s.state),
                          s.link + (s.detail.isEmpty() ? QString() : ": " + s.detail));
            if (s.dataAgeMs >= 0)
                ind->setDataAgeMs(s.dataAgeMs);
        });
    }
#ifndef OCU_HAVE_OCU_VIEW3D
    (void)feed;
#endif
    // Data age per protocol from the newest machine data, refreshed every second.
    auto* ages = new QTimer(&window);
    QHash<Protocol, LinkIndicator*> indicators;
    for (const auto& m : modules)
        indicators.insert(m->protocol(), window.linkIndicator(m->displayName()));
    FleetContext* fleetContext = ctx;
    connect(ages, &QTimer::timeout, &window, [fleetContext, indicators] {
        QHash<Protocol, qint64> newest;
        for (const MachineState& m : fleetContext->fleet()->machinesSnapshot())
            newest[m.protocol] = std::max(newest.value(m.protocol, 0), m.lastDataMs);
        const qint64 now = fleetContext->fleet()->nowMs();
        for (auto it = newest.begin(); it != newest.end(); ++it)
            if (LinkIndicator* ind = indicators.value(it.key()); ind && it.value() > 0)
                ind->setDataAgeMs(std::max<qint64>(0, now - it.value()));
    });
    ages->start(1000);
}

// The event log and the alarm count, STOP ALL, and the red banner of a stop that did not reach everything.
void SiteRuntime::Impl::connectAlarmsAndStops(MainWindow& window) const {
    FleetContext* c = ctx;
    window.setPanelWidget(Panel::EventLog, new EventLogWidget(c->alarms()));
    connect(c->alarms(), &AlarmModel::unacknowledgedCountChanged, &window,
            &MainWindow::setUnacknowledgedAlarms);
    window.setUnacknowledgedAlarms(c->alarms()->unacknowledgedCount());
    connect(&window, &MainWindow::stopAllRequested, c->gate(),
            [c] { c->gate()->stopAll(QStringLiteral("gui")); });
    if (HardwareStopButton* button = stopButton.get()) {
        // Its own words: "down" beside a button would read as "pressed".
        auto* lamp = new QLabel(&window);
        lamp->setObjectName(QStringLiteral("label-stop-button"));
        auto show = [lamp, button](bool up, const QString& device) {
            const QString dot = up ? QStringLiteral("#2e7d32") : QStringLiteral("#c62828");
            lamp->setText(QStringLiteral("<span style='color:%1'>&#9679;</span> %2")
                              .arg(dot, up ? SiteRuntime::tr("STOP button ready")
                                           : SiteRuntime::tr("STOP button not connected")));
            lamp->setToolTip(
                up ? SiteRuntime::tr("%1: %2 triggers STOP ALL").arg(device, button->description())
                   : SiteRuntime::tr("No device with %1 is connected; STOP ALL stays on F12, "
                                     "Ctrl+Shift+Space and the toolbar")
                         .arg(button->description()));
        };
        show(button->connected(), button->deviceName());
        connect(button, &HardwareStopButton::connectionChanged, lamp, show);
        window.addStatusWidget(lamp);
    }
    // A stop that did not reach every target, or that a machine did not confirm, is shown loudly until the
    // operator dismisses it or a later STOP ALL reaches everything.
    QPointer<MainWindow> win(&window);
    connect(c->gate(), &CommandGate::stopFinished, &window, [win](const CommandResult& r, const QString&) {
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
    connect(c->gate(), &CommandGate::stopUnconfirmed, &window, [win](const QString&, const QString& text) {
        if (!win)
            return;
        const QString line = QTime::currentTime().toString(QStringLiteral("HH:mm:ss ")) + text;
        win->showStopBanner(win->stopBannerVisible() ? win->stopBannerText() + QLatin1Char('\n') + line
                                                     : line);
    });
}

HeadlessMonitor* SiteRuntime::attachHeadless(QIODevice* out) {
    Impl& d = *m_impl;
    HeadlessMonitor* mon = HeadlessMonitor::attach(d.ctx, out);
    for (const auto& m : d.modules)
        m->registerHeadless(mon->commands());
    return mon;
}

int SiteRuntime::runHeadless(QApplication& app, double durationSeconds, const QString& commandSocket) {
    HeadlessMonitor* mon = attachHeadless();
    mon->setRateLimitMs(static_cast<int>(1000.0 / m_config.fleet.monitorRateHz));
    std::unique_ptr<HeadlessCommandSocket> socket;
    if (!commandSocket.isEmpty()) {
        socket = std::make_unique<HeadlessCommandSocket>(mon);
        QString error;
        if (!socket->listen(commandSocket, error)) {
            std::fprintf(stderr, "ocu: %s\n", qPrintable(error));
            return 2;
        }
    }
    if (!mon->startStdin() && durationSeconds <= 0 && !socket) {
        std::fputs("ocu: --headless reads commands from stdin, which is not readable; give --duration\n",
                   stderr);
        return 2;
    }
    if (durationSeconds > 0)
        QTimer::singleShot(static_cast<int>(durationSeconds * 1000), &app, &QApplication::quit);
    else if (!socket) // a service's stdin is /dev/null: with a socket, only a signal ends the run
        connect(mon, &HeadlessMonitor::inputFinished, &app, &QApplication::quit);
    const int rc = execUnlessQuitting(app); // SIGINT/SIGTERM quit as end of input does
    mon->stopStdin();                       // no early stop through the bridges once they are being torn down
    socket.reset();                         // no command arrives while the stacks stop
    stop();
    return rc;
}

QJsonObject SiteRuntime::writeShiftReport(const QString& pdf, const QString& csv) {
    const ShiftReportRequest r{pdf, csv, std::nullopt, QString::fromStdString(m_config.name)};
    for (const auto& m : m_impl->modules)
        if (ProductionModel* model = m->production())
            return ocu::writeShiftReport(model, m->bridge(), m_impl->ctx->fleet(), r);
    return ocu::writeShiftReport(nullptr, nullptr, m_impl->ctx->fleet(), r);
}

} // namespace ocu
