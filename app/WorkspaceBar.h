#pragma once
// The workspace bar at the top of the window, beside STOP ALL (like QGroundControl's Fly/Plan switch): one
// button per workspace the site offers, Alt+1 … Alt+5 from anywhere in the window.
#include "app/WorkspaceLayout.h"

#include <QMap>
#include <QToolBar>

class QAction;
class QActionGroup;

namespace ocu {

class WorkspaceBar : public QToolBar {
    Q_OBJECT
public:
    explicit WorkspaceBar(QWidget* parent = nullptr);

    // The workspaces whose buttons show (the others keep their place and key, hidden and inactive).
    void setOffered(const QList<Workspace>& offered);
    bool isOffered(Workspace workspace) const;
    // Checks the workspace's button (no signal).
    void setCurrent(Workspace workspace);
    QAction* action(Workspace workspace) const { return m_actions.value(workspace); }
    // The keys of the offered workspaces for Help › Keyboard shortcuts ("Alt+4: Monitor").
    QStringList keyboardHelp() const;

signals:
    void chosen(Workspace workspace);

private:
    QActionGroup* m_group;
    QMap<Workspace, QAction*> m_actions;
};

} // namespace ocu
