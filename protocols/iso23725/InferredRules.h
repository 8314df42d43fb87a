#pragma once
// The single adapter for every rule of the ISO 23725 working model marked [I] (inferred) in
// shared/research/iso23725.md. Nothing public fixes these; when the full standard is at hand, each
// question (Q1..Q12 of the note) is answered here and nowhere else.
#include <string>

namespace ocu::iso23725 {

struct InferredRules {
    // §9: accept the aliases seen in public text (HeightAccuracy, EquipmentID, AttachmentV1, "default task").
    bool acceptAliases = true;
    // §9: repair timestamps such as "2018-10-31T09:30:10.43.511Z" (warning) instead of rejecting them.
    bool repairTimestamps = true;
    // §9: accept numbers sent as strings ("Heading":"222") and decimals for integer members (rounded).
    bool acceptNumericStrings = true;
    // §9: HaulTruckAssignmentResponseV1 examples lack Version: accept a missing header Version (warning).
    bool acceptMissingVersion = true;
    // §4.3: enumerations are matched case-insensitively on input and emitted in canonical case.
    bool caseInsensitiveEnums = true;
    // Q4: the all-stop status may be named MachineAllStopStatusV1 in the standard.
    std::string allStopStatusAlias = "MachineAllStopStatusV1";
    // Q10: map service identification member (§10.6.1).
    std::string mapServiceMember = "MapServiceV1";
    // Q6: negative WayIds in RouteV1 (traverse against node order) are not emitted unless enabled.
    bool emitNegativeWayIds = false;
    // §5 #21: RouteV1 is optional; when set, an assignment without a route gets the shortest one over
    // MapConnectivityV1. Off: the AHS plans the route itself.
    bool sendRoutes = true;
    // §4.2: Protocol values other than ISO23725 are kept as out-of-standard messages (never fatal).
    std::string protocol = "ISO23725";
};

// Process-wide defaults used by the codec when no explicit rules are passed.
const InferredRules& defaultInferredRules();

} // namespace ocu::iso23725
