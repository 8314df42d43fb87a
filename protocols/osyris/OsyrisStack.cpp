#include "protocols/osyris/OsyrisStack.h"

#include "protocols/common/IoThread.h"
#include "protocols/common/Log.h"

#include <boost/asio/steady_timer.hpp>

#include <atomic>

namespace ocu::osyris {

namespace asio = boost::asio;

struct OsyrisStack::Impl {
    IoThread io{"osyris", true};
    asio::steady_timer beat{io.context()};
    std::unique_ptr<RibbonStore> store;
    std::unique_ptr<StationCore> core;
    std::unique_ptr<OsyrisTransport> transport; // after core: it counts into the core's counters
    RxImpairment imp;
    std::atomic<bool> running{false};
    bool lastSendOk = false; // io thread: the last datagram went to every destination
    std::chrono::steady_clock::time_point nextBeat;
    int beatMs = 100;
    std::atomic<std::int64_t> maxHandlerNs{0};

    // Runs one io-thread handler and keeps the longest duration seen.
    template <class F> void timed(F&& f) {
        const auto t0 = std::chrono::steady_clock::now();
        f();
        const std::int64_t ns =
            std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - t0)
                .count();
        std::int64_t seen = maxHandlerNs.load(std::memory_order_relaxed);
        while (ns > seen && !maxHandlerNs.compare_exchange_weak(seen, ns, std::memory_order_relaxed)) {
        }
    }

    void scheduleBeat() {
        beat.expires_at(nextBeat);
        beat.async_wait([this](boost::system::error_code ec) {
            if (ec || !running)
                return;
            timed([this] { core->tick(); });
            nextBeat += std::chrono::milliseconds(beatMs);
            auto now = std::chrono::steady_clock::now();
            if (nextBeat < now)
                nextBeat = now; // never burst to catch up after a stall
            scheduleBeat();
        });
    }
};

OsyrisStack::OsyrisStack(OsyrisConfig cfg, OsyrisListener& listener)
    : m_cfg(std::move(cfg)), m_listener(listener), m_grid(m_cfg.passCount), m_impl(std::make_unique<Impl>()) {
    m_impl->beatMs = m_cfg.beatMs;
}

OsyrisStack::~OsyrisStack() {
    stop();
}

Counters& OsyrisStack::counters() {
    return m_impl->core ? m_impl->core->counters() : m_fallbackCounters;
}
std::chrono::nanoseconds OsyrisStack::maxHandlerDuration() const {
    return std::chrono::nanoseconds(m_impl->maxHandlerNs.load());
}
void OsyrisStack::resetMaxHandlerDuration() {
    m_impl->maxHandlerNs = 0;
}

std::chrono::milliseconds OsyrisStack::ioStalledFor() const {
    return m_impl->io.sinceLastTurn();
}
void OsyrisStack::postToIo(std::function<void()> f) {
    if (m_impl->running)
        m_impl->io.post(std::move(f));
}
RibbonStore* OsyrisStack::store() {
    return m_impl->store.get();
}
StationCore* OsyrisStack::core() {
    return m_impl->core.get();
}
bool OsyrisStack::running() const {
    return m_impl->running;
}

void OsyrisStack::callOnIo(const std::function<void()>& f) {
    m_impl->io.call([&] { f(); });
}

void OsyrisStack::setPassCountSettings(const PassCountSettings& s) {
    if (!m_impl->running) {
        m_grid.setSettings(s);
        m_cfg.passCount = s;
        return;
    }
    m_impl->io.post([this, s] {
        if (m_impl->core)
            m_impl->core->setPassCountSettings(s);
    });
}

std::shared_ptr<const PassCountSnapshot> OsyrisStack::passCounts() {
    return m_impl->io.call([this] { return m_grid.snapshot(); });
}

bool OsyrisStack::start(std::string* error) {
    if (m_impl->running)
        return true;
    auto fail = [&](const std::string& msg) {
        if (error)
            *error = msg;
        logWarning("osyris", msg);
        m_listener.onEvent(Severity::Error, msg);
        return false;
    };
    auto st = RibbonStore::open(m_cfg.sqlitePath);
    if (!st)
        return fail(st.error());
    m_impl->store = std::move(*st);
    m_impl->transport.reset(); // a restart: the old transport counted into the old core's counters
    Impl* impl = m_impl.get();
    m_impl->core = std::make_unique<StationCore>(
        m_cfg, SteadyClock::instance(), *m_impl->store, &m_grid, &m_listener,
        [impl](const Bytes& d) { impl->lastSendOk = impl->transport->send(d); },
        static_cast<std::uint32_t>(m_cfg.stationIndex) * 7919u + 17u);
    m_impl->transport = std::make_unique<OsyrisTransport>(m_impl->io.context(), m_impl->core->counters());
    m_impl->transport->setImpairment(m_impl->imp);
    try {
        m_impl->transport->open(m_cfg);
    } catch (const std::exception& e) {
        m_impl->transport.reset();
        m_impl->core.reset();
        return fail(e.what());
    }
    m_localPort = m_impl->transport->localPort();
    m_impl->running = true;
    m_impl->io.start();
    m_impl->io.post([impl] {
        impl->core->start();
        impl->core->updateGrid(); // counts of a reopened site file appear at once
        impl->transport->startReceive([impl](ByteSpan d) { impl->timed([&] { impl->core->receive(d); }); });
        impl->nextBeat = std::chrono::steady_clock::now() + std::chrono::milliseconds(impl->beatMs);
        impl->scheduleBeat();
    });
    return true;
}

void OsyrisStack::stop() {
    if (!m_impl->running)
        return;
    m_impl->io.call([this] {
        m_impl->running = false;
        m_impl->beat.cancel();
        m_impl->transport->close(); // IGMP leave
        if (m_impl->store)
            m_impl->store->commit();
    });
    m_impl->io.stop();
}

void OsyrisStack::sendText(std::string text, std::uint8_t to) {
    if (!m_impl->running)
        return;
    m_impl->io.post([this, t = std::move(text), to] { m_impl->core->sendText(t, to); });
}

void OsyrisStack::sendText(std::string text, std::uint8_t to, OutcomeCallback done) {
    const std::string target = to == kIdxAll ? groupTarget() : "osyris:" + std::to_string(to);
    if (!m_impl->running) {
        done({TargetOutcome{target, false, "the OSYRIS station is not running"}});
        return;
    }
    // From the calling thread at once (issue 13 §10: the STOP text does not wait for the io thread to wake
    // up); the io thread sends it instead when the socket would not take it without waiting.
    if (StationCore* c = m_impl->core.get(); c && m_impl->transport) {
        const Bytes d = c->textDatagram(text, to);
        std::string why;
        std::size_t taken = 0;
        const bool all = m_impl->transport->sendFromAnyThread(d, &why, &taken);
        if (taken > 0)
            c->textSent(d.size());
        if (all) {
            done({TargetOutcome{target, true, {}}});
            return;
        }
        if (taken > 0) { // some destinations have it: sending again would show it twice there
            done({TargetOutcome{target, false, "socket error: " + why}});
            return;
        }
    }
    m_impl->io.post([this, t = std::move(text), to, target, done = std::move(done)] {
        TargetOutcome o{target, false, "the OSYRIS station is not running"};
        if (m_impl->running && m_impl->transport) {
            m_impl->lastSendOk = false;
            m_impl->core->sendText(t, to);
            o.sent = m_impl->lastSendOk;
            if (!o.sent)
                o.reason = "socket error: " + m_impl->transport->lastError();
        }
        done({std::move(o)});
    });
}

void OsyrisStack::ping(std::uint8_t idx) {
    if (!m_impl->running)
        return;
    m_impl->io.post([this, idx] { m_impl->core->ping(idx); });
}

void OsyrisStack::ping(std::uint8_t idx, OutcomeCallback done) {
    const std::string target = "osyris:" + std::to_string(idx);
    if (!m_impl->running) {
        done({TargetOutcome{target, false, "the OSYRIS station is not running"}});
        return;
    }
    m_impl->io.post([this, idx, target, done = std::move(done)] {
        TargetOutcome o{target, false, "the OSYRIS station is not running"};
        if (m_impl->running && m_impl->transport) {
            m_impl->lastSendOk = false;
            m_impl->core->pingNow(idx);
            o.sent = m_impl->lastSendOk;
            o.reason = o.sent ? std::string() : "socket error: " + m_impl->transport->lastError();
        }
        done({std::move(o)});
    });
}

void OsyrisStack::publishOwnPosition(CmPos p, std::vector<PosProp> props) {
    if (!m_impl->running)
        return;
    m_impl->io.post(
        [this, p, pr = std::move(props)]() mutable { m_impl->core->publishOwnPosition(p, std::move(pr)); });
}

void OsyrisStack::setImpairment(const RxImpairment& imp) {
    auto apply = [this, imp] {
        m_impl->imp = imp;
        if (m_impl->transport)
            m_impl->transport->setImpairment(imp);
    };
    if (m_impl->running)
        m_impl->io.post(apply);
    else
        apply();
}

} // namespace ocu::osyris
