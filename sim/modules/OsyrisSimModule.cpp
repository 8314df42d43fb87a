// The OSYRIS simulators of the simulated site: a paver and its rollers compacting a road near the site's road
// area, one station each on a multicast group, with the OCU's station index and machine names for the
// console.
#include "sim/SimModule.h"

#include "sim/SimulatedSite.h"
#include "sim/osyris/OsyrisDemo.h"

#include <nlohmann/json.hpp>

namespace ocu::sim {

namespace {

class OsyrisSimModule final : public SimModule {
public:
    std::string displayName() const override { return "OSYRIS"; }
    std::string summary() const override { return "an OSYRIS paving train"; }
    std::vector<SimOption> options() const override {
        return {{{"rollers"},
                 "N",
                 "Number of simulated rollers (0-3).",
                 [](const std::string& v, SiteConfig& c) {
                     return intOption("rollers", v, c.simulation.osyrisRollers, 3);
                 }},
                // The simulated paving train on a long job.
                {{"paving-job"},
                 "file",
                 "The paving train drives a long job: a LandXML file (first alignment, UTM) or \"built-in\".",
                 [](const std::string& v, SiteConfig& c) {
                     c.simulation.osyrisPavingJob = v;
                     return std::string();
                 }},
                {{"speedup"},
                 "factor",
                 "Simulated seconds per real second for the rollers (1-1000).",
                 [](const std::string& v, SiteConfig& c) {
                     return numberOption("speedup", v, c.simulation.osyrisSpeedUp, 1, 1000, "1..1000");
                 }},
                {{"lifts"}, "n", "Lifts of the paving job (1-20).", [](const std::string& v, SiteConfig& c) {
                     return intOption("lifts", v, c.simulation.osyrisLifts, 20);
                 }}};
    }
    std::string checkSimulation(const SiteConfig& config) const override {
        return config.simulation.osyrisLifts < 1 ? "--lifts must be 1..20" : std::string();
    }

    std::string start(SiteConfig& config, const GeoFrame& site) override {
        const auto& s = config.simulation;
        if (s.osyrisRollers <= 0)
            return {};
        osyris::OsyrisDemoOptions o;
        o.rollers = s.osyrisRollers;
        o.speedUp = s.osyrisSpeedUp;
        o.interfaceAddress = s.interfaceAddress;
        const GeoPoint road = site.toGeodetic({SimulatedSite::kRoadAreaE, SimulatedSite::kRoadAreaN, 0});
        if (!s.osyrisPavingJob.empty()) { // the paving train on a long job
            osyris::PavingJob job;
            if (s.osyrisPavingJob == "built-in") {
                job = osyris::builtInPavingJob();
            } else {
                auto loaded = osyris::pavingJobFromLandXml(s.osyrisPavingJob, road);
                if (!loaded)
                    return "simulated OSYRIS site: " + loaded.error();
                job = std::move(loaded.value());
            }
            job.lifts = s.osyrisLifts;
            job.liftThickness = s.osyrisLiftThickness;
            o.pavingJob = std::make_shared<const osyris::PavingJob>(std::move(job));
        }
        auto demo = std::make_unique<osyris::OsyrisDemo>(o);
        std::string err;
        if (!demo->start(&err))
            return "simulated OSYRIS site: " + err;
        auto c = demo->ocuConfig();
        c.originLat = road.lat;
        c.originLon = road.lon;
        c.originAlt = road.alt;
        if (config.osyris) {
            c.sqlitePath = config.osyris->sqlitePath;
            c.passCount = config.osyris->passCount;
        }
        if (o.pavingJob && !(c.passCount.liftThickness > 0)) { // count in the job's lifts
            c.passCount.liftThickness = o.pavingJob->liftThickness;
            c.passCount.liftBase = o.pavingJob->baseZ;
        }
        config.osyris = c;
        m_demo = std::move(demo);
        return {};
    }
    void stop() override {
        if (m_demo)
            m_demo->stop();
        m_demo.reset();
    }
    bool running() const override { return m_demo != nullptr; }

    std::vector<std::string> describe(const SiteConfig& config) const override {
        if (!m_demo)
            return {};
        std::vector<std::string> out{"OSYRIS: " + std::to_string(m_demo->stationCount()) + " stations on " +
                                     config.osyris->group + ":" + std::to_string(config.osyris->port) +
                                     " (interface " + config.osyris->interfaceAddress + ")"};
        if (const auto& job = m_demo->options().pavingJob)
            out.push_back("OSYRIS paving job: " + job->source + ", " + std::to_string(int(job->length())) +
                          " m, " + std::to_string(job->lifts) + " lifts of " +
                          std::to_string(int(job->liftThickness * 100)) + " cm, paver " +
                          std::to_string(int(job->paverSpeed * 60)) + " m/min, speed-up " +
                          std::to_string(int(config.simulation.osyrisSpeedUp)));
        return out;
    }

    void writeConsoleConfig(const SiteConfig& config, nlohmann::json& out) const override {
        using nlohmann::json;
        if (!m_demo)
            return;
        const std::string iface = config.simulation.interfaceAddress;
        const auto& o = *config.osyris;
        json machines = json::array();
        for (const auto& [idx, name] : o.machineNames) {
            auto t = o.machineTypes.find(idx);
            machines.push_back(
                {{"idx", idx}, {"name", name}, {"type", t == o.machineTypes.end() ? "" : t->second}});
        }
        out["osyris"] = {{"group", o.group},
                         {"port", o.port},
                         {"interface", iface == "127.0.0.1" ? "127.0.0.1" : "0.0.0.0"},
                         {"multicastTtl", o.multicastTtl},
                         {"originLat", o.originLat},
                         {"originLon", o.originLon},
                         {"originAlt", o.originAlt},
                         {"machines", machines}};
    }

private:
    std::unique_ptr<osyris::OsyrisDemo> m_demo;
};

} // namespace

std::unique_ptr<SimModule> makeOsyrisSimModule() {
    return std::make_unique<OsyrisSimModule>();
}

} // namespace ocu::sim
