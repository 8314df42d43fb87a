#pragma once
// Hand-off of control between consoles as the JAUS stack knows it (Enhanced Access Control and the
// HandoffController, AEP-4818 §6.3; public 1.1 layouts, MessagesHandoff.h): this console's own request for a
// vehicle another console holds, and the requests the vehicle forwarded to this console while it holds the
// vehicle. Every phase comes from the vehicle's answers (ConfirmHandoffRequest, RequestReleaseControl,
// ReportControl), never from what was asked. The console's models mirror it in JausHandoff.
#include <cstdint>
#include <string>
#include <vector>

#include "protocols/common/Clock.h"
#include "protocols/jaus/JudpCodec.h"

namespace ocu::jaus {

enum class HandoffPhase {
    None,       // no request of ours
    Requesting, // RequestHandoff sent, no answer yet
    Queued,     // the vehicle queued it and asked the holder; re-asserted within the request timeout
    Granted,    // the holder granted it: RequestControl sent, not yet confirmed
    Completed,  // control is ours through the hand-off
    Denied,     // the holder (or the vehicle) said no
    TimedOut,   // the holder did not answer within the decision timeout (the vehicle's TIMEOUT)
    Refused,    // NOT_AVAILABLE or INSUFFICIENT_AUTHORITY from the vehicle (reason says which)
    Cancelled,  // withdrawn by this console (RemoveHandoffRequest)
    Preempting, // the vehicle offers no Enhanced Access Control: RequestControl with our authority instead
    Waiting,    // the holder answered WAIT (DEFERRED, or FKIE's 7): still queued, re-asserted, decision time
                // anew
};
const char* nameFor(HandoffPhase p);

// A request the vehicle forwarded to us (RequestReleaseControl) while we hold it, waiting for our answer.
struct HandoffPrompt {
    std::uint8_t id = 0;        // the vehicle's queue entry
    JausId requester;           // the asking console's JAUS ID
    std::uint8_t authority = 0; // its authority
    std::string explanation;    // its words (our consoles send "<call sign>: <reason>")
    TimePoint received{};       // when the vehicle first forwarded it (the stack's clock)
    std::int64_t receivedUnixMs = 0;
    double decisionTimeoutS =
        60;              // the vehicle's Handoff Decision Timeout (ReportHandoffTimeout), 60 s default
    bool waited = false; // we answered WAIT (its decision time started again then)
    bool operator==(const HandoffPrompt&) const = default;
};

struct HandoffStatus {
    bool offered = false; // a component of the vehicle offers EnhancedAccessControl
    JausId component;     // that component, zero when none
    HandoffPhase phase = HandoffPhase::None;
    std::string reason;         // the last outcome in words (who granted, denied, why refused)
    std::uint8_t queueId = 0;   // our entry in the vehicle's queue (valid while Queued)
    double requestTimeoutS = 5; // the vehicle's Handoff Request Timeout (ReportEnhancedTimeout), 5 s default
    double decisionTimeoutS = 60;
    std::vector<HandoffPrompt> prompts; // forwarded requests we have not answered
    bool operator==(const HandoffStatus&) const = default;
};

} // namespace ocu::jaus
