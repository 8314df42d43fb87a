#include "app/PassCountDock.h"

#include "widgets/PassCountPanel.h"

#include <QCoreApplication>
#include <QScrollArea>
#include <QTabWidget>

namespace ocu {

PassCountDock::PassCountDock(PassCountPanel* panel) : m_panel(panel), m_content(panel) {}

int PassCountDock::addTab(QWidget* page, const QString& title) {
    if (!m_tabs) {
        m_tabs = new QTabWidget;
        // The panel (summary, lift, filters, histogram) scrolls inside its tab: beside it the areas panel
        // stays in view in a low dock (1366 x 768).
        auto* passScroll = new QScrollArea;
        passScroll->setFrameShape(QFrame::NoFrame);
        passScroll->setWidgetResizable(true);
        passScroll->setWidget(m_panel);
        m_tabs->addTab(passScroll, QCoreApplication::translate("ocu::SiteRuntime", "Pass counts"));
        m_content = m_tabs;
    }
    return m_tabs->addTab(page, title);
}

void PassCountDock::wrap(const std::function<QWidget*(QWidget* content)>& wrap) {
    m_content = wrap(m_content);
}

} // namespace ocu
