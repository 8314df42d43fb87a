// Mission upload figures on loopback: a 1,000-waypoint local list uploaded to a simulated UGV (DeleteElement,
// SetElement parts below 1.4 kB each confirmed before the next) and read back (count, list, every element
// with eight queries outstanding) until the console shows it "uploaded". Prints the time from the command to
// the verified state and the datagrams each way, for several runs (median and worst).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>
#include <vector>

#include "protocols/common/GeoFrame.h"
#include "protocols/common/Log.h"
#include "protocols/jaus/JausStack.h"
#include "sim/jaus/JausDemo.h"

using namespace ocu;
using namespace ocu::jaus;
using Clk = std::chrono::steady_clock;

namespace {

struct Quiet : JausListener {
    void onSubsystemChanged(const SubsystemSnapshot&) override {}
    void onEvent(const JausEvent&) override {}
};

template <class Pred> bool waitFor(Pred p, double seconds) {
    const auto end =
        Clk::now() + std::chrono::duration_cast<Clk::duration>(std::chrono::duration<double>(seconds));
    while (Clk::now() < end) {
        if (p())
            return true;
        std::this_thread::sleep_for(std::chrono::microseconds(500));
    }
    return p();
}

} // namespace

int main(int argc, char** argv) {
    setLogThreshold(LogLevel::Error);
    const int waypoints = argc > 1 ? std::atoi(argv[1]) : 1000;
    const int runs = argc > 2 ? std::atoi(argv[2]) : 5;
    sim::JausDemoOptions o;
    o.count = 1;
    sim::JausDemo demo(o);
    JausConfig c;
    c.subsystemId = 200;
    c.callSign = "OCU-200";
    c.authority = 205;
    demo.configure(c);
    Quiet quiet;
    JausStack stack(c, quiet);
    stack.start();
    auto snap = [&] { return stack.snapshot(126); };
    if (!waitFor(
            [&] {
                auto s = snap();
                return s && s->globalPose && s->localPose;
            },
            20)) {
        std::fprintf(stderr, "bench_mission: the simulated UGV was not discovered\n");
        return 1;
    }
    stack.requestControl(126, {});
    if (!waitFor(
            [&] {
                auto s = snap();
                return s && s->controlledByUs;
            },
            20)) {
        std::fprintf(stderr, "bench_mission: no control of the simulated UGV\n");
        return 1;
    }
    // A 1,000-point lawnmower pattern 1 m apart around the origin.
    const GeoFrame frame(o.origin);
    std::vector<MissionPoint> points;
    for (int i = 0; i < waypoints; ++i) {
        const int row = i / 50, col = row % 2 ? 49 - i % 50 : i % 50;
        const GeoPoint g = frame.toGeodetic(EnuPoint{double(col), double(row), 0});
        points.push_back(MissionPoint{g.lat, g.lon, 1.0, 0.5});
    }
    std::vector<double> ms;
    std::vector<std::uint64_t> txs, rxs;
    for (int run = 0; run < runs; ++run) {
        const std::uint64_t tx0 = stack.counters().get("tx.datagrams"),
                            rx0 = stack.counters().get("rx.datagrams");
        const auto t0 = Clk::now();
        stack.missionUpload(126, points, false, {});
        if (!waitFor(
                [&] {
                    auto s = snap();
                    return s && s->mission.phase == MissionPhase::Uploaded;
                },
                120)) {
            auto s = snap();
            std::fprintf(stderr, "bench_mission: not uploaded (%s: %s)\n",
                         s ? nameFor(s->mission.phase) : "?", s ? s->mission.reason.c_str() : "");
            return 1;
        }
        ms.push_back(std::chrono::duration<double, std::milli>(Clk::now() - t0).count());
        txs.push_back(stack.counters().get("tx.datagrams") - tx0);
        rxs.push_back(stack.counters().get("rx.datagrams") - rx0);
        std::printf(
            "run %d: %d waypoints uploaded and read back in %.1f ms, %llu datagrams sent, %llu received\n",
            run + 1, waypoints, ms.back(), (unsigned long long)txs.back(), (unsigned long long)rxs.back());
    }
    std::vector<double> sorted = ms;
    std::sort(sorted.begin(), sorted.end());
    std::printf(
        "bench_mission: %d waypoints, upload + read-back median %.1f ms, worst %.1f ms; datagrams per upload "
        "%llu sent / %llu received (periodic traffic of the link included)\n",
        waypoints, sorted[sorted.size() / 2], sorted.back(), (unsigned long long)txs.back(),
        (unsigned long long)rxs.back());
    stack.stop();
    demo.stop();
    return 0;
}
