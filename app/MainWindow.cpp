#include "app/MainWindow.h"

#include "app/Theme.h"
#include "widgets/StopAllButton.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileDialog>
#include <QFrame>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QResizeEvent>
#include <QScreen>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>
#include <QToolBar>
#include <QToolButton>
#include <QVBoxLayout>

namespace ocu {

namespace {
constexpr int kLayoutVersion = 1;

// The main panels with their Ctrl+N (docs/keyboard.md); the protocol modules' panels have 4, 5 and 8.
QList<PanelSpec> mainPanels() {
    const PanelPlace none = PanelPlace::SideColumn; // the main panels have their own places
    return {
        {MainWindow::panelKey(Panel::Fleet), MainWindow::tr("Fleet"), none, 1, false, false, {}},
        {MainWindow::panelKey(Panel::SiteMap), MainWindow::tr("Site map (2D)"), none, 2, false, false, {}},
        {MainWindow::panelKey(Panel::Site3D), MainWindow::tr("Site 3D"), none, 3, false, false, {}},
        {MainWindow::panelKey(Panel::PassCounts), MainWindow::tr("Pass counts"), none, 6, false, true, {}},
        {MainWindow::panelKey(Panel::EventLog), MainWindow::tr("Event log"), none, 7, false, true, {}}};
}

bool isMainPanel(const QString& key) {
    for (const PanelSpec& p : mainPanels())
        if (p.key == key)
            return true;
    return false;
}

// Shortcut order (the View menu, Ctrl+N); panels without a shortcut last, in the order given.
void sortPanels(QList<PanelSpec>& panels) {
    std::stable_sort(panels.begin(), panels.end(), [](const PanelSpec& a, const PanelSpec& b) {
        return (a.shortcutDigit ? a.shortcutDigit : 100) < (b.shortcutDigit ? b.shortcutDigit : 100);
    });
}

// "a, b and c".
QString listText(const QStringList& items) {
    if (items.size() < 2)
        return items.value(0);
    return MainWindow::tr("%1 and %2")
        .arg(items.mid(0, items.size() - 1).join(QStringLiteral(", ")), items.last());
}
} // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setObjectName(QStringLiteral("OcuMainWindow"));
    setWindowTitle(tr("Operator Control Unit"));
    setDockNestingEnabled(true);
    setDockOptions(QMainWindow::AnimatedDocks | QMainWindow::AllowNestedDocks |
                   QMainWindow::AllowTabbedDocks | QMainWindow::GroupedDragging);
    m_panels = mainPanels();
    for (const PanelSpec& p : std::as_const(m_panels))
        createDock(p);
    createToolBar();
    createMenus();
    createStatusBar();
    applyDefaultLayout();
    m_defaultState = saveState(kLayoutVersion);
}

MainWindow::~MainWindow() = default;

QString MainWindow::panelKey(Panel panel) {
    switch (panel) {
    case Panel::Fleet:
        return QStringLiteral("fleet");
    case Panel::SiteMap:
        return QStringLiteral("map");
    case Panel::Site3D:
        return QStringLiteral("3d");
    case Panel::PassCounts:
        return QStringLiteral("passcounts");
    case Panel::EventLog:
        return QStringLiteral("events");
    }
    return {};
}

QStringList MainWindow::panelKeys() const {
    QStringList keys;
    for (const PanelSpec& p : m_panels)
        keys << p.key;
    return keys;
}

QStringList MainWindow::panelKeysWith(const QList<PanelSpec>& modulePanels) {
    QList<PanelSpec> all = mainPanels() + modulePanels;
    sortPanels(all);
    QStringList keys;
    for (const PanelSpec& p : all)
        keys << p.key;
    return keys;
}

QString MainWindow::panelTitle(const QString& key) const {
    for (const PanelSpec& p : m_panels)
        if (p.key == key)
            return p.title;
    return {};
}

void MainWindow::createDock(const PanelSpec& spec) {
    auto* dock = new QDockWidget(spec.title, this);
    dock->setObjectName(QStringLiteral("dock-") + spec.key);
    dock->setFeatures(QDockWidget::DockWidgetClosable | QDockWidget::DockWidgetMovable |
                      QDockWidget::DockWidgetFloatable);
    auto* empty = new QLabel(tr("Starting…"), dock);
    empty->setAlignment(Qt::AlignCenter);
    dock->setWidget(empty);
    m_docks.insert(spec.key, dock);
}

void MainWindow::addPanels(const QList<PanelSpec>& panels) {
    bool added = false;
    for (const PanelSpec& p : panels) {
        if (m_docks.contains(p.key))
            continue;
        createDock(p);
        m_panels << p;
        if (p.place == PanelPlace::SideColumn && !m_sideColumn)
            m_sideColumn = m_docks.value(p.key);
        added = true;
    }
    if (!added)
        return;
    sortPanels(m_panels);
    fillPanelMenus();
    // The default layout again with them: splits before tabs (a split beside a tabbed dock only adds a tab).
    for (QDockWidget* d : std::as_const(m_docks))
        removeDockWidget(d);
    applyDefaultLayout();
    m_defaultState = saveState(kLayoutVersion);
    m_fitPending = true;
    m_raisePending = true; // a tab group laid out again keeps its first tab in front until shown
}

void MainWindow::setPanelWidget(const QString& key, QWidget* widget) {
    QDockWidget* d = m_docks.value(key);
    if (!d)
        return;
    QWidget* old = d->widget();
    QWidget* content = widget;
    bool scrolls = false;
    for (const PanelSpec& p : std::as_const(m_panels))
        if (p.key == key)
            scrolls = p.scrolls;
    // Panels of controls (not a map or a table that scroll by themselves) scroll when their dock is narrower
    // than they need, instead of forcing the whole column wide and squeezing the map (German
    // texts at 1366 x 768 left the map a small square).
    if (widget != nullptr && scrolls) {
        auto* scroll = new QScrollArea;
        scroll->setObjectName(QStringLiteral("panel-scroll"));
        scroll->setFrameShape(QFrame::NoFrame);
        scroll->setWidgetResizable(true);
        scroll->setWidget(widget);
        content = scroll;
    }
    d->setWidget(content);
    if (old && old != content)
        old->deleteLater();
}

QWidget* MainWindow::panelWidget(const QString& key) const {
    QDockWidget* d = m_docks.value(key);
    if (!d)
        return nullptr;
    QWidget* w = d->widget();
    if (auto* scroll = qobject_cast<QScrollArea*>(w);
        scroll && scroll->objectName() == QLatin1String("panel-scroll"))
        return scroll->widget();
    return w;
}

void MainWindow::createToolBar() {
    auto* tb = new QToolBar(tr("Safety"), this);
    tb->setObjectName(QStringLiteral("toolbar-safety"));
    // The stop must never be hidden: not movable, not floatable, no context menu to close it.
    tb->setMovable(false);
    tb->setFloatable(false);
    tb->toggleViewAction()->setVisible(false);
    tb->setContextMenuPolicy(Qt::PreventContextMenu);
    tb->setIconSize(QSize(28, 28));
    addToolBar(Qt::TopToolBarArea, tb);

    m_stopAll = new QAction(tr("STOP ALL"), this);
    m_stopAll->setObjectName(QStringLiteral("action-stop-all"));
    m_stopAll->setShortcuts({QKeySequence(Qt::Key_F12), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Space)});
    m_stopAll->setShortcutContext(Qt::ApplicationShortcut); // also from floating panels
    setStopAllReach({});
    // A held F12 must not stop again and again (each stop is a command with its own audit line).
    m_stopAll->setAutoRepeat(false);
    connect(m_stopAll, &QAction::triggered, this, &MainWindow::stopAllRequested);
    // The button acts on the press, not on the release (StopAllButton).
    auto* stopButton = new StopAllButton(tb);
    stopButton->setDefaultAction(m_stopAll);
    stopButton->setToolButtonStyle(tb->toolButtonStyle());
    stopButton->setIconSize(tb->iconSize());
    tb->addWidget(stopButton);
    m_stopAllButton = stopButton;
    if (m_stopAllButton) {
        m_stopAllButton->setObjectName(QStringLiteral("button-stop-all"));
        m_stopAllButton->setMinimumSize(150, 40);
        m_stopAllButton->setFocusPolicy(Qt::StrongFocus);
        m_stopAllButton->setStyleSheet(QStringLiteral(
            "QToolButton { background:#c81e1e; color:white; font-weight:bold; font-size:16px;"
            " border:2px solid #7a0b0b; border-radius:6px; padding:4px 14px; }"
            "QToolButton:hover { background:#e02626; } QToolButton:pressed { background:#8e1010; }"
            "QToolButton:focus { border:3px solid #ffd400; }"));
    }
    tb->addSeparator();

    // The failed-stop banner: a full-width red bar under the safety toolbar, shown only while a stop did not
    // reach every target. Not movable, not closable except by its own Dismiss button.
    addToolBarBreak(Qt::TopToolBarArea);
    m_bannerBar = new QToolBar(tr("Stop failure"), this);
    m_bannerBar->setObjectName(QStringLiteral("toolbar-stop-banner"));
    m_bannerBar->setMovable(false);
    m_bannerBar->setFloatable(false);
    m_bannerBar->toggleViewAction()->setVisible(false);
    m_bannerBar->setContextMenuPolicy(Qt::PreventContextMenu);
    auto* banner = new QFrame(m_bannerBar);
    banner->setObjectName(QStringLiteral("stop-banner"));
    banner->setStyleSheet(
        QStringLiteral("#stop-banner { background:#b00000; border:2px solid #5c0000; }"
                       "#stop-banner QLabel { color:white; font-weight:bold; font-size:15px; }"));
    auto* row = new QHBoxLayout(banner);
    row->setContentsMargins(10, 6, 10, 6);
    m_bannerLabel = new QLabel(banner);
    m_bannerLabel->setObjectName(QStringLiteral("label-stop-banner"));
    m_bannerLabel->setWordWrap(true);
    m_bannerLabel->setTextFormat(Qt::PlainText);
    m_bannerLabel->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
    row->addWidget(m_bannerLabel, 1);
    auto* dismiss = new QPushButton(tr("Dismiss"), banner);
    dismiss->setObjectName(QStringLiteral("button-dismiss-stop-banner"));
    dismiss->setToolTip(tr("Hide this warning. It does not change what the machines do."));
    connect(dismiss, &QPushButton::clicked, this, &MainWindow::clearStopBanner);
    row->addWidget(dismiss);
    m_bannerBar->addWidget(banner);
    addToolBar(Qt::TopToolBarArea, m_bannerBar);
    m_bannerBar->hide();
}

void MainWindow::showStopBanner(const QString& text) {
    m_bannerText = text;
    m_bannerLabel->setText(text);
    m_bannerBar->show();
}

void MainWindow::clearStopBanner() {
    m_bannerText.clear();
    m_bannerLabel->clear();
    m_bannerBar->hide();
}

void MainWindow::createMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    m_fileMenu = file;
    QAction* shot = file->addAction(tr("Save &screenshot…"));
    shot->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_P));
    connect(shot, &QAction::triggered, this, [this] {
        const QString f = QFileDialog::getSaveFileName(this, tr("Save screenshot"), QStringLiteral("ocu.png"),
                                                       tr("PNG images (*.png)"));
        if (!f.isEmpty())
            grab().save(f, "PNG");
    });
    file->addSeparator();
    QAction* quit = file->addAction(tr("&Quit"));
    quit->setShortcut(QKeySequence::Quit);
    connect(quit, &QAction::triggered, this, &QWidget::close);

    m_viewMenu = menuBar()->addMenu(tr("&View"));
    m_resetAction = new QAction(tr("&Reset layout"), this);
    m_resetAction->setObjectName(QStringLiteral("action-reset-layout"));
    connect(m_resetAction, &QAction::triggered, this, &MainWindow::resetLayout);
    m_nightAction = new QAction(tr("&Night palette"), this);
    m_nightAction->setObjectName(QStringLiteral("action-night"));
    m_nightAction->setCheckable(true);
    m_nightAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_N));
    connect(m_nightAction, &QAction::toggled, this, &MainWindow::setNightMode);
    // A keyboard-only path to every panel (also listed in Help > Keyboard shortcuts and
    // docs/keyboard.md).
    m_goMenu = new QMenu(tr("&Go to panel"), this);
    fillPanelMenus();

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    QAction* keys = help->addAction(tr("&Keyboard shortcuts"));
    connect(keys, &QAction::triggered, this,
            [this] { QMessageBox::information(this, tr("Keyboard shortcuts"), keyboardHelpText()); });
    QAction* about = help->addAction(tr("&About"));
    connect(about, &QAction::triggered, this, [this] {
        QMessageBox::about(this, tr("About the Operator Control Unit"),
                           tr("Operator Control Unit %1\n%2 on one console.")
                               .arg(QApplication::applicationVersion(), listText(m_aboutProtocols)));
    });
}

// The View menu and its Go to panel submenu, in the panels' order (again when a module adds panels).
void MainWindow::fillPanelMenus() {
    m_viewMenu->clear();
    m_goMenu->clear();
    for (const PanelSpec& p : std::as_const(m_panels)) {
        m_viewMenu->addAction(m_docks.value(p.key)->toggleViewAction());
        QAction* go = m_goActions.value(p.key);
        if (!go) {
            go = new QAction(p.title, this);
            go->setObjectName(QStringLiteral("action-go-") + p.key);
            if (p.shortcutDigit > 0)
                go->setShortcut(QKeySequence(Qt::CTRL | static_cast<Qt::Key>(Qt::Key_0 + p.shortcutDigit)));
            go->setShortcutContext(Qt::ApplicationShortcut);
            connect(go, &QAction::triggered, this, [this, key = p.key] { focusPanel(key); });
            addAction(go); // active even when the menu bar is hidden
            m_goActions.insert(p.key, go);
        }
        m_goMenu->addAction(go);
    }
    m_viewMenu->addSeparator();
    m_viewMenu->addAction(m_resetAction);
    m_viewMenu->addAction(m_nightAction);
    m_viewMenu->addMenu(m_goMenu);
}

void MainWindow::raisePanel(const QString& key) {
    if (QDockWidget* d = dock(key)) {
        d->raise();
        m_raisedPanels << key;
    }
}

void MainWindow::setStopAllReach(const QStringList& reach) {
    const QString what = reach.isEmpty()
                             ? tr("Stop every machine this console can reach")
                             : tr("Stop every machine this console can reach: %1").arg(listText(reach));
    m_stopAll->setToolTip(
        tr("%1 (F12 or Ctrl+Shift+Space). Stopping never asks for confirmation; a stop that does not reach "
           "everything shows a red banner.")
            .arg(what));
}

void MainWindow::setAboutProtocols(const QStringList& protocols) {
    m_aboutProtocols = protocols;
}

void MainWindow::createStatusBar() {
    m_alarmLabel = new QLabel(this);
    m_alarmLabel->setObjectName(QStringLiteral("label-alarms"));
    statusBar()->addPermanentWidget(m_alarmLabel);
    setUnacknowledgedAlarms(0);
}

LinkIndicator* MainWindow::addLinkIndicator(const QString& protocol) {
    if (LinkIndicator* existing = m_links.value(protocol))
        return existing;
    auto* ind = new LinkIndicator(protocol, this);
    // Left of the alarm label, after the indicators added before.
    statusBar()->insertPermanentWidget(static_cast<int>(m_links.size()), ind);
    m_links.insert(protocol, ind);
    return ind;
}

void MainWindow::addStatusWidget(QWidget* widget) {
    statusBar()->insertPermanentWidget(static_cast<int>(m_links.size()) + m_statusWidgets, widget);
    ++m_statusWidgets;
}

void MainWindow::setUnacknowledgedAlarms(int count) {
    m_unacked = count;
    m_alarmLabel->setText(count == 0 ? tr("No unacknowledged alarms")
                                     : tr("%n unacknowledged alarm(s)", "", count));
    m_alarmLabel->setStyleSheet(count == 0
                                    ? QString()
                                    : QStringLiteral("background:#c81e1e; color:white; font-weight:bold;"
                                                     " padding:1px 6px; border-radius:3px;"));
}

void MainWindow::setNightMode(bool night) {
    m_night = night;
    if (m_nightAction && m_nightAction->isChecked() != night)
        m_nightAction->setChecked(night);
    if (auto* app = qobject_cast<QApplication*>(QCoreApplication::instance()))
        applyTheme(*app, night ? Theme::Night : Theme::Day);
}

QList<QDockWidget*> MainWindow::frontDocks() const {
    QList<QDockWidget*> out{m_docks.value(panelKey(Panel::SiteMap))};
    for (const PanelSpec& p : m_panels)
        if (p.front && !isMainPanel(p.key))
            out << m_docks.value(p.key);
    return out;
}

void MainWindow::applyDefaultLayout() {
    // The default layout: fleet list left, map in the middle with 3D as a tab, the modules' side column
    // right, event log and pass counts (with the modules' panels beside them) along the bottom. Splits first,
    // tabs last: tabifying before a split drags the whole tab group along.
    QDockWidget* fleet = dock(Panel::Fleet);
    QDockWidget* map = dock(Panel::SiteMap);
    QDockWidget* events = dock(Panel::EventLog);
    QDockWidget* passCounts = dock(Panel::PassCounts);
    QDockWidget* side = m_sideColumn;
    addDockWidget(Qt::LeftDockWidgetArea, fleet);
    addDockWidget(Qt::LeftDockWidgetArea, map);
    splitDockWidget(fleet, map, Qt::Horizontal);
    if (side)
        splitDockWidget(map, side, Qt::Horizontal);
    addDockWidget(Qt::BottomDockWidgetArea, events);
    splitDockWidget(events, passCounts, Qt::Horizontal);
    tabifyDockWidget(map, dock(Panel::Site3D));
    for (const PanelSpec& p : std::as_const(m_panels)) {
        if (isMainPanel(p.key) || m_docks.value(p.key) == side)
            continue;
        tabifyDockWidget(p.place == PanelPlace::SideColumn ? side : passCounts, m_docks.value(p.key));
    }
    for (QDockWidget* d : std::as_const(m_docks))
        d->show();
    for (QDockWidget* d : frontDocks())
        d->raise();
    if (side)
        resizeDocks({fleet, map, side}, {420, 900, 380}, Qt::Horizontal);
    else
        resizeDocks({fleet, map}, {420, 1280}, Qt::Horizontal);
    resizeDocks({map, events}, {700, 220}, Qt::Vertical);
}

void MainWindow::focusPanel(const QString& key) {
    QDockWidget* d = m_docks.value(key);
    if (d == nullptr)
        return;
    d->show();
    d->raise();
    QWidget* w = panelWidget(key);
    if (w == nullptr)
        return;
    // The panel's first control that takes the keyboard (or the panel itself).
    QWidget* target = w;
    if (!(w->focusPolicy() & Qt::TabFocus)) {
        for (QWidget* c : w->findChildren<QWidget*>())
            if ((c->focusPolicy() & Qt::TabFocus) && c->isEnabled() && c->isVisibleTo(w)) {
                target = c;
                break;
            }
    }
    target->setFocus(Qt::ShortcutFocusReason);
}

QString MainWindow::keyboardHelpText() const {
    // The go-to-panel lines come from the window's own Ctrl+N actions (the main panels and the
    // ones a protocol module adds, e.g. Ctrl+9 Production), so the help never lists fewer than exist.
    QStringList lines{tr("F12 or Ctrl+Shift+Space: STOP ALL")};
    for (const PanelSpec& p : m_panels)
        if (!p.keyboardHelp.isEmpty())
            lines << p.keyboardHelp;
    lines << QStringList{
        tr("Site map: arrows pan, +/- or wheel zoom (about the cursor), F follow the selected machine, Home "
           "whole site, Shift+Home the fleet, S the selection, A the area under the cursor, C centre; "
           "double-click selects; click an edge arrow to go to machines outside the view"),
        tr("Ctrl+Shift+N: night palette"), tr("Ctrl+Shift+P: save a screenshot"),
        tr("Go to a panel (raises it and puts the keyboard focus in it):")};
    QStringList go;
    for (const QAction* a : actions())
        if (a->objectName().startsWith(QLatin1String("action-go-")) && !a->shortcut().isEmpty())
            go << QStringLiteral("    %1: %2")
                      .arg(a->shortcut().toString(QKeySequence::NativeText),
                           QString(a->text()).remove(QLatin1Char('&')));
    go.sort(); // Ctrl+1 … Ctrl+9, whichever module added its panel when
    lines << go;
    lines << tr("Tab / Shift+Tab: next / previous control in a panel; arrows move in lists and tables; Space "
                "or Enter presses the focused button")
          << tr("See docs/keyboard.md for the full list.");
    return lines.join(QLatin1Char('\n'));
}

void MainWindow::fitDocksToWindow() {
    const int w = width(), h = height();
    if (w < 200 || h < 200)
        return;
    // Fleet list a quarter, the map the most, the modules' side column about a quarter; the bottom row a
    // quarter of the height. Minimum sizes of the panels still apply.
    if (QDockWidget* side = m_sideColumn)
        resizeDocks({dock(Panel::Fleet), dock(Panel::SiteMap), side},
                    {w * 24 / 100, w * 50 / 100, w * 26 / 100}, Qt::Horizontal);
    else
        resizeDocks({dock(Panel::Fleet), dock(Panel::SiteMap)}, {w * 24 / 100, w * 76 / 100}, Qt::Horizontal);
    // On a short screen (a 1366x768 field laptop) the bottom row (event log, the tables beside the pass
    // counts) gets 40 % and its right side half of it, so a table there shows its rows, not two.
    // 30 % left the event log four table rows at 1920x1080 (40 % three at 1366x768, German two
    // rows of controls more); 36 % / 42 % give it ten / six rows and the map
    // still ~60 % of the height.
    const int bottom = h < 900 ? 42 : 36;
    const int right = w < 1600 ? 50 : 55; // at 1920: all ten columns of a table of ten
    resizeDocks({dock(Panel::SiteMap), dock(Panel::EventLog)}, {h * (100 - bottom) / 100, h * bottom / 100},
                Qt::Vertical);
    resizeDocks({dock(Panel::EventLog), dock(Panel::PassCounts)}, {w * (100 - right) / 100, w * right / 100},
                Qt::Horizontal);
    m_fitPending = false;
}

void MainWindow::showFirstStart() {
    if (QScreen* s = screen())
        resize(s->availableGeometry().size());
    showMaximized();
}

void MainWindow::resizeEvent(QResizeEvent* event) {
    QMainWindow::resizeEvent(event);
    if (m_fitPending && isVisible())
        fitDocksToWindow();
}

void MainWindow::showEvent(QShowEvent* event) {
    QMainWindow::showEvent(event);
    if (m_raisePending) {
        m_raisePending = false;
        for (QDockWidget* d : frontDocks())
            d->raise();
        for (const QString& key : std::as_const(m_raisedPanels))
            if (QDockWidget* d = dock(key))
                d->raise();
    }
    if (m_fitPending) // the size was set before show (screenshot, restored geometry without a state)
        fitDocksToWindow();
}

void MainWindow::resetLayout() {
    for (QDockWidget* d : std::as_const(m_docks)) {
        d->setFloating(false);
        d->show();
    }
    if (!restoreState(m_defaultState, kLayoutVersion))
        applyDefaultLayout();
    fitDocksToWindow();
    for (QDockWidget* d : frontDocks())
        d->raise();
    m_bannerBar->setVisible(!m_bannerText.isEmpty()); // a saved layout never hides a failed stop
}

void MainWindow::saveLayout() const {
    QSettings s;
    s.setValue(QStringLiteral("window/geometry"), saveGeometry());
    s.setValue(QStringLiteral("window/state"), saveState(kLayoutVersion));
    s.setValue(QStringLiteral("window/night"), m_night);
}

bool MainWindow::restoreLayout() {
    QSettings s;
    const QByteArray geometry = s.value(QStringLiteral("window/geometry")).toByteArray();
    const QByteArray state = s.value(QStringLiteral("window/state")).toByteArray();
    setNightMode(s.value(QStringLiteral("window/night"), false).toBool());
    if (geometry.isEmpty() || state.isEmpty())
        return false;
    restoreGeometry(geometry);
    const bool ok = restoreState(state, kLayoutVersion);
    // The operator's own sizes and the tabs they had in front stay.
    m_fitPending = !ok;
    m_raisePending = m_raisePending && !ok;
    m_bannerBar->setVisible(!m_bannerText.isEmpty()); // a saved layout never hides a failed stop
    return ok;
}

void MainWindow::closeEvent(QCloseEvent* event) {
    saveLayout();
    QMainWindow::closeEvent(event);
}

} // namespace ocu
