#include "sim/osyris/OsyrisDemo.h"

#include "protocols/common/Clock.h"
#include "protocols/common/IoThread.h"
#include "protocols/common/Udp.h"

#include <boost/asio/steady_timer.hpp>

#include <atomic>
#include <random>

namespace ocu::sim::osyris {

namespace {
// A free UDP port in the IANA dynamic range 49152-65535 that OSYRIS §7 prescribes (the kernel's ephemeral
// range starts lower, so findFreeUdpPort() alone may give a port the configuration would refuse).
std::uint16_t freeDynamicPort() {
    std::random_device rd;
    std::mt19937 rng(rd());
    std::uniform_int_distribution<int> dist(49152, 65535);
    boost::asio::io_context ctx;
    for (int attempt = 0; attempt < 200; ++attempt) {
        const auto port = static_cast<std::uint16_t>(dist(rng));
        boost::asio::ip::udp::socket s(ctx);
        boost::system::error_code ec;
        s.open(boost::asio::ip::udp::v4(), ec);
        s.bind({boost::asio::ip::address_v4::any(), port}, ec);
        if (!ec)
            return port;
    }
    return findFreeUdpPort();
}
} // namespace

using namespace ocu::osyris;

// A simulated driver's display: a message from the console to this machine or to all is
// acknowledged to its sender; messages from other machines are only read. Runs on the station's io thread.
struct CrewListener : OsyrisListener {
    CrewListener(std::uint8_t ocu, std::optional<SimulatedMachine> m)
        : ocuIndex(ocu), machine(std::move(m)) {}
    void onText(std::uint8_t who, const std::string& text) override {
        if (who != ocuIndex || !machine || !station)
            return;
        received.fetch_add(1);
        station->sendText(machine->crewReply(text), who);
    }
    std::uint8_t ocuIndex;
    std::optional<SimulatedMachine> machine;
    OsyrisStack* station = nullptr;
    std::atomic<int> received{0};
};

struct OsyrisDemo::Impl {
    std::vector<std::unique_ptr<CrewListener>> crews; // parallel to stations
    std::vector<std::unique_ptr<OsyrisStack>> stations;
    std::vector<std::optional<SimulatedMachine>> machines; // parallel to stations
    IoThread driver{"osyris-demo"};
    std::unique_ptr<boost::asio::steady_timer> timer;
    std::chrono::steady_clock::time_point t0;
    double nextT = 0;
    bool running = false;
    std::atomic<bool> paused{false};
};

OsyrisDemo::OsyrisDemo(OsyrisDemoOptions opts) : m_opts(std::move(opts)), m_impl(std::make_unique<Impl>()) {}
OsyrisDemo::~OsyrisDemo() {
    stop();
}

std::size_t OsyrisDemo::stationCount() const {
    return m_impl->stations.size();
}
OsyrisStack& OsyrisDemo::station(std::size_t i) {
    return *m_impl->stations.at(i);
}

double OsyrisDemo::simTime() const {
    if (!m_impl->running)
        return 0;
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_impl->t0).count() *
           m_opts.speedUp;
}

OsyrisConfig OsyrisDemo::ocuConfig() const {
    OsyrisConfig c;
    c.addressing = Addressing::Multicast;
    c.group = m_opts.group;
    c.port = m_opts.port;
    c.interfaceAddress = m_opts.interfaceAddress;
    // On loopback never leaves the host; on a LAN address one segment (as the JAUS simulators).
    c.multicastTtl = m_opts.interfaceAddress == "127.0.0.1" ? 0 : 1;
    c.beatMs = m_opts.beatMs;
    c.checksum = m_opts.checksum;
    c.stationIndex = m_opts.ocuIndex;
    c.active = 15;
    c.sendPeriodMs = 2000;
    c.ttlBeats = 10;
    for (auto& m : m_machines) {
        c.machineNames[m.idx] = m.name;
        c.machineTypes[m.idx] = m.kind == MachineKind::Paver    ? "paver"
                                : m.kind == MachineKind::Roller ? "roller"
                                                                : "relay";
    }
    return c;
}

bool OsyrisDemo::start(std::string* error) {
    if (m_impl->running)
        return true;
    if (m_opts.port == 0)
        m_opts.port = freeDynamicPort();
    m_machines.clear();
    std::vector<std::pair<std::optional<MachineSpec>, std::uint8_t>> plan;
    std::uint8_t next = 0;
    if (m_opts.paver)
        plan.emplace_back(paverSpec(), next++);
    const double lanes[] = {-1.2, 1.2, 0.0};
    const double widths[] = {2.1, 1.7, 2.0};
    for (int r = 0; r < std::min(m_opts.rollers, 3); ++r)
        plan.emplace_back(rollerSpec("Roller " + std::to_string(r + 1), lanes[r], widths[r], 12.0 * r,
                                     static_cast<std::uint32_t>(r + 1)),
                          next++);
    if (m_opts.relay)
        plan.emplace_back(std::nullopt, next++);
    for (auto& [spec, idx] : plan) {
        if (spec) {
            spec->crewMessageEveryS = m_opts.crewMessageEveryS;
            if (m_opts.pavingJob) {
                spec->job = m_opts.pavingJob;
                spec->paverStartX = 0;
                spec->paverSpeed = m_opts.pavingJob->paverSpeed;
            }
        }
        OsyrisConfig c = ocuConfig();
        c.stationIndex = idx;
        c.active = spec ? 15 : 7; // §7 default for machines, plus a driver's display for messages (bit 8)
        auto crew = std::make_unique<CrewListener>(
            m_opts.ocuIndex, spec ? std::optional<SimulatedMachine>(*spec) : std::nullopt);
        auto st = std::make_unique<OsyrisStack>(c, *crew);
        crew->station = st.get();
        auto imp = m_opts.impairment;
        imp.seed += idx;
        st->setImpairment(imp);
        std::string err;
        if (!st->start(&err)) {
            if (error)
                *error = err;
            stop();
            return false;
        }
        m_machines.push_back({idx, spec ? spec->name : "Relay", spec ? spec->kind : MachineKind::Relay});
        if (spec) {
            // The paver starts ahead of the rollers' window; shadow (bridge) on a short stretch for roller 2.
            if (spec->kind == MachineKind::Roller && spec->name == "Roller 2") {
                spec->shadowFromX = 18;
                spec->shadowToX = 21;
            }
            m_impl->machines.emplace_back(SimulatedMachine(*spec));
        } else {
            m_impl->machines.emplace_back(std::nullopt);
        }
        m_impl->stations.push_back(std::move(st));
        m_impl->crews.push_back(std::move(crew));
    }
    m_impl->running = true;
    m_impl->t0 = std::chrono::steady_clock::now();
    m_impl->nextT = 0;
    m_impl->driver.start();
    m_impl->timer = std::make_unique<boost::asio::steady_timer>(m_impl->driver.context());
    if (m_opts.pavingJob) // at most 40 positions per real second per machine, whatever the speed-up
        m_opts.positionPeriodS = std::max(m_opts.positionPeriodS, m_opts.speedUp / 40.0);
    auto periodMs = std::max(5.0, 1000.0 * m_opts.positionPeriodS / std::max(0.01, m_opts.speedUp));
    m_impl->driver.post([this, periodMs] {
        auto step = [this, periodMs](auto&& self) -> void {
            double t = simTime();
            while (m_impl->nextT <= t) {
                for (std::size_t i = 0; i < m_impl->stations.size(); ++i)
                    if (m_impl->machines[i] && !m_impl->paused) {
                        m_impl->stations[i]->publishOwnPosition(
                            m_impl->machines[i]->poseAt(m_impl->nextT, unixMillisNow()));
                        if (auto msg = m_impl->machines[i]->crewMessage(
                                m_impl->nextT - m_opts.positionPeriodS, m_impl->nextT))
                            m_impl->stations[i]->sendText(*msg, m_opts.ocuIndex);
                    }
                m_impl->nextT += m_opts.positionPeriodS;
            }
            m_impl->timer->expires_after(std::chrono::microseconds(static_cast<long>(periodMs * 1000)));
            m_impl->timer->async_wait([self](boost::system::error_code ec) {
                if (!ec)
                    self(self);
            });
        };
        step(step);
    });
    return true;
}

int OsyrisDemo::crewMessagesReceived(std::size_t station) const {
    return station < m_impl->crews.size() ? m_impl->crews[station]->received.load() : 0;
}

void OsyrisDemo::setPaused(bool paused) {
    m_impl->paused = paused;
}

void OsyrisDemo::setImpairment(const RxImpairment& imp) {
    for (std::size_t i = 0; i < m_impl->stations.size(); ++i) {
        auto x = imp;
        x.seed += static_cast<std::uint32_t>(i);
        m_impl->stations[i]->setImpairment(x);
    }
}

void OsyrisDemo::stop() {
    if (m_impl->running) {
        m_impl->driver.call([this] { m_impl->timer->cancel(); });
        m_impl->driver.stop();
        m_impl->running = false;
    }
    for (auto& s : m_impl->stations)
        s->stop();
    m_impl->stations.clear();
    m_impl->machines.clear();
    m_impl->crews.clear();
}

} // namespace ocu::sim::osyris
