#pragma once
// The ISO 23725 module's production part: the production model fed by the bridge's production
// reports (area names from its MapConnectivityV1), and its panel with the live charts and the shift report
// button.
#include <QString>

class QWidget;

namespace ocu {

class FleetContext;
class IsoBridge;
class ProductionModel;

// Owned by the bridge; the module keeps it and offers it (ProtocolModule::production()).
ProductionModel* attachProductionModel(IsoBridge* bridge);
// The production panel's content (the module's "production" panel).
QWidget* makeProductionView(FleetContext* fleet, IsoBridge* bridge, ProductionModel* model,
                            const QString& siteName);

} // namespace ocu
