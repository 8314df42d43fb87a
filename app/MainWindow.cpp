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
}

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setObjectName(QStringLiteral("OcuMainWindow"));
    setWindowTitle(tr("Operator Control Unit"));
    setDockNestingEnabled(true);
    setDockOptions(QMainWindow::AnimatedDocks | QMainWindow::AllowNestedDocks |
                   QMainWindow::AllowTabbedDocks | QMainWindow::GroupedDragging);
    createDocks();
    createToolBar();
    createMenus();
    createStatusBar();
    applyDefaultLayout();
    m_defaultState = saveState(kLayoutVersion);
}

MainWindow::~MainWindow() = default;

QList<Panel> MainWindow::panels() {
    return {Panel::Fleet,  Panel::SiteMap,    Panel::Site3D,   Panel::JausControl,
            Panel::Teleop, Panel::PassCounts, Panel::EventLog, Panel::Dispatch};
}

QString MainWindow::panelKey(Panel panel) {
    switch (panel) {
    case Panel::Fleet:
        return QStringLiteral("fleet");
    case Panel::SiteMap:
        return QStringLiteral("map");
    case Panel::Site3D:
        return QStringLiteral("3d");
    case Panel::JausControl:
        return QStringLiteral("jaus");
    case Panel::Teleop:
        return QStringLiteral("teleop");
    case Panel::PassCounts:
        return QStringLiteral("passcounts");
    case Panel::EventLog:
        return QStringLiteral("events");
    case Panel::Dispatch:
        return QStringLiteral("dispatch");
    }
    return {};
}

QString MainWindow::panelTitle(Panel panel) const {
    switch (panel) {
    case Panel::Fleet:
        return tr("Fleet");
    case Panel::SiteMap:
        return tr("Site map (2D)");
    case Panel::Site3D:
        return tr("Site 3D");
    case Panel::JausControl:
        return tr("JAUS control");
    case Panel::Teleop:
        return tr("Teleop");
    case Panel::PassCounts:
        return tr("Pass counts");
    case Panel::EventLog:
        return tr("Event log");
    case Panel::Dispatch:
        return tr("Dispatch");
    }
    return {};
}

void MainWindow::createDocks() {
    for (Panel p : panels()) {
        auto* dock = new QDockWidget(panelTitle(p), this);
        dock->setObjectName(QStringLiteral("dock-") + panelKey(p));
        dock->setFeatures(QDockWidget::DockWidgetClosable | QDockWidget::DockWidgetMovable |
                          QDockWidget::DockWidgetFloatable);
        auto* empty = new QLabel(tr("Starting…"), dock);
        empty->setAlignment(Qt::AlignCenter);
        dock->setWidget(empty);
        m_docks.insert(p, dock);
    }
}

void MainWindow::setPanelWidget(Panel panel, QWidget* widget) {
    QDockWidget* d = m_docks.value(panel);
    QWidget* old = d->widget();
    QWidget* content = widget;
    // Panels of controls (not a map or a table that scroll by themselves) scroll when their dock is narrower
    // than they need, instead of forcing the whole column wide and squeezing the map (German
    // texts at 1366 x 768 left the map a small square).
    if (widget != nullptr &&
        (panel == Panel::JausControl || panel == Panel::Teleop || panel == Panel::PassCounts ||
         panel == Panel::Dispatch || panel == Panel::EventLog)) {
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

QWidget* MainWindow::panelWidget(Panel panel) const {
    QWidget* w = m_docks.value(panel)->widget();
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
    m_stopAll->setToolTip(tr(
        "Stop every machine this console can reach: JAUS emergency stop to every discovered vehicle, "
        "ISO 23725 all-stop to every AHS link and the OSYRIS stop message (F12 or Ctrl+Shift+Space). "
        "Stopping never asks for confirmation; a stop that does not reach everything shows a red banner."));
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

    QMenu* view = menuBar()->addMenu(tr("&View"));
    for (Panel p : panels()) {
        QAction* a = m_docks.value(p)->toggleViewAction();
        view->addAction(a);
    }
    view->addSeparator();
    QAction* reset = view->addAction(tr("&Reset layout"));
    reset->setObjectName(QStringLiteral("action-reset-layout"));
    connect(reset, &QAction::triggered, this, &MainWindow::resetLayout);
    m_nightAction = view->addAction(tr("&Night palette"));
    m_nightAction->setObjectName(QStringLiteral("action-night"));
    m_nightAction->setCheckable(true);
    m_nightAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_N));
    connect(m_nightAction, &QAction::toggled, this, &MainWindow::setNightMode);

    createPanelShortcuts(view);

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    QAction* keys = help->addAction(tr("&Keyboard shortcuts"));
    connect(keys, &QAction::triggered, this,
            [this] { QMessageBox::information(this, tr("Keyboard shortcuts"), keyboardHelpText()); });
    QAction* about = help->addAction(tr("&About"));
    connect(about, &QAction::triggered, this, [this] {
        QMessageBox::about(this, tr("About the Operator Control Unit"),
                           tr("Operator Control Unit %1\nJAUS (AS5669A/AS5710A, AEP-4818 IOP), ISO 23725 "
                              "and OSYRIS on one console.")
                               .arg(QApplication::applicationVersion()));
    });
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

void MainWindow::applyDefaultLayout() {
    // Dispatcher layout: fleet list left, map in the middle with 3D as a tab, JAUS and teleop right,
    // event log and pass counts along the bottom.
    // Splits first, tabs last: tabifying before a split drags the whole tab group along.
    addDockWidget(Qt::LeftDockWidgetArea, m_docks[Panel::Fleet]);
    addDockWidget(Qt::LeftDockWidgetArea, m_docks[Panel::SiteMap]);
    splitDockWidget(m_docks[Panel::Fleet], m_docks[Panel::SiteMap], Qt::Horizontal);
    splitDockWidget(m_docks[Panel::SiteMap], m_docks[Panel::JausControl], Qt::Horizontal);
    addDockWidget(Qt::BottomDockWidgetArea, m_docks[Panel::EventLog]);
    splitDockWidget(m_docks[Panel::EventLog], m_docks[Panel::PassCounts], Qt::Horizontal);
    tabifyDockWidget(m_docks[Panel::SiteMap], m_docks[Panel::Site3D]);
    tabifyDockWidget(m_docks[Panel::JausControl], m_docks[Panel::Teleop]);
    tabifyDockWidget(m_docks[Panel::PassCounts],
                     m_docks[Panel::Dispatch]); // the dispatcher's table
    for (QDockWidget* d : std::as_const(m_docks))
        d->show();
    m_docks[Panel::SiteMap]->raise();
    m_docks[Panel::JausControl]->raise();
    m_docks[Panel::Dispatch]->raise();
    resizeDocks({m_docks[Panel::Fleet], m_docks[Panel::SiteMap], m_docks[Panel::JausControl]},
                {420, 900, 380}, Qt::Horizontal);
    resizeDocks({m_docks[Panel::SiteMap], m_docks[Panel::EventLog]}, {700, 220}, Qt::Vertical);
}

void MainWindow::focusPanel(Panel panel) {
    QDockWidget* d = m_docks.value(panel);
    if (d == nullptr)
        return;
    d->show();
    d->raise();
    QWidget* w = panelWidget(panel);
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

void MainWindow::createPanelShortcuts(QMenu* view) {
    // A keyboard-only path to every panel (also listed in Help > Keyboard shortcuts and
    // docs/keyboard.md).
    QMenu* go = view->addMenu(tr("&Go to panel"));
    int n = 1;
    for (Panel p : panels()) {
        QAction* a = go->addAction(panelTitle(p));
        a->setObjectName(QStringLiteral("action-go-") + panelKey(p));
        a->setShortcut(QKeySequence(Qt::CTRL | static_cast<Qt::Key>(Qt::Key_0 + n++)));
        a->setShortcutContext(Qt::ApplicationShortcut);
        connect(a, &QAction::triggered, this, [this, p] { focusPanel(p); });
        addAction(a); // active even when the menu bar is hidden
    }
}

QString MainWindow::keyboardHelpText() const {
    // The go-to-panel lines come from the window's own Ctrl+N actions (the main panels and the
    // ones a protocol module adds, e.g. Ctrl+9 Production), so the help never lists fewer than exist.
    QStringList lines{
        tr("F12 or Ctrl+Shift+Space: STOP ALL"),
        tr("Teleop panel: W/A/S/D or arrows with the dead-man key held; Space or Esc: emergency stop"),
        tr("Dispatch: F6 next truck needing work, Alt+T task, Alt+D destination, Alt+M pick on map, "
           "Ctrl+Enter assign, Alt+R reset"),
        tr("Site map: arrows pan, +/- or wheel zoom (about the cursor), F follow the selected machine, Home "
           "whole site, Shift+Home the fleet, S the selection, A the area under the cursor, C centre; "
           "double-click selects; click an edge arrow to go to machines outside the view"),
        tr("Ctrl+Shift+N: night palette"),
        tr("Ctrl+Shift+P: save a screenshot"),
        tr("Go to a panel (raises it and puts the keyboard focus in it):")};
    for (const QAction* a : actions())
        if (a->objectName().startsWith(QLatin1String("action-go-")) && !a->shortcut().isEmpty())
            lines << QStringLiteral("    %1: %2")
                         .arg(a->shortcut().toString(QKeySequence::NativeText),
                              QString(a->text()).remove(QLatin1Char('&')));
    lines << tr("Tab / Shift+Tab: next / previous control in a panel; arrows move in lists and tables; Space "
                "or Enter presses the focused button")
          << tr("See docs/keyboard.md for the full list.");
    return lines.join(QLatin1Char('\n'));
}

void MainWindow::fitDocksToWindow() {
    const int w = width(), h = height();
    if (w < 200 || h < 200)
        return;
    // Fleet list a quarter, the map the most, the JAUS/teleop column about a quarter; the bottom row a
    // quarter of the height. Minimum sizes of the panels still apply.
    resizeDocks({m_docks[Panel::Fleet], m_docks[Panel::SiteMap], m_docks[Panel::JausControl]},
                {w * 24 / 100, w * 50 / 100, w * 26 / 100}, Qt::Horizontal);
    // On a short screen (a 1366x768 field laptop) the bottom row (event log, dispatch) gets 40 %
    // and the dispatch side half of it, so the dispatch table shows trucks, not two rows.
    // 30 % left the event log four table rows at 1920x1080 (40 % three at 1366x768, German two
    // rows of controls more); 36 % / 42 % give it ten / six rows and the map
    // still ~60 % of the height.
    const int bottom = h < 900 ? 42 : 36;
    const int dispatch = w < 1600 ? 50 : 55; // at 1920: all ten columns of the dispatch table
    resizeDocks({m_docks[Panel::SiteMap], m_docks[Panel::EventLog]},
                {h * (100 - bottom) / 100, h * bottom / 100}, Qt::Vertical);
    resizeDocks({m_docks[Panel::EventLog], m_docks[Panel::PassCounts]},
                {w * (100 - dispatch) / 100, w * dispatch / 100}, Qt::Horizontal);
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
    m_docks[Panel::SiteMap]->raise();
    m_docks[Panel::JausControl]->raise();
    m_docks[Panel::Dispatch]->raise();
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
    m_fitPending = !ok;                               // the operator's own sizes stay
    m_bannerBar->setVisible(!m_bannerText.isEmpty()); // a saved layout never hides a failed stop
    return ok;
}

void MainWindow::closeEvent(QCloseEvent* event) {
    saveLayout();
    QMainWindow::closeEvent(event);
}

} // namespace ocu
