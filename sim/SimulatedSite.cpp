#include "sim/SimulatedSite.h"

#include "protocols/common/GeoFrame.h"
#include "protocols/common/Log.h"

#ifdef OCU_HAVE_SIM_JAUS
#include "sim/jaus/JausDemo.h"
#endif
#ifdef OCU_HAVE_SIM_ISO23725
#include "sim/iso23725/IsoDemo.h"
#endif
#ifdef OCU_HAVE_SIM_OSYRIS
#include "sim/osyris/OsyrisDemo.h"
#endif

#include <exception>

namespace ocu::sim {

struct SimulatedSite::Impl {
#ifdef OCU_HAVE_SIM_JAUS
    std::unique_ptr<JausDemo> jaus;
#endif
#ifdef OCU_HAVE_SIM_ISO23725
    std::unique_ptr<IsoDemo> iso;
#endif
#ifdef OCU_HAVE_SIM_OSYRIS
    std::unique_ptr<osyris::OsyrisDemo> osyris;
#endif
};

SimulatedSite::SimulatedSite() : m_impl(std::make_unique<Impl>()) {}
SimulatedSite::~SimulatedSite() {
    stop();
}

JausDemo* SimulatedSite::jaus() const {
#ifdef OCU_HAVE_SIM_JAUS
    return m_impl->jaus.get();
#else
    return nullptr;
#endif
}
IsoDemo* SimulatedSite::iso() const {
#ifdef OCU_HAVE_SIM_ISO23725
    return m_impl->iso.get();
#else
    return nullptr;
#endif
}
osyris::OsyrisDemo* SimulatedSite::osyris() const {
#ifdef OCU_HAVE_SIM_OSYRIS
    return m_impl->osyris.get();
#else
    return nullptr;
#endif
}

std::string SimulatedSite::start(SiteConfig& config) {
    std::string errors;
    auto fail = [&](const std::string& what) {
        logError("ocu.sim", what);
        errors += (errors.empty() ? "" : "\n") + what;
    };
    [[maybe_unused]] const GeoFrame frame(config.origin);
    [[maybe_unused]] const auto& s = config.simulation;
#ifdef OCU_HAVE_SIM_JAUS
    if (s.jausUgvs > 0) {
        try {
            JausDemoOptions o;
            o.count = s.jausUgvs;
            o.origin = frame.toGeodetic({kUgvAreaE, kUgvAreaN, 0});
            o.interfaceAddress = s.interfaceAddress;
            m_impl->jaus = std::make_unique<JausDemo>(o);
            if (!config.jaus)
                config.jaus = jaus::JausConfig{};
            m_impl->jaus->configure(*config.jaus);
        } catch (const std::exception& e) {
            fail(std::string("simulated JAUS UGVs: ") + e.what());
        }
    }
#endif
#ifdef OCU_HAVE_SIM_ISO23725
    if (s.ahsTrucks > 0) {
        SimulatedAhsConfig c;
        c.truckCount = s.ahsTrucks;
        c.origin = config.origin;
        c.positionRateHz = 2.0;
        c.separateMapService = s.ahsSeparateMapService;
        c.bindAddress = s.interfaceAddress;
        auto demo = std::make_unique<IsoDemo>(startIsoDemo(c));
        if (!demo->ahs) {
            fail("simulated AHS: " + demo->error);
        } else {
            // The demo's link and FMS fleet go into the site's section; other keys of a given section stay.
            if (config.iso23725)
                config.iso23725->links = demo->config.links;
            else
                config.iso23725 = demo->config;
            m_impl->iso = std::move(demo);
        }
    }
#endif
#ifdef OCU_HAVE_SIM_OSYRIS
    if (s.osyrisRollers > 0) {
        osyris::OsyrisDemoOptions o;
        o.rollers = s.osyrisRollers;
        o.speedUp = s.osyrisSpeedUp;
        o.interfaceAddress = s.interfaceAddress;
        auto demo = std::make_unique<osyris::OsyrisDemo>(o);
        std::string err;
        if (!demo->start(&err)) {
            fail("simulated OSYRIS site: " + err);
        } else {
            auto c = demo->ocuConfig();
            const GeoPoint road = frame.toGeodetic({kRoadAreaE, kRoadAreaN, 0});
            c.originLat = road.lat;
            c.originLon = road.lon;
            c.originAlt = road.alt;
            if (config.osyris) {
                c.sqlitePath = config.osyris->sqlitePath;
                c.passCount = config.osyris->passCount;
            }
            config.osyris = c;
            m_impl->osyris = std::move(demo);
        }
    }
#endif
    return errors;
}

void SimulatedSite::stop() {
#ifdef OCU_HAVE_SIM_OSYRIS
    if (m_impl->osyris)
        m_impl->osyris->stop();
    m_impl->osyris.reset();
#endif
#ifdef OCU_HAVE_SIM_ISO23725
    if (m_impl->iso && m_impl->iso->ahs)
        m_impl->iso->ahs->stop();
    m_impl->iso.reset();
#endif
#ifdef OCU_HAVE_SIM_JAUS
    if (m_impl->jaus)
        m_impl->jaus->stop();
    m_impl->jaus.reset();
#endif
}

} // namespace ocu::sim
