// The ISO 23725 simulator of the simulated site: an AHS with its haul trucks on a generated open pit around
// the site origin, serving the FMS over WebSocket (and its map service on a socket of its own when asked).
#include "sim/SimModule.h"

#include "sim/iso23725/IsoDemo.h"
#include "sim/iso23725/PitTerrain.h"

#include <nlohmann/json.hpp>

namespace ocu::sim {

namespace {

class IsoSimModule final : public SimModule {
public:
    std::string displayName() const override { return "ISO 23725"; }
    std::string summary() const override { return "an ISO 23725 AHS with haul trucks"; }
    std::vector<SimOption> options() const override {
        return {{{"trucks"},
                 "N",
                 "Number of simulated haul trucks (≤ 1000).",
                 [](const std::string& v, SiteConfig& c) {
                     return intOption("trucks", v, c.simulation.ahsTrucks, 1000);
                 }},
                {{"separate-map-service"},
                 "",
                 "The AHS serves its ISO 23725 map service on a socket of its own (the written configuration "
                 "gets "
                 "its mapUrl).",
                 [](const std::string&, SiteConfig& c) {
                     c.simulation.ahsSeparateMapService = true;
                     return std::string();
                 }},
                {{"position-rate", "truck-rate"},
                 "HZ",
                 "Positions per second of each simulated haul truck (1-10; --truck-rate is the older name).",
                 [](const std::string& v, SiteConfig& c) {
                     return numberOption("position-rate", v, c.simulation.ahsPositionRateHz, 1, 10, "1..10");
                 }}};
    }

    std::string start(SiteConfig& config, const GeoFrame&) override {
        const auto& s = config.simulation;
        if (s.ahsTrucks <= 0)
            return {};
        SimulatedAhsConfig c;
        c.truckCount = s.ahsTrucks;
        c.origin = config.origin;
        c.positionRateHz = s.ahsPositionRateHz;
        c.separateMapService = s.ahsSeparateMapService;
        c.bindAddress = s.interfaceAddress;
        auto demo = std::make_unique<IsoDemo>(startIsoDemo(c));
        if (!demo->ahs)
            return "simulated AHS: " + demo->error;
        // The demo's link and FMS fleet go into the site's section; other keys of a given section stay.
        if (config.iso23725)
            config.iso23725->links = demo->config.links;
        else
            config.iso23725 = demo->config;
        m_demo = std::move(demo);
        // The pit's DEM and hillshade, consistent with the map the AHS serves; the site uses
        // them as map background and 3D terrain unless its configuration names others.
        m_terrain = {};
        if (config.background.raster.empty() || config.terrain.dem.empty()) {
            const PitLayout layout{c.shovelCount, c.dumpCount, c.origin};
            m_terrain = writePitTerrain(generatePitMap(layout, 0), c.origin, defaultPitTerrainDir(layout));
            if (m_terrain.error.empty()) {
                if (config.background.raster.empty())
                    config.background.raster = m_terrain.hillshade;
                if (config.terrain.dem.empty())
                    config.terrain.dem = m_terrain.dem;
            }
        }
        return {};
    }
    void stop() override {
        if (m_demo && m_demo->ahs)
            m_demo->ahs->stop();
        m_demo.reset();
    }
    bool running() const override { return m_demo && m_demo->ahs; }

    std::vector<std::string> describe(const SiteConfig& config) const override {
        std::vector<std::string> lines;
        if (!running())
            return lines;
        for (const auto& l : config.iso23725->links)
            lines.push_back("ISO 23725: AHS with " + std::to_string(config.simulation.ahsTrucks) +
                            " trucks at " + l.ws.url + (l.mapWs.url.empty() ? "" : ", map service at ") +
                            l.mapWs.url);
        if (!m_terrain.error.empty())
            lines.push_back("ISO 23725: no pit terrain: " + m_terrain.error);
        else if (!m_terrain.dem.empty())
            lines.push_back("ISO 23725: pit terrain " + m_terrain.dem + ", hillshade " + m_terrain.hillshade);
        return lines;
    }

    void writeConsoleConfig(const SiteConfig& config, nlohmann::json& out) const override {
        using nlohmann::json;
        if (!running())
            return;
        json links = json::array();
        for (const auto& l : config.iso23725->links) {
            json link = {{"name", l.name}, {"url", l.ws.url}};
            if (!l.mapWs.url.empty())
                link["mapUrl"] = l.mapWs.url;
            links.push_back(link);
        }
        // The FMS fleet too (the manned machines and the trucks it expects from the AHS): a console
        // configured from this file must not report its own simulator's trucks as fleet
        // discrepancies.
        json fleet = json::array();
        for (const auto& e : config.iso23725->fleet) {
            json m = {{"equipmentId", e.equipmentId},
                      {"hid", e.hid},
                      {"type", e.type},
                      {"oem", e.oem},
                      {"model", e.model},
                      {"autonomous", e.autonomous}};
            if (e.length)
                m["length"] = *e.length;
            if (e.width)
                m["width"] = *e.width;
            fleet.push_back(std::move(m));
        }
        out["iso23725"] = {{"fmsId", config.iso23725->fmsId},
                           {"sendPositions", config.iso23725->sendPositions},
                           {"links", links},
                           {"fleet", fleet}};
        // The pit's hillshade and DEM (or what the simulator's own configuration named), absolute paths.
        if (!config.background.raster.empty())
            out["background"] = {{"raster", config.background.raster}};
        if (!config.terrain.dem.empty())
            out["terrain"] = {{"dem", config.terrain.dem}};
    }

private:
    std::unique_ptr<IsoDemo> m_demo;
    PitTerrainFiles m_terrain;
};

} // namespace

std::unique_ptr<SimModule> makeIsoSimModule() {
    return std::make_unique<IsoSimModule>();
}

} // namespace ocu::sim
