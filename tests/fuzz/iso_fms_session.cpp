// Fuzz harness: an ISO 23725 session (FmsCore, the FMS side) on a fake clock, fed one frame per input line on
// the main channel; lines starting with '#' drive the session instead (see step()): map channel frames,
// reconnects, time passing, all-stop and map commands. Stateful: fleet definition, machines, all-stop with
// its timeouts, the map assembly and diagnostics carry over. Invariants: every frame the console sends
// decodes with the console's own decoder; no machine the listener is told about lacks an equipment id.
#include "protocols/iso23725/FmsCore.h"
#include "tests/fuzz/FuzzSupport.h"

using namespace ocu;
using namespace ocu::iso23725;

namespace {

const Guid kFms = "0f1e2d3c-4b5a-4968-8776-a5b4c3d2e1f0";
const Guid kTruck = "c3a51f7e-0d24-4b9a-8f63-1e2d4c5b6a78";
const Guid kLight = "5a6b7c8d-9e0f-4a1b-8c2d-3e4f5a6b7c8d";

struct Outbound final : FmsOutbound {
    bool up = true;
    bool sendMain(std::string text) override {
        OCU_FUZZ_CHECK(decodeMessage(text).ok());
        return up;
    }
    bool sendMap(std::string text) override {
        OCU_FUZZ_CHECK(decodeMessage(text).ok());
        return up;
    }
};

struct Listener final : IsoListener {
    void onMachineChanged(const IsoMachineSnapshot& m) override { OCU_FUZZ_CHECK(!m.equipmentId.empty()); }
};

IsoConfig config() {
    IsoConfig c;
    c.fmsId = kFms;
    c.fleet = {Equipment{kTruck, "HT01", "HaulTruck", "OEM", "793F", true, 12.9, 7.6},
               Equipment{kLight, "LV07", "LightVehicle", "OEM", "Hilux", false, 5.3, 1.9}};
    return c;
}

bool startsWith(std::string_view s, std::string_view p) {
    return s.substr(0, p.size()) == p;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    ocu::fuzz::quietLogs();
    static const IsoConfig cfg = config();
    FakeClock clock;
    Counters counters;
    Listener listener;
    Outbound out;
    FmsCore session(cfg, IsoLinkConfig{"ahs", {}, {}}, listener, counters, clock, out);
    session.opened("127.0.0.1:9000");
    fuzz::Lines lines(data, size);
    std::string_view line;
    for (int n = 0; n < 512 && lines.next(line); ++n) {
        if (!startsWith(line, "#")) {
            session.text(line);
        } else if (startsWith(line, "#map ")) {
            session.mapText(line.substr(5));
        } else if (line == "#tick") {
            clock.advance(std::chrono::milliseconds(500));
            session.poll();
        } else if (line == "#wait") {
            clock.advance(std::chrono::seconds(30));
            session.poll();
        } else if (line == "#close") {
            out.up = false;
            session.closed("peer closed");
        } else if (line == "#open") {
            out.up = true;
            session.opened("127.0.0.1:9000");
        } else if (line == "#binary") {
            session.binaryFrame(line.size());
        } else if (line == "#stop") {
            session.allStopApply();
        } else if (line == "#release") {
            session.allStopRemove();
        } else if (line == "#fetchmap") {
            session.fetchMap();
        } else if (line == "#own") {
            IsoPosition p;
            p.latitude = -23.36;
            p.longitude = 119.73;
            session.sendOwnPositions({{kLight, p}});
            session.flushPositions();
        }
    }
    clock.advance(std::chrono::seconds(1));
    session.poll();
    return 0;
}
