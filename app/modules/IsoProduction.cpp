#include "app/modules/IsoProduction.h"

#include "models/FleetContext.h"
#include "models/ProductionModel.h"
#include "models/bridges/IsoBridge.h"
#include "widgets/production/ProductionView.h"
#include "widgets/production/ShiftReport.h"

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

QWidget* makeProductionView(FleetContext* fleet, IsoBridge* bridge, ProductionModel* model,
                            const QString& siteName) {
    auto* view = new ProductionView(model);
    view->setSiteName(siteName);
    FleetModel* fleetModel = fleet ? fleet->fleet() : nullptr;
    view->setMapSnapshotSource([fleetModel, bridge](const QSize& size) {
        return renderSiteSnapshot(fleetModel, bridge->siteMap(), size);
    });
    return view;
}

} // namespace ocu
