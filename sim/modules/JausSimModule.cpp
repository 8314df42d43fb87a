// The JAUS simulators of the simulated site: N RAS-G IOP UGVs on loopback (or the given interface), one
// multicast group, started in a row near the site's UGV area.
#include "sim/SimModule.h"

#include "sim/SimulatedSite.h"
#include "sim/jaus/JausDemo.h"

#include <nlohmann/json.hpp>

#include <exception>

namespace ocu::sim {

namespace {

class JausSimModule final : public SimModule {
public:
    std::string displayName() const override { return "JAUS"; }
    std::string summary() const override { return "JAUS UGVs"; }
    std::vector<SimOption> options() const override {
        return {{{"ugvs"}, "N", "Number of simulated JAUS UGVs.", [](const std::string& v, SiteConfig& c) {
                     return intOption("ugvs", v, c.simulation.jausUgvs, 50);
                 }}};
    }

    std::string start(SiteConfig& config, const GeoFrame& site) override {
        const auto& s = config.simulation;
        if (s.jausUgvs <= 0)
            return {};
        try {
            JausDemoOptions o;
            o.count = s.jausUgvs;
            o.origin = site.toGeodetic({SimulatedSite::kUgvAreaE, SimulatedSite::kUgvAreaN, 0});
            o.interfaceAddress = s.interfaceAddress;
            o.video = true; // simulated cameras over RTSP, announced through the IOP services
            m_demo = std::make_unique<JausDemo>(o);
            if (!config.jaus)
                config.jaus = jaus::JausConfig{};
            m_demo->configure(*config.jaus);
        } catch (const std::exception& e) {
            return std::string("simulated JAUS UGVs: ") + e.what();
        }
        return {};
    }
    void stop() override {
        if (m_demo)
            m_demo->stop();
        m_demo.reset();
    }
    bool running() const override { return m_demo != nullptr; }

    std::vector<std::string> describe(const SiteConfig& config) const override {
        std::vector<std::string> lines;
        if (!m_demo)
            return lines;
        lines.push_back("JAUS: " + std::to_string(m_demo->ugvs().size()) + " UGVs, multicast " +
                        config.jaus->transport.multicastGroup + ":" +
                        std::to_string(m_demo->multicastPort()) + " on 127.0.0.1");
        for (auto& u : m_demo->ugvs())
            lines.push_back("  " + u->config().callSign + " subsystem " +
                            std::to_string(u->config().subsystemId) +
                            ", unicast 127.0.0.1:" + std::to_string(u->localPort()));
        for (auto& u : m_demo->ugvs()) // the cameras (also announced through the IOP services)
            for (const SimCameraConfig& c : u->config().cameras)
                if (std::string url = u->cameraUrl(c.sensorId); !url.empty())
                    lines.push_back("  " + u->config().callSign + " camera " + std::to_string(c.sensorId) +
                                    " \"" + c.name + "\" " + url);
        return lines;
    }

    void writeConsoleConfig(const SiteConfig& config, nlohmann::json& out) const override {
        using nlohmann::json;
        if (!m_demo)
            return;
        const std::string iface = config.simulation.interfaceAddress;
        json statics = json::array();
        for (auto& u : m_demo->ugvs())
            statics.push_back(
                {{"subsystem", u->config().subsystemId}, {"address", iface}, {"port", u->localPort()}});
        out["jaus"] = {{"subsystem_id", 200},
                       {"call_sign", "OCU"},
                       {"role", "primary_operator"},
                       {"authority", 205},
                       {"port", 0},
                       {"multicast_group", config.jaus->transport.multicastGroup},
                       {"multicast_port", m_demo->multicastPort()},
                       {"multicast_ttl", iface == "127.0.0.1" ? 0 : 1},
                       {"interface_address", iface == "127.0.0.1" ? "127.0.0.1" : "0.0.0.0"},
                       {"static_endpoints", statics}};
    }

private:
    std::unique_ptr<JausDemo> m_demo;
};

} // namespace

std::unique_ptr<SimModule> makeJausSimModule() {
    return std::make_unique<JausSimModule>();
}

} // namespace ocu::sim
