#include "sim/iso23725/IsoDemo.h"

namespace ocu::sim {

IsoDemo startIsoDemo(SimulatedAhsConfig ahsConfig) {
    IsoDemo demo;
    if (ahsConfig.bindAddress.empty())
        ahsConfig.bindAddress = "127.0.0.1";
    ahsConfig.port = 0; // the OS picks a free port: no race with another process
    auto ahs = std::make_unique<SimulatedAhs>(ahsConfig);
    if (!ahs->start()) {
        demo.error = "simulated AHS did not start: " + ahs->lastError();
        return demo;
    }
    iso23725::IsoLinkConfig link;
    link.name = "ahs";
    link.ws.url = ahs->url();
    link.ws.backoffMin = std::chrono::milliseconds(500);
    link.ws.backoffMax = std::chrono::milliseconds(5000);
    if (ahsConfig.separateMapService) { // Q10: the map service on its own socket, same timing
        link.mapWs = link.ws;
        link.mapWs.url = ahs->mapUrl();
    }
    demo.config.links.push_back(link);
    demo.config.fmsId = "1b9e6a40-3c2d-4f87-8e15-6a7b9c0d2e41";
    demo.config.fleet.push_back(iso23725::Equipment{"a2d4f6b8-1c3e-4a5b-9d7f-0e2c4b6a8d13", "SH01", "Shovel",
                                                    "Hitachi", "EX5600", false, 20.5, 8.6});
    demo.config.fleet.push_back(iso23725::Equipment{"9f8e7d6c-5b4a-4c3d-8e2f-1a0b9c8d7e65", "LV07",
                                                    "LightVehicle", "Toyota", "Land Cruiser 79", false, 5.2,
                                                    1.9});
    for (auto& e : ahs->fleet())
        demo.config.fleet.push_back(e);
    demo.config.sendPositions = true;
    demo.ahs = std::move(ahs);
    return demo;
}

} // namespace ocu::sim
