#include "protocols/common/CommandOutcome.h"

namespace ocu {

const char* nameFor(OutcomeReason reason) {
    switch (reason) {
    case OutcomeReason::None:
        return "none";
    case OutcomeReason::NotPermitted:
        return "not_permitted";
    case OutcomeReason::UnknownTarget:
        return "unknown_target";
    case OutcomeReason::LinkDown:
        return "link_down";
    case OutcomeReason::NotRunning:
        return "not_running";
    case OutcomeReason::NotSupported:
        return "not_supported";
    case OutcomeReason::InvalidArgument:
        return "invalid_argument";
    case OutcomeReason::NotControlled:
        return "not_controlled";
    case OutcomeReason::SendFailed:
        return "send_failed";
    case OutcomeReason::NoAnswer:
        return "no_answer";
    case OutcomeReason::Refused:
        return "refused";
    }
    return "refused";
}

} // namespace ocu
