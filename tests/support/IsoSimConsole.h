#pragma once
// Test support for the loopback tests of the console's ISO 23725 side against the simulated AHS (one
// place for what several tests repeated): the simulated AHS's configuration and the console's one-link
// configuration with quick reconnects and liveness (pings every 500 ms).
#include "protocols/iso23725/IsoConfig.h"
#include "sim/iso23725/SimulatedAhs.h"

#include <chrono>
#include <string>

namespace isosim {

// `timeScale` > 1 runs the haul cycle faster (a cycle in well under a minute at 8).
inline ocu::sim::SimulatedAhsConfig ahsConfig(int trucks, double positionRateHz, double timeScale = 1.0) {
    ocu::sim::SimulatedAhsConfig c;
    c.truckCount = trucks;
    c.healthEvents = false;
    c.positionRateHz = positionRateHz;
    c.timeScale = timeScale;
    return c;
}

// One link "ahs" to `url`. A simulation running faster than real time moves its trucks further between
// reports than a real truck: give it `maxSpeedMps` (0 = the default plausibility limit).
inline ocu::iso23725::IsoConfig
consoleConfig(const std::string& url, std::chrono::milliseconds deadAfter = std::chrono::milliseconds(3000),
              double maxSpeedMps = 0) {
    ocu::iso23725::IsoConfig c;
    c.links.push_back(ocu::iso23725::IsoLinkConfig{"ahs", {}, {}});
    c.links[0].ws.url = url;
    c.links[0].ws.backoffMin = std::chrono::milliseconds(100);
    c.links[0].ws.backoffMax = std::chrono::milliseconds(400);
    c.links[0].ws.pingInterval = std::chrono::milliseconds(500);
    c.links[0].ws.deadAfter = deadAfter;
    if (maxSpeedMps > 0)
        c.plausibility.maxSpeedMps = maxSpeedMps;
    return c;
}

} // namespace isosim
