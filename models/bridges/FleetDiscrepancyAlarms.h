#pragma once
// ISO 23725 fleet discrepancies as alarms (EEMUA 191 / ISA-18.2): one alarm per cause and link,
// not one per machine. 1,000 machines of the AHS missing from the FMS fleet make one alarm "1,000 machines of
// the AHS are not in the FMS fleet on <link>" whose details list the machines. Its key (cause, link, source)
// is the same on every console and on every re-check, so a repeat updates the alarm instead of adding one.
#include "models/FleetEvent.h"
#include "protocols/iso23725/FleetDiscrepancies.h"

#include <QVector>

#include <string>
#include <vector>

namespace ocu {

QVector<FleetEvent> fleetDiscrepancyAlarms(const std::string& link,
                                           const std::vector<iso23725::FleetDiscrepancy>& items);

} // namespace ocu
