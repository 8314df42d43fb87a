#include "sim/iso23725/SimulatedAhs.h"

#include "sim/iso23725/AhsSessions.h"
#include "sim/iso23725/HaulFleet.h"
#include "sim/iso23725/PitMapGenerator.h"

#include "protocols/common/IoThread.h"

#include <boost/asio/steady_timer.hpp>

#include <algorithm>
#include <cmath>
#include <thread>

namespace ocu::sim {

using namespace ocu::iso23725;

// The parts of the simulated AHS: the pit map (generated), the haul fleet driving on it, and the FMS
// sessions serving both; one io thread runs them, a timer advances the fleet and sends the positions.
struct SimulatedAhs::Impl {
    Impl(SimulatedAhsConfig c, Counters& counters)
        : cfg(std::move(c)), io("sim-iso23725"), timer(io.context()),
          map(generatePitMap(PitLayout{cfg.shovelCount, cfg.dumpCount, cfg.origin}, unixMillisNow())),
          fleet(
              map, HaulFleetConfig{cfg.truckCount, cfg.seed, cfg.healthEvents}, counters,
              [this](const Body& member, const Guid& eq) {
                  sessions.broadcast(member, eq.empty() ? std::nullopt : std::optional<Guid>(eq));
              },
              [this] { return now(); }),
          sessions(io.context(), cfg, map, fleet, counters) {}

    SimulatedAhsConfig cfg;
    // Times the trucks report (cycle state times): the wall clock, or simulated time from the start when the
    // simulation runs faster (timeScale), so a cycle's durations are the simulated ones.
    std::int64_t startUnixMs = unixMillisNow();
    double simSeconds = 0;
    std::int64_t now() const {
        return cfg.timeScale == 1.0 ? unixMillisNow() : startUnixMs + std::llround(simSeconds * 1000);
    }
    IoThread io;
    boost::asio::steady_timer timer;
    PitMap map;
    HaulFleet fleet;
    AhsSessions sessions;

    double tickSeconds() const { return 1.0 / std::clamp(cfg.positionRateHz, 1.0, 10.0); }

    // One simulation step per position period: the fleet moves (and reports what changed), then every
    // truck's position goes out (§7.4: 1-10 Hz).
    void schedule() {
        timer.expires_after(std::chrono::microseconds(static_cast<std::int64_t>(1e6 * tickSeconds())));
        timer.async_wait([this](boost::system::error_code ec) {
            if (ec)
                return;
            simSeconds += tickSeconds() * cfg.timeScale;
            fleet.tick(tickSeconds() * cfg.timeScale);
            sessions.sendPositions();
            schedule();
        });
    }
};

SimulatedAhs::SimulatedAhs(SimulatedAhsConfig config)
    : m_impl(std::make_unique<Impl>(std::move(config), m_counters)) {}

SimulatedAhs::~SimulatedAhs() {
    stop();
}

bool SimulatedAhs::start() {
    auto& d = *m_impl;
    if (d.io.running())
        return true;
    d.io.start();
    auto r = d.io.call([&]() -> Result<bool> {
        auto s = d.sessions.start();
        if (s)
            d.schedule();
        return s;
    });
    if (!r) {
        m_error = r.error();
        d.io.call([&] { d.sessions.release(); });
        d.io.stop();
        return false;
    }
    return true;
}

void SimulatedAhs::stop() {
    auto& d = *m_impl;
    if (!d.io.running())
        return;
    d.io.call([&] {
        d.timer.cancel();
        d.sessions.stop();
    });
    d.io.stop();
    d.sessions.release();
}

bool SimulatedAhs::running() const {
    return m_impl->io.running();
}

std::uint16_t SimulatedAhs::port() const {
    auto& d = *m_impl;
    return const_cast<IoThread&>(d.io).call([&] { return d.sessions.port(); });
}

std::string SimulatedAhs::url() const {
    return std::string(m_impl->cfg.tls ? "wss://" : "ws://") + m_impl->cfg.bindAddress + ":" +
           std::to_string(port()) + m_impl->cfg.path;
}

std::uint16_t SimulatedAhs::mapPort() const {
    auto& d = *m_impl;
    return const_cast<IoThread&>(d.io).call([&] { return d.sessions.mapPort(); });
}

std::string SimulatedAhs::mapUrl() const {
    return std::string(m_impl->cfg.tls ? "wss://" : "ws://") + m_impl->cfg.bindAddress + ":" +
           std::to_string(mapPort()) + m_impl->cfg.mapPath;
}

std::vector<Equipment> SimulatedAhs::fleet() const {
    return m_impl->fleet.equipment();
}

SimulatedAhsStats SimulatedAhs::stats() {
    auto& d = *m_impl;
    return d.io.call([&] {
        SimulatedAhsStats s;
        s.positionsSent = d.sessions.positionsSent();
        s.framesReceived = d.sessions.framesReceived();
        s.queuedBytes = d.sessions.queuedBytes();
        s.sessions = d.sessions.sessionCount();
        s.mapSessions = d.sessions.mapSessionCount();
        s.allStopOn = d.fleet.allStopOn();
        for (auto& t : d.fleet.trucks())
            s.movingTrucks += t.motion.speed() > 0.05 ? 1 : 0;
        s.fmsFirstMessages = d.sessions.fmsFirstMessages();
        return s;
    });
}

void SimulatedAhs::bumpMapChangeSet() {
    m_impl->io.post([d = m_impl.get()] {
        d->map.edited(unixMillisNow());
        d->sessions.announceMapChange();
    });
}

void SimulatedAhs::sendRaw(const std::string& text) {
    m_impl->io.post([d = m_impl.get(), text] { d->sessions.broadcastRaw(text, false); });
}

void SimulatedAhs::sendRawBinary(const std::string& data) {
    m_impl->io.post([d = m_impl.get(), data] { d->sessions.broadcastRaw(data, true); });
}

void SimulatedAhs::freezeFor(std::chrono::milliseconds d) {
    m_impl->io.post([d] { std::this_thread::sleep_for(d); });
}

void SimulatedAhs::setTruckManual(int index, bool manual) {
    m_impl->io.post([d = m_impl.get(), index, manual] { d->fleet.setManual(index, manual); });
}

void SimulatedAhs::setTruckCustodian(int index, const std::string& actor) {
    m_impl->io.post([d = m_impl.get(), index, actor] { d->fleet.setCustodian(index, actor); });
}

void SimulatedAhs::setWayClosed(std::int64_t wayId, bool closed) {
    m_impl->io.post([d = m_impl.get(), wayId, closed] { d->fleet.setWayClosed(wayId, closed); });
}

SimulatedAhs::DispatchView SimulatedAhs::dispatchView() {
    return m_impl->io.call([&] {
        DispatchView v;
        const auto& m = m_impl->map;
        v.loadAreas = m.loadAreas;
        v.dumpAreas = m.dumpAreas;
        v.parkArea = m.parkArea;
        v.parkRoad = m.parkRoad;
        v.rampDown = m.rampDown;
        v.rampUp = m.rampUp;
        for (auto& t : m_impl->fleet.trucks())
            v.trucks.push_back(DispatchView::Truck{t.id, t.custodian, t.idle, t.productionState,
                                                   t.assignments.size(), t.motion.wayId()});
        return v;
    });
}

std::vector<double> SimulatedAhs::truckSpeedsKmh() {
    return m_impl->io.call([&] {
        std::vector<double> v;
        for (auto& t : m_impl->fleet.trucks())
            v.push_back(t.motion.speed() * 3.6);
        return v;
    });
}

} // namespace ocu::sim
