#include "app/MainWindow.h"
#include "app/ProtocolModule.h"
#include "app/SiteLoader.h"
#include "app/SiteRuntime.h"
#include "app/WorkspaceBar.h"
#include "models/AlarmModel.h"
#include "models/CommandGate.h"
#include "models/FleetContext.h"
#include "models/FleetModel.h"
#include "protocols/osyris/OsyrisStack.h"

#include <QAction>
#include <QDockWidget>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QScreen>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QToolBar>
#include <QToolButton>
#include <QTranslator>
#include <QVBoxLayout>
#include <QtTest>

#include <atomic>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/udp.hpp>

using namespace ocu;

namespace {
// An OSYRIS station of the test on the console's group: counts the STOP texts that reach the wire.
struct StopTexts : osyris::OsyrisListener {
    std::atomic<int> stops{0};
    void onText(std::uint8_t, const std::string& text) override {
        if (text.find("STOP ALL") != std::string::npos)
            ++stops;
    }
};

// The panels the protocol modules of this build add to the window.
QList<PanelSpec> modulePanels() {
    QList<PanelSpec> out;
    for (const auto& m : makeProtocolModules())
        out += m->panels();
    return out;
}

// The panels without a Ctrl shortcut: reached through View › Go to panel (none today; a module may add one).
const QStringList kWithoutDigit{};

// The Ctrl+N of a panel, from its go-to action.
QKeySequence goShortcut(const MainWindow& w, const QString& key) {
    auto* a = w.findChild<QAction*>(QStringLiteral("action-go-") + key);
    return a ? a->shortcut() : QKeySequence();
}
} // namespace

namespace {
// A bridge with two links whose stacks counted rejects.
struct CountingBridge : ocu::FleetBridge {
    CountingBridge() : FleetBridge(ocu::Protocol::Iso23725) {}
    ocu::Counters first, second;
    QVector<ocu::LinkCounters> linkCounters() const override {
        return {ocu::LinkCounters::of(QStringLiteral("iso23725:ahs-1"), first),
                ocu::LinkCounters::of(QStringLiteral("iso23725:ahs-2"), second)};
    }
    void stopAll(ocu::OutcomeCallback done) override { done({}); }
    void stopMachine(const QString&, ocu::OutcomeCallback done) override { done({}); }
    void clearStop(const QString&, ocu::OutcomeCallback done) override { done({}); }
};
} // namespace

class TestMainWindow : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true); // QSettings go to a test location
        QCoreApplication::setOrganizationName("OCU-test");
        QCoreApplication::setApplicationName("test_main_window");
    }
    // The real window's STOP ALL, clicked and by its shortcut, puts the stop on the wire of all
    // three protocols. JAUS and ISO 23725: the simulated machines report the stop (which they only do after
    // receiving SetEmergency / all-stop Apply); OSYRIS: a station of the test receives the STOP text.
    void stopAllButtonAndShortcutReachTheWire() {
        auto site = loadSite({});
        QVERIFY(site.ok());
        SiteConfig cfg = std::move(site.value());
        cfg.simulation.ahsTrucks = 2;
        SiteRuntime runtime(cfg);
        runtime.start();
        MainWindow window;
        runtime.populate(window);
        window.resize(1366, 768);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        auto* fleet = runtime.findChild<FleetModel*>();
        auto* gate = runtime.findChild<CommandGate*>();
        QVERIFY(fleet && gate);
        QVERIFY(runtime.config().osyris);

        StopTexts texts;
        osyris::OsyrisConfig listen = *runtime.config().osyris;
        listen.stationIndex = 201;
        listen.sqlitePath.clear();
        osyris::OsyrisStack station(listen, texts);
        std::string err;
        QVERIFY2(station.start(&err), err.c_str());

        auto machinesOf = [&](Protocol p) {
            QStringList ids;
            for (const auto& m : fleet->machinesSnapshot())
                if (m.protocol == p && m.link == LinkState::Up)
                    ids << m.id;
            return ids;
        };
        auto allStopped = [&](Protocol p) {
            const auto all = fleet->machinesSnapshot();
            int n = 0;
            for (const auto& m : all)
                if (m.protocol == p) {
                    if (m.stop != StopState::Stopped)
                        return false;
                    ++n;
                }
            return n > 0;
        };
        // Every machine known and running, the OSYRIS station heard (otherwise the stop text is refused).
        QTRY_VERIFY_WITH_TIMEOUT(machinesOf(Protocol::Jaus).size() >= 2 &&
                                     machinesOf(Protocol::Iso23725).size() >= 2 &&
                                     machinesOf(Protocol::Osyris).size() >= 2,
                                 30000);
        QTRY_VERIFY_WITH_TIMEOUT(!allStopped(Protocol::Iso23725) && !allStopped(Protocol::Jaus), 30000);

        QSignalSpy finished(gate, &CommandGate::stopFinished);
        QTest::mouseClick(window.stopAllButton(), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 20000);
        const auto first = finished.first().at(0).value<CommandResult>();
        QVERIFY2(first.ok, qPrintable(first.message));
        QTRY_VERIFY_WITH_TIMEOUT(allStopped(Protocol::Jaus), 20000);
        QTRY_VERIFY_WITH_TIMEOUT(allStopped(Protocol::Iso23725), 20000);
        QTRY_COMPARE_WITH_TIMEOUT(texts.stops.load(), 1, 20000);
        QVERIFY(!window.stopBannerVisible());

        // Release everything (deliberately, with tokens), wait until the machines report running again.
        for (const QString& id : machinesOf(Protocol::Jaus) + machinesOf(Protocol::Iso23725).mid(0, 1))
            gate->clearStop(id, gate->requestClearToken(id), QStringLiteral("test"));
        QTRY_VERIFY_WITH_TIMEOUT(
            [&] {
                for (const auto& m : fleet->machinesSnapshot())
                    if (m.protocol != Protocol::Osyris && m.stop == StopState::Stopped)
                        return false;
                return true;
            }(),
            30000);

        // The keyboard shortcut (F12) does the same.
        finished.clear();
        QTest::keyClick(&window, Qt::Key_F12);
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 20000);
        QVERIFY(finished.first().at(0).value<CommandResult>().ok);
        QTRY_VERIFY_WITH_TIMEOUT(allStopped(Protocol::Jaus), 20000);
        QTRY_VERIFY_WITH_TIMEOUT(allStopped(Protocol::Iso23725), 20000);
        QTRY_COMPARE_WITH_TIMEOUT(texts.stops.load(), 2, 20000);
        station.stop();

        // With the stacks gone nothing can be sent; the window says so loudly, naming each
        // target.
        // Before the stop the link indicators showed the stacks up; once the runtime stopped them they show
        // down, said by the stack's own state (not the last report of a link that no longer exists).
        for (const char* p : {"JAUS", "ISO 23725", "OSYRIS"})
            QTRY_COMPARE_WITH_TIMEOUT(window.linkIndicator(p)->state(), LinkIndicator::State::Up, 10000);
        runtime.stop();
        for (const char* p : {"JAUS", "ISO 23725", "OSYRIS"}) {
            QTRY_COMPARE_WITH_TIMEOUT(window.linkIndicator(p)->state(), LinkIndicator::State::Down, 5000);
            QVERIFY2(window.linkIndicator(p)->toolTip().contains(QLatin1String("stopped")),
                     qPrintable(window.linkIndicator(p)->toolTip()));
        }
        finished.clear();
        QTest::mouseClick(window.stopAllButton(), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 20000);
        QVERIFY(!finished.first().at(0).value<CommandResult>().ok);
        QTRY_VERIFY_WITH_TIMEOUT(window.stopBannerVisible(), 20000);
        QVERIFY(window.stopBannerBar()->isVisible());
        for (const char* what : {"jaus", "iso23725 link", "osyris group"})
            QVERIFY2(window.stopBannerText().contains(QLatin1String(what)),
                     qPrintable(window.stopBannerText()));
        // Screenshots for people (OCU_SCREENSHOT_DIR): the failed-stop banner at two window sizes.
        const QString shots = qEnvironmentVariable("OCU_SCREENSHOT_DIR");
        if (!shots.isEmpty())
            for (QSize size : {QSize(1366, 768), QSize(1920, 1080)}) {
                window.resize(size);
                QTest::qWait(300);
                window.grab().save(QStringLiteral("%1/stop-banner-%2x%3.png")
                                       .arg(shots)
                                       .arg(size.width())
                                       .arg(size.height()));
            }
    }

    // A stop that does not reach everything is shown in a red banner naming what was missed,
    // which stays until dismissed or a later full STOP ALL.
    void failedStopShowsBannerUntilDismissedOrFullSuccess() {
        MainWindow window;
        window.resize(1366, 768);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(!window.stopBannerVisible());
        QVERIFY(!window.stopBannerBar()->isVisible());
        window.showStopBanner(QStringLiteral("STOP ALL did NOT reach: iso23725 link ahs: link ahs is down"));
        QVERIFY(window.stopBannerBar()->isVisible());
        auto* label = window.findChild<QLabel*>(QStringLiteral("label-stop-banner"));
        QVERIFY(label && label->text().contains(QStringLiteral("iso23725 link ahs")));
        window.resetLayout(); // a layout change never hides it
        QVERIFY(window.stopBannerBar()->isVisible());
        auto* dismiss = window.findChild<QPushButton*>(QStringLiteral("button-dismiss-stop-banner"));
        QVERIFY(dismiss);
        QTest::mouseClick(dismiss, Qt::LeftButton);
        QVERIFY(!window.stopBannerVisible());
        QVERIFY(!window.stopBannerBar()->isVisible());
    }

    void everyPanelIsADock() {
        MainWindow w;
        QCOMPARE(w.panelKeys(), QStringList({"fleet", "map", "3d", "passcounts", "events"}));
        w.addPanels(modulePanels());
        QCOMPARE(w.panelKeys().size(), 5 + modulePanels().size());
        QStringList titles;
        for (const QString& key : w.panelKeys()) {
            QDockWidget* d = w.dock(key);
            QVERIFY(d);
            QCOMPARE(d->objectName(), QStringLiteral("dock-") + key); // the name saved layouts keep
            QVERIFY(d->features() & QDockWidget::DockWidgetClosable);
            QVERIFY(d->features() & QDockWidget::DockWidgetMovable);
            titles << d->windowTitle();
        }
        if (makeProtocolModules().size() == 3) // every protocol: the panels in their Ctrl+N order
            QCOMPARE(titles, QStringList({"Fleet", "Site map (2D)", "Site 3D", "JAUS control", "Teleop",
                                          "Pass counts", "Event log", "Dispatch", "Production", "Video",
                                          "Mission", "Areas and reports", "Crew messages"}));
    }
    void stopAllAlwaysVisibleWithShortcut() {
        MainWindow w;
        w.resize(1200, 800);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.stopAllButton());
        QVERIFY(w.stopAllButton()->isVisible());
        QCOMPARE(w.stopAllAction()->shortcut(), QKeySequence(Qt::Key_F12));
        QCOMPARE(w.stopAllAction()->shortcutContext(), Qt::ApplicationShortcut);
        // The safety toolbar cannot be hidden, moved off or floated.
        auto* tb = w.findChild<QToolBar*>("toolbar-safety");
        QVERIFY(tb);
        QVERIFY(!tb->isMovable());
        QVERIFY(!tb->toggleViewAction()->isVisible());
        QSignalSpy spy(&w, &MainWindow::stopAllRequested);
        QTest::keyClick(&w, Qt::Key_F12);
        QCOMPARE(spy.count(), 1);
        QTest::mouseClick(w.stopAllButton(), Qt::LeftButton);
        QCOMPARE(spy.count(), 2);
        // Keyboard: focus the button and press Space.
        w.stopAllButton()->setFocus();
        QTest::keyClick(w.stopAllButton(), Qt::Key_Space);
        QCOMPARE(spy.count(), 3);
    }
    // STOP ALL acts on the press, not on the release: mouse button down, a touch landing, F12 or
    // Ctrl+Shift+Space going down, Space on the focused button going down. A release, and a held key's
    // auto-repeat, stop nothing more.
    void stopAllFiresOnPressAndKeyDown() {
        MainWindow w;
        w.resize(1200, 800);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QSignalSpy spy(&w, &MainWindow::stopAllRequested);
        QToolButton* b = w.stopAllButton();
        QTest::mousePress(b, Qt::LeftButton, {}, b->rect().center());
        QCOMPARE(spy.count(), 1);
        QTest::mouseRelease(b, Qt::LeftButton, {}, b->rect().center());
        QCOMPARE(spy.count(), 1);
        QTest::keyPress(&w, Qt::Key_F12);
        QCOMPARE(spy.count(), 2);
        QTest::keyRelease(&w, Qt::Key_F12);
        QTest::keyPress(&w, Qt::Key_Space, Qt::ControlModifier | Qt::ShiftModifier);
        QCOMPARE(spy.count(), 3);
        QTest::keyRelease(&w, Qt::Key_Space, Qt::ControlModifier | Qt::ShiftModifier);
        b->setFocus();
        QTest::keyPress(b, Qt::Key_Space);
        QCOMPARE(spy.count(), 4);
        QKeyEvent repeat(QEvent::KeyPress, Qt::Key_Space, Qt::NoModifier, QStringLiteral(" "), true);
        QApplication::sendEvent(b, &repeat);
        QCOMPARE(spy.count(), 4);
        QTest::keyRelease(b, Qt::Key_Space);
        QCOMPARE(spy.count(), 4);
        // A touch: the stop on the touch's landing, nothing on lifting the finger.
        QPointingDevice* touch = QTest::createTouchDevice();
        const QPoint at = b->mapTo(&w, b->rect().center());
        QTest::touchEvent(&w, touch).press(0, at, &w);
        QTRY_COMPARE(spy.count(), 5);
        QTest::touchEvent(&w, touch).release(0, at, &w);
        QCoreApplication::processEvents();
        QCOMPARE(spy.count(), 5);
    }
    // Ctrl+1 … Ctrl+8 raise each panel (also a closed one or a hidden tab) and put the keyboard
    // focus in it; the default layout gives the map most of a 1366 x 768 window.
    void keyboardPathToEveryPanel() {
        MainWindow w;
        w.addPanels(modulePanels());
        QMap<QString, QLineEdit*> edits;
        for (const QString& p : w.panelKeys()) {
            auto* box = new QWidget;
            auto* l = new QVBoxLayout(box);
            auto* label = new QLabel(w.panelTitle(p)); // takes no focus: the edit below gets it
            auto* edit = new QLineEdit;
            l->addWidget(label);
            l->addWidget(edit);
            edits.insert(p, edit);
            w.setPanelWidget(p, box);
        }
        w.resize(1366, 768);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QTRY_VERIFY(w.dock(Panel::SiteMap)->width() >= 1366 * 40 / 100);
        w.dock(Panel::EventLog)->close();
        for (const QString& p : w.panelKeys()) {
            const QKeySequence go = goShortcut(w, p);
            if (kWithoutDigit.contains(p)) { // its go-to action in the View menu
                QVERIFY2(go.isEmpty(), qPrintable(p));
                w.findChild<QAction*>(QStringLiteral("action-go-") + p)->trigger();
                QTRY_VERIFY2(edits[p]->isVisible(), qPrintable(w.panelTitle(p)));
                QTRY_VERIFY2(edits[p]->hasFocus(), qPrintable(w.panelTitle(p)));
                continue;
            }
            QVERIFY2(go.count() == 1 && (go[0].keyboardModifiers() & Qt::ControlModifier), qPrintable(p));
            QTest::keyClick(&w, go[0].key(), Qt::ControlModifier);
            QTRY_VERIFY2(edits[p]->isVisible(), qPrintable(w.panelTitle(p)));
            QTRY_VERIFY2(edits[p]->hasFocus(), qPrintable(w.panelTitle(p)));
        }
    }
    // Help › Keyboard shortcuts names every go-to-panel shortcut the window has, also one a
    // protocol module adds later (Ctrl+9 Production); it said "Ctrl+1 … Ctrl+7" while Ctrl+8 and Ctrl+9
    // existed.
    void helpListsEveryPanelShortcut() {
        MainWindow w;
        w.addPanels(modulePanels());
        auto* production = new QAction(QStringLiteral("Production"), &w);
        production->setObjectName(QStringLiteral("action-go-production"));
        production->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_9));
        w.addAction(production);
        const QString help = w.keyboardHelpText();
        for (const QString& p : w.panelKeys()) {
            if (kWithoutDigit.contains(p)) { // no Ctrl+N: its own keys are listed
                QVERIFY2(help.contains(w.panelTitle(p) + QStringLiteral(" panel:")), qPrintable(help));
                continue;
            }
            const QString line = QStringLiteral("%1: %2").arg(
                goShortcut(w, p).toString(QKeySequence::NativeText), w.panelTitle(p));
            QVERIFY2(help.contains(line), qPrintable(line + QStringLiteral(" missing in:\n") + help));
        }
        QVERIFY2(help.contains(QKeySequence(Qt::CTRL | Qt::Key_9).toString(QKeySequence::NativeText) +
                               QStringLiteral(": Production")),
                 qPrintable(help));
        QVERIFY(help.contains(QStringLiteral("STOP ALL")));
        QVERIFY(!help.contains(QStringLiteral("… Ctrl+7"))); // no hard-coded range
    }
    // The first start (no saved layout) opens maximized, at the screen's available size, not
    // at the widgets' size hint (1200 x 720 on a 1920 x 1080 screen).
    void firstStartFillsTheScreen() {
        MainWindow w;
        w.showFirstStart();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.screen());
        const QSize avail = w.screen()->availableGeometry().size();
        QTRY_VERIFY2(w.isMaximized() || w.frameGeometry().size() == avail,
                     qPrintable(QStringLiteral("%1x%2 on %3x%4")
                                    .arg(w.width())
                                    .arg(w.height())
                                    .arg(avail.width())
                                    .arg(avail.height())));
        QTRY_VERIFY(w.width() >= avail.width() * 95 / 100 && w.height() >= avail.height() * 90 / 100);
    }
    void closeAndReopenPanel() {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QDockWidget* d = w.dock(Panel::EventLog);
        QVERIFY(d->isVisible());
        d->close();
        QVERIFY(!d->isVisible());
        d->toggleViewAction()->trigger(); // View menu entry
        QVERIFY(d->isVisible());
    }
    void layoutIsSavedAndRestored() {
        // A module's panel too: its dock is added before the layout is restored, under the same name.
        const QString modulePanel = modulePanels().isEmpty() ? QString() : modulePanels().first().key;
        {
            MainWindow w;
            w.addPanels(modulePanels());
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            w.dock(Panel::PassCounts)->close();
            w.dock(Panel::Fleet)->setFloating(true);
            if (!modulePanel.isEmpty())
                w.dock(modulePanel)->close();
            w.saveLayout();
        }
        MainWindow w2;
        w2.addPanels(modulePanels());
        QVERIFY(w2.restoreLayout());
        w2.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w2));
        QVERIFY(!w2.dock(Panel::PassCounts)->isVisible());
        QVERIFY(w2.dock(Panel::Fleet)->isFloating());
        if (!modulePanel.isEmpty())
            QVERIFY(!w2.dock(modulePanel)->isVisible());
        w2.resetLayout();
        QVERIFY(w2.dock(Panel::PassCounts)->isVisible());
        QVERIFY(!w2.dock(Panel::Fleet)->isFloating());
        if (!modulePanel.isEmpty())
            QVERIFY(w2.dock(modulePanel)->isVisible());
    }
    // The workspace bar beside STOP ALL: a button per workspace the panels make worth offering, Alt+1 …
    // Alt+5 from anywhere, listed in Help; each workspace shows the panels of its kinds and no other; STOP
    // ALL stays visible and on F12 in every one.
    void workspaceBarSwitchesWorkspaces() {
        QSettings().clear();
        MainWindow w;
        w.addPanels(modulePanels());
        w.resize(1366, 768);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        auto* bar = w.findChild<QToolBar*>("toolbar-workspaces");
        QVERIFY(bar && bar->isVisible());
        // In STOP ALL's row: no height taken from the map.
        QCOMPARE(bar->geometry().top(), w.findChild<QToolBar*>("toolbar-safety")->geometry().top());
        QSignalSpy stops(&w, &MainWindow::stopAllRequested);
        const QString help = w.keyboardHelpText();
        int digit = 0, offered = 0;
        for (Workspace ws : kAllWorkspaces) {
            ++digit;
            const QKeySequence key(Qt::ALT | static_cast<Qt::Key>(Qt::Key_0 + digit));
            QCOMPARE(w.workspaceBar()->action(ws)->shortcut(), key);
            if (!w.offeredWorkspaces().contains(ws))
                continue;
            ++offered;
            const QString line =
                key.toString(QKeySequence::NativeText) + QStringLiteral(": ") + workspaceTitle(ws);
            QVERIFY2(help.contains(line), qPrintable(line + QStringLiteral(" missing in:\n") + help));
            QTest::keyClick(&w, static_cast<Qt::Key>(Qt::Key_0 + digit), Qt::AltModifier);
            QTRY_COMPARE(w.workspace(), ws);
            QVERIFY(w.workspaceBar()->action(ws)->isChecked());
            const WorkspacePlan plan = workspacePlan(ws);
            const QList<PanelKind> kinds = plan.main + plan.sideTop + plan.sideBottom;
            for (const QString& p : w.panelKeys())
                QVERIFY2(w.dock(p)->toggleViewAction()->isChecked() == kinds.contains(w.panelKind(p)),
                         qPrintable(workspaceKey(ws) + QLatin1Char(' ') + p));
            QVERIFY(w.stopAllButton()->isVisible());
            QTest::keyClick(&w, Qt::Key_F12);
            QCOMPARE(stops.count(), offered);
            // A panel of another workspace still comes on its Ctrl+N, in this workspace.
            if (!w.dock(Panel::Fleet)->toggleViewAction()->isChecked()) {
                QTest::keyClick(&w, Qt::Key_1, Qt::ControlModifier);
                QTRY_VERIFY(w.dock(Panel::Fleet)->isVisible());
                QCOMPARE(w.workspace(), ws);
            }
        }
        QVERIFY(offered >= 3); // Compaction (the pass counts), Monitor, All
    }
    // The role chooses the first workspace.
    void roleChoosesTheFirstWorkspace() {
        QCOMPARE(firstWorkspaceFor(OperatorRole::Monitor), Workspace::Monitor);
        QCOMPARE(firstWorkspaceFor(OperatorRole::Dispatcher), Workspace::Dispatch);
        QCOMPARE(firstWorkspaceFor(OperatorRole::SiteManager), Workspace::Compaction);
        QCOMPARE(firstWorkspaceFor(OperatorRole::UgvOperator), Workspace::Ugv);
        QCOMPARE(firstWorkspaceFor(OperatorRole::Supervisor), Workspace::All);
        QCOMPARE(firstWorkspaceFor(OperatorRole::Admin), Workspace::All);
        QSettings().clear();
        MainWindow w;
        w.addPanels(modulePanels());
        w.setOperator(QStringLiteral("mona"), Workspace::Monitor);
        QCOMPARE(w.workspace(), Workspace::Monitor);
        // A role's workspace this site does not offer (no panel of its kinds): All.
        MainWindow bare;
        bare.removePanel(MainWindow::panelKey(Panel::PassCounts));
        QVERIFY(!bare.offeredWorkspaces().contains(Workspace::Compaction));
        bare.setOperator(QStringLiteral("sam"), Workspace::Compaction);
        QCOMPARE(bare.workspace(), Workspace::All);
        QVERIFY(!bare.workspaceBar()->action(Workspace::Compaction)->isVisible());
    }
    // Each person's arrangement of each workspace comes back for them on the next start, per screen set-up:
    // a dock closed and a dock floated (onto a second screen, say) stay so; another person starts from the
    // default; View › Reset workspace puts the default back.
    void arrangementKeptPerPersonAndScreenSetup() {
        QSettings().clear();
        {
            MainWindow w;
            w.addPanels(modulePanels());
            w.setOperator(QStringLiteral("alice"), Workspace::Monitor);
            QCOMPARE(w.workspace(), Workspace::Monitor);
            w.resize(1366, 768);
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            w.dock(Panel::Fleet)->setFloating(true);
            w.setWorkspace(Workspace::All);
            QVERIFY(!w.dock(Panel::Fleet)->isFloating()); // All's own arrangement
            w.dock(Panel::EventLog)->close();
            w.close(); // saves
        }
        const QString group = QStringLiteral("workspaces/alice/") + MainWindow::screenSetupKey();
        QVERIFY(QSettings().contains(group + QStringLiteral("/monitor/state")));
        QVERIFY(QSettings().contains(group + QStringLiteral("/all/state")));
        {
            MainWindow w;
            w.addPanels(modulePanels());
            w.setOperator(QStringLiteral("alice"), Workspace::Monitor);
            QVERIFY(w.restoreLayout());
            QCOMPARE(w.workspace(), Workspace::All); // where she left
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            QVERIFY(!w.dock(Panel::EventLog)->isVisible());
            w.setWorkspace(Workspace::Monitor);
            QTRY_VERIFY(w.dock(Panel::Fleet)->isFloating());
            w.resetLayout();
            QVERIFY(!w.dock(Panel::Fleet)->isFloating());
            QVERIFY(w.dock(Panel::Fleet)->isVisible());
        }
        {
            MainWindow w;
            w.addPanels(modulePanels());
            w.setOperator(QStringLiteral("bob"), Workspace::Monitor);
            QVERIFY(!w.restoreLayout());
            QCOMPARE(w.workspace(), Workspace::Monitor);
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            QVERIFY(!w.dock(Panel::Fleet)->isFloating());
            QVERIFY(w.dock(Panel::EventLog)->isVisible());
        }
    }
    // A switch of operator at a running console keeps the previous person's arrangement and shows the next
    // person's (their last workspace, else their role's).
    void switchOfOperatorShowsTheirArrangement() {
        QSettings().clear();
        MainWindow w;
        w.addPanels(modulePanels());
        w.setOperator(QStringLiteral("alice"), Workspace::All);
        w.resize(1366, 768);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QTRY_VERIFY(w.dock(Panel::Fleet)->isVisible());
        w.dock(Panel::Fleet)->close();
        w.setOperator(QStringLiteral("bob"), Workspace::Monitor);
        QCOMPARE(w.workspace(), Workspace::Monitor);
        QTRY_VERIFY(w.dock(Panel::Fleet)->isVisible());
        w.setOperator(QStringLiteral("alice"), Workspace::Monitor);
        QCOMPARE(w.workspace(), Workspace::All);
        QVERIFY(!w.dock(Panel::Fleet)->isVisible());
    }
    void nightPalette() {
        MainWindow w;
        const QColor day = qApp->palette().color(QPalette::Window);
        w.setNightMode(true);
        const QColor night = qApp->palette().color(QPalette::Window);
        QVERIFY(night.lightness() < 80);
        QVERIFY(day != night);
        w.setNightMode(false);
        QVERIFY(qApp->palette().color(QPalette::Window).lightness() > 150);
    }
#ifdef OCU_SITE_HAVE_JAUS
    // The JAUS port held by another process without SO_REUSEADDR (a node manager): the console starts, the
    // status bar says "JAUS: no group socket (<port> held by another process)" beside the JAUS lamp, and the
    // event log has the warning with the reason.
    void heldJausPortIsShownInTheStatusBar() {
        namespace asio = boost::asio;
        asio::io_context io;
        asio::ip::udp::socket nodeManager(io);
        nodeManager.open(asio::ip::udp::v4());
        // The wildcard, as node managers bind: only that collides with the console's group-address bind.
        nodeManager.bind(asio::ip::udp::endpoint(asio::ip::address_v4::any(), 0));
        const quint16 held = nodeManager.local_endpoint().port();
        SiteConfig cfg;
        cfg.simulation.enabled = false;
        jaus::JausConfig j;
        j.transport.bindAddress = "127.0.0.1";
        j.transport.port = 0;
        j.transport.multicastPort = held;
        j.transport.multicastTtl = 0;
        j.transport.interfaceAddress = "127.0.0.1";
        cfg.jaus = j;
        SiteRuntime runtime(cfg);
        runtime.start();
        MainWindow window;
        runtime.populate(window);
        LinkIndicator* ind = window.linkIndicator(QStringLiteral("JAUS"));
        QVERIFY(ind);
        QCOMPARE(ind->note(), QStringLiteral("JAUS: no group socket (%1 held by another process)").arg(held));
        auto* note = ind->findChild<QLabel*>(QStringLiteral("link-note"));
        QVERIFY(note && !note->isHidden());
        QCOMPARE(note->text(), ind->note());
        AlarmModel* alarms = runtime.findChild<FleetContext*>()->alarms();
        auto warned = [alarms] {
            int n = 0;
            for (int r = 0; r < alarms->rowCount(); ++r)
                n += alarms->eventAt(r).text.contains(QStringLiteral("no group socket")) ? 1 : 0;
            return n;
        };
        QTRY_COMPARE_WITH_TIMEOUT(warned(), 1, 10000);
        // Translated like the other status texts.
        auto* bridge = runtime.findChild<FleetBridge*>();
        QVERIFY(bridge);
        for (const auto& [lang, text] :
             {std::pair{"de", "JAUS: kein Gruppen-Socket (Port %1 von einem anderen Prozess belegt)"},
              std::pair{"fr", "JAUS : pas de socket de groupe (port %1 occupé par un autre processus)"}}) {
            QTranslator t;
            QVERIFY(t.load(QStringLiteral(":/i18n/ocu_%1.qm").arg(QLatin1String(lang))));
            QCoreApplication::installTranslator(&t);
            QCOMPARE(bridge->statusNote(), QString::fromUtf8(text).arg(held));
            QCoreApplication::removeTranslator(&t);
        }
        runtime.stop();
    }
#endif
    void linkDetailsShowRejectCounters() {
        // The link details (the indicator's tooltip) show each link's rejected input by reason,
        // taken from the bridge every second.
        CountingBridge bridge;
        bridge.first.add("rx.rejected.invalid_json", 2);
        bridge.first.add("rx.out_of_standard");
        bridge.first.add("rx.frames", 40); // not a reject
        LinkIndicator ind(QStringLiteral("ISO 23725"));
        ind.setState(LinkIndicator::State::Up, QStringLiteral("iso23725:ahs-1: connected"));
        ind.watchBridge(&bridge);
        const QString d = ind.details();
        QVERIFY2(d.contains(QStringLiteral("iso23725:ahs-1: 3 inputs rejected")), qPrintable(d));
        QVERIFY2(d.contains(QStringLiteral("rejected.invalid_json: 2")), qPrintable(d));
        QVERIFY2(d.contains(QStringLiteral("out_of_standard: 1")), qPrintable(d));
        QVERIFY2(!d.contains(QStringLiteral("frames")), qPrintable(d));
        QVERIFY2(d.contains(QStringLiteral("iso23725:ahs-2: no input rejected")), qPrintable(d));
        bridge.second.add("rx.implausible.speed");
        QTRY_VERIFY_WITH_TIMEOUT(ind.details().contains(QStringLiteral("iso23725:ahs-2: 1 inputs rejected")),
                                 10000);
        QVERIFY(ind.details().contains(QStringLiteral("implausible.speed: 1")));
    }
    void linkIndicatorsAndAlarms() {
        MainWindow w;
        // The runtime adds one indicator per protocol module.
        QVERIFY(!w.linkIndicator("JAUS"));
        for (const char* p : {"JAUS", "ISO 23725", "OSYRIS"}) {
            LinkIndicator* added = w.addLinkIndicator(p);
            QVERIFY(added);
            QCOMPARE(w.linkIndicator(p), added);
        }
        LinkIndicator* j = w.linkIndicator("JAUS");
        j->setState(LinkIndicator::State::Up);
        j->setDataAgeMs(1500);
        QVERIFY2(j->text().startsWith("JAUS up · 1.5 s"), qPrintable(j->text()));
        j->setState(LinkIndicator::State::Down);
        QVERIFY(j->text().startsWith("JAUS down"));
        // A standing condition of the stack beside the lamp (FleetBridge::statusNote), until cleared.
        auto* note = j->findChild<QLabel*>("link-note");
        QVERIFY(note);
        QVERIFY(note->isHidden());
        j->setNote(QStringLiteral("JAUS: no group socket (3794 held by another process)"));
        QCOMPARE(note->text(), QStringLiteral("JAUS: no group socket (3794 held by another process)"));
        QVERIFY(!note->isHidden());
        QVERIFY(j->details().contains(QStringLiteral("no group socket")));
        j->setNote({});
        QVERIFY(note->isHidden());
        w.setUnacknowledgedAlarms(3);
        auto* label = w.findChild<QLabel*>("label-alarms");
        QVERIFY(label->text().contains("3"));
        w.setUnacknowledgedAlarms(0);
        QCOMPARE(label->text(), QString("No unacknowledged alarms"));
    }
};

QTEST_MAIN(TestMainWindow)
#include "test_main_window.moc"
