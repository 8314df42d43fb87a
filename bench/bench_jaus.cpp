// JAUS figures: encode+decode of ReportGlobalPose and SetWrenchEffort (whole JUDP datagram, both ways) and
// the loopback QueryHeartbeatPulse -> ReportHeartbeatPulse round trip against a simulated UGV (p50/p99).
#include <benchmark/benchmark.h>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/udp.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <vector>

#include "protocols/common/Log.h"
#include "protocols/jaus/JudpCodec.h"
#include "protocols/jaus/Messages.h"
#include "sim/jaus/JausDemo.h"

using namespace ocu;
using namespace ocu::jaus;

namespace {

JudpHeader header() {
    JudpHeader h;
    h.destination = JausId{2, 1, 1};
    h.source = JausId{126, 1, 199};
    return h;
}

void BM_ReportGlobalPoseEncodeDecode(benchmark::State& state) {
    GlobalPose p;
    p.lat = 48.137154;
    p.lon = 11.576124;
    p.alt = 520;
    p.yaw = 1.0;
    const JudpHeader h = header();
    double sink = 0;
    for (auto _ : state) {
        p.lat = *p.lat + 1e-7;
        Bytes d = encodeDatagram(h, encode(p));
        auto dec = decodeDatagram(d);
        auto g = decodeGlobalPose(dec->messages.front().payload);
        sink += *g->lat;
    }
    benchmark::DoNotOptimize(sink);
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ReportGlobalPoseEncodeDecode);

void BM_SetWrenchEffortEncodeDecode(benchmark::State& state) {
    WrenchEffort w;
    w.propLinX = 50;
    w.propRotZ = -25;
    const JudpHeader h = header();
    double sink = 0;
    for (auto _ : state) {
        w.propLinX = *w.propLinX + 1e-3;
        Bytes d = encodeDatagram(h, encodeWrench(msg::SetWrenchEffort, w));
        auto dec = decodeDatagram(d);
        auto r = decodeWrench(dec->messages.front().payload);
        sink += *r->propLinX;
    }
    benchmark::DoNotOptimize(sink);
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SetWrenchEffortEncodeDecode);

// One simulated UGV on loopback; a plain UDP client sends QueryHeartbeatPulse and waits for the report.
void BM_LoopbackHeartbeatRoundTrip(benchmark::State& state) {
    setLogThreshold(LogLevel::Warning);
    sim::JausDemoOptions o;
    o.count = 1;
    sim::JausDemo demo(o);
    namespace asio = boost::asio;
    asio::io_context io;
    asio::ip::udp::socket s(io, asio::ip::udp::endpoint(asio::ip::address_v4::loopback(), 0));
    s.non_blocking(false);
    const asio::ip::udp::endpoint ugv(asio::ip::address_v4::loopback(), demo.ugvs()[0]->localPort());
    JudpHeader h;
    h.source = JausId{200, 1, 1};
    h.destination = JausId{126, 1, 1};
    std::vector<double> rtts;
    std::array<std::uint8_t, 2048> buf{};
    for (auto _ : state) {
        h.sequence++;
        Bytes d = encodeDatagram(h, encodeEmpty(msg::QueryHeartbeatPulse));
        const auto t0 = std::chrono::steady_clock::now();
        s.send_to(asio::buffer(d), ugv);
        for (;;) {
            asio::ip::udp::endpoint from;
            std::size_t n = s.receive_from(asio::buffer(buf), from);
            auto dec = decodeDatagram(ByteSpan(buf.data(), n));
            if (dec && !dec->messages.empty() && dec->messages[0].messageId() == msg::ReportHeartbeatPulse)
                break;
        }
        rtts.push_back(
            std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count());
    }
    std::sort(rtts.begin(), rtts.end());
    if (!rtts.empty()) {
        state.counters["p50_us"] = rtts[rtts.size() / 2];
        state.counters["p99_us"] = rtts[std::min(rtts.size() - 1, rtts.size() * 99 / 100)];
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LoopbackHeartbeatRoundTrip)->Iterations(5000)->UseRealTime();

} // namespace

BENCHMARK_MAIN();
