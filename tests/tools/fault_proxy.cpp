// fault_proxy: a userspace netem for kernels without it. Bridges every Ethernet frame between two interfaces
// (AF_PACKET, so UDP unicast and multicast, TCP and ARP alike, addresses untouched) and applies a FaultLink
// per direction. Runs in a namespace of its own between the console's and the simulators'
// (scripts/fault-tests.sh).
//
//   fault_proxy --a IF --b IF [--faults SPEC] [--faults-ab SPEC] [--faults-ba SPEC] [--seed N]
//   SIGUSR1: partition (drop everything both ways) · SIGUSR2: heal · SIGHUP: counters now · SIGTERM/SIGINT:
//   end
//
// SPEC as parseFaultProfile: "loss=0.3,dup=0.1,reorder=0.1,delay=300,jitter=100,rate=20000,queue=2000".
#include "tests/tools/FaultLink.h"

#include <boost/asio/generic/raw_protocol.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/signal_set.hpp>
#include <boost/asio/steady_timer.hpp>

#include <arpa/inet.h>
#include <linux/if_packet.h>
#include <net/ethernet.h>
#include <net/if.h>
#include <sys/socket.h>

#include <cstdio>
#include <cstring>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace asio = boost::asio;
using ocu::tools::FaultLink;
using RawSocket = asio::generic::raw_protocol::socket;

// struct virtio_net_hdr (<linux/virtio_net.h> does not compile as C++): passed through untouched.
constexpr std::size_t kVnetHeaderBytes = 10;

// A packet socket on one interface with virtio-net headers, so segmentation-offloaded frames (up to 64 KiB)
// and frames with checksums left to the hardware pass through intact, as a tap device would carry them.
RawSocket openInterface(asio::io_context& io, const std::string& name) {
    const unsigned index = if_nametoindex(name.c_str());
    if (index == 0)
        throw std::runtime_error("no interface " + name);
    const asio::generic::raw_protocol proto(AF_PACKET, htons(ETH_P_ALL));
    RawSocket s(io, proto);
    const int on = 1;
    if (setsockopt(s.native_handle(), SOL_PACKET, PACKET_VNET_HDR, &on, sizeof on) != 0)
        throw std::runtime_error("PACKET_VNET_HDR on " + name + ": " + std::strerror(errno));
    // Our own sends on this interface must not come back to us as frames to forward (a loop).
    setsockopt(s.native_handle(), SOL_PACKET, PACKET_IGNORE_OUTGOING, &on, sizeof on);
    sockaddr_ll addr{};
    addr.sll_family = AF_PACKET;
    addr.sll_protocol = htons(ETH_P_ALL);
    addr.sll_ifindex = int(index);
    s.bind(asio::generic::raw_protocol::endpoint(&addr, sizeof addr));
    s.non_blocking(true);
    return s;
}

// One direction: frames read from `in`, held until their departure times, written to `out`.
class Direction {
public:
    Direction(asio::io_context& io, std::string name, RawSocket& in, RawSocket& out, FaultLink link)
        : m_name(std::move(name)), m_in(in), m_out(out), m_timer(io), m_link(std::move(link)) {}

    void start() { receive(); }
    FaultLink& link() { return m_link; }

    void printCounters() const {
        const auto& c = m_link.counters();
        std::printf("{\"direction\":\"%s\",\"in\":%llu,\"sent\":%llu,\"lost\":%llu,\"partitioned\":%llu,"
                    "\"overflow\":%llu,\"duplicated\":%llu,\"reordered\":%llu,\"send_failed\":%llu}\n",
                    m_name.c_str(), (unsigned long long)c.in, (unsigned long long)c.sent,
                    (unsigned long long)c.lost, (unsigned long long)c.partitioned,
                    (unsigned long long)c.overflow, (unsigned long long)c.duplicated,
                    (unsigned long long)c.reordered, (unsigned long long)m_sendFailed);
        std::fflush(stdout);
    }

private:
    void receive() {
        m_in.async_receive_from(asio::buffer(m_buffer), m_from,
                                [this](boost::system::error_code ec, std::size_t n) {
                                    if (ec == asio::error::operation_aborted)
                                        return;
                                    if (!ec)
                                        onFrame(n);
                                    receive();
                                });
    }

    void onFrame(std::size_t n) {
        const auto* ll = reinterpret_cast<const sockaddr_ll*>(m_from.data());
        if (ll->sll_pkttype == PACKET_OUTGOING || n <= kVnetHeaderBytes)
            return;
        const auto now = FaultLink::Clock::now();
        const auto times = m_link.offer(n - kVnetHeaderBytes, now);
        if (times.empty())
            return;
        auto frame =
            std::make_shared<std::vector<unsigned char>>(m_buffer.begin(), m_buffer.begin() + long(n));
        for (const auto& t : times)
            m_queue.emplace(t, frame);
        arm();
    }

    void arm() {
        if (m_queue.empty())
            return;
        const auto first = m_queue.begin()->first;
        if (m_armed && m_armedFor <= first)
            return;
        m_armed = true;
        m_armedFor = first;
        m_timer.expires_at(first);
        m_timer.async_wait([this](boost::system::error_code ec) {
            if (ec == asio::error::operation_aborted)
                return; // re-armed earlier; that wait handles the queue
            m_armed = false;
            sendDue();
        });
    }

    void sendDue() {
        const auto now = FaultLink::Clock::now();
        while (!m_queue.empty() && m_queue.begin()->first <= now) {
            boost::system::error_code ec;
            m_out.send(asio::buffer(*m_queue.begin()->second), 0, ec);
            if (ec)
                ++m_sendFailed;
            m_queue.erase(m_queue.begin());
        }
        arm();
    }

    std::string m_name;
    RawSocket& m_in;
    RawSocket& m_out;
    asio::steady_timer m_timer;
    FaultLink m_link;
    std::vector<unsigned char> m_buffer = std::vector<unsigned char>(kVnetHeaderBytes + 65600);
    asio::generic::raw_protocol::endpoint m_from;
    std::multimap<FaultLink::Clock::time_point, std::shared_ptr<std::vector<unsigned char>>> m_queue;
    bool m_armed = false;
    FaultLink::Clock::time_point m_armedFor{};
    unsigned long long m_sendFailed = 0;
};

struct Options {
    std::string a, b, faultsAb, faultsBa;
    unsigned long long seed = 1;
};

int usage(const char* why) {
    std::fprintf(
        stderr,
        "fault_proxy: %s\nusage: fault_proxy --a IF --b IF [--faults SPEC] [--faults-ab SPEC] "
        "[--faults-ba SPEC] [--seed N]\n  SPEC: loss=P,dup=P,reorder=P,delay=MS,jitter=MS,rate=BITS_PER_S,"
        "queue=MS\n  SIGUSR1 partitions, SIGUSR2 heals, SIGHUP prints the counters\n",
        why);
    return 2;
}

} // namespace

int main(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (i + 1 >= argc)
            return usage(("missing value after " + arg).c_str());
        const std::string v = argv[++i];
        if (arg == "--a")
            o.a = v;
        else if (arg == "--b")
            o.b = v;
        else if (arg == "--faults")
            o.faultsAb = o.faultsBa = v;
        else if (arg == "--faults-ab")
            o.faultsAb = v;
        else if (arg == "--faults-ba")
            o.faultsBa = v;
        else if (arg == "--seed")
            o.seed = std::stoull(v);
        else
            return usage(("unknown option " + arg).c_str());
    }
    if (o.a.empty() || o.b.empty())
        return usage("--a and --b are required");
    std::string error;
    const auto ab = ocu::tools::parseFaultProfile(o.faultsAb, error);
    const auto ba = ocu::tools::parseFaultProfile(o.faultsBa, error);
    if (!error.empty())
        return usage(error.c_str());

    try {
        asio::io_context io;
        RawSocket sa = openInterface(io, o.a);
        RawSocket sb = openInterface(io, o.b);
        Direction forward(io, o.a + ">" + o.b, sa, sb, FaultLink(ab, o.seed));
        Direction backward(io, o.b + ">" + o.a, sb, sa, FaultLink(ba, o.seed + 1));
        forward.start();
        backward.start();

        asio::signal_set signals(io, SIGUSR1, SIGUSR2, SIGHUP);
        asio::signal_set endSignals(io, SIGTERM, SIGINT);
        std::function<void()> waitSignal = [&] {
            signals.async_wait([&](boost::system::error_code ec, int sig) {
                if (ec)
                    return;
                if (sig == SIGUSR1 || sig == SIGUSR2) {
                    forward.link().setPartitioned(sig == SIGUSR1);
                    backward.link().setPartitioned(sig == SIGUSR1);
                    std::printf("{\"partitioned\":%s}\n", sig == SIGUSR1 ? "true" : "false");
                    std::fflush(stdout);
                } else {
                    forward.printCounters();
                    backward.printCounters();
                }
                waitSignal();
            });
        };
        waitSignal();
        endSignals.async_wait([&](boost::system::error_code, int) { io.stop(); });
        std::printf("{\"ready\":true}\n");
        std::fflush(stdout);
        io.run();
        forward.printCounters();
        backward.printCounters();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fault_proxy: %s\n", e.what());
        return 1;
    }
    return 0;
}
