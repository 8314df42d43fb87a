// Fuzz harness: the site configuration (protocols/site/SiteConfig: JSON with line tracking, every protocol's
// section, strict key checking). Invariant: parsing is deterministic, and a failure always says why.
#include "protocols/site/SiteConfig.h"
#include "tests/fuzz/FuzzSupport.h"

using namespace ocu;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    ocu::fuzz::quietLogs();
    std::string_view text(reinterpret_cast<const char*>(data), data ? size : 0);
    auto a = parseSiteConfig(text, "fuzz-site.json");
    if (!a)
        OCU_FUZZ_CHECK(!a.error().empty());
    auto b = parseSiteConfig(text, "fuzz-site.json");
    OCU_FUZZ_CHECK(a.ok() == b.ok());
    if (!a)
        OCU_FUZZ_CHECK(a.error() == b.error());
    return 0;
}
