#pragma once
// Configuration of the ISO 23725 stack: the site configuration's `iso23725` object (docs/iso23725.md).
#include "protocols/iso23725/InferredRules.h"
#include "protocols/iso23725/Messages.h"
#include "protocols/iso23725/WsEndpoint.h"

#include "protocols/common/PosePlausibility.h"

#include <chrono>
#include <string>
#include <vector>

namespace ocu {
class ConfigObject;
}

namespace ocu::iso23725 {

struct IsoLinkConfig {
    std::string name; // shown to the operator, used as the link key in commands and callbacks
    WsOptions ws;     // URL, role, TLS, ping/dead/backoff, max frame size
    // Q10 [I]: the map service on its own socket (client role, TLS and timing as ws); empty url = the map
    // service shares the main socket.
    WsOptions mapWs;
};

struct IsoConfig {
    bool enabled = true;
    // The FMS's own fleet id, sent as AHSId in its FleetDefinitionV2 ([I], research note §6 example 1).
    Guid fmsId = "00000000-0000-4000-8000-000000000000";
    std::vector<IsoLinkConfig> links;
    // The FMS's configured fleet: manned machines it owns (Autonomous=false; sent in its FleetDefinitionV2)
    // and the autonomous machines it expects from the AHS (compared with the AHS list, never sent).
    std::vector<Equipment> fleet;
    bool sendPositions = false;                           // send MachinePositionV1 for own manned machines
    double positionRateHz = 1.0;                          // 1-10 Hz (§7.4)
    std::chrono::milliseconds allStopAckTimeout{2000};    // [I] §7.6
    std::chrono::milliseconds allStopStatusTimeout{5000}; // [I] §7.6
    double dimensionTolerance = 0.05;                     // metres, for fleet discrepancy checks
    // §5 #15 [I] (Q7): InterfaceDiagnosticV1 "periodic (60 s) + on error"; error reports are sent at most
    // once per errorDiagnosticInterval (the rest are batched into the next one) so bad input cannot flood the
    // AHS.
    std::chrono::milliseconds interfaceDiagnosticPeriod{60000};
    std::chrono::milliseconds errorDiagnosticInterval{1000};
    InferredRules rules;
    // Positions outside these are not drawn: the machine is marked implausible, its last good position kept
    // (checked by the console's bridge in the site frame).
    PoseLimits plausibility;
};

// Reads the `iso23725` object strictly (unknown keys, wrong types and bad values are errors naming the key).
IsoConfig parseIsoConfig(ocu::ConfigObject& section);

} // namespace ocu::iso23725
