#pragma once
// Starts the simulated AHS on a free loopback port and fills an IsoConfig so the OCU connects to it
// (built-in simulated site, ocu-sim).
#include "protocols/iso23725/IsoConfig.h"
#include "sim/iso23725/SimulatedAhs.h"

#include <memory>

namespace ocu::sim {

struct IsoDemo {
    std::unique_ptr<SimulatedAhs> ahs; // null when it could not start (see error)
    iso23725::IsoConfig config; // one client link "ahs" to the simulator, plus a small manned FMS fleet
    std::string error;
};

// Geo-referenced around ahsConfig.origin. The FMS fleet holds a shovel and a light vehicle (manned, sent in
// the FMS fleet definition) and the simulator's trucks as the expected autonomous fleet.
IsoDemo startIsoDemo(SimulatedAhsConfig ahsConfig = {});

} // namespace ocu::sim
