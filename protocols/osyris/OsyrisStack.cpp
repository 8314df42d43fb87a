#include "protocols/osyris/OsyrisStack.h"

#include "protocols/common/IoThread.h"
#include "protocols/common/Log.h"
#include "protocols/common/MessageTap.h"

#include <boost/asio/steady_timer.hpp>

#include <algorithm>
#include <atomic>

namespace ocu::osyris {

namespace asio = boost::asio;

struct OsyrisStack::Impl {
    explicit Impl(Clock& clk) : clock(clk) {}
    Clock& clock; // the Beat and the station's timeouts are measured on it
    IoThread io{"osyris", true};
    asio::steady_timer beat{io.context()};
    std::unique_ptr<RibbonStore> store;
    std::unique_ptr<StationCore> core;
    std::unique_ptr<OsyrisTransport> transport; // after core: it counts into the core's counters
    RxImpairment imp;
    std::atomic<bool> running{false};
    bool lastSendOk = false; // io thread: the last datagram went to every destination
    TimePoint nextBeat;
    int beatMs = 100;
    std::atomic<std::int64_t> maxHandlerNs{0};
    MessageTap* tap = nullptr; // the flight recorder's
    std::string tapLink;
    OsyrisConfig tapCfg; // checksum, MaxLen and our own index, as the station decodes

    // The datagram to the tap, before the station handles it - raw as received, and each message
    // the codec accepts (with the station's checksum and MaxLen) as its own bytes. Our own looped-back
    // datagrams are not inbound.
    void tapDatagram(ByteSpan d) {
        const OsyrisConfig& cfg = tapCfg;
        if (tap->wantsRaw())
            tap->onRaw({"osyris", tapLink, {}, {}, d});
        const DecodedDatagram dd =
            decodeDatagram(d, cfg.checksum, static_cast<std::size_t>(std::max(cfg.maxLen, 1500)));
        if (dd.messages.empty() || dd.messages.front().header.who == cfg.stationIndex)
            return;
        char peer[4];
        const unsigned who = dd.messages.front().header.who;
        peer[0] = char('0' + who / 100), peer[1] = char('0' + who / 10 % 10), peer[2] = char('0' + who % 10);
        const std::string_view peerView = who >= 100  ? std::string_view(peer, 3)
                                          : who >= 10 ? std::string_view(peer + 1, 2)
                                                      : std::string_view(peer + 2, 1);
        std::size_t off = 0;
        for (const Message& m : dd.messages) {
            const std::size_t len = m.header.len;
            if (len == 0 || off + len > d.size())
                break;
            std::string_view type = "Cm?";
            switch (m.header.type) {
            case std::uint16_t(MsgType::Pos):
                type = "CmPos";
                break;
            case std::uint16_t(MsgType::Request):
                type = "CmRequest";
                break;
            case std::uint16_t(MsgType::Msg):
            case kTypeMsgAlt:
                type = "CmMsg";
                break;
            case std::uint16_t(MsgType::PosProps):
                type = "CmPosProps";
                break;
            }
            tap->onDecoded({"osyris", tapLink, peerView, type, d.subspan(off, len)});
            off += len;
        }
    }

    // Runs one io-thread handler and keeps the longest duration seen: the io thread's real work, so on the
    // steady clock, not on the stack's Clock (a test's FakeClock would measure nothing).
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

    // The Beat is due at nextBeat on the stack's Clock; the timer sleeps for what is left of it, at most one
    // Beat (a FakeClock that does not move still gets a Beat per beatMs of real time).
    void scheduleBeat() {
        beat.expires_after(std::clamp(nextBeat - clock.now(), Duration::zero(),
                                      Duration(std::chrono::milliseconds(beatMs))));
        beat.async_wait([this](boost::system::error_code ec) {
            if (ec || !running)
                return;
            timed([this] { core->tick(); });
            nextBeat += std::chrono::milliseconds(beatMs);
            auto now = clock.now();
            if (nextBeat < now)
                nextBeat = now; // never burst to catch up after a stall
            scheduleBeat();
        });
    }
};

OsyrisStack::OsyrisStack(OsyrisConfig cfg, OsyrisListener& listener, Clock& clock)
    : m_cfg(std::move(cfg)), m_listener(listener), m_grid(m_cfg.passCount),
      m_impl(std::make_unique<Impl>(clock)) {
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
        m_cfg, m_impl->clock, *m_impl->store, &m_grid, &m_listener,
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
        impl->transport->startReceive([impl](ByteSpan d) {
            impl->timed([&] {
                if (impl->tap)
                    impl->tapDatagram(d);
                impl->core->receive(d);
            });
        });
        impl->nextBeat = impl->clock.now() + std::chrono::milliseconds(impl->beatMs);
        impl->scheduleBeat();
    });
    return true;
}

void OsyrisStack::setMessageTap(MessageTap* tap) {
    m_impl->tap = tap;
    m_impl->tapLink = "osyris:" + m_cfg.group + ":" + std::to_string(m_cfg.port);
    m_impl->tapCfg = m_cfg;
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
        done(
            {TargetOutcome::refused(target, OutcomeReason::NotRunning, "the OSYRIS station is not running")});
        return;
    }
    // From the calling thread at once (the STOP text does not wait for the io thread to wake
    // up, docs/decisions/stop-from-callers-thread.md); the io thread sends it instead when the socket would
    // not take it without waiting.
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
            done({TargetOutcome::refused(target, OutcomeReason::SendFailed, "socket error: " + why)});
            return;
        }
    }
    m_impl->io.post([this, t = std::move(text), to, target, done = std::move(done)] {
        TargetOutcome o =
            TargetOutcome::refused(target, OutcomeReason::NotRunning, "the OSYRIS station is not running");
        if (m_impl->running && m_impl->transport) {
            m_impl->lastSendOk = false;
            m_impl->core->sendText(t, to);
            o = m_impl->lastSendOk
                    ? TargetOutcome::sentTo(target)
                    : TargetOutcome::refused(target, OutcomeReason::SendFailed,
                                             "socket error: " + m_impl->transport->lastError());
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
        done(
            {TargetOutcome::refused(target, OutcomeReason::NotRunning, "the OSYRIS station is not running")});
        return;
    }
    m_impl->io.post([this, idx, target, done = std::move(done)] {
        TargetOutcome o =
            TargetOutcome::refused(target, OutcomeReason::NotRunning, "the OSYRIS station is not running");
        if (m_impl->running && m_impl->transport) {
            m_impl->lastSendOk = false;
            m_impl->core->pingNow(idx);
            o = m_impl->lastSendOk
                    ? TargetOutcome::sentTo(target)
                    : TargetOutcome::refused(target, OutcomeReason::SendFailed,
                                             "socket error: " + m_impl->transport->lastError());
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
