#pragma once
// The fleet check of an ISO 23725 link ([ISO-seed] FleetDefinitionV2): the AHS's fleet definition against the
// fleet the FMS is configured with. One line per discrepancy, for the operator: an autonomous machine the AHS
// does not list, a machine listed by both (manned at the FMS), a different HID, type or dimensions (beyond
// the tolerance, m), a machine of the AHS the FMS does not know. Empty when both agree.
#include "protocols/iso23725/Messages.h"

#include <string>
#include <vector>

namespace ocu::iso23725 {

// The cause of a discrepancy: the operator sees one alarm per cause and link (EEMUA 191 / ISA-18.2: one
// cause, one alarm), with the machines in its details.
enum class DiscrepancyCause {
    MissingFromAhs,
    ListedByBoth,
    HidDiffers,
    TypeDiffers,
    DimensionsDiffer,
    NotInFms
};

struct FleetDiscrepancy {
    DiscrepancyCause cause = DiscrepancyCause::NotInFms;
    std::string machine; // equipment id
    std::string text;    // one line for the operator
};

// Stable identifier of a cause ("fleet.not_in_fms", ...), used in alarm keys shared by consoles.
const char* causeId(DiscrepancyCause cause);

std::vector<FleetDiscrepancy> checkFleet(const FleetDefinitionV2& ahs, const std::vector<Equipment>& fms,
                                         double dimensionTolerance);
// The texts of checkFleet, in the same order.
std::vector<std::string> fleetDiscrepancies(const FleetDefinitionV2& ahs, const std::vector<Equipment>& fms,
                                            double dimensionTolerance);
std::vector<std::string> discrepancyTexts(const std::vector<FleetDiscrepancy>& items);

} // namespace ocu::iso23725
