// MainWindow's workspaces: laying the docks out for the workspace shown (app/WorkspaceLayout.h), switching
// workspace, and keeping each person's arrangement per screen set-up in QSettings.
#include "app/MainWindow.h"
#include "app/WorkspaceBar.h"

#include <QDockWidget>
#include <QGuiApplication>
#include <QResizeEvent>
#include <QScreen>
#include <QSet>
#include <QSettings>
#include <QTimer>
#include <QToolBar>

#include <algorithm>

namespace ocu {

namespace {
// Arrangements saved before there were workspaces, or before a vehicle's video was a panel of its own, are
// not restored (their docks were in other places).
constexpr int kLayoutVersion = 3;
} // namespace

QList<Workspace> MainWindow::offeredWorkspaces() const {
    QSet<PanelKind> present;
    for (const PanelSpec& p : m_panels)
        present.insert(p.kind);
    QList<Workspace> out;
    for (Workspace w : kAllWorkspaces) {
        const QList<PanelKind> needs = workspacePlan(w).needs;
        if (needs.isEmpty() ||
            std::any_of(needs.begin(), needs.end(), [&present](PanelKind k) { return present.contains(k); }))
            out << w;
    }
    return out;
}

void MainWindow::updateOfferedWorkspaces() {
    const QList<Workspace> offered = offeredWorkspaces();
    m_workspaceBar->setOffered(offered);
    if (!offered.contains(m_workspace))
        m_workspace = Workspace::All;
    m_workspaceBar->setCurrent(m_workspace);
}

MainWindow::Groups MainWindow::workspaceGroups() const {
    const WorkspacePlan plan = workspacePlan(m_workspace);
    Groups g;
    QSet<QDockWidget*> used;
    const auto take = [&](const QList<PanelKind>& kinds, QList<QDockWidget*>& out) {
        for (PanelKind k : kinds)
            for (const PanelSpec& p : m_panels)
                if (QDockWidget* d = m_docks.value(p.key); d && p.kind == k && !used.contains(d)) {
                    out << d;
                    used.insert(d);
                }
    };
    take(plan.main, g.main);
    take(plan.sideTop, g.top);
    take(plan.sideBottom, g.bottom);
    // A panel of no kind a workspace names (shown in All) goes where its module places it: with the vehicle
    // and fleet panels, or with the tables.
    for (const PanelSpec& p : m_panels)
        if (QDockWidget* d = m_docks.value(p.key);
            p.kind == PanelKind::Other && p.place == PanelPlace::SideColumn && g.bottom.removeOne(d))
            g.top << d;
    // A workspace without its main panel on this site: the side column's panels move up.
    while (g.main.isEmpty() && (!g.top.isEmpty() || !g.bottom.isEmpty())) {
        g.main = g.top;
        g.top = g.bottom;
        g.bottom.clear();
    }
    for (const PanelSpec& p : m_panels)
        if (QDockWidget* d = m_docks.value(p.key); d && !used.contains(d))
            g.others << d;
    return g;
}

void MainWindow::applyDefaultLayout() {
    // The main area on the left, the side column's top and bottom groups on the right; splits first, tabs
    // last (tabifying before a split drags the whole tab group along). The panels this workspace does not
    // show wait hidden as tabs of its last group: Ctrl+N or the View menu brings one there.
    const Groups g = workspaceGroups();
    for (QDockWidget* d : std::as_const(m_docks)) {
        d->setFloating(false);
        removeDockWidget(d);
    }
    if (g.main.isEmpty())
        return;
    QDockWidget* main = g.main.first();
    QDockWidget* top = g.top.value(0);
    QDockWidget* bottom = g.bottom.value(0);
    addDockWidget(Qt::LeftDockWidgetArea, main);
    if (top)
        splitDockWidget(main, top, Qt::Horizontal);
    if (bottom)
        splitDockWidget(top ? top : main, bottom, top ? Qt::Vertical : Qt::Horizontal);
    for (const QList<QDockWidget*>* group : {&g.main, &g.top, &g.bottom})
        for (QDockWidget* d : group->mid(1))
            tabifyDockWidget(group->first(), d);
    QDockWidget* last = bottom ? bottom : top ? top : main;
    for (QDockWidget* d : g.others)
        tabifyDockWidget(last, d);
    for (const QList<QDockWidget*>* group : {&g.main, &g.top, &g.bottom})
        for (QDockWidget* d : *group)
            d->show();
    for (QDockWidget* d : g.others)
        d->hide();
    for (QDockWidget* d : {main, top, bottom})
        if (d)
            d->raise();
    m_fitPending = true;
    m_raisePending = true; // a tab group laid out again keeps its first tab in front until shown
    m_bannerBar->setVisible(!m_bannerText.isEmpty());
}

void MainWindow::layOutAgain() {
    applyDefaultLayout();
    if (!isVisible())
        return; // shared out on the first show
    // The docks just placed are sized by the layout's next pass: shared out after it.
    QTimer::singleShot(0, this, [this] {
        if (m_fitPending)
            fitDocksToWindow();
    });
}

void MainWindow::fitDocksToWindow() {
    const int w = width(), h = height();
    if (w < 200 || h < 200)
        return;
    const WorkspacePlan plan = workspacePlan(m_workspace);
    const Groups g = workspaceGroups();
    if (g.main.isEmpty())
        return;
    // The main area's share of the width (the map or the video keeps most of the window: 45 % of a
    // 1366 x 768 window, 55 % of 1920 x 1080), the side column the rest, split between its groups.
    const int mainPercent = w < 1600 ? plan.mainPercentSmall : plan.mainPercentLarge;
    QDockWidget* top = g.top.value(0);
    QDockWidget* bottom = g.bottom.value(0);
    if (QDockWidget* side = top ? top : bottom)
        resizeDocks({g.main.first(), side}, {w * mainPercent / 100, w * (100 - mainPercent) / 100},
                    Qt::Horizontal);
    const int topPercent = w >= 1600 && plan.topPercentLarge > 0 ? plan.topPercentLarge : plan.topPercent;
    if (top && bottom)
        resizeDocks({top, bottom}, {h * topPercent / 100, h * (100 - topPercent) / 100}, Qt::Vertical);
    m_fitPending = false;
}

void MainWindow::setWorkspace(Workspace workspace) {
    if (!offeredWorkspaces().contains(workspace)) {
        m_workspaceBar->setCurrent(m_workspace);
        return;
    }
    if (workspace == m_workspace) {
        m_workspaceBar->setCurrent(m_workspace);
        return;
    }
    keepArrangement();
    m_workspace = workspace;
    m_workspaceBar->setCurrent(workspace);
    if (!restoreArrangement(workspace))
        layOutAgain();
    if (isVisible())
        m_raisePending = false; // applyDefaultLayout raised the groups' first tabs already
    QSettings().setValue(settingsGroup() + QStringLiteral("/current"), workspaceKey(workspace));
}

void MainWindow::setOperator(const QString& user, Workspace first) {
    if (user == m_user && !m_user.isEmpty())
        return;
    const bool live = isVisible(); // a switch of operator at a running console
    if (live)
        keepArrangement(); // the previous person's
    m_user = user;
    m_arrangements.clear();
    Workspace w = first;
    if (live)
        workspaceFromKey(QSettings().value(settingsGroup() + QStringLiteral("/current")).toString(), &w);
    if (!offeredWorkspaces().contains(w))
        w = offeredWorkspaces().contains(first) ? first : Workspace::All;
    m_workspace = w;
    m_workspaceBar->setCurrent(w);
    if (!live || !restoreArrangement(w))
        layOutAgain();
}

QString MainWindow::screenSetupKey() {
    // Each screen's place and size: a laptop alone and the same laptop with its second screen are two
    // set-ups, each with its own arrangements (a dock floated onto the second screen comes back there).
    QStringList screens;
    for (const QScreen* s : QGuiApplication::screens()) {
        const QRect g = s->geometry();
        screens << QStringLiteral("%1x%2+%3+%4").arg(g.width()).arg(g.height()).arg(g.x()).arg(g.y());
    }
    screens.sort();
    return screens.isEmpty() ? QStringLiteral("none") : screens.join(QLatin1Char('_'));
}

QString MainWindow::settingsGroup() const {
    QString user = m_user;
    user.replace(QLatin1Char('/'), QLatin1Char('_'));
    return QStringLiteral("workspaces/%1/%2")
        .arg(user.isEmpty() ? QStringLiteral("-") : user, screenSetupKey());
}

void MainWindow::keepArrangement() {
    // Only a shown window has sizes worth keeping (shared out first if a new arrangement still waits for it).
    if (!isVisible())
        return;
    if (m_fitPending)
        fitDocksToWindow();
    const QByteArray state = saveState(kLayoutVersion);
    m_arrangements.insert(m_workspace, state);
    QSettings settings;
    settings.setValue(
        settingsGroup() + QLatin1Char('/') + workspaceKey(m_workspace) + QStringLiteral("/state"), state);
    settings.setValue(settingsGroup() + QStringLiteral("/current"), workspaceKey(m_workspace));
}

bool MainWindow::restoreArrangement(Workspace workspace) {
    QByteArray state = m_arrangements.value(workspace);
    if (state.isEmpty())
        state = QSettings()
                    .value(settingsGroup() + QLatin1Char('/') + workspaceKey(workspace) +
                           QStringLiteral("/state"))
                    .toByteArray();
    if (state.isEmpty() || !restoreState(state, kLayoutVersion))
        return false;
    // The person's own sizes, tabs in front and floating docks (also on a second screen) stay.
    m_fitPending = false;
    m_raisePending = false;
    m_bannerBar->setVisible(!m_bannerText.isEmpty()); // a saved layout never hides a failed stop
    return true;
}

void MainWindow::resetLayout() {
    m_arrangements.remove(m_workspace);
    QSettings().remove(settingsGroup() + QLatin1Char('/') + workspaceKey(m_workspace));
    for (QDockWidget* d : std::as_const(m_docks))
        d->setFloating(false);
    layOutAgain();
    if (isVisible())
        m_raisePending = false;
}

void MainWindow::saveLayout() {
    keepArrangement();
    QSettings s;
    const QString g = settingsGroup();
    s.setValue(g + QStringLiteral("/geometry"), saveGeometry());
    s.setValue(g + QStringLiteral("/current"), workspaceKey(m_workspace));
    s.setValue(QStringLiteral("window/night"), m_night);
}

bool MainWindow::restoreLayout() {
    QSettings s;
    const QString g = settingsGroup();
    setNightMode(s.value(QStringLiteral("window/night"), false).toBool());
    const QByteArray geometry = s.value(g + QStringLiteral("/geometry")).toByteArray();
    Workspace w = m_workspace;
    if (workspaceFromKey(s.value(g + QStringLiteral("/current")).toString(), &w) &&
        offeredWorkspaces().contains(w) && w != m_workspace) {
        m_workspace = w;
        m_workspaceBar->setCurrent(w);
        applyDefaultLayout();
    }
    if (geometry.isEmpty())
        return false;
    restoreGeometry(geometry);
    return restoreArrangement(m_workspace);
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
        const Groups g = workspaceGroups();
        for (const QList<QDockWidget*>* group : {&g.main, &g.top, &g.bottom})
            if (!group->isEmpty())
                group->first()->raise();
        for (const QString& key : std::as_const(m_raisedPanels))
            if (QDockWidget* d = dock(key); d && d->isVisible())
                d->raise();
    }
    // The size was set before show (first start, screenshot, restored geometry without a state): shared out
    // once the layout has placed the docks at it (shared out now, the layout's first pass undoes it).
    if (m_fitPending)
        QTimer::singleShot(0, this, [this] {
            if (m_fitPending)
                fitDocksToWindow();
        });
}

} // namespace ocu
