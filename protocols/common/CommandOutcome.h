#pragma once
// What one command did for one target, as far as the wire is concerned: sent = the message
// was handed to the socket by this process; not sent = refused, with a reason an operator can act on (its
// kind in `cause`, its words in `reason`). A stack reports the outcomes of one command exactly once, on its
// io thread, through an OutcomeCallback. Confirmation (the machine reporting the new state) is a separate,
// later matter. See docs/decisions/command-outcome-per-target.md.
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace ocu {

// Why a target was not sent, as a kind a program can act on (the text says it for people).
enum class OutcomeReason {
    None,            // sent
    NotPermitted,    // this console's role forbids it, or a release came without its deliberate confirmation
    UnknownTarget,   // no such machine, link or station
    LinkDown,        // the target's link is down, or the target was never heard
    NotRunning,      // the stack is not running (it would never send it)
    NotSupported,    // the protocol has no such command
    InvalidArgument, // an argument is malformed or out of range
    NotControlled,   // the command needs control of the vehicle, which this console does not hold
    SendFailed,      // the socket did not take the message
    NoAnswer,        // the stack did not answer within the gate's deadline
    Refused,         // the protocol's own rules refused it (the text says which)
};

// "none", "not_permitted", "unknown_target", ... (headless results and audit lines).
const char* nameFor(OutcomeReason reason);

struct TargetOutcome {
    TargetOutcome() = default;
    // A refusal without a kind of its own is a protocol refusal (Refused).
    TargetOutcome(std::string target_, bool sent_, std::string reason_ = {}, std::string note_ = {})
        : target(std::move(target_)), sent(sent_),
          cause(sent_ ? OutcomeReason::None : OutcomeReason::Refused), reason(std::move(reason_)),
          note(std::move(note_)) {}
    static TargetOutcome sentTo(std::string target, std::string note = {}) {
        return TargetOutcome(std::move(target), true, {}, std::move(note));
    }
    static TargetOutcome refused(std::string target, OutcomeReason cause, std::string reason) {
        TargetOutcome o(std::move(target), false, std::move(reason));
        o.cause = cause;
        return o;
    }
    // The target as the console names it: a machine ("jaus:126", "iso23725:<guid>", "osyris:<station>") or a
    // link ("iso23725 link ahs", "osyris group 239.255.0.1:5000").
    std::string target;
    bool sent = false;
    OutcomeReason cause = OutcomeReason::None; // None when sent
    std::string reason;                        // why it was not sent, for people; empty when sent
    // What else the operator should know about a sent target, e.g. "link down since 12 s: sent to its last
    // address 10.0.0.5:3794; no answer expected until it is back, confirmation pending". Empty: nothing.
    std::string note;
};

using OutcomeCallback = std::function<void(std::vector<TargetOutcome>)>;

inline bool allSent(const std::vector<TargetOutcome>& outcomes) {
    if (outcomes.empty())
        return false;
    for (const auto& o : outcomes)
        if (!o.sent)
            return false;
    return true;
}

} // namespace ocu
