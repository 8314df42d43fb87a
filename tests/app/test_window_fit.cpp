// Panels that fit a field laptop: the whole console on the built-in simulated site, default
// layout, at 1366x768 and 1920x1080, in English and German. Checked from the real widgets:
// - the event log's table shows a useful number of rows (it showed three at 1366x768), the dispatch table
// too;
// - the 2D map keeps most of the window, the JAUS / teleop column is wide enough for its controls;
// - no panel of controls needs to scroll sideways (its controls' row is cut at the dock's edge otherwise), on
//   every tab of every dock (each tab raised in turn);
// - no button is narrower than its text.
#include "app/LinkIndicator.h"
#include "app/MainWindow.h"
#include "app/SiteLoader.h"
#include "app/SiteRuntime.h"

#include "tests/support/BuiltProtocols.h"
#include "widgets/SiteMapView.h"
#ifdef OCU_TEST_WITH_JAUS
#include "widgets/jaus/TeleopVideoPane.h"
#endif

#include <QAbstractButton>
#include <QDockWidget>
#include <QHeaderView>
#include <QScrollArea>
#include <QScrollBar>
#include <QStandardPaths>
#include <QTableView>
#include <QTemporaryDir>
#include <QTranslator>
#include <QtTest>

#include <algorithm>
#include <string_view>

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
        for (QScrollArea* s : d->findChildren<QScrollArea*>())
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

// The console on the built-in simulated site, shown at `size`; the run's recording goes into a temporary
// directory, not into the home directory.
struct BuiltInConsole {
    QTemporaryDir recordings;
    std::unique_ptr<SiteRuntime> runtime;
    std::unique_ptr<MainWindow> window;
    QString open(QSize size) { // empty on success, else why not
        auto site = loadSite({});
        if (!site.ok() || !recordings.isValid())
            return QStringLiteral("built-in site or temporary directory not available");
        SiteConfig cfg = std::move(site.value());
        cfg.record.dir = recordings.path().toStdString();
        runtime = std::make_unique<SiteRuntime>(cfg);
        runtime->start();
        window = std::make_unique<MainWindow>();
        runtime->populate(*window);
        window->resize(size);
        window->show();
        return QTest::qWaitForWindowExposed(window.get()) ? QString() : QStringLiteral("window not exposed");
    }
    ~BuiltInConsole() {
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

// Problems of the docks now on screen: a panel scroll area that needs to scroll sideways, a button narrower
// than its text.
QStringList cutOff(MainWindow& w) {
    QStringList out;
    for (QDockWidget* d : w.findChildren<QDockWidget*>()) {
        if (!d->isVisible() || d->visibleRegion().isEmpty())
            continue;
        for (QScrollArea* s : d->findChildren<QScrollArea*>()) {
            if (s->objectName() != QLatin1String("panel-scroll") && s->parentWidget() != d)
                continue;
            if (s->isVisible() && s->horizontalScrollBar()->maximum() > 0)
                out << QStringLiteral("%1 scrolls sideways by %2 px (dock %3 px wide)")
                           .arg(d->windowTitle())
                           .arg(s->horizontalScrollBar()->maximum())
                           .arg(d->width());
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

} // namespace

class TestWindowFit : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void defaultLayoutFits_data() {
        QTest::addColumn<QSize>("size");
        QTest::addColumn<QString>("lang");
        QTest::newRow("1366x768 en") << QSize(1366, 768) << QString();
        QTest::newRow("1366x768 de") << QSize(1366, 768) << QStringLiteral("de");
        QTest::newRow("1920x1080 en") << QSize(1920, 1080) << QString();
        QTest::newRow("1920x1080 de") << QSize(1920, 1080) << QStringLiteral("de");
    }
    void defaultLayoutFits() {
        QFETCH(QSize, size);
        QFETCH(QString, lang);
        QTranslator tr;
        if (!lang.isEmpty()) {
            QVERIFY(tr.load(QStringLiteral(":/i18n/ocu_%1.qm").arg(lang)));
            QCoreApplication::installTranslator(&tr);
        }
        BuiltInConsole console;
        const QString opened = console.open(size);
        QVERIFY2(opened.isEmpty(), qPrintable(opened));
        MainWindow& window = *console.window;
        QTRY_VERIFY_WITH_TIMEOUT(siteUp(window), 20000);
        QTRY_VERIFY_WITH_TIMEOUT(layoutSettled(window), 10000);

        QStringList problems;
        auto* map = qobject_cast<SiteMapView*>(window.panelWidget(Panel::SiteMap));
        QVERIFY(map);
        QTableView* events = mainTable(window.panelWidget(Panel::EventLog));
        QVERIFY(events);
        QTableView* dispatch = mainTable(window.panelWidget(QStringLiteral("dispatch")));
        const int eventRows = visibleRows(events);
        const int dispatchRows = dispatch ? visibleRows(dispatch) : -1;
        const int jausWidth = ocutest::kWithJaus ? window.dock(QStringLiteral("jaus"))->width() : -1;
        qInfo("%dx%d %s: map %dx%d, event rows %d, dispatch rows %d, fleet %d px, JAUS column %d px",
              size.width(), size.height(), qPrintable(lang.isEmpty() ? QStringLiteral("en") : lang),
              map->width(), map->height(), eventRows, dispatchRows, window.dock(Panel::Fleet)->width(),
              jausWidth);
        const bool small = size.height() < 900;
        if (eventRows < (small ? 6 : 10))
            problems << QStringLiteral("event log shows %1 rows").arg(eventRows);
        if (dispatch && dispatchRows < (small ? 4 : 8))
            problems << QStringLiteral("dispatch table shows %1 rows").arg(dispatchRows);
        if (map->width() < size.width() * 40 / 100 || map->height() < size.height() * 45 / 100)
            problems << QStringLiteral("map only %1x%2").arg(map->width()).arg(map->height());
        if (ocutest::kWithJaus && jausWidth < 340)
            problems << QStringLiteral("JAUS / teleop column %1 px").arg(jausWidth);

        // Every tab of every tabbed dock, raised in turn.
        problems << cutOff(window);
        for (const char* p : {"3d", "teleop", "passcounts"}) {
            QDockWidget* d = window.dock(QLatin1String(p));
            if (!d && !ocutest::kWithJaus && p == std::string_view("teleop"))
                continue; // the teleop panel is the JAUS module's
            QVERIFY2(d, p);
            d->raise();
            QTRY_VERIFY_WITH_TIMEOUT(raisedAndSettled(window, d), 10000);
            problems << cutOff(window);
        }
        for (QDockWidget* d : window.findChildren<QDockWidget*>())
            if (d->objectName() == QLatin1String("dock-production")) {
                d->raise();
                QTRY_VERIFY_WITH_TIMEOUT(raisedAndSettled(window, d), 10000);
                problems << cutOff(window);
            }
        problems.removeDuplicates();
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QStringLiteral("\n"))));
        if (!lang.isEmpty())
            QCoreApplication::removeTranslator(&tr);
    }

#ifdef OCU_TEST_WITH_JAUS
    // In the default layout the teleop panel is a tab behind "JAUS control". Nobody sees it there,
    // so its video pane must want no video (nothing received or decoded) until its tab is raised, and again
    // none once another tab is raised over it.
    void teleopTabBehindAnotherWantsNoVideo() {
        BuiltInConsole console;
        const QString opened = console.open(QSize(1366, 768));
        QVERIFY2(opened.isEmpty(), qPrintable(opened));
        MainWindow& window = *console.window;
        QTRY_VERIFY_WITH_TIMEOUT(siteUp(window), 20000);
        QTRY_VERIFY_WITH_TIMEOUT(layoutSettled(window), 10000);
        auto* pane = window.findChild<TeleopVideoPane*>();
        QVERIFY(pane);
        window.dock(QStringLiteral("jaus"))->raise();
        QTRY_VERIFY_WITH_TIMEOUT(raisedAndSettled(window, window.dock(QStringLiteral("jaus"))), 10000);
        QVERIFY2(!pane->wantsVideo(), "teleop tab behind JAUS control wants video");
        window.dock(QStringLiteral("teleop"))->raise();
        QTRY_VERIFY_WITH_TIMEOUT(pane->wantsVideo(), 5000);
        window.dock(QStringLiteral("jaus"))->raise();
        QTRY_VERIFY_WITH_TIMEOUT(!pane->wantsVideo(), 5000);
    }
#endif
};

QTEST_MAIN(TestWindowFit)
#include "test_window_fit.moc"
