#include "sim/SimulatedSite.h"

#include "protocols/common/GeoFrame.h"
#include "protocols/common/Log.h"

namespace ocu::sim {

SimulatedSite::SimulatedSite() : m_modules(makeSimModules()) {}

SimulatedSite::~SimulatedSite() {
    stop();
}

std::string SimulatedSite::start(SiteConfig& config) {
    std::string errors;
    const GeoFrame frame(config.origin);
    for (auto& m : m_modules) {
        const std::string what = m->start(config, frame);
        if (what.empty())
            continue;
        logError("ocu.sim", what);
        errors += (errors.empty() ? "" : "\n") + what;
    }
    return errors;
}

void SimulatedSite::stop() {
    // In reverse start order.
    for (auto it = m_modules.rbegin(); it != m_modules.rend(); ++it)
        (*it)->stop();
}

} // namespace ocu::sim
