// Fuzz harness: the OSYRIS §7 XML configuration import (protocols/osyris/OsyrisConfig: importOsyrisXml, items
// as elements or attributes anywhere in the document, case-insensitive). Invariants: deterministic; a failure
// says why; an accepted file gives values inside the ranges §7 allows (the station engine divides by Beat and
// sizes datagrams by MinLen/MaxLen), and leaves what it does not name as the base had it.
#include "protocols/osyris/OsyrisConfig.h"
#include "tests/fuzz/FuzzSupport.h"

#include <cmath>
#include <string>

using namespace ocu;
using namespace ocu::osyris;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    ocu::fuzz::quietLogs();
    const std::string text(reinterpret_cast<const char*>(data), data ? size : 0);
    OsyrisConfig base;
    base.stationIndex = 77;
    base.sqlitePath = "fuzz.sqlite";
    base.machineNames[3] = "R3";
    auto a = importOsyrisXml(text, base);
    auto b = importOsyrisXml(text, base);
    OCU_FUZZ_CHECK(a.ok() == b.ok());
    if (!a) {
        OCU_FUZZ_CHECK(!a.error().empty());
        OCU_FUZZ_CHECK(a.error() == b.error());
        return 0;
    }
    const OsyrisConfig& c = *a;
    OCU_FUZZ_CHECK(c.port == base.port || c.port >= 49152);
    OCU_FUZZ_CHECK(c.beatMs >= 5 && c.beatMs <= 10000);
    OCU_FUZZ_CHECK(c.minLen >= 0 && c.minLen <= c.maxLen);
    OCU_FUZZ_CHECK(c.maxLen >= int(kMsgSize) && c.maxLen <= 65507);
    OCU_FUZZ_CHECK(c.sendPeriodMs >= 10 && c.sendPeriodMs <= 600000);
    OCU_FUZZ_CHECK(c.ttlBeats >= 1 && c.ttlBeats <= 10000);
    OCU_FUZZ_CHECK(c.active >= 0 && c.active <= 15);
    OCU_FUZZ_CHECK(std::isfinite(c.maxRange) && c.maxRange >= 0 && c.maxRange <= 1e6);
    OCU_FUZZ_CHECK(!c.group.empty());
    // Not §7 items: the base's values stay.
    OCU_FUZZ_CHECK(c.stationIndex == base.stationIndex && c.sqlitePath == base.sqlitePath &&
                   c.machineNames == base.machineNames);
    OCU_FUZZ_CHECK(b->beatMs == c.beatMs && b->port == c.port && b->group == c.group &&
                   b->tailPos == c.tailPos);
    return 0;
}
