#include "protocols/jaus/JausStack.h"

#include <boost/asio/steady_timer.hpp>

#include <algorithm>
#include <atomic>
#include <map>
#include <mutex>
#include <thread>

#include "protocols/common/IoThread.h"
#include "protocols/common/Log.h"
#include "protocols/common/MessageTap.h"
#include "protocols/jaus/JausCore.h"
#include "protocols/jaus/JudpTransport.h"
#include "protocols/jaus/Messages.h"

namespace ocu::jaus {

struct JausStack::Impl : JausOutput {
    Impl(JausConfig c, JausListener& l, Clock& clk)
        : cfg(std::move(c)), listener(l), clock(clk), io("jaus", true),
          transport(io.context(), cfg.transport, counters, clock, "ocu.jaus"),
          core(cfg, listener, *this, clock, counters), timer(io.context()) {}

    void send(const JausId& dst, const Bytes& payload, SendOptions o) override {
        transport.send(cfg.ownId(), dst, payload, o);
    }
    std::string sendOrWhy(const JausId& dst, const Bytes& payload, SendOptions o) override {
        return transport.send(cfg.ownId(), dst, payload, o);
    }
    std::string endpointOf(const JausId& id) const override { return transport.endpointOf(id); }

    void scheduleTick() {
        timer.expires_after(std::chrono::milliseconds(10));
        timer.async_wait([this](boost::system::error_code ec) {
            if (ec)
                return;
            core.tick();
            refreshStopPlans();
            scheduleTick();
        });
    }

    // ---- STOP ALL fast path (docs/decisions/stop-from-callers-thread.md) ----
    // The io thread keeps, per discovered subsystem, the SetEmergency datagram the core would send now
    // (routed and encoded; refreshed every tick). A stop sends these from the caller's thread at once, then
    // tells the core on the io thread, which learns them as sent (retries, drive session, status query) and
    // sends the rest (subsystems without a plan: JTCP, unknown address, fault injection) itself.
    struct StopPlan {
        std::uint16_t subsystem = 0;
        PlannedDatagram datagram;
        bool operator==(const StopPlan&) const = default;
    };
    static constexpr EmergencyCode kPlannedCode = EmergencyCode::Safety; // what the console's stops use

    void refreshStopPlans() {
        std::vector<StopPlan> plans;
        const Bytes payload = encodeU16(msg::SetEmergency, std::uint16_t(kPlannedCode));
        for (std::uint16_t ss : core.subsystems()) {
            auto target = core.emergencyTarget(ss);
            if (!target)
                continue;
            if (auto p = transport.plan(cfg.ownId(), *target, payload, SendOptions{Priority::Safety, false}))
                plans.push_back(StopPlan{ss, std::move(*p)});
        }
        if (plans == stopPlans) // written only here (io thread): no lock needed to read
            return;
        std::lock_guard lock(stopMutex);
        stopPlans = std::move(plans);
    }
    void clearStopPlans() {
        std::lock_guard lock(stopMutex);
        stopPlans.clear();
    }
    // Any thread: sends the planned SetEmergency of every subsystem (or of `only`); returns those the socket
    // took.
    std::vector<std::uint16_t> sendStopPlans(EmergencyCode code, std::optional<std::uint16_t> only) {
        std::vector<std::uint16_t> sent;
        if (code != kPlannedCode)
            return sent;
        std::lock_guard lock(stopMutex);
        for (const StopPlan& p : stopPlans) {
            if (only && p.subsystem != *only)
                continue;
            if (transport.sendPlanned(cfg.ownId(), p.datagram).empty())
                sent.push_back(p.subsystem);
        }
        return sent;
    }
    template <class F> void post(F&& f) {
        if (!running)
            return;
        io.post(std::forward<F>(f));
    }

    JausConfig cfg;
    JausListener& listener;
    Clock& clock;
    Counters counters;
    IoThread io;
    JudpTransport transport;
    JausCore core;
    boost::asio::steady_timer timer;
    std::map<std::string, TimePoint> lastDecodeEvent;
    std::mutex stopMutex;            // guards stopPlans against the callers of the fast path
    std::vector<StopPlan> stopPlans; // written on the io thread only
    std::atomic<bool> running{false};
    std::atomic<std::uint16_t> port{0};
    MessageTap* tap = nullptr; // the flight recorder's
    mutable std::mutex groupMutex;
    std::optional<GroupSocketProblem> groupProblem; // as of the last start(), under groupMutex
};

JausStack::JausStack(JausConfig config, JausListener& listener, Clock& clock)
    : m_impl(std::make_unique<Impl>(std::move(config), listener, clock)) {}

JausStack::~JausStack() {
    stop();
}

void JausStack::start() {
    if (m_impl->running)
        return;
    Impl* d = m_impl.get();
    d->transport.setLocalIds([d](const JausId& id) { return id == d->cfg.ownId(); });
    if (d->tap && d->tap->wantsRaw())
        d->transport.setRawHandler([d](ByteSpan data, const std::string& peer) {
            d->tap->onRaw({"jaus", "jaus", peer, {}, data});
        });
    d->transport.setHandlers(
        [d](const JausId& src, const JausId& dst, ByteSpan p) {
            if (d->tap) {
                // The message code (little-endian, AS5669A §4.2) names the type; the payload is what
                // JausCore decodes again.
                static constexpr char kHex[] = "0123456789ABCDEF";
                const unsigned code = unsigned(p[0]) | unsigned(p[1]) << 8;
                const char type[4] = {kHex[code >> 12], kHex[(code >> 8) & 15], kHex[(code >> 4) & 15],
                                      kHex[code & 15]};
                const std::string peer = src.toString();
                d->tap->onDecoded({"jaus", "jaus", peer, std::string_view(type, 4), p});
            }
            d->core.handle(src, dst, p);
        },
        [d](const std::string& reason, const std::string& text) {
            // One decode-error event per reason and second: bad peers must not flood the console.
            auto now = d->clock.now();
            auto& last = d->lastDecodeEvent[reason];
            if (last != TimePoint{} && now - last < std::chrono::seconds(1))
                return;
            last = now;
            d->listener.onEvent(
                JausEvent{Severity::Warning, EventKind::DecodeError, 0, "rejected datagram: " + text});
        });
    d->transport.open();
    d->port = d->transport.localPort();
    const std::optional<GroupSocketProblem> group = d->transport.groupSocketProblem();
    {
        std::lock_guard lock(d->groupMutex);
        d->groupProblem = group;
    }
    logInfo("ocu.jaus", "JAUS " + d->cfg.ownId().toString() + " (" + d->cfg.callSign + ") on UDP port " +
                            std::to_string(d->port.load()) + (group ? " (no group socket)" : ""));
    d->running = true;
    d->io.start();
    // The operator learns it once, as the transport logged it; listeners hear events on the io thread only.
    if (group)
        d->io.post([d, text = toText(*group)] {
            d->listener.onEvent(JausEvent{Severity::Warning, EventKind::TransportError, 0, text});
        });
    d->io.post([d] {
        d->core.tick();
        d->scheduleTick();
    });
}

void JausStack::stop() {
    if (!m_impl || !m_impl->running)
        return;
    Impl* d = m_impl.get();
    d->io.call([d] {
        d->core.releaseAll();
        d->timer.cancel();
        return 0;
    });
    // UDP sends are synchronous; JTCP writes are asynchronous: give the releases up to 300 ms to leave.
    for (int i = 0; i < 30 && d->io.call([d] { return d->transport.pendingTcpWrites(); }) > 0; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    d->io.call([d] {
        d->clearStopPlans();
        d->transport.close();
        return 0;
    });
    d->running = false;
    d->io.stop();
}

void JausStack::setMessageTap(MessageTap* tap) {
    m_impl->tap = tap;
}

bool JausStack::running() const {
    return m_impl->running;
}

#define OCU_JAUS_POST(expr)                                                                                  \
    do {                                                                                                     \
        Impl* d = m_impl.get();                                                                              \
        d->post([=] { (void)(expr); });                                                                      \
    } while (0)

void JausStack::releaseAll() {
    OCU_JAUS_POST((d->core.releaseAll(), 0));
}
void JausStack::discoverNow() {
    OCU_JAUS_POST((d->core.discoverNow(), 0));
}

#define OCU_JAUS_OUTCOME(ss, expr)                                                                           \
    do {                                                                                                     \
        Impl* d = m_impl.get();                                                                              \
        d->post([=, done = std::move(done)] {                                                                \
            TargetOutcome o = d->core.outcome(ss, (expr));                                                   \
            if (done)                                                                                        \
                done({std::move(o)});                                                                        \
        });                                                                                                  \
    } while (0)

void JausStack::requestControl(std::uint16_t ss, OutcomeCallback done) {
    OCU_JAUS_OUTCOME(ss, d->core.requestControl(ss));
}
void JausStack::releaseControl(std::uint16_t ss, OutcomeCallback done) {
    OCU_JAUS_OUTCOME(ss, d->core.releaseControl(ss));
}
void JausStack::setEmergency(std::uint16_t ss, EmergencyCode code, OutcomeCallback done) {
    Impl* d = m_impl.get();
    if (!d->running)
        return;
    const bool early = !d->sendStopPlans(code, ss).empty();
    d->post([=, done = std::move(done)] {
        TargetOutcome o = early ? d->core.emergencySent(ss, code)
                                : d->core.emergencyOutcome(ss, d->core.setEmergency(ss, code));
        if (done)
            done({std::move(o)});
    });
}
void JausStack::clearEmergency(std::uint16_t ss, OutcomeCallback done) {
    OCU_JAUS_OUTCOME(ss, d->core.clearEmergency(ss));
}
void JausStack::resume(std::uint16_t ss, OutcomeCallback done) {
    OCU_JAUS_OUTCOME(ss, d->core.resume(ss));
}
void JausStack::standby(std::uint16_t ss, OutcomeCallback done) {
    OCU_JAUS_OUTCOME(ss, d->core.standby(ss));
}
void JausStack::shutdown(std::uint16_t ss, OutcomeCallback done) {
    OCU_JAUS_OUTCOME(ss, d->core.shutdown(ss));
}
void JausStack::reset(std::uint16_t ss, OutcomeCallback done) {
    OCU_JAUS_OUTCOME(ss, d->core.reset(ss));
}
void JausStack::startDriving(std::uint16_t ss, OutcomeCallback done) {
    OCU_JAUS_OUTCOME(ss, d->core.startDriving(ss));
}
void JausStack::setDriveCommand(std::uint16_t ss, DriveCommand c, OutcomeCallback done) {
    OCU_JAUS_OUTCOME(ss, d->core.setDriveCommand(ss, c));
}
void JausStack::stopDriving(std::uint16_t ss, OutcomeCallback done) {
    OCU_JAUS_OUTCOME(ss, d->core.stopDriving(ss));
}
void JausStack::panTilt(std::uint16_t ss, std::uint16_t sensorId, double panRate, double tiltRate,
                        OutcomeCallback done) {
    OCU_JAUS_OUTCOME(ss, d->core.panTilt(ss, sensorId, panRate, tiltRate));
}
void JausStack::missionUpload(std::uint16_t ss, std::vector<MissionPoint> points, std::optional<bool> global,
                              OutcomeCallback done) {
    OCU_JAUS_OUTCOME(ss, d->core.missionUpload(ss, points, global));
}
void JausStack::missionStart(std::uint16_t ss, int fromIndex, OutcomeCallback done) {
    OCU_JAUS_OUTCOME(ss, d->core.missionStart(ss, fromIndex));
}
void JausStack::missionPause(std::uint16_t ss, OutcomeCallback done) {
    OCU_JAUS_OUTCOME(ss, d->core.missionPause(ss));
}
void JausStack::missionResume(std::uint16_t ss, OutcomeCallback done) {
    OCU_JAUS_OUTCOME(ss, d->core.missionResume(ss));
}
void JausStack::missionAbort(std::uint16_t ss, OutcomeCallback done) {
    OCU_JAUS_OUTCOME(ss, d->core.missionAbort(ss));
}
void JausStack::goTo(std::uint16_t ss, MissionPoint point, OutcomeCallback done) {
    OCU_JAUS_OUTCOME(ss, d->core.goTo(ss, point));
}
void JausStack::setPlatformMode(std::uint16_t ss, std::uint8_t mode, OutcomeCallback done) {
    OCU_JAUS_OUTCOME(ss, d->core.setPlatformMode(ss, mode));
}
void JausStack::setPlatformState(std::uint16_t ss, std::uint8_t state, OutcomeCallback done) {
    OCU_JAUS_OUTCOME(ss, d->core.setPlatformState(ss, state));
}
void JausStack::setLights(std::uint16_t ss, std::uint32_t mask, std::uint32_t on, OutcomeCallback done) {
    OCU_JAUS_OUTCOME(ss, d->core.setLights(ss, mask, on));
}
void JausStack::resetTripOdometer(std::uint16_t ss, OutcomeCallback done) {
    OCU_JAUS_OUTCOME(ss, d->core.resetTripOdometer(ss));
}
void JausStack::queryOdometry(std::uint16_t ss, OutcomeCallback done) {
    OCU_JAUS_OUTCOME(ss, d->core.queryOdometry(ss));
}
void JausStack::handoffRequest(std::uint16_t ss, std::string reason, OutcomeCallback done) {
    OCU_JAUS_OUTCOME(ss, d->core.handoffRequest(ss, reason));
}
void JausStack::handoffCancel(std::uint16_t ss, OutcomeCallback done) {
    OCU_JAUS_OUTCOME(ss, d->core.handoffCancel(ss));
}
void JausStack::handoffAnswer(std::uint16_t ss, std::uint8_t requestId, bool accept, OutcomeCallback done) {
    OCU_JAUS_OUTCOME(ss, d->core.handoffAnswer(ss, requestId, accept));
}
void JausStack::handoffWait(std::uint16_t ss, std::uint8_t requestId, OutcomeCallback done) {
    OCU_JAUS_OUTCOME(ss, d->core.handoffWait(ss, requestId));
}
void JausStack::setEmergencyAll(EmergencyCode code, OutcomeCallback done) {
    Impl* d = m_impl.get();
    if (!d->running)
        return;
    auto early = d->sendStopPlans(code, std::nullopt);
    d->post([=, done = std::move(done), early = std::move(early)] {
        auto outcomes = d->core.setEmergencyAll(code, early);
        if (done)
            done(std::move(outcomes));
    });
}

#undef OCU_JAUS_POST

void JausStack::setTransmitFaults(double loss, int delayMs) {
    Impl* d = m_impl.get();
    d->post([d, loss, delayMs] {
        NetFaults f;
        f.loss = loss;
        f.delay = std::chrono::milliseconds(delayMs);
        d->transport.setFaults(f);
    });
}

std::size_t JausStack::plannedStopCount() const {
    Impl* d = m_impl.get();
    std::lock_guard lock(d->stopMutex);
    return d->stopPlans.size();
}

Counters& JausStack::counters() {
    return m_impl->counters;
}
std::chrono::milliseconds JausStack::ioStalledFor() const {
    return m_impl->io.sinceLastTurn();
}
void JausStack::postToIo(std::function<void()> f) {
    m_impl->post(std::move(f));
}
const JausConfig& JausStack::config() const {
    return m_impl->cfg;
}
std::uint16_t JausStack::localPort() const {
    return m_impl->port;
}

std::optional<GroupSocketProblem> JausStack::groupSocketProblem() const {
    std::lock_guard lock(m_impl->groupMutex);
    return m_impl->groupProblem;
}

std::optional<SubsystemSnapshot> JausStack::snapshot(std::uint16_t ss) const {
    Impl* d = m_impl.get();
    if (!d->running)
        return d->core.snapshot(ss);
    return d->io.call([d, ss] { return d->core.snapshot(ss); });
}

std::vector<std::uint16_t> JausStack::subsystems() const {
    Impl* d = m_impl.get();
    if (!d->running)
        return d->core.subsystems();
    return d->io.call([d] { return d->core.subsystems(); });
}

} // namespace ocu::jaus
