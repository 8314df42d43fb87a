#pragma once
// The console's main window: dockable, closable, re-openable panels around the site, a toolbar whose
// STOP ALL is always visible, and a status bar with one indicator per protocol link.
#include <QMainWindow>
#include <QMap>

#include "app/LinkIndicator.h"

class QDockWidget;
class QLabel;
class QMenu;
class QToolBar;
class QToolButton;

namespace ocu {

enum class Panel { Fleet, SiteMap, Site3D, JausControl, Teleop, PassCounts, EventLog, Dispatch };

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    static QList<Panel> panels();
    static QString
    panelKey(Panel panel); // stable name: fleet, map, 3d, jaus, teleop, passcounts, events, dispatch
    QString panelTitle(Panel panel) const;

    QDockWidget* dock(Panel panel) const { return m_docks.value(panel); }
    // Replaces the panel's content; the window takes ownership.
    void setPanelWidget(Panel panel, QWidget* widget);
    QWidget* panelWidget(Panel panel) const;

    QAction* stopAllAction() const { return m_stopAll; }
    QToolButton* stopAllButton() const { return m_stopAllButton; }
    // One indicator per protocol link, added by the runtime for each protocol module (left to right).
    LinkIndicator* addLinkIndicator(const QString& protocol);
    LinkIndicator* linkIndicator(const QString& protocol) const { return m_links.value(protocol); }
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

    // Layout persistence (QSettings). restoreLayout() returns false when nothing was saved.
    void saveLayout() const;
    bool restoreLayout();
    void resetLayout();
    // Shares the window's width and height among the default docks in proportion (at 1366 x 768
    // the map must not end up a small square); called on the first show of a default layout and by
    // resetLayout().
    void fitDocksToWindow();
    // First start (no saved layout): maximized, or the screen's available size where maximizing is not
    // possible (offscreen).
    void showFirstStart();
    // Raises the panel and puts the keyboard focus on its first control (Ctrl+1 … Ctrl+8).
    void focusPanel(Panel panel);
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
    void createDocks();
    void createToolBar();
    void createMenus();
    void createStatusBar();
    void applyDefaultLayout();
    void createPanelShortcuts(QMenu* view);

    QMap<Panel, QDockWidget*> m_docks;
    QMap<QString, LinkIndicator*> m_links;
    QAction* m_stopAll = nullptr;
    QToolButton* m_stopAllButton = nullptr;
    QAction* m_nightAction = nullptr;
    QLabel* m_alarmLabel = nullptr;
    QToolBar* m_bannerBar = nullptr;
    QLabel* m_bannerLabel = nullptr;
    QString m_bannerText;
    QByteArray m_defaultState;
    int m_unacked = 0;
    bool m_night = false;
    bool m_fitPending = true; // default layout not yet shared out for the real window size
};

} // namespace ocu
