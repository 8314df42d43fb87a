#pragma once
// The OCU (or a simulated machine) as an OSYRIS station: owns the io thread and the Beat timer, and wires an
// OsyrisTransport (the UDP socket) to a StationCore (the protocol) and the pass-count grid. Everything except
// the constructor's arguments is thread-safe; listener callbacks run on the io thread.
#include "protocols/osyris/OsyrisConfig.h"
#include "protocols/osyris/OsyrisTransport.h"
#include "protocols/osyris/PassCountGrid.h"
#include "protocols/osyris/RibbonStore.h"
#include "protocols/osyris/StationCore.h"

#include "protocols/common/Clock.h"
#include "protocols/common/CommandOutcome.h"
#include "protocols/common/Counters.h"

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace ocu {
class MessageTap;
}

namespace ocu::osyris {

class OsyrisStack {
public:
    // The Beat and every timeout of the station are measured on `clock`, which must outlive the stack.
    OsyrisStack(OsyrisConfig cfg, OsyrisListener& listener, Clock& clock = SteadyClock::instance());
    ~OsyrisStack();
    OsyrisStack(const OsyrisStack&) = delete;
    OsyrisStack& operator=(const OsyrisStack&) = delete;

    // Opens the ribbon store and the socket, joins the group and starts the Beat. On failure returns false
    // with the reason in *error (also reported through onEvent, on the calling thread).
    bool start(std::string* error = nullptr);
    void stop();
    // Every message of another station that the codec accepts (and, when the tap wants them, every
    // datagram as received) goes to `tap` on the io thread. Set before start(); the tap outlives the run.
    void setMessageTap(MessageTap* tap);
    bool running() const;

    void sendText(std::string text, std::uint8_t to = kIdxAll);
    // The text as its own datagram at once (not with the next Beat), with its outcome: `done`
    // runs once with one TargetOutcome for the group (target groupTarget()): sent when the socket took the
    // datagram for every destination, otherwise the reason. Sent from the calling thread (and `done` run
    // there) when the socket takes it at once; otherwise on the io thread (and `done` there).
    void sendText(std::string text, OutcomeCallback done) {
        sendText(std::move(text), kIdxAll, std::move(done));
    }
    // The same to one station (CmMsg IdxWhose = to; kIdxAll = everybody): the outcome's target is then
    // "osyris:<to>" (the datagram still goes to the group: OSYRIS addresses by IdxWhose, not by socket).
    void sendText(std::string text, std::uint8_t to, OutcomeCallback done);
    std::string groupTarget() const {
        return "osyris group " + m_cfg.group + ":" + std::to_string(m_cfg.port);
    }
    void ping(std::uint8_t idx);
    // A ping as its own datagram at once, with its outcome: one TargetOutcome "osyris:<idx>", sent when the
    // socket took it (the PONG, an event with the round trip, is the confirmation). Threads as sendText.
    void ping(std::uint8_t idx, OutcomeCallback done);
    // For stations that are machines (simulated rollers): write a position into the own ribbon.
    void publishOwnPosition(CmPos p, std::vector<PosProp> props = {});
    void setImpairment(const RxImpairment& imp);
    // Filters, lifts: the io thread recounts the whole job from the ribbons.
    void setPassCountSettings(const PassCountSettings& s);

    const OsyrisConfig& config() const { return m_cfg; }
    Counters& counters();
    // Watchdog: how long the io thread has not turned (0 while it turns or is not running).
    std::chrono::milliseconds ioStalledFor() const;
    // Runs f on the io thread without waiting (diagnostics; tests block the thread with it on purpose).
    void postToIo(std::function<void()> f);
    // Thread-safe (own locks); valid after start().
    RibbonStore* store();
    // A snapshot of the pass counts now, taken on the io thread (blocking: tests, diagnostics). The GUI gets
    // its snapshots through OsyrisListener::onPassCounts instead.
    std::shared_ptr<const PassCountSnapshot> passCounts();
    std::uint16_t localPort() const { return m_localPort; }
    // The longest a single io-thread handler (one received datagram, one Beat) has run since start or the
    // last reset (no single input may stall the io thread). Thread-safe.
    std::chrono::nanoseconds maxHandlerDuration() const;
    void resetMaxHandlerDuration();
    // Runs f(core) on the io thread and returns its result (tests, diagnostics).
    template <class F> auto withCore(F&& f) -> decltype(f(std::declval<StationCore&>()));

private:
    struct Impl;
    OsyrisConfig m_cfg;
    OsyrisListener& m_listener;
    PassCountGrid m_grid; // io thread only
    std::unique_ptr<Impl> m_impl;
    std::uint16_t m_localPort = 0;
    Counters m_fallbackCounters;
    StationCore* core();
    void callOnIo(const std::function<void()>& f);
};

template <class F> auto OsyrisStack::withCore(F&& f) -> decltype(f(std::declval<StationCore&>())) {
    using R = decltype(f(std::declval<StationCore&>()));
    if constexpr (std::is_void_v<R>) {
        callOnIo([&] { f(*core()); });
    } else {
        std::optional<R> out;
        callOnIo([&] { out.emplace(f(*core())); });
        return std::move(*out);
    }
}

} // namespace ocu::osyris
