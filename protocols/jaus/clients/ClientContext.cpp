#include "protocols/jaus/clients/ClientContext.h"

#include <algorithm>

#include "protocols/common/Log.h"

namespace ocu::jaus {

namespace {
constexpr const char* kLog = "ocu.jaus";
}

Duration secondsD(double s) {
    return std::chrono::duration_cast<Duration>(std::chrono::duration<double>(s));
}
Duration periodOf(double hz) {
    return secondsD(1.0 / std::max(hz, 0.01));
}

ClientContext::ClientContext(JausConfig config, JausListener& listener, JausOutput& output,
                             const Clock& clock, Counters& counters)
    : m_cfg(std::move(config)), m_listener(listener), m_out(output), m_clock(clock), m_counters(counters),
      m_self(m_cfg.ownId()) {}

bool ClientContext::send(const JausId& dst, const Bytes& payload, SendOptions o) {
    m_counters.add("tx.messages");
    m_lastSendError = m_out.sendOrWhy(dst, payload, o);
    if (m_lastSendError.empty())
        return true;
    m_counters.add("tx.failed");
    return false;
}

void ClientContext::notify(Severity s, EventKind k, std::uint16_t ss, std::string text) {
    if (s != Severity::Info)
        logWarning(kLog, text);
    m_listener.onEvent(JausEvent{s, k, ss, std::move(text)});
}

void ClientContext::changed(const RemoteSubsystem& r) {
    m_listener.onSubsystemChanged(r.snap);
}

bool ClientContext::refuse(std::uint16_t ss, const std::string& why, OutcomeReason cause) {
    m_counters.add("cmd.refused");
    m_lastRefusal = why;
    m_lastRefusalCause = cause;
    notify(Severity::Warning, EventKind::CommandRefused, ss, why);
    return false;
}

bool ClientContext::refuseQuietly(const std::string& why, OutcomeReason cause) {
    m_counters.add("cmd.refused");
    m_lastRefusal = why;
    m_lastRefusalCause = cause;
    return false;
}

std::string ClientContext::noTarget(std::uint16_t ss, const char* service) const {
    const RemoteSubsystem* r = find(ss);
    const std::string name = "subsystem " + std::to_string(ss);
    if (!r)
        return name + " has not been discovered (no message from it yet)";
    if (!r->components.known)
        return name + " (" + r->snap.callSign + ") has not reported its services yet (no ReportServices)";
    return "no component of " + name + " offers " + service + " (directly or by inheritance)";
}

bool ClientContext::refuseNoTarget(std::uint16_t ss, const char* service) {
    const RemoteSubsystem* r = find(ss);
    const OutcomeReason cause = !r                    ? OutcomeReason::UnknownTarget
                                : r->components.known ? OutcomeReason::NotSupported
                                                      : OutcomeReason::Refused;
    return refuse(ss, noTarget(ss, service), cause);
}

bool ClientContext::sendFailed(std::uint16_t ss, const char* what) {
    return refuse(
        ss, std::string(what) + " for subsystem " + std::to_string(ss) + " was not sent: " + m_lastSendError,
        OutcomeReason::SendFailed);
}

void ClientContext::rejected(const JausId& src, const std::string& error) {
    m_counters.add("rx.rejected." + rejectReason(error));
    logWarning(kLog, "from " + src.toString() + ": " + error);
}

RemoteSubsystem* ClientContext::find(std::uint16_t ss) {
    auto it = m_remotes.find(ss);
    return it == m_remotes.end() ? nullptr : &it->second;
}
const RemoteSubsystem* ClientContext::find(std::uint16_t ss) const {
    auto it = m_remotes.find(ss);
    return it == m_remotes.end() ? nullptr : &it->second;
}

RemoteSubsystem& ClientContext::remote(std::uint16_t ss) {
    auto it = m_remotes.find(ss);
    if (it != m_remotes.end())
        return it->second;
    RemoteSubsystem& r = m_remotes[ss];
    r.snap.subsystem = ss;
    r.snap.access = AccessState::Monitoring;
    r.snap.link = LinkState::Up;
    r.components.platformManager = JausId{ss, 1, 1};
    return r;
}

} // namespace ocu::jaus
