#pragma once
// What the pass-count dock shows, as the protocol modules fill it: the pass-count panel, tabs a module adds
// beside it (the first one turns the dock into tabs), and a module's wrapper around the whole (e.g. the
// compaction areas beside it). SiteRuntime puts content() into the dock once every module has populated.
#include <QString>

#include <functional>

class QTabWidget;
class QWidget;

namespace ocu {

class PassCountPanel;

class PassCountDock {
public:
    explicit PassCountDock(PassCountPanel* panel);

    PassCountPanel* panel() const { return m_panel; }
    // A tab beside the pass counts (before any wrap()); returns its index in tabs().
    int addTab(QWidget* page, const QString& title);
    // The tabs, once a module has added one (else nullptr).
    QTabWidget* tabs() const { return m_tabs; }
    // Puts what the dock shows so far into wrap(content), e.g. a splitter with a panel beside it.
    void wrap(const std::function<QWidget*(QWidget* content)>& wrap);

    QWidget* content() const { return m_content; }

private:
    PassCountPanel* m_panel;
    QTabWidget* m_tabs = nullptr;
    QWidget* m_content;
};

} // namespace ocu
