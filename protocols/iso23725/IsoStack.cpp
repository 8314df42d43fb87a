#include "protocols/iso23725/IsoStack.h"

#include "protocols/iso23725/WsEndpoint.h"

#include "protocols/common/IoThread.h"
#include "protocols/common/Log.h"
#include "protocols/iso23725/LogCategory.h"

#include <boost/asio/steady_timer.hpp>

#include <atomic>
#include <cmath>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <vector>

namespace ocu::iso23725 {

// How often the sessions' deadlines are checked: the resolution of the all-stop and diagnostic timers.
static constexpr std::chrono::milliseconds kPollInterval{100};
// Positions reach the listener in batches (FmsCore::flushPositions), at most this long after they arrived:
// the console's bridge hands them to the GUI thread once per batch instead of once per message.
static constexpr std::chrono::milliseconds kPositionBatchInterval{5};
// At most this many machines per listener call and io-thread handler: a burst of 1,000 trucks' positions is
// handed over in short steps (under 0.3 ms each in the console's bridge: bench_iso_bridge measures 8 us of
// io-thread time per position, decoding included), so an all-stop requested meanwhile waits for one step,
// not for the whole burst (ISO 23725 §7.6: the all-stop is the FMS's safety command).
static constexpr std::size_t kPositionStep = 32;

namespace {

// Commands that must not wait behind telemetry: all-stop Apply and Remove (§7.6). They keep their own order
// (a Remove never overtakes the Apply before it). Any thread hands one in; the io thread runs them at its
// next turn (a posted handler), and before every received frame and between two steps of a position batch, so
// a backlog of queued handlers or of buffered frames does not delay them. A Beast stream is written by the io
// thread only: the job runs there and its frame goes next on the socket (WsEndpoint::sendUrgent).
struct UrgentLane {
    explicit UrgentLane(boost::asio::io_context& io) : io(io) {}
    void push(std::function<void()> job) {
        {
            std::lock_guard lock(mutex);
            jobs.push_back(std::move(job));
            pending.store(true, std::memory_order_release);
        }
        boost::asio::post(io, [this] { run(); });
    }
    // Io thread only.
    void run() {
        while (pending.load(std::memory_order_acquire)) {
            std::vector<std::function<void()>> now;
            {
                std::lock_guard lock(mutex);
                now.swap(jobs);
                pending.store(false, std::memory_order_relaxed);
            }
            for (auto& job : now)
                job();
        }
    }
    boost::asio::io_context& io;
    std::mutex mutex;
    std::vector<std::function<void()>> jobs;
    std::atomic<bool> pending{false};
};

// Arms one timer when positions are waiting; when it fires, hands every link's batch to the listener in steps
// of kPositionStep machines, one io-thread handler each (re-posted while positions wait), with the urgent
// commands run before each step.
struct PositionFlush {
    PositionFlush(boost::asio::io_context& io, UrgentLane& urgent) : timer(io), urgent(urgent) {}
    void arm() {
        if (armed || stepping || stopped)
            return;
        armed = true;
        timer.expires_after(kPositionBatchInterval);
        timer.async_wait([this](boost::system::error_code ec) {
            armed = false;
            if (!ec)
                step();
        });
    }
    void step() {
        stepping = false;
        if (stopped)
            return;
        urgent.run();
        if (!flushStep())
            return;
        stepping = true;
        boost::asio::post(timer.get_executor(), [this] { step(); });
    }
    boost::asio::steady_timer timer;
    UrgentLane& urgent;
    bool armed = false;
    bool stepping = false; // a step is posted: the rest of the batch follows without the timer
    bool stopped = false;
    // One step over every link; true while positions are still waiting.
    std::function<bool()> flushStep;
};

// One link: the FMS session (all behaviour) and the sockets it talks through.
struct Link final : FmsOutbound {
    struct MainHandler final : WsHandler {
        Link* link = nullptr;
        void onOpen(SessionId id, const std::string& peer) override { link->mainOpened(id, peer); }
        void onText(SessionId id, std::string text) override {
            link->urgent.run(); // before the frame: a stop requested meanwhile goes first
            if (link->mainSession != id)
                return;
            link->session->text(text);
            if (link->session->positionsPending())
                link->positionFlush.arm();
        }
        void onClose(SessionId id, const std::string& reason) override {
            if (link->mainSession != id)
                return;
            link->mainSession.reset();
            link->session->closed(reason);
        }
        void onBinaryFrame(SessionId id, std::size_t bytes) override {
            if (link->mainSession == id)
                link->session->binaryFrame(bytes);
        }
        void onConnectFailed(const std::string& reason, std::chrono::milliseconds retryIn) override {
            link->session->connectFailed(reason, retryIn);
        }
    };
    struct MapHandler final : WsHandler {
        Link* link = nullptr;
        void onOpen(SessionId id, const std::string& peer) override {
            link->mapSession = id;
            link->session->mapOpened(peer);
        }
        void onText(SessionId id, std::string text) override {
            link->urgent.run(); // a map chunk can take long to check: a stop requested meanwhile goes first
            if (link->mapSession == id)
                link->session->mapText(text);
        }
        void onClose(SessionId id, const std::string& reason) override {
            if (link->mapSession != id)
                return;
            link->mapSession.reset();
            link->session->mapClosed(reason);
        }
    };

    Link(const IsoConfig& cfg, const IsoLinkConfig& lc, IsoListener& listener, Counters& counters,
         Clock& clock, boost::asio::io_context& io, PositionFlush& flush, UrgentLane& urgent)
        : session(std::make_unique<FmsCore>(cfg, lc, listener, counters, clock, *this)), positionFlush(flush),
          urgent(urgent) {
        mainHandler.link = this;
        mapHandler.link = this;
        main = std::make_unique<WsEndpoint>(io, lc.ws, mainHandler, counters, clock);
        if (!lc.mapWs.url.empty())
            map = std::make_unique<WsEndpoint>(io, lc.mapWs, mapHandler, counters, clock);
    }

    void mainOpened(SessionId id, const std::string& peer) {
        if (mainSession) { // service role: a second AHS connection replaces the first
            logWarning(kLog,
                       "link " + session->name() + ": new connection from " + peer + " replaces the old one");
            auto old = *mainSession;
            mainSession.reset(); // so the old session's close is not reported as the link going down
            main->close(old, "replaced");
            session->closed("replaced by a new connection from " + peer);
        }
        mainSession = id;
        session->opened(peer);
    }

    bool sendMain(std::string text) override {
        return mainSession && main->send(*mainSession, std::move(text));
    }
    bool sendMainUrgent(std::string text) override {
        return mainSession && main->sendUrgent(*mainSession, std::move(text));
    }
    bool sendMap(std::string text) override {
        return mapSession && map && map->send(*mapSession, std::move(text));
    }

    std::unique_ptr<FmsCore> session;
    PositionFlush& positionFlush;
    UrgentLane& urgent;
    MainHandler mainHandler;
    MapHandler mapHandler;
    std::unique_ptr<WsEndpoint> main;
    std::unique_ptr<WsEndpoint> map;
    std::optional<SessionId> mainSession;
    std::optional<SessionId> mapSession;
};

} // namespace

struct IsoStack::Impl {
    Impl(IsoConfig c, IsoListener& l, Counters& counters, Clock& clock)
        : cfg(std::move(c)), listener(l), counters(counters), clock(clock), io("iso23725", true),
          positionTimer(io.context()), pollTimer(io.context()), urgent(io.context()),
          positionFlush(io.context(), urgent) {
        // One set of counters per link, feeding the stack's totals; never changed after construction, so
        // any thread may read them.
        for (auto& lc : cfg.links)
            linkCounters.try_emplace(lc.name, std::make_unique<Counters>(&counters));
        positionFlush.flushStep = [this] {
            bool more = false;
            for (auto& [name, l] : links) {
                urgent.run();
                l->session->flushPositions(kPositionStep);
                more = more || l->session->positionsPending();
            }
            return more;
        };
    }

    IsoConfig cfg;
    IsoListener& listener;
    Counters& counters;
    Clock& clock; // every session's and socket's timeouts are measured on it
    IoThread io;
    std::map<std::string, std::unique_ptr<Link>> links;
    std::map<std::string, std::unique_ptr<Counters>> linkCounters;
    std::map<Guid, IsoPosition> ownPositions;
    boost::asio::steady_timer positionTimer;
    boost::asio::steady_timer pollTimer;
    UrgentLane urgent;
    PositionFlush positionFlush;
    MessageTap* tap = nullptr; // the flight recorder's

    FmsCore* session(const std::string& name, const char* what) {
        auto it = links.find(name);
        if (it == links.end()) {
            const std::string text = std::string(what) + " refused: no ISO 23725 link named '" + name + "'";
            logWarning(kLog, text);
            listener.onEvent(IsoSeverity::Warning, text);
            return nullptr;
        }
        return it->second->session.get();
    }

    void positionTick() {
        auto period =
            std::chrono::milliseconds(static_cast<int>(1000.0 / std::clamp(cfg.positionRateHz, 1.0, 10.0)));
        positionTimer.expires_after(period);
        positionTimer.async_wait([this](boost::system::error_code ec) {
            if (ec)
                return;
            if (cfg.sendPositions)
                for (auto& [name, l] : links)
                    l->session->sendOwnPositions(ownPositions);
            positionTick();
        });
    }

    void pollTick() {
        pollTimer.expires_after(kPollInterval);
        pollTimer.async_wait([this](boost::system::error_code ec) {
            if (ec)
                return;
            for (auto& [name, l] : links)
                l->session->poll();
            pollTick();
        });
    }
};

// ---------------------------------------------------------------- IsoStack

IsoStack::IsoStack(IsoConfig config, IsoListener& listener, Clock& clock)
    : m_impl(std::make_unique<Impl>(std::move(config), listener, m_counters, clock)) {}

IsoStack::~IsoStack() {
    stop();
}

void IsoStack::setMessageTap(MessageTap* tap) {
    m_impl->tap = tap;
}

bool IsoStack::start() {
    auto& d = *m_impl;
    if (d.io.running())
        return true;
    d.io.start();
    return d.io.call([&] {
        d.positionFlush.armed = d.positionFlush.stepping = d.positionFlush.stopped = false;
        bool ok = true;
        for (auto& lc : d.cfg.links) {
            auto l = std::make_unique<Link>(d.cfg, lc, d.listener, *d.linkCounters.at(lc.name), d.clock,
                                            d.io.context(), d.positionFlush, d.urgent);
            l->session->setMessageTap(d.tap);
            auto r = l->main->start();
            if (r && l->map)
                if (auto rm = l->map->start(); !rm)
                    r = makeError("map service " + lc.mapWs.url + ": " + rm.error());
            if (!r) {
                ok = false;
                const std::string text = "link " + lc.name + " cannot start: " + r.error();
                logWarning(kLog, text);
                d.listener.onEvent(IsoSeverity::Error, text);
            }
            d.listener.onLinkState(lc.name, LinkState::Unknown, r ? "connecting" : r.error());
            d.links[lc.name] = std::move(l);
        }
        d.positionTick();
        d.pollTick();
        return ok;
    });
}

void IsoStack::stop() {
    auto& d = *m_impl;
    if (!d.io.running())
        return;
    // Every WebSocket gets a close frame with 1001 "going away" (RFC 6455 §7.4.1) instead of a dropped TCP
    // connection (the peer would see 1006); the peer has kCloseGrace to answer, then the sockets are dropped.
    constexpr auto kCloseGrace = std::chrono::milliseconds(500);
    auto closed = std::make_shared<std::promise<void>>();
    auto finished = closed->get_future();
    d.io.call([&] {
        d.positionTimer.cancel();
        d.pollTimer.cancel();
        d.positionFlush.timer.cancel();
        d.positionFlush.stopped = true;
        std::vector<WsEndpoint*> endpoints;
        for (auto& [n, l] : d.links) {
            endpoints.push_back(l->main.get());
            if (l->map)
                endpoints.push_back(l->map.get());
        }
        if (endpoints.empty()) {
            closed->set_value();
            return;
        }
        auto left = std::make_shared<std::size_t>(endpoints.size());
        for (WsEndpoint* e : endpoints)
            e->shutdown(kCloseGrace, [left, closed] {
                if (--*left == 0)
                    closed->set_value();
            });
    });
    finished.wait_for(kCloseGrace + std::chrono::milliseconds(200));
    d.io.stop();
    d.links.clear();
}

void IsoStack::allStopApply(const std::string& link, OutcomeCallback done) {
    m_impl->urgent.push([d = m_impl.get(), link, done = std::move(done)] {
        TargetOutcome o = TargetOutcome::refused(linkTarget(link), OutcomeReason::UnknownTarget,
                                                 "no ISO 23725 link named " + link);
        if (auto* s = d->session(link, "all-stop Apply")) {
            o = s->allStopApply() ? TargetOutcome::sentTo(o.target) : s->refusalFor(o.target);
        }
        done({std::move(o)});
    });
}

void IsoStack::allStopRemove(const std::string& link, OutcomeCallback done) {
    m_impl->urgent.push([d = m_impl.get(), link, done = std::move(done)] {
        TargetOutcome o = TargetOutcome::refused(linkTarget(link), OutcomeReason::UnknownTarget,
                                                 "no ISO 23725 link named " + link);
        if (auto* s = d->session(link, "all-stop Remove")) {
            o = s->allStopRemove() ? TargetOutcome::sentTo(o.target) : s->refusalFor(o.target);
        }
        done({std::move(o)});
    });
}

void IsoStack::setOwnPosition(const Guid& equipmentId, double lat, double lon, double elevation,
                              double headingDeg, double speedKmh) {
    m_impl->io.post([d = m_impl.get(), equipmentId, lat, lon, elevation, headingDeg, speedKmh] {
        IsoPosition p;
        p.latitude = lat;
        p.longitude = lon;
        p.elevation = elevation;
        p.heading = std::fmod(std::fmod(headingDeg, 360.0) + 360.0, 360.0);
        p.speedKmh = speedKmh;
        p.measuredUnixMs = unixMillisNow();
        d->ownPositions[equipmentId] = p;
    });
}

void IsoStack::requestAssignment(const std::string& link, const Guid& equipmentId,
                                 std::vector<AssignmentItem> items, OutcomeCallback done) {
    m_impl->io.post(
        [d = m_impl.get(), link, equipmentId, items = std::move(items), done = std::move(done)]() mutable {
            TargetOutcome o = TargetOutcome::refused(machineTarget(equipmentId), OutcomeReason::UnknownTarget,
                                                     "no ISO 23725 link named " + link);
            if (auto* s = d->session(link, "assignment request")) {
                o = s->requestAssignment(equipmentId, std::move(items)) ? TargetOutcome::sentTo(o.target)
                                                                        : s->refusalFor(o.target);
            }
            done({std::move(o)});
        });
}

void IsoStack::resetAssignment(const std::string& link, const Guid& equipmentId, OutcomeCallback done) {
    m_impl->io.post([d = m_impl.get(), link, equipmentId, done = std::move(done)] {
        TargetOutcome o = TargetOutcome::refused(machineTarget(equipmentId), OutcomeReason::UnknownTarget,
                                                 "no ISO 23725 link named " + link);
        if (auto* s = d->session(link, "assignment reset")) {
            o = s->resetAssignment(equipmentId) ? TargetOutcome::sentTo(o.target) : s->refusalFor(o.target);
        }
        done({std::move(o)});
    });
}

void IsoStack::fetchMap(const std::string& link, OutcomeCallback done) {
    m_impl->io.post([d = m_impl.get(), link, done = std::move(done)] {
        TargetOutcome o = TargetOutcome::refused(linkTarget(link), OutcomeReason::UnknownTarget,
                                                 "no ISO 23725 link named " + link);
        if (auto* s = d->session(link, "map fetch")) {
            o = s->fetchMap() ? TargetOutcome::sentTo(o.target) : s->refusalFor(o.target);
        }
        done({std::move(o)});
    });
}

std::vector<IsoMachineSnapshot> IsoStack::machines(const std::string& link) {
    return m_impl->io.call([&] {
        std::vector<IsoMachineSnapshot> out;
        auto it = m_impl->links.find(link);
        if (it != m_impl->links.end())
            for (auto& [id, m] : it->second->session->machines())
                out.push_back(m);
        return out;
    });
}

AllStopStatus IsoStack::allStop(const std::string& link) {
    return m_impl->io.call([&] {
        auto it = m_impl->links.find(link);
        return it == m_impl->links.end() ? AllStopStatus{} : it->second->session->allStop();
    });
}

LinkState IsoStack::linkState(const std::string& link) {
    return m_impl->io.call([&] {
        auto it = m_impl->links.find(link);
        return it == m_impl->links.end() ? LinkState::Unknown : it->second->session->state();
    });
}

LinkState IsoStack::mapServiceState(const std::string& link) {
    return m_impl->io.call([&] {
        auto it = m_impl->links.find(link);
        if (it == m_impl->links.end())
            return LinkState::Unknown;
        auto& s = *it->second->session;
        return s.separateMapService() ? s.mapChannelState() : s.state();
    });
}

Counters* IsoStack::linkCounters(const std::string& link) const {
    auto it = m_impl->linkCounters.find(link);
    return it == m_impl->linkCounters.end() ? nullptr : it->second.get();
}

std::chrono::milliseconds IsoStack::ioStalledFor() const {
    return m_impl->io.sinceLastTurn();
}

void IsoStack::postToIo(std::function<void()> f) {
    if (m_impl->io.running())
        m_impl->io.post(std::move(f));
}

std::vector<std::string> IsoStack::linkNames() const {
    std::vector<std::string> out;
    for (auto& l : m_impl->cfg.links)
        out.push_back(l.name);
    return out;
}

std::shared_ptr<const MapModel> IsoStack::map(const std::string& link) {
    return m_impl->io.call([&]() -> std::shared_ptr<const MapModel> {
        auto it = m_impl->links.find(link);
        return it == m_impl->links.end() ? nullptr : it->second->session->map();
    });
}

} // namespace ocu::iso23725
