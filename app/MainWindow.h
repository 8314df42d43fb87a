#pragma once
// The console's main window: dockable, closable, re-openable panels around the site, a toolbar whose
// STOP ALL is always visible, and a status bar with one indicator per protocol link.
#include <QMainWindow>
#include <QMap>
#include <QStringList>

#include "app/LinkIndicator.h"
#include "app/WorkspaceLayout.h"

class QDockWidget;
class QLabel;
class QMenu;
class QToolBar;
class QToolButton;

namespace ocu {

class WorkspaceBar;

// The panels every console has. A protocol module adds its own (addPanels(), app/ProtocolModule.h).
enum class Panel { Fleet, SiteMap, Site3D, PassCounts, EventLog };

// Where a panel of PanelKind::Other goes in the All workspace (a panel's kind decides the workspaces and
// the group, app/WorkspaceLayout.h).
enum class PanelPlace {
    SideColumn,       // with the vehicle and fleet panels
    BesidePassCounts, // with the pass counts and the tables
};

// A panel contributed by a protocol module.
struct PanelSpec {
    QString key{};   // stable name: the dock's object name "dock-<key>" (saved layouts) and `--view <key>`
    QString title{}; // the dock's title, the View menu's and the go-to action's text
    PanelPlace place = PanelPlace::SideColumn;
    int shortcutDigit = 0; // Ctrl+<digit> raises it and focuses its first control (docs/keyboard.md); 0: none
    bool front = false;    // not read: the order of the kinds in a workspace decides the tab in front
    bool scrolls = true;   // a panel of controls scrolls in a dock narrower than it needs
    QString keyboardHelp{};            // its line in Help › Keyboard shortcuts (empty: none)
    PanelKind kind = PanelKind::Other; // what it shows: the workspaces it appears in (app/WorkspaceLayout.h)
    Qt::Key shortcutKey = Qt::Key_unknown; // Ctrl+<key> for a panel past Ctrl+9 (shortcutDigit 0)
};

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Stable names of the main panels: fleet, map, 3d, passcounts, events.
    static QString panelKey(Panel panel);
    // Every panel of this window, the modules' ones included, in the order of their Ctrl+N shortcuts.
    QStringList panelKeys() const;
    // The same for a window that has the main panels and these of the modules (the command line's --view).
    static QStringList panelKeysWith(const QList<PanelSpec>& modulePanels);
    QString panelTitle(Panel panel) const { return panelTitle(panelKey(panel)); }
    QString panelTitle(const QString& key) const;

    // Adds the docks of a protocol module's panels (before the window is shown or a layout restored) and lays
    // the default layout out again with them.
    void addPanels(const QList<PanelSpec>& panels);

    QDockWidget* dock(Panel panel) const { return dock(panelKey(panel)); }
    QDockWidget* dock(const QString& key) const { return m_docks.value(key); }
    // Replaces the panel's content; the window takes ownership.
    void setPanelWidget(Panel panel, QWidget* widget) { setPanelWidget(panelKey(panel), widget); }
    void setPanelWidget(const QString& key, QWidget* widget);
    QWidget* panelWidget(Panel panel) const { return panelWidget(panelKey(panel)); }
    QWidget* panelWidget(const QString& key) const;

    // Brings the panel to the front of its tab group, also over the default layout's front tabs on the first
    // show (a saved layout restored later still wins).
    void raisePanel(Panel panel) { raisePanel(panelKey(panel)); }
    void raisePanel(const QString& key);

    // What STOP ALL reaches, one phrase per protocol module, for its tooltip; the protocols of this build for
    // Help › About.
    void setStopAllReach(const QStringList& reach);
    // The File menu (others add their actions before Quit).
    QMenu* fileMenu() const { return m_fileMenu; }
    void setAboutProtocols(const QStringList& protocols);

    QAction* stopAllAction() const { return m_stopAll; }
    QToolButton* stopAllButton() const { return m_stopAllButton; }
    // One indicator per protocol link, added by the runtime for each protocol module (left to right).
    LinkIndicator* addLinkIndicator(const QString& protocol);
    LinkIndicator* linkIndicator(const QString& protocol) const { return m_links.value(protocol); }
    // A status-bar widget of the console's own (not a link), right of the link indicators.
    void addStatusWidget(QWidget* widget);
    void setUnacknowledgedAlarms(int count);

    // The red banner naming what a stop did not reach; stays until dismissed or cleared (a later full stop).
    void showStopBanner(const QString& text);
    void clearStopBanner();
    bool stopBannerVisible() const { return !m_bannerText.isEmpty(); }
    QString stopBannerText() const { return m_bannerText; }
    QToolBar* stopBannerBar() const { return m_bannerBar; }
    int unacknowledgedAlarms() const { return m_unacked; }

    void setNightMode(bool night);
    bool nightMode() const { return m_night; }

    // Takes a panel out of the window (a panel whose data this site does not have: no protocol feeds it).
    void removePanel(const QString& key);
    PanelKind panelKind(const QString& key) const;

    // Workspaces (app/WorkspaceLayout.h): the one shown, switching (the arrangement of the one left is kept),
    // the ones the panels of this site make worth offering.
    Workspace workspace() const { return m_workspace; }
    void setWorkspace(Workspace workspace);
    QList<Workspace> offeredWorkspaces() const;
    WorkspaceBar* workspaceBar() const { return m_workspaceBar; }
    // The person at the console: their arrangements are kept apart from other people's (per person and per
    // screen set-up); shows their last workspace, else `first` (their role's).
    void setOperator(const QString& user, Workspace first);
    QString operatorName() const { return m_user; }
    // The key of the screen set-up the arrangements are saved under (each screen's geometry).
    static QString screenSetupKey();

    // Layout persistence (QSettings, per person and screen set-up): the window, the workspace shown and
    // each workspace's arrangement. restoreLayout() returns false when nothing was saved.
    void saveLayout();
    bool restoreLayout();
    // View › Reset workspace: the current workspace's default arrangement, its saved one forgotten.
    void resetLayout();
    // Shares the window's width and height among the workspace's docks (the map or the video keeps most of
    // the window); called on the first show of a default arrangement and by resetLayout().
    void fitDocksToWindow();
    // First start (no saved layout): maximized, or the screen's available size where maximizing is not
    // possible (offscreen).
    void showFirstStart();
    // Raises the panel and puts the keyboard focus on its first control (Ctrl+1 … Ctrl+8).
    void focusPanel(Panel panel) { focusPanel(panelKey(panel)); }
    void focusPanel(const QString& key);
    // Help › Keyboard shortcuts: every Ctrl+N go-to-panel action of the window, modules' ones included.
    QString keyboardHelpText() const;

signals:
    void stopAllRequested();
    void alarmsClicked();
    void screenshotRequested(const QString& file);

protected:
    void closeEvent(QCloseEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void showEvent(QShowEvent* event) override;

private:
    void createDock(const PanelSpec& spec);
    void createToolBar();
    void createMenus();
    void fillPanelMenus();
    void createStatusBar();
    // The workspace's default arrangement (app/MainWindowWorkspaces.cpp).
    void applyDefaultLayout();
    void layOutAgain(); // applyDefaultLayout(), sized for the window once laid out
    struct Groups {
        QList<QDockWidget*> main, top, bottom, others;
    };
    Groups workspaceGroups() const;
    QString settingsGroup() const;
    void keepArrangement(); // the current workspace's arrangement, in memory and in the settings
    bool restoreArrangement(Workspace workspace);
    void updateOfferedWorkspaces();

    QList<PanelSpec> m_panels; // every panel, in the order of their shortcuts
    QMap<QString, QDockWidget*> m_docks;
    QMap<QString, QAction*> m_goActions;
    WorkspaceBar* m_workspaceBar = nullptr;
    Workspace m_workspace = Workspace::All;
    QString m_user;                             // whose arrangements (empty: the console's)
    QMap<Workspace, QByteArray> m_arrangements; // this run's, by workspace
    QMenu* m_viewMenu = nullptr;
    QMenu* m_fileMenu = nullptr;
    QMenu* m_goMenu = nullptr;
    QAction* m_resetAction = nullptr;
    QStringList m_aboutProtocols;
    QStringList m_raisedPanels; // raisePanel() before the first show
    QMap<QString, LinkIndicator*> m_links;
    int m_statusWidgets = 0; // addStatusWidget's, between the link indicators and the alarm label
    QAction* m_stopAll = nullptr;
    QToolButton* m_stopAllButton = nullptr;
    QAction* m_nightAction = nullptr;
    QLabel* m_alarmLabel = nullptr;
    QToolBar* m_bannerBar = nullptr;
    QLabel* m_bannerLabel = nullptr;
    QString m_bannerText;
    int m_unacked = 0;
    bool m_night = false;
    bool m_fitPending = true;    // default layout not yet shared out for the real window size
    bool m_raisePending = false; // the default layout's front tabs to raise on the first show
};

} // namespace ocu
