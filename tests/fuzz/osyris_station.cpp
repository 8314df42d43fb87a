// Fuzz harness: the OSYRIS station engine (StationCore, seed 004 §4-§6) on a fake clock, fed a sequence of
// steps split from the input (FuzzSupport.h Steps): datagrams from the network, Beats, time passing, pings.
// Stateful: late join, the repair engine's wishes and assets, the ribbon store and the pass-count grid all
// carry over from one datagram to the next. Invariants: every datagram the station sends decodes cleanly
// with its own codec and fits MaxLen; a position the listener gets as plausible has finite coordinates.
#include "protocols/osyris/StationCore.h"
#include "tests/fuzz/FuzzSupport.h"

#include <cmath>

using namespace ocu;
using namespace ocu::osyris;

namespace {

struct Checker final : OsyrisListener {
    void onMachinePosition(const MachineSnapshot& m) override {
        if (m.implausible.empty()) {
            OCU_FUZZ_CHECK(std::isfinite(m.x) && std::isfinite(m.y) && std::isfinite(m.z));
            OCU_FUZZ_CHECK(std::isfinite(m.lat) && std::isfinite(m.lon));
        }
    }
    bool readyForPassCounts() override { return true; }
};

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    ocu::fuzz::quietLogs();
    FakeClock clock;
    auto store = RibbonStore::inMemory();
    OsyrisConfig cfg;
    cfg.stationIndex = 200;
    cfg.originLat = 48.1;
    cfg.originLon = 11.5;
    PassCountGrid grid(cfg.passCount);
    Checker listener;
    std::size_t sent = 0;
    StationCore core(cfg, clock, *store, &grid, &listener, [&](const Bytes& d) {
        ++sent;
        OCU_FUZZ_CHECK(d.size() <= std::size_t(cfg.maxLen));
        DecodedDatagram back = decodeDatagram(ByteSpan(d), cfg.checksum);
        OCU_FUZZ_CHECK(back.reason.empty());
        OCU_FUZZ_CHECK(!back.messages.empty());
    });
    core.start();
    const auto beat = std::chrono::milliseconds(cfg.beatMs);
    fuzz::Steps steps(data, size);
    std::uint8_t op = 0;
    std::span<const std::uint8_t> body;
    for (int n = 0; n < 256 && steps.next(op, body); ++n) {
        switch (op % 5) {
        case 0:
            core.receive(ByteSpan(body));
            break;
        case 1:
            core.receive(ByteSpan(body));
            clock.advance(beat);
            core.tick();
            break;
        case 2:
            clock.advance(beat);
            core.tick();
            break;
        case 3: // a pause: up to 63 Beats (stale holds, TTLs, late answers)
            clock.advance(beat * (op >> 2));
            core.tick();
            break;
        case 4:
            core.ping(body.empty() ? std::uint8_t(7) : body[0]);
            break;
        }
    }
    clock.advance(beat);
    core.tick();
    core.updateGrid();
    (void)sent;
    return 0;
}
