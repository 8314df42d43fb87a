#pragma once
// What one command did for one target, as far as the wire is concerned (issue 13 §1): sent = the message
// was handed to the socket by this process; not sent = refused, with a reason an operator can act on.
// A stack reports the outcomes of one command exactly once, on its io thread, through an OutcomeCallback.
// Confirmation (the machine reporting the new state) is a separate, later matter.
#include <functional>
#include <string>
#include <vector>

namespace ocu {

struct TargetOutcome {
    // The target as the console names it: a machine ("jaus:126", "iso23725:<guid>", "osyris:<station>") or a
    // link ("iso23725 link ahs", "osyris group 239.255.0.1:5000").
    std::string target;
    bool sent = false;
    std::string reason; // why it was not sent; empty when sent
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
