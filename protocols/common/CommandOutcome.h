#pragma once
// What one command did for one target, as far as the wire is concerned: sent = the message
// was handed to the socket by this process; not sent = refused, with a reason an operator can act on.
// A stack reports the outcomes of one command exactly once, on its io thread, through an OutcomeCallback.
// Confirmation (the machine reporting the new state) is a separate, later matter.
// See docs/decisions/command-outcome-per-target.md.
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace ocu {

struct TargetOutcome {
    TargetOutcome() = default;
    TargetOutcome(std::string target_, bool sent_, std::string reason_ = {}, std::string note_ = {})
        : target(std::move(target_)), sent(sent_), reason(std::move(reason_)), note(std::move(note_)) {}
    // The target as the console names it: a machine ("jaus:126", "iso23725:<guid>", "osyris:<station>") or a
    // link ("iso23725 link ahs", "osyris group 239.255.0.1:5000").
    std::string target;
    bool sent = false;
    std::string reason; // why it was not sent; empty when sent
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
