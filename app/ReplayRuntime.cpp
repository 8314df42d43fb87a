#include "app/ReplayRuntime.h"

#include "app/ConsoleApp.h"
#include "app/HeadlessMonitor.h"
#include "app/HeadlessReplay.h"
#include "app/MainWindow.h"
#include "app/ProtocolModule.h"
#include "app/Screenshot.h"
#ifdef OCU_HAVE_OCU_VIEW3D
#include "app/Site3DFeed.h"
#include "widgets/view3d/Site3DView.h"
#endif
#include "models/AlarmModel.h"
#include "models/FleetModel.h"
#include "models/FleetSelection.h"
#include "models/recording/ReplayController.h"
#include "protocols/common/GeoFrame.h"
#include "widgets/EventLogWidget.h"
#include "widgets/FleetListWidget.h"
#include "widgets/PassCountPanel.h"
#include "widgets/ReplayTimeline.h"
#include "widgets/SiteMapView.h"

#include <QAction>
#include <QApplication>
#include <QDateTime>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QPushButton>
#include <QShortcut>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>

#include <cstdio>

namespace ocu {

using recording::Recording;
using recording::ReplayController;

namespace {

QString utc(qint64 ms) {
    return QDateTime::fromMSecsSinceEpoch(ms, Qt::UTC).toString(QStringLiteral("yyyy-MM-dd HH:mm:ss"));
}

QWidget* replayNotice(const QString& text) {
    auto* l = new QLabel(text);
    l->setAlignment(Qt::AlignCenter);
    l->setWordWrap(true);
    l->setMargin(20);
    return l;
}

LinkIndicator::State replayIndicatorState(LinkState s) {
    switch (s) {
    case LinkState::Up:
        return LinkIndicator::State::Up;
    case LinkState::Degraded:
    case LinkState::Unknown:
        return LinkIndicator::State::Degraded;
    case LinkState::Down:
        break;
    }
    return LinkIndicator::State::Down;
}

// The protocol's name for the operator, as its module says it (the recording's key when this build has none).
QString protocolLabel(const QString& protocol) {
    for (const auto& m : makeProtocolModules())
        if (toText(m->protocol()) == protocol)
            return m->displayName();
    return protocol;
}

int fail(const QString& msg) {
    std::fprintf(stderr, "ocu: %s\n", qPrintable(msg));
    return 2;
}

// Event log widget for the controller's current alarm model; commands (acknowledging) are off in a replay.
EventLogWidget* eventLog(AlarmModel* alarms) {
    auto* w = new EventLogWidget(alarms);
    w->ackButton()->setEnabled(false);
    w->ackAllButton()->setEnabled(false);
    w->ackButton()->setToolTip(QCoreApplication::translate("Replay", "Replay: acknowledgements are replayed, "
                                                                     "not made"));
    return w;
}

} // namespace

namespace {

// The banner, impossible to mistake a replay for the live site, and STOP ALL greyed out.
void addReplayBanner(MainWindow& window, const Recording* rec) {
    auto* banner = new QToolBar(QCoreApplication::translate("Replay", "Replay"), &window);
    banner->setObjectName(QStringLiteral("replayBanner"));
    banner->setMovable(false);
    auto* bannerLabel = new QLabel(banner);
    bannerLabel->setObjectName(QStringLiteral("replayBannerLabel"));
    bannerLabel->setText(QCoreApplication::translate("Replay",
                                                     "REPLAY — %1 — recorded %2 to %3 UTC — not live, "
                                                     "commands disabled")
                             .arg(QFileInfo(rec->path()).fileName(), utc(rec->startMs()), utc(rec->endMs())));
    bannerLabel->setStyleSheet(
        QStringLiteral("QLabel { background: #7b1fa2; color: white; font-weight: bold; "
                       "font-size: 15px; padding: 6px 14px; }"));
    bannerLabel->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
    banner->addWidget(bannerLabel);
    window.addToolBarBreak(Qt::TopToolBarArea);
    window.addToolBar(Qt::TopToolBarArea, banner);

    // STOP ALL stays visible (the layout operators know) but does nothing in a replay.
    window.stopAllAction()->setEnabled(false);
    window.stopAllAction()->setToolTip(
        QCoreApplication::translate("Replay", "Replay: commands are disabled"));
    if (window.stopAllButton()) {
        window.stopAllButton()->setEnabled(false);
        window.stopAllButton()->setStyleSheet(
            QStringLiteral("QToolButton { background: #9e9e9e; color: #eeeeee; }"));
    }
}

// The timeline under the panels, and its keys.
void addTimeline(MainWindow& window, ReplayController* c) {
    const Recording* rec = c->recording();
    auto* bar = new QToolBar(QCoreApplication::translate("Replay", "Timeline"), &window);
    bar->setObjectName(QStringLiteral("replayTimelineBar"));
    bar->setMovable(false);
    auto* timeline = new ReplayTimeline(bar);
    timeline->setObjectName(QStringLiteral("replayTimeline"));
    timeline->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
    bar->addWidget(timeline);
    window.addToolBar(Qt::BottomToolBarArea, bar);
    timeline->setRange(rec->startMs(), rec->endMs());
    QVector<TimelineMarker> markers;
    for (const recording::Marker& m : rec->markers())
        markers.push_back({m.t, m.kind == recording::Marker::Kind::Command, m.bad, m.text});
    timeline->setMarkers(markers);
    const qint64 start = rec->startMs();
    timeline->setTimeParser([start](const QString& s) { return recording::parseReplayTime(s, start); });
    QObject::connect(timeline, &ReplayTimeline::seekRequested, c, &ReplayController::seek);
    QObject::connect(timeline, &ReplayTimeline::playToggled, c, &ReplayController::togglePlay);
    QObject::connect(timeline, &ReplayTimeline::speedRequested, c, &ReplayController::setSpeed);
    QObject::connect(timeline, &ReplayTimeline::reverseRequested, c, &ReplayController::setReverse);
    QObject::connect(timeline, &ReplayTimeline::stepRequested, c, &ReplayController::step);
    QObject::connect(c, &ReplayController::positionChanged, timeline, &ReplayTimeline::setPosition);
    QObject::connect(c, &ReplayController::playingChanged, timeline, &ReplayTimeline::setPlaying);
    QObject::connect(c, &ReplayController::speedChanged, timeline, &ReplayTimeline::setSpeed);
    QObject::connect(c, &ReplayController::reverseChanged, timeline, &ReplayTimeline::setReverse);
    timeline->setPosition(c->position());
    timeline->setSpeed(c->speed());

    // Keys: Space, + / -, Left / Right (Shift: 10 s), Home / End.
    auto key = [&window](const QKeySequence& k, auto fn) {
        auto* s = new QShortcut(k, &window);
        s->setContext(Qt::WindowShortcut);
        QObject::connect(s, &QShortcut::activated, &window, fn);
    };
    key(QKeySequence(Qt::Key_Space), [c] { c->togglePlay(); });
    key(QKeySequence(Qt::Key_Plus), [c] { c->faster(); });
    key(QKeySequence(Qt::Key_Equal), [c] { c->faster(); });
    key(QKeySequence(Qt::Key_Minus), [c] { c->slower(); });
    key(QKeySequence(Qt::Key_Right), [c] { c->step(+1); });
    key(QKeySequence(Qt::Key_Left), [c] { c->step(-1); });
    key(QKeySequence(Qt::SHIFT | Qt::Key_Right), [c] {
        c->pause();
        c->moveTo(c->position() + 10000);
    });
    key(QKeySequence(Qt::SHIFT | Qt::Key_Left), [c] {
        c->pause();
        c->moveTo(c->position() - 10000);
    });
    key(QKeySequence(Qt::Key_Home), [c] { c->seek(c->startMs()); });
    key(QKeySequence(Qt::Key_End), [c] { c->seek(c->endMs()); });
}

// Link indicators: one per protocol the recording has links of.
void addLinkIndicators(MainWindow& window, ReplayController* c) {
    const Recording* rec = c->recording();
    QHash<QString, LinkIndicator*> indicators;
    for (const recording::RecordedLink& l : rec->links(std::numeric_limits<qint64>::min(), rec->endMs()))
        if (!indicators.contains(l.protocol))
            indicators.insert(l.protocol, window.addLinkIndicator(protocolLabel(l.protocol)));
    auto showLink = [indicators](const recording::RecordedLink& l) {
        if (LinkIndicator* ind = indicators.value(l.protocol)) {
            ind->setState(replayIndicatorState(l.state),
                          l.link + (l.detail.isEmpty() ? QString() : ": " + l.detail));
            if (l.dataAgeMs >= 0)
                ind->setDataAgeMs(l.dataAgeMs);
        }
    };
    QObject::connect(c, &ReplayController::linkChanged, &window, showLink);
    auto showLinks = [showLink](const QVector<recording::RecordedLink>& links) {
        for (const auto& l : links)
            showLink(l);
    };
    QObject::connect(c, &ReplayController::linksReset, &window, showLinks);
    showLinks(rec->linksAt(c->position()));
}

struct ReplayViews {
    SiteMapView* map = nullptr;
    FleetSelection* selection = nullptr;
#ifdef OCU_HAVE_OCU_VIEW3D
    Site3DFeed* feed = nullptr;
#endif
};

// The fleet list, the 2D map, the 3D view and the event log, on the replayed models.
ReplayViews addViews(MainWindow& window, ReplayController* c) {
    const Recording* rec = c->recording();
    FleetModel* fleet = c->fleet();
    auto* selection = new FleetSelection(fleet, &window);
    auto* list = new FleetListWidget(fleet, selection); // no command gate: no commands
    window.setPanelWidget(Panel::Fleet, list);
    GeoPoint origin;
    origin.lat = rec->meta(QStringLiteral("origin_lat")).toDouble();
    origin.lon = rec->meta(QStringLiteral("origin_lon")).toDouble();
    origin.alt = rec->meta(QStringLiteral("origin_alt")).toDouble();
    auto* map = new SiteMapView;
    map->setFleet(fleet, selection);
    map->setGeoFrame(GeoFrame(origin));
    map->setSiteMap(rec->siteMapAt(c->position()));
    window.setPanelWidget(Panel::SiteMap, map);
    QObject::connect(list, &FleetListWidget::centerOnMapRequested, map, &SiteMapView::centerOnMachine);
#ifdef OCU_HAVE_OCU_VIEW3D
    auto* view3d = new Site3DView;
    auto* feed = new Site3DFeed(view3d, fleet, selection, view3d);
    feed->setSiteMap(rec->siteMapAt(c->position()));
    window.setPanelWidget(Panel::Site3D, view3d);
#endif
    QObject::connect(c, &ReplayController::siteMapChanged, map,
                     [map
#ifdef OCU_HAVE_OCU_VIEW3D
                      ,
                      feed
#endif
    ](const SiteMapData& m) {
                         map->setSiteMap(m);
#ifdef OCU_HAVE_OCU_VIEW3D
                         feed->setSiteMap(m);
#endif
                         map->fitToContent();
                     });
    QTimer::singleShot(0, map, [map] { map->fitToContent(); });
    window.setPanelWidget(Panel::EventLog, eventLog(c->alarms()));
    QObject::connect(c, &ReplayController::alarmsReplaced, &window, [&window](AlarmModel* a) {
        window.setPanelWidget(Panel::EventLog, eventLog(a));
        window.setUnacknowledgedAlarms(a->unacknowledgedCount());
        QObject::connect(a, &AlarmModel::unacknowledgedCountChanged, &window,
                         &MainWindow::setUnacknowledgedAlarms);
    });
    QObject::connect(c->alarms(), &AlarmModel::unacknowledgedCountChanged, &window,
                     &MainWindow::setUnacknowledgedAlarms);
    window.setUnacknowledgedAlarms(c->alarms()->unacknowledgedCount());
#ifdef OCU_HAVE_OCU_VIEW3D
    return {map, selection, feed};
#else
    return {map, selection};
#endif
}

// The pass counts as they were at the replay time (overlay on the map, the panel's histogram, the 3D
// surface).
void addPassCounts(MainWindow& window, ReplayController* c, const ReplayViews& v) {
    const Recording* rec = c->recording();
    SiteMapView* map = v.map;
#ifdef OCU_HAVE_OCU_VIEW3D
    Site3DFeed* feed = v.feed;
#endif
    if (rec->hasPassCounts()) {
        auto* passPanel = new PassCountPanel;
        passPanel->setLayer(c->passCounts());
        map->setPassCountLayer(c->passCounts());
        window.setPanelWidget(Panel::PassCounts, passPanel);
        QObject::connect(passPanel, &PassCountPanel::paletteChanged, map, &SiteMapView::setPassPalette);
        QObject::connect(passPanel, &PassCountPanel::targetChanged, map, &SiteMapView::setPassTarget);
        QObject::connect(c, &ReplayController::passCountsChanged, map,
                         [map, passPanel, shown = c->passCounts()](const PassCountLayer* layer) mutable {
                             if (layer != shown) { // a new grid
                                 shown = layer;
                                 map->setPassCountLayer(layer);
                                 passPanel->setLayer(layer);
                             } else {
                                 map->passCountChanged();
                                 passPanel->layerChanged();
                             }
                         });
#ifdef OCU_HAVE_OCU_VIEW3D
        // The 3D surface too, in the 2D map's palette and target.
        feed->setPassCountLayer(c->passCounts());
        feed->setPassPalette(map->passPalette());
        feed->setPassTarget(map->passTarget());
        QObject::connect(passPanel, &PassCountPanel::paletteChanged, feed, &Site3DFeed::setPassPalette);
        QObject::connect(passPanel, &PassCountPanel::targetChanged, feed, &Site3DFeed::setPassTarget);
        QObject::connect(c, &ReplayController::passCountsChanged, feed, [feed](const PassCountLayer* layer) {
            feed->setPassCountLayer(layer); // marks it dirty; a new revision or grid is pushed
        });
#endif
    } else {
        window.setPanelWidget(Panel::PassCounts, replayNotice(QCoreApplication::translate(
                                                     "Replay", "This recording holds no pass "
                                                               "counts.")));
    }
}

} // namespace

void populateReplayWindow(MainWindow& window, ReplayController* c) {
    // The protocol modules' panels, as in the live console, each saying that commands are off.
    const QString off =
        QCoreApplication::translate("Replay", "Replay: commands are disabled. This panel acts on "
                                              "live machines only.");
    const auto modules = makeProtocolModules();
    for (const auto& m : modules) {
        window.addPanels(m->panels());
        for (const PanelSpec& p : m->panels())
            window.setPanelWidget(p.key, replayNotice(off));
    }
    addReplayBanner(window, c->recording());
    addTimeline(window, c);
    addLinkIndicators(window, c);
    const ReplayViews views = addViews(window, c);
    addPassCounts(window, c, views);
    // The modules' views of their own records (a vehicle's mission), on the same map and selection.
    const GeoFrame frame(GeoPoint{c->recording()->meta(QStringLiteral("origin_lat")).toDouble(),
                                  c->recording()->meta(QStringLiteral("origin_lon")).toDouble(),
                                  c->recording()->meta(QStringLiteral("origin_alt")).toDouble()});
    for (const auto& m : modules)
        m->populateReplay({window, c, views.selection, views.map, frame});
}

static int runExports(const Recording& rec, const CommandLineOptions& o) {
    const qint64 from =
        o.exportFrom.isEmpty() ? rec.startMs() : recording::parseReplayTime(o.exportFrom, rec.startMs());
    const qint64 to =
        o.exportTo.isEmpty() ? rec.endMs() : recording::parseReplayTime(o.exportTo, rec.startMs());
    if (from < 0 || to < 0)
        return fail(QCoreApplication::translate("Replay", "--from/--to: not a time"));
    QString err;
    auto toFile = [&](const QString& path, auto fn) {
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate)) {
            err = QStringLiteral("%1: %2").arg(path, f.errorString());
            return false;
        }
        return fn(&f);
    };
    if (!o.exportJsonl.isEmpty() &&
        !toFile(o.exportJsonl, [&](QIODevice* d) { return rec.exportJsonLines(d, from, to, &err); }))
        return fail(err);
    if (!o.exportCsv.isEmpty() &&
        !toFile(o.exportCsv, [&](QIODevice* d) { return rec.exportCsv(d, from, to, &err); }))
        return fail(err);
    if (!o.exportSlice.isEmpty() && !rec.exportSlice(o.exportSlice, from, to, &err))
        return fail(err);
    return 0;
}

int runReplay(QApplication& app, const CommandLineOptions& options) {
    QString err;
    auto rec = Recording::open(options.replayFile, &err);
    if (!rec)
        return fail(err);
    if (!options.exportJsonl.isEmpty() || !options.exportCsv.isEmpty() || !options.exportSlice.isEmpty())
        return runExports(*rec, options);
    qint64 at = rec->startMs();
    if (!options.replayAt.isEmpty()) {
        at = recording::parseReplayTime(options.replayAt, rec->startMs());
        if (at < 0)
            return fail(
                QCoreApplication::translate("Replay", "--at: \"%1\" is not a time").arg(options.replayAt));
    }
    FleetModel fleet;
    ReplayController controller(rec.get(), &fleet);
    controller.seek(at);

    if (options.headless) {
        QFile out;
        if (!out.open(stdout, QIODevice::WriteOnly | QIODevice::Unbuffered))
            return fail(QStringLiteral("stdout: %1").arg(out.errorString()));
        HeadlessReplay replay(&controller, &out);
        replay.monitor().startStdin(); // queries ("list") answered from the replayed state
        if (!options.replaySpeedSet || options.replaySpeed <= 0) {
            replay.runToEnd(100, [] { return quitSignal() != 0; });
            return 0;
        }
        controller.setSpeed(options.replaySpeed);
        QObject::connect(&controller, &ReplayController::finished, &app, &QApplication::quit);
        if (options.durationSeconds > 0)
            QTimer::singleShot(int(options.durationSeconds * 1000), &app, &QApplication::quit);
        controller.play();
        return execUnlessQuitting(app);
    }

    MainWindow window;
    window.setWindowTitle(QCoreApplication::translate("Replay", "Operator Control Unit — REPLAY %1")
                              .arg(QFileInfo(options.replayFile).fileName()));
    populateReplayWindow(window, &controller);
    const bool screenshot = !options.screenshotFile.isEmpty();
    window.resize(screenshot ? options.size : QSize(1600, 1000));
    if (options.replaySpeedSet)
        controller.setSpeed(options.replaySpeed);
    window.show();
    if (screenshot) {
        int exitCode = 0;
        QTimer::singleShot(static_cast<int>(options.settleSeconds * 1000), &window, [&] {
            const QString e = saveScreenshot(window, options.view, options.screenshotFile);
            if (!e.isEmpty()) {
                std::fprintf(stderr, "ocu: screenshot failed: %s\n", qPrintable(e));
                exitCode = 4;
            }
            app.quit();
        });
        execUnlessQuitting(app);
        return exitCode;
    }
    return execUnlessQuitting(app);
}

} // namespace ocu
