#pragma once
// What the JAUS client services of one console share: the configuration, the clock, the way out to the
// transport, the listener, the counters and the record of every remote subsystem. JausCore owns one; each
// client (clients/*Client.h) holds a reference. No sockets and no threads here.
#include <cstdint>
#include <map>
#include <string>

#include "protocols/common/Clock.h"
#include "protocols/common/CommandOutcome.h"
#include "protocols/common/Counters.h"
#include "protocols/jaus/JausConfig.h"
#include "protocols/jaus/JausOutput.h"
#include "protocols/jaus/JausTypes.h"

namespace ocu::jaus {

// Who offers what on one remote subsystem, learnt by the DiscoveryClient (ReportIdentification,
// ReportServices); the other clients read it to address their queries and commands. The Core Mobility
// Component lives in the snapshot (SubsystemSnapshot::mobilityComponent) because the console shows it.
struct ComponentTable {
    // A services answer or registration listed a component with services: events, polls and commands may
    // start. An answer listing no component at all leaves it false (the vehicle has not told us yet).
    bool known = false;
    JausId platformManager; // identification, services, heartbeat
    JausId globalPoseSensor, localPoseSensor, velocitySensor, healthMonitor, platformSpecs;
    // The components offering AccessControl and Management directly or by inheritance (ServiceInheritance.h);
    // zero when the subsystem has none.
    JausId accessControl, management;
    // The demands the mobility component's services accept: SetVelocityCommand (VelocityStateDriver) and
    // SetWrenchEffort (PrimitiveDriver).
    bool driverTakesVelocity = false, driverTakesEffort = false;
};

// One remote subsystem (a vehicle) as the console knows it. Each client writes only its own fields of the
// snapshot; its private state it keeps itself, keyed by subsystem ID.
struct RemoteSubsystem {
    SubsystemSnapshot snap;
    ComponentTable components;

    std::uint16_t id() const { return snap.subsystem; }
    const JausId& mobility() const { return snap.mobilityComponent; }
    // Where RequestControl / ReleaseControl / QueryControl go: the driver (teleop needs control of it),
    // else the component that offers AccessControl (by inheritance too). Zero when none is known.
    JausId controlTarget() const { return mobility().subsystem ? mobility() : components.accessControl; }
    // Where SetEmergency / ClearEmergency / QueryStatus / Resume... go: the component that offers Management
    // (the driver when it does). Zero when none is known.
    JausId managementTarget() const {
        return components.management.subsystem ? components.management : mobility();
    }
    bool reachable() const { return snap.link != LinkState::Down; }
};

class ClientContext {
public:
    ClientContext(JausConfig config, JausListener& listener, JausOutput& output, const Clock& clock,
                  Counters& counters);

    const JausConfig& config() const { return m_cfg; }
    const JausId& self() const { return m_self; }
    TimePoint now() const { return m_clock.now(); }
    Counters& counters() { return m_counters; }

    // True when the message was handed to a socket; otherwise lastSendError() says why.
    bool send(const JausId& destination, const Bytes& payload, SendOptions options = {});
    const std::string& lastSendError() const { return m_lastSendError; }
    std::string endpointOf(const JausId& id) const { return m_out.endpointOf(id); }
    // An event for the operator; warnings and errors are logged too.
    void notify(Severity severity, EventKind kind, std::uint16_t subsystem, std::string text);
    // The subsystem's snapshot changed: hand it to the listener.
    void changed(const RemoteSubsystem& remote);
    // A command the console does not send: counter, CommandRefused event; returns false. `cause` is the
    // outcome's kind; Refused means the service's own rules (the text says which).
    bool refuse(std::uint16_t subsystem, const std::string& why,
                OutcomeReason cause = OutcomeReason::Refused);
    // The same without the event (a refusal repeated at a stream's rate, e.g. a held pan-tilt key: the
    // first one was an event already); counted and the outcome's reason all the same.
    bool refuseQuietly(const std::string& why, OutcomeReason cause = OutcomeReason::Refused);
    // refuse() for a command with no component to go to (noTarget's words): UnknownTarget while the
    // subsystem was never heard, NotSupported when none of its components offers `service`.
    bool refuseNoTarget(std::uint16_t subsystem, const char* service);
    // Why a command for a subsystem has no component to go to, in words an operator can act on: not
    // discovered, services not reported yet, or no component offering `service` (directly or by inheritance).
    std::string noTarget(std::uint16_t subsystem, const char* service) const;
    // A command whose message could not be handed to a socket: refuse() with the transport's reason.
    bool sendFailed(std::uint16_t subsystem, const char* what);
    // The reason given by the latest refuse() (the command outcome's reason) and its kind.
    const std::string& lastRefusal() const { return m_lastRefusal; }
    OutcomeReason lastRefusalCause() const { return m_lastRefusalCause; }
    // A message that did not decode: counter rx.rejected.<reason> and a log line.
    void rejected(const JausId& source, const std::string& error);

    RemoteSubsystem* find(std::uint16_t subsystem);
    const RemoteSubsystem* find(std::uint16_t subsystem) const;
    // The record of a subsystem, created on first contact (link up, monitoring, platform manager ss.1.1).
    RemoteSubsystem& remote(std::uint16_t subsystem);
    void erase(std::uint16_t subsystem) { m_remotes.erase(subsystem); }
    std::map<std::uint16_t, RemoteSubsystem>& remotes() { return m_remotes; }
    const std::map<std::uint16_t, RemoteSubsystem>& remotes() const { return m_remotes; }

private:
    JausConfig m_cfg;
    JausListener& m_listener;
    JausOutput& m_out;
    const Clock& m_clock;
    Counters& m_counters;
    std::string m_lastRefusal;
    OutcomeReason m_lastRefusalCause = OutcomeReason::None;
    std::string m_lastSendError;
    JausId m_self;
    std::map<std::uint16_t, RemoteSubsystem> m_remotes;
};

// Clock helpers shared by the clients.
Duration secondsD(double s);
Duration periodOf(double hz); // 1 / hz, at most 100 s

} // namespace ocu::jaus
