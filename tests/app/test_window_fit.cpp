// Every workspace fits a field laptop: the whole console on the built-in simulated site, each workspace in
// its default arrangement, at 1366x768 and 1920x1080, in English and German, with the control-room panel (a
// control-room history configured) in the workspaces that show it. Checked from the real widgets:
// - the map (the video in the UGV workspace) gets at least 45 % of a 1366x768 window and 55 % of 1920x1080;
// - nothing in a dock scrolls sideways (a panel of controls would have its row cut at the dock's edge; the
//   tables and lists elide their long texts instead), on every tab of every dock of the workspace (each tab
//   raised in turn), and no button is narrower than its text;
// - the workspace shows the panels of its kinds and no other; STOP ALL stays visible;
// - the event log and the dispatch table show a useful number of rows where they are in front, the event
//   log's message column keeps its share of the width;
// - the UGV workspace's drive controls need no scrolling, with a row to spare, and its map is over 200 px
//   high;
// - a site without a protocol has none of its panels, in no workspace (the paving demo: no JAUS, no ISO
// 23725;
//   the built-in site without OSYRIS: no pass counts, no crew messages).
#include "app/LinkIndicator.h"
#include "app/MainWindow.h"
#include "app/SiteLoader.h"
#include "app/SiteRuntime.h"
#include "app/WorkspaceBar.h"

#include "models/AlarmModel.h"
#include "tests/support/BuiltProtocols.h"
#include "widgets/EventLogWidget.h"
#include "widgets/SiteMapView.h"
#ifdef OCU_TEST_WITH_JAUS
#include "widgets/jaus/TeleopVideoPane.h"
#endif

#include <QAbstractButton>
#include <QAbstractScrollArea>
#include <QAction>
#include <QDockWidget>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSet>
#include <QSettings>
#include <QStandardPaths>
#include <QTableView>
#include <QTemporaryDir>
#include <QToolButton>
#include <QTranslator>
#include <QtTest>

#include <algorithm>

using namespace ocu;

namespace {

// The site runs: every link indicator of the status bar shows its link up, so the simulators' machines
// are in the panels.
bool siteUp(MainWindow& w) {
    const QList<LinkIndicator*> links = w.findChildren<LinkIndicator*>();
    return !links.isEmpty() && std::all_of(links.begin(), links.end(), [](const LinkIndicator* l) {
        return l->state() == LinkIndicator::State::Up;
    });
}

// What the checks below read: the docks on screen, their panels' scroll ranges and their buttons.
QString layoutFingerprint(MainWindow& w) {
    QStringList parts;
    for (QDockWidget* d : w.findChildren<QDockWidget*>()) {
        if (!d->isVisible() || d->visibleRegion().isEmpty())
            continue;
        parts << QStringLiteral("%1 %2x%3").arg(d->objectName()).arg(d->width()).arg(d->height());
        for (QAbstractScrollArea* s : d->findChildren<QAbstractScrollArea*>())
            if (s->isVisible())
                parts << QString::number(s->horizontalScrollBar()->maximum());
        for (QAbstractButton* b : d->findChildren<QAbstractButton*>())
            if (b->isVisible())
                parts << QStringLiteral("%1 %2").arg(b->width()).arg(b->minimumSizeHint().width());
    }
    return parts.join(QLatin1Char(';'));
}

// The layout has settled once a pass of the event loop (posted layout requests, resizes, deferred shows)
// changes nothing the checks read.
bool layoutSettled(MainWindow& w) {
    const QString before = layoutFingerprint(w);
    QCoreApplication::sendPostedEvents();
    QCoreApplication::processEvents();
    return !before.isEmpty() && layoutFingerprint(w) == before;
}

// `dock` raised over its tab group: on screen and laid out.
bool raisedAndSettled(MainWindow& w, QDockWidget* dock) {
    return dock->isVisible() && !dock->visibleRegion().isEmpty() && layoutSettled(w);
}

// Waits until two samples of the layout agree. Not through QTRY_VERIFY: it evaluates its expression again
// after success, and a second pair of samples of a layout still settling can differ and fail the test.
bool waitSettled(MainWindow& w, QDockWidget* raised = nullptr, int timeoutMs = 10000) {
    return QTest::qWaitFor([&] { return raised ? raisedAndSettled(w, raised) : layoutSettled(w); },
                           timeoutMs);
}

// The console on a site (the built-in simulated site when file is empty), shown at `size`; the run's
// recording goes into a temporary directory, not into the home directory.
struct Console {
    QTemporaryDir recordings;
    std::unique_ptr<SiteRuntime> runtime;
    std::unique_ptr<MainWindow> window;
    // withRoom: with a control-room history (a database that is not there: the console works on its outbox),
    // so that the control-room panel is in its workspaces.
    QString open(QSize size, const QString& file = {}, bool withoutOsyris = false,
                 bool withRoom = false) { // empty on success
        auto site = loadSite(file);
        if (!site.ok() || !recordings.isValid())
            return QStringLiteral("site or temporary directory not available");
        SiteConfig cfg = std::move(site.value());
        cfg.record.dir = recordings.path().toStdString();
        if (withRoom)
            cfg.historyPostgres = PostgresHistoryConfig{
                "host=" + recordings.path().toStdString() + "/no-server port=1 user=ocu dbname=ocu",
                "fit-desk", recordings.filePath(QStringLiteral("outbox.sqlite")).toStdString()};
        if (withoutOsyris) {
#ifdef OCU_TEST_WITH_OSYRIS
            cfg.osyris.reset(); // a build without OSYRIS has no such section
#endif
            cfg.simulation.osyrisRollers = 0;
        }
        runtime = std::make_unique<SiteRuntime>(cfg);
        runtime->start();
        window = std::make_unique<MainWindow>();
        runtime->populate(*window);
        window->resize(size);
        window->show();
        return QTest::qWaitForWindowExposed(window.get()) ? QString() : QStringLiteral("window not exposed");
    }
    ~Console() {
        window.reset(); // before the runtime whose models it shows
        runtime.reset();
    }
};

// The table of a panel: the largest visible QTableView in it.
QTableView* mainTable(QWidget* panel) { // null: no such panel in this build
    QTableView* best = nullptr;
    if (!panel)
        return nullptr;
    for (QTableView* t : panel->findChildren<QTableView*>())
        if (t->isVisible() && (!best || t->height() > best->height()))
            best = t;
    return best;
}

int visibleRows(QTableView* t) {
    const int row = t->verticalHeader()->defaultSectionSize();
    return row > 0 ? t->viewport()->height() / row : 0;
}

// Problems of the docks now on screen: a scroll area (a panel, a table, a list, a text) that needs to scroll
// sideways, a table whose columns are wider than it, a button narrower than its text.
QStringList cutOff(MainWindow& w) {
    QStringList out;
    for (QDockWidget* d : w.findChildren<QDockWidget*>()) {
        if (!d->isVisible() || d->visibleRegion().isEmpty())
            continue;
        for (QAbstractScrollArea* s : d->findChildren<QAbstractScrollArea*>()) {
            if (!s->isVisible() || s->visibleRegion().isEmpty())
                continue;
            if (s->horizontalScrollBar()->maximum() > 0)
                out << QStringLiteral("%1: %2 %3 scrolls sideways by %4 px (dock %5 px wide)")
                           .arg(d->windowTitle(), QString::fromLatin1(s->metaObject()->className()),
                                s->objectName())
                           .arg(s->horizontalScrollBar()->maximum())
                           .arg(d->width());
            auto* t = qobject_cast<QTableView*>(s);
            if (t && t->horizontalHeader()->length() > t->viewport()->width())
                out << QStringLiteral("%1: table %2 scrolls sideways (columns %3 px, view %4 px)")
                           .arg(d->windowTitle(), t->objectName())
                           .arg(t->horizontalHeader()->length())
                           .arg(t->viewport()->width());
        }
        for (QAbstractButton* b : d->findChildren<QAbstractButton*>()) {
            if (!b->isVisible() || b->text().isEmpty() || b->visibleRegion().isEmpty())
                continue;
            if (b->width() + 1 < b->minimumSizeHint().width())
                out << QStringLiteral("%1: button \"%2\" %3 px < %4 px")
                           .arg(d->windowTitle(), b->text())
                           .arg(b->width())
                           .arg(b->minimumSizeHint().width());
        }
    }
    return out;
}

// The docks the workspace shows (open, whether in front of their tab group or behind another tab).
QList<QDockWidget*> shownDocks(MainWindow& w) {
    QList<QDockWidget*> out;
    for (const QString& key : w.panelKeys())
        if (QDockWidget* d = w.dock(key); d && d->toggleViewAction()->isChecked())
            out << d;
    return out;
}

QString keyOf(QDockWidget* d) {
    return d->objectName().mid(5); // "dock-<key>"
}

// The panel whose share of the window is checked: the video in the UGV workspace, else the map.
QWidget* mainView(MainWindow& w) {
#ifdef OCU_TEST_WITH_JAUS
    if (w.workspace() == Workspace::Ugv)
        return w.findChild<TeleopVideoPane*>();
#endif
    return w.panelWidget(Panel::SiteMap);
}

#ifdef OCU_TEST_WITH_JAUS
// The teleop panel's controls in the height their dock gives them, at its width, one row to spare.
QStringList teleopRoom(MainWindow& w) {
    QWidget* panel = w.panelWidget(QStringLiteral("teleop"));
    auto* scroll = w.dock(QStringLiteral("teleop"))->findChild<QScrollArea*>(QStringLiteral("panel-scroll"));
    if (!panel || !scroll || !panel->isVisible())
        return {QStringLiteral("ugv: teleop panel not in front")};
    // Measured with the video playing: while it is not, a line says that driving is held.
    auto* hold = panel->findChild<QLabel*>(QStringLiteral("label-video-watchdog"));
    if (!hold || !QTest::qWaitFor([&] { return !hold->isVisible() && layoutSettled(w); }, 10000))
        return {QStringLiteral("ugv: the video does not play")};
    const int width = scroll->viewport()->width();
    const int need = panel->hasHeightForWidth() ? panel->heightForWidth(width) : panel->sizeHint().height();
    // The lights bar is one of the rows: it must lie on a single row at this width.
    auto* lights = panel->findChild<QWidget*>(QStringLiteral("illumination-bar"));
    qInfo("  ugv: teleop controls need %dx%d, have %dx%d; lights bar %d px high", width, need, width,
          scroll->viewport()->height(), lights ? lights->height() : -1);
    QStringList out;
    if (need > scroll->viewport()->height())
        out << QStringLiteral("ugv: teleop controls need %1 px, have %2 px")
                   .arg(need)
                   .arg(scroll->viewport()->height());
    if (!lights)
        out << QStringLiteral("ugv: no lights bar in the teleop panel");
    else if (lights->height() > 2 * QPushButton(QStringLiteral("Lights")).sizeHint().height() - 4)
        out << QStringLiteral("ugv: the lights bar wraps (%1 px high)").arg(lights->height());
    if (scroll->verticalScrollBar()->maximum() > 0)
        out << QStringLiteral("ugv: teleop controls scroll by %1 px")
                   .arg(scroll->verticalScrollBar()->maximum());
    return out;
}
#endif

// The UGV workspace's map beside the video: at least this high (and twice as wide).
constexpr int kUgvMapMinHeight = 200;

// The checks of one workspace, in the window as it is now.
QStringList checkWorkspace(MainWindow& window, QSize size) {
    QStringList problems;
    const QString ws = workspaceKey(window.workspace());
    const bool small = size.height() < 900;

    // Only the panels of the workspace's kinds, and all of them.
    const WorkspacePlan plan = workspacePlan(window.workspace());
    const QList<PanelKind> kinds = plan.main + plan.sideTop + plan.sideBottom;
    QSet<QString> shown;
    for (QDockWidget* d : shownDocks(window)) {
        shown << keyOf(d);
        if (!kinds.contains(window.panelKind(keyOf(d))))
            problems << QStringLiteral("%1: panel %2 is not of this workspace").arg(ws, keyOf(d));
    }
    for (const QString& key : window.panelKeys())
        if (kinds.contains(window.panelKind(key)) && !shown.contains(key))
            problems << QStringLiteral("%1: panel %2 missing").arg(ws, key);
    if (!window.stopAllButton()->isVisible() || window.stopAllButton()->visibleRegion().isEmpty())
        problems << QStringLiteral("%1: STOP ALL not visible").arg(ws);

    // The map's (the video's) share of the window.
    QWidget* view = mainView(window);
    if (!view || !view->isVisible()) {
        problems << QStringLiteral("%1: no map / video on screen").arg(ws);
    } else {
        const double share = double(view->width()) * view->height() / (double(size.width()) * size.height());
        qInfo("  %s: %s %dx%d = %.1f %% of the window", qPrintable(ws), view->metaObject()->className(),
              view->width(), view->height(), share * 100);
        if (share < (small ? 0.45 : 0.55))
            problems << QStringLiteral("%1: %2 only %3x%4 (%5 %)")
                            .arg(ws, QString::fromLatin1(view->metaObject()->className()))
                            .arg(view->width())
                            .arg(view->height())
                            .arg(share * 100, 0, 'f', 1);
    }

#ifdef OCU_TEST_WITH_JAUS
    // Beside the video, the UGV operator's map is big enough to follow the vehicle's mission on.
    if (window.workspace() == Workspace::Ugv) {
        QWidget* map = window.panelWidget(Panel::SiteMap);
        qInfo("  ugv: map %dx%d", map ? map->width() : -1, map ? map->height() : -1);
        if (!map || !map->isVisible() || map->height() < kUgvMapMinHeight ||
            map->width() < 2 * kUgvMapMinHeight)
            problems << QStringLiteral("ugv: map only %1x%2")
                            .arg(map ? map->width() : -1)
                            .arg(map ? map->height() : -1);
    }
    // The drive controls in front of the UGV workspace need no scrolling, with one row to spare (a bar of
    // toggles beside the stop): the stop, the stick and the settings are in sight together.
    if (window.workspace() == Workspace::Ugv)
        problems << teleopRoom(window);
#endif

    // Rows of the tables in front.
    if (QTableView* events = mainTable(window.panelWidget(Panel::EventLog)); events && events->isVisible()) {
        const int rows = visibleRows(events);
        if (rows < (small ? 6 : 10))
            problems << QStringLiteral("%1: event log shows %2 rows").arg(ws).arg(rows);
        // The message gets the width the other columns leave, never less than its share.
        const int message = events->columnWidth(AlarmModel::ColText), all = events->viewport()->width();
        qInfo("  %s: event log message column %d of %d px", qPrintable(ws), message, all);
        if (message * 100 < all * EventLogWidget::kMessagePercent - all)
            problems
                << QStringLiteral("%1: event log message column %2 of %3 px").arg(ws).arg(message).arg(all);
    }
    if (QTableView* dispatch = mainTable(window.panelWidget(QStringLiteral("dispatch")));
        dispatch && dispatch->isVisible()) {
        const int rows = visibleRows(dispatch);
        if (rows < (small ? 4 : 8))
            problems << QStringLiteral("%1: dispatch table shows %2 rows").arg(ws).arg(rows);
    }

    // Every tab of the workspace, raised in turn.
    problems << cutOff(window);
    for (QDockWidget* d : shownDocks(window)) {
        d->raise();
        if (!QTest::qWaitFor([&] { return raisedAndSettled(window, d); }, 10000))
            problems << QStringLiteral("%1: %2 does not settle when raised").arg(ws, keyOf(d));
        problems << cutOff(window);
    }
    return problems;
}

void loadLanguage(QTranslator& tr, const QString& lang) {
    if (!lang.isEmpty() && tr.load(QStringLiteral(":/i18n/ocu_%1.qm").arg(lang)))
        QCoreApplication::installTranslator(&tr);
}

} // namespace

class TestWindowFit : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }
    // Each row starts from the default arrangements (a saved one of an earlier row or run would be restored).
    void init() { QSettings().clear(); }

    void everyWorkspaceFits_data() {
        QTest::addColumn<QSize>("size");
        QTest::addColumn<QString>("lang");
        QTest::newRow("1366x768 en") << QSize(1366, 768) << QString();
        QTest::newRow("1366x768 de") << QSize(1366, 768) << QStringLiteral("de");
        QTest::newRow("1920x1080 en") << QSize(1920, 1080) << QString();
        QTest::newRow("1920x1080 de") << QSize(1920, 1080) << QStringLiteral("de");
    }
    void everyWorkspaceFits() {
        QFETCH(QSize, size);
        QFETCH(QString, lang);
        QTranslator tr;
        loadLanguage(tr, lang);
        QVERIFY(lang.isEmpty() || !tr.isEmpty());
        Console console;
        const QString opened = console.open(size, {}, false, /*withRoom*/ true);
        QVERIFY2(opened.isEmpty(), qPrintable(opened));
        MainWindow& window = *console.window;
        QTRY_VERIFY_WITH_TIMEOUT(siteUp(window), 20000);
        QVERIFY(window.dock(QStringLiteral("room")));

        // The built-in site runs every protocol of the build: every workspace of it is offered.
        QList<Workspace> expected{Workspace::Monitor, Workspace::All};
        if (ocutest::kWithOsyris)
            expected.prepend(Workspace::Compaction);
        if (ocutest::kWithIso23725)
            expected.prepend(Workspace::Dispatch);
        if (ocutest::kWithJaus)
            expected.insert(expected.indexOf(Workspace::Monitor), Workspace::Ugv);
        QCOMPARE(window.offeredWorkspaces(), expected);

        QStringList problems;
        for (Workspace w : window.offeredWorkspaces()) {
            window.setWorkspace(w);
            QCOMPARE(window.workspace(), w);
            QVERIFY(waitSettled(window));
            problems << checkWorkspace(window, size);
        }
        problems.removeDuplicates();
        QCoreApplication::removeTranslator(&tr);
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QStringLiteral("\n"))));
    }

    // The paving demo runs OSYRIS only: no JAUS, ISO 23725 or their panels anywhere, and neither the Dispatch
    // nor the UGV workspace; its workspaces fit too.
    void pavingDemoHasNoPanelOfAnAbsentProtocol() {
        if (!ocutest::kWithOsyris)
            QSKIP("the paving demo runs OSYRIS");
        Console console;
        const QString opened = console.open(
            QSize(1366, 768), QStringLiteral(OCU_SOURCE_DIR "/resources/sites/paving-demo.json"));
        QVERIFY2(opened.isEmpty(), qPrintable(opened));
        MainWindow& window = *console.window;
        QTRY_VERIFY_WITH_TIMEOUT(siteUp(window), 20000);
        for (const char* absent : {"jaus", "teleop", "dispatch", "production"}) {
            QVERIFY2(!window.dock(QLatin1String(absent)), absent);
            QVERIFY2(!window.findChild<QDockWidget*>(QStringLiteral("dock-") + QLatin1String(absent)),
                     absent);
        }
        QCOMPARE(window.linkIndicator(QStringLiteral("JAUS")), nullptr);
        QCOMPARE(window.offeredWorkspaces(),
                 QList<Workspace>({Workspace::Compaction, Workspace::Monitor, Workspace::All}));
        QVERIFY(!window.workspaceBar()->action(Workspace::Ugv)->isVisible());
        QVERIFY(!window.workspaceBar()->action(Workspace::Dispatch)->isVisible());
        QStringList problems;
        for (Workspace w : window.offeredWorkspaces()) {
            window.setWorkspace(w);
            QVERIFY(waitSettled(window));
            problems << checkWorkspace(window, window.size());
        }
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QStringLiteral("\n"))));
    }

    // A site without OSYRIS: no pass counts, crew messages or areas, and no Compaction workspace.
    void siteWithoutOsyrisHasNoPassCounts() {
        if (!ocutest::kWithJaus && !ocutest::kWithIso23725)
            QSKIP("no other protocol in this build");
        Console console;
        const QString opened = console.open(QSize(1366, 768), {}, /*withoutOsyris*/ true);
        QVERIFY2(opened.isEmpty(), qPrintable(opened));
        MainWindow& window = *console.window;
        for (const char* absent : {"passcounts", "crew", "areas"})
            QVERIFY2(!window.dock(QLatin1String(absent)), absent);
        QVERIFY(!window.offeredWorkspaces().contains(Workspace::Compaction));
    }

#ifdef OCU_TEST_WITH_JAUS
    // A video nobody sees costs nothing: the video panel behind another tab wants no video (nothing received
    // or decoded) until its tab is raised, and again none once another tab is raised over it.
    void videoTabBehindAnotherWantsNoVideo() {
        Console console;
        const QString opened = console.open(QSize(1366, 768));
        QVERIFY2(opened.isEmpty(), qPrintable(opened));
        MainWindow& window = *console.window;
        QTRY_VERIFY_WITH_TIMEOUT(siteUp(window), 20000);
        QVERIFY(waitSettled(window));
        auto* pane = window.findChild<TeleopVideoPane*>();
        QVERIFY(pane);
        window.dock(QStringLiteral("jaus"))->raise();
        QVERIFY(waitSettled(window, window.dock(QStringLiteral("jaus"))));
        QVERIFY2(!pane->wantsVideo(), "video tab behind JAUS control wants video");
        window.dock(QStringLiteral("video"))->raise();
        QTRY_VERIFY_WITH_TIMEOUT(pane->wantsVideo(), 5000);
        window.dock(QStringLiteral("jaus"))->raise();
        QTRY_VERIFY_WITH_TIMEOUT(!pane->wantsVideo(), 5000);
    }
#endif
};

QTEST_MAIN(TestWindowFit)
#include "test_window_fit.moc"
