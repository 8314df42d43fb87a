#pragma once
// The ISO 23725 module's production part: the production model fed by the bridge's production
// reports (area names from its MapConnectivityV1), and its dock in the main window (tabbed with the event
// log) with the live charts and the shift report button.
#include <QString>

namespace ocu {

class FleetContext;
class IsoBridge;
class MainWindow;
class ProductionModel;

// Owned by the bridge; the module keeps it and offers it (ProtocolModule::production()).
ProductionModel* attachProductionModel(IsoBridge* bridge);
void addProductionDock(MainWindow& window, FleetContext* fleet, IsoBridge* bridge, ProductionModel* model,
                       const QString& siteName);

} // namespace ocu
