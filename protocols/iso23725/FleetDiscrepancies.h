#pragma once
// The fleet check of an ISO 23725 link ([ISO-seed] FleetDefinitionV2): the AHS's fleet definition against the
// fleet the FMS is configured with. One line per discrepancy, for the operator: an autonomous machine the AHS
// does not list, a machine listed by both (manned at the FMS), a different HID, type or dimensions (beyond
// the tolerance, m), a machine of the AHS the FMS does not know. Empty when both agree.
#include "protocols/iso23725/Messages.h"

#include <string>
#include <vector>

namespace ocu::iso23725 {

std::vector<std::string> fleetDiscrepancies(const FleetDefinitionV2& ahs, const std::vector<Equipment>& fms,
                                            double dimensionTolerance);

} // namespace ocu::iso23725
