#include "app/WorkspaceBar.h"

#include <QAction>
#include <QActionGroup>
#include <QKeySequence>

namespace ocu {

WorkspaceBar::WorkspaceBar(QWidget* parent)
    : QToolBar(tr("Workspaces"), parent), m_group(new QActionGroup(this)) {
    setObjectName(QStringLiteral("toolbar-workspaces"));
    setMovable(false);
    setFloatable(false);
    setContextMenuPolicy(Qt::PreventContextMenu);
    toggleViewAction()->setVisible(false);
    setToolButtonStyle(Qt::ToolButtonTextOnly);
    m_group->setExclusive(true);
    int digit = 1;
    for (Workspace w : kAllWorkspaces) {
        auto* a = new QAction(workspaceTitle(w), this);
        a->setObjectName(QStringLiteral("action-workspace-") + workspaceKey(w));
        a->setCheckable(true);
        // Alt+digit: Ctrl+digit goes to a panel (docs/keyboard.md).
        a->setShortcut(QKeySequence(Qt::ALT | static_cast<Qt::Key>(Qt::Key_0 + digit++)));
        a->setShortcutContext(Qt::ApplicationShortcut); // also from a floating panel
        a->setToolTip(
            tr("%1 workspace (%2)").arg(a->text(), a->shortcut().toString(QKeySequence::NativeText)));
        m_group->addAction(a);
        addAction(a);
        m_actions.insert(w, a);
        connect(a, &QAction::triggered, this, [this, w] { emit chosen(w); });
    }
    // A tab-like look: the current workspace stands out.
    setStyleSheet(QStringLiteral("QToolButton { padding:6px 12px; font-weight:bold; }"
                                 "QToolButton:checked { background:palette(highlight);"
                                 " color:palette(highlighted-text); border-radius:4px; }"));
}

void WorkspaceBar::setOffered(const QList<Workspace>& offered) {
    for (auto it = m_actions.begin(); it != m_actions.end(); ++it) {
        const bool on = offered.contains(it.key());
        it.value()->setVisible(on);
        it.value()->setEnabled(on);
    }
}

bool WorkspaceBar::isOffered(Workspace workspace) const {
    QAction* a = m_actions.value(workspace);
    return a && a->isVisible();
}

void WorkspaceBar::setCurrent(Workspace workspace) {
    if (QAction* a = m_actions.value(workspace))
        a->setChecked(true);
}

QStringList WorkspaceBar::keyboardHelp() const {
    QStringList out;
    for (Workspace w : kAllWorkspaces)
        if (isOffered(w))
            out << QStringLiteral("    %1: %2")
                       .arg(m_actions.value(w)->shortcut().toString(QKeySequence::NativeText),
                            m_actions.value(w)->text());
    return out;
}

} // namespace ocu
