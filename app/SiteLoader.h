#pragma once
#include "protocols/site/SiteConfig.h"

#include <QString>

namespace ocu {

// The built-in simulated site (resource :/sites/simulated-site.json) or a file given with --config.
Result<SiteConfig> loadSite(const QString& configFile);
QString builtInSitePath();

} // namespace ocu
