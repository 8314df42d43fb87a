#include "app/modules/IsoProduction.h"

#include "app/MainWindow.h"
#include "models/FleetContext.h"
#include "models/ProductionModel.h"
#include "models/bridges/IsoBridge.h"
#include "widgets/production/ProductionView.h"
#include "widgets/production/ShiftReport.h"

#include <QAction>
#include <QDockWidget>
#include <QKeySequence>
#include <QScrollArea>

namespace ocu {

ProductionModel* attachProductionModel(IsoBridge* bridge) {
    qRegisterMetaType<ProductionReport>(); // queued from the stack's io thread
    auto* model = new ProductionModel(bridge);
    model->setObjectName(QStringLiteral("production"));
    QObject::connect(bridge, &IsoBridge::productionReport, model, &ProductionModel::addReport,
                     Qt::QueuedConnection);
    QObject::connect(bridge, &IsoBridge::dispatchChanged, model, [bridge, model] {
        for (const IsoDestination& d : bridge->destinations())
            model->setAreaName(d.wayId, d.name);
    });
    return model;
}

void addProductionDock(MainWindow& window, FleetContext* fleet, IsoBridge* bridge, ProductionModel* model,
                       const QString& siteName) {
    if (!model)
        return;
    auto* view = new ProductionView(model);
    view->setSiteName(siteName);
    FleetModel* fleetModel = fleet ? fleet->fleet() : nullptr;
    view->setMapSnapshotSource([fleetModel, bridge](const QSize& size) {
        return renderSiteSnapshot(fleetModel, bridge->siteMap(), size);
    });
    auto* dock = new QDockWidget(QObject::tr("Production"), &window);
    dock->setObjectName(QStringLiteral("dock-production"));
    // Not closable: it has no entry in the View menu to bring it back.
    dock->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable);
    // Scrolls rather than forcing the bottom row wider than a 1366 px screen.
    auto* scroll = new QScrollArea;
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidgetResizable(true);
    scroll->setWidget(view);
    dock->setWidget(scroll);
    window.addDockWidget(Qt::BottomDockWidgetArea, dock);
    if (QDockWidget* events = window.dock(Panel::EventLog)) {
        window.tabifyDockWidget(events, dock);
        events->raise();
    }
    // A keyboard path here too (Ctrl+9, after the Ctrl+1 … Ctrl+8 panels; docs/keyboard.md):
    // raises the panel and puts the focus on its first control.
    auto* go = new QAction(QObject::tr("Production"), dock);
    go->setObjectName(QStringLiteral("action-go-production"));
    go->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_9));
    go->setShortcutContext(Qt::ApplicationShortcut);
    QObject::connect(go, &QAction::triggered, dock, [dock, view] {
        dock->show();
        dock->raise();
        for (QWidget* c : view->findChildren<QWidget*>())
            if ((c->focusPolicy() & Qt::TabFocus) && c->isEnabled() && c->isVisibleTo(view)) {
                c->setFocus(Qt::ShortcutFocusReason);
                return;
            }
        view->setFocus(Qt::ShortcutFocusReason);
    });
    window.addAction(go);
}

} // namespace ocu
