#pragma once
// Hand-off of control between consoles (AEP-4818 §6.3: Enhanced Access Control on the vehicle, a
// HandoffController on each console; public 1.1 layouts, MessagesHandoff.h). Both sides of it:
//  * requester: a vehicle another console holds: QueryEnhancedTimeout / QueryHandoffTimeout, then
//    RequestHandoff(our authority, "<call sign>: <reason>") to the component offering EnhancedAccessControl,
//    re-asserted every third of the vehicle's Handoff Request Timeout (5 s by default, so within it as the
//    profile requires) until the answer is final. DEFERRED (or FKIE's private 7) is the holder's WAIT: still
//    queued and re-asserted, the decision time starting again; QUEUED waits for the holder (up to the Handoff
//    Decision Timeout, 60 s by default); GRANTED is followed by our RequestControl (the EAC leaves control to
//    the requester's own request, FKIE's EAC and jaus-autonomy.md §8); DENIED, TIMEOUT, NOT_AVAILABLE and
//    INSUFFICIENT_AUTHORITY end it with the reason. RemoveHandoffRequest withdraws it.
//  * a vehicle without Enhanced Access Control: the ordinary AccessControl pre-emption rules apply
//    (AS5710A: only a higher authority takes control), so the console sends RequestControl and says so;
//  * holder: RequestReleaseControl forwarded by the vehicle lists every queued request (who, authority,
//    explanation); each is shown to the operator (SubsystemSnapshot::handoff.prompts) until answered with
//    ConfirmReleaseControl (GRANTED or DENIED; at most one GRANTED; WAIT keeps it) or until the decision
//    timeout passes, when the vehicle answers the requester TIMEOUT itself. After a GRANTED the vehicle's
//    RejectControl ends our control as a release, not as a loss.
// Results go to SubsystemSnapshot::handoff; each step the operator should know of is a HandoffChanged event.
#include <cstdint>
#include <map>
#include <string>

#include "protocols/jaus/MessagesHandoff.h"
#include "protocols/jaus/clients/ClientService.h"

namespace ocu::jaus {

class AccessControlClient;

class HandoffClient : public ClientService {
public:
    HandoffClient(ClientContext& context, AccessControlClient& access)
        : ClientService(context), m_access(access) {}

    void registerMessages(MessageTable& table) override;
    void onServicesKnown(RemoteSubsystem& remote) override;
    void tick(RemoteSubsystem& remote, TimePoint now) override;
    void forget(std::uint16_t subsystem) override { m_state.erase(subsystem); }

    // Commands; each returns false with the reason (ClientContext::refuse) when nothing went out.
    bool request(std::uint16_t subsystem, const std::string& reason);
    bool cancel(std::uint16_t subsystem);
    // The answer to a forwarded request (its queue ID): GRANTED, DENIED or WAIT (the request stays, shown as
    // answered "wait", and its decision time starts again as the vehicle restarts it).
    bool answer(std::uint16_t subsystem, std::uint8_t id, ReleaseCode code);

private:
    struct State {
        TimePoint since{}, lastSent{}, grantedAt{};
        std::string explanation;
        bool timeoutsQueried = false;
        JausId eacOfPrompts; // the component that forwarded the prompts (answers go there)
        // Who held the vehicle while we asked: the vehicle may report it uncontrolled before its late
        // GRANTED arrives.
        JausId holder;
    };
    // The component offering EnhancedAccessControl (the control target when it does), zero when none.
    static JausId locate(const RemoteSubsystem& remote);
    void setPhase(RemoteSubsystem& remote, HandoffPhase phase, std::string reason, Severity severity);
    void sendRequest(RemoteSubsystem& remote, State& state);
    void queryTimeouts(RemoteSubsystem& remote, State& state);
    // Control through the ordinary AccessControl rules (no EAC, or nobody holds the vehicle).
    bool preempt(RemoteSubsystem& remote, const std::string& why);
    void tickRequest(RemoteSubsystem& remote, State& state, TimePoint now);
    void tickPrompts(RemoteSubsystem& remote, TimePoint now);

    void onConfirm(RemoteSubsystem& remote, const JausId& source, ByteSpan payload);
    void onReleaseRequest(RemoteSubsystem& remote, const JausId& source, ByteSpan payload);

    AccessControlClient& m_access;
    std::map<std::uint16_t, State> m_state;
};

} // namespace ocu::jaus
