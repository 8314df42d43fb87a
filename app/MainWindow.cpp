#include "app/MainWindow.h"

#include "app/Theme.h"
#include "app/WorkspaceBar.h"
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

// The main panels with their Ctrl+N (docs/keyboard.md); the protocol modules' panels have 4, 5, 8 and 9.
QList<PanelSpec> mainPanels() {
    const PanelPlace side = PanelPlace::SideColumn, table = PanelPlace::BesidePassCounts;
    return {{MainWindow::panelKey(Panel::Fleet),
             MainWindow::tr("Fleet"),
             side,
             1,
             false,
             false,
             {},
             PanelKind::Fleet},
            {MainWindow::panelKey(Panel::SiteMap),
             MainWindow::tr("Site map (2D)"),
             side,
             2,
             false,
             false,
             {},
             PanelKind::Map},
            {MainWindow::panelKey(Panel::Site3D),
             MainWindow::tr("Site 3D"),
             side,
             3,
             false,
             false,
             {},
             PanelKind::Site3D},
            {MainWindow::panelKey(Panel::PassCounts),
             MainWindow::tr("Pass counts"),
             table,
             6,
             false,
             true,
             {},
             PanelKind::PassCounts},
            {MainWindow::panelKey(Panel::EventLog),
             MainWindow::tr("Event log"),
             table,
             7,
             false,
             true,
             {},
             PanelKind::Alarms}};
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
    updateOfferedWorkspaces();
    applyDefaultLayout();
}

MainWindow::~MainWindow() {
    // The panels go in their order, whatever the docks' order among the window's children after a layout:
    // a panel may use one listed after it (drive controls whose picture is a panel of its own).
    for (const PanelSpec& p : std::as_const(m_panels))
        delete m_docks.take(p.key);
}

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
        added = true;
    }
    if (!added)
        return;
    sortPanels(m_panels);
    fillPanelMenus();
    updateOfferedWorkspaces();
    // The workspace's default arrangement again with them.
    m_arrangements.clear();
    applyDefaultLayout();
}

void MainWindow::removePanel(const QString& key) {
    QDockWidget* d = m_docks.take(key);
    if (!d)
        return;
    m_panels.erase(
        std::remove_if(m_panels.begin(), m_panels.end(), [&key](const PanelSpec& p) { return p.key == key; }),
        m_panels.end());
    removeDockWidget(d);
    delete d;
    delete m_goActions.take(key);
    fillPanelMenus();
    updateOfferedWorkspaces();
    m_arrangements.clear();
    applyDefaultLayout();
}

PanelKind MainWindow::panelKind(const QString& key) const {
    for (const PanelSpec& p : m_panels)
        if (p.key == key)
            return p.kind;
    return PanelKind::Other;
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
    // The workspaces beside STOP ALL, in the same row (no height taken from the map).
    m_workspaceBar = new WorkspaceBar(this);
    addToolBar(Qt::TopToolBarArea, m_workspaceBar);
    connect(m_workspaceBar, &WorkspaceBar::chosen, this, &MainWindow::setWorkspace);

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
    m_resetAction = new QAction(tr("&Reset workspace"), this);
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
            else if (p.shortcutKey != Qt::Key_unknown)
                go->setShortcut(QKeySequence(Qt::CTRL | p.shortcutKey));
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
        tr("Workspaces (View › Reset workspace puts the current one back as it was):")};
    lines << m_workspaceBar->keyboardHelp();
    lines << tr("Go to a panel (raises it and puts the keyboard focus in it):");
    QStringList go;
    for (const QAction* a : actions())
        if (a->objectName().startsWith(QLatin1String("action-go-")) && !a->shortcut().isEmpty())
            go << QStringLiteral("    %1: %2")
                      .arg(a->shortcut().toString(QKeySequence::NativeText),
                           QString(a->text()).remove(QLatin1Char('&')));
    go.sort(); // Ctrl+0 … Ctrl+9, then the letters, whichever module added its panel when
    lines << go;
    lines << tr("Tab / Shift+Tab: next / previous control in a panel; arrows move in lists and tables; Space "
                "or Enter presses the focused button")
          << tr("See docs/keyboard.md for the full list.");
    return lines.join(QLatin1Char('\n'));
}

void MainWindow::closeEvent(QCloseEvent* event) {
    saveLayout();
    QMainWindow::closeEvent(event);
}

} // namespace ocu
