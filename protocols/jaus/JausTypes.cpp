#include "protocols/jaus/JausTypes.h"

namespace ocu::jaus {

const char* nameFor(LinkState s) {
    switch (s) {
    case LinkState::Up:
        return "up";
    case LinkState::Degraded:
        return "degraded";
    case LinkState::Down:
        return "down";
    }
    return "?";
}
const char* nameFor(AccessState s) {
    switch (s) {
    case AccessState::NotAvailable:
        return "NOT_AVAILABLE";
    case AccessState::NotControlled:
        return "NOT_CONTROLLED";
    case AccessState::Monitoring:
        return "MONITORING";
    case AccessState::ControlAccepted:
        return "CONTROL_ACCEPTED";
    case AccessState::ControlReleased:
        return "CONTROL_RELEASED";
    case AccessState::Timeout:
        return "TIMEOUT";
    case AccessState::InsufficientAuthority:
        return "INSUFFICIENT_AUTHORITY";
    case AccessState::Preempted:
        return "PREEMPTED";
    }
    return "?";
}
const char* nameFor(EventKind k) {
    switch (k) {
    case EventKind::Discovered:
        return "discovered";
    case EventKind::LinkLost:
        return "link-lost";
    case EventKind::LinkRestored:
        return "link-restored";
    case EventKind::ControlAccepted:
        return "control-accepted";
    case EventKind::ControlRejected:
        return "control-rejected";
    case EventKind::ControlReleased:
        return "control-released";
    case EventKind::ControlLost:
        return "control-lost";
    case EventKind::ControlPreempted:
        return "control-preempted";
    case EventKind::Emergency:
        return "emergency";
    case EventKind::EmergencyCleared:
        return "emergency-cleared";
    case EventKind::ManagementChanged:
        return "management-changed";
    case EventKind::HealthFault:
        return "health-fault";
    case EventKind::DecodeError:
        return "decode-error";
    case EventKind::CommandRefused:
        return "command-refused";
    case EventKind::TransportError:
        return "transport-error";
    case EventKind::DriveNotSent:
        return "drive-not-sent";
    case EventKind::MissionChanged:
        return "mission-changed";
    case EventKind::HandoffChanged:
        return "handoff-changed";
    }
    return "?";
}

const char* nameFor(MissionPhase p) {
    switch (p) {
    case MissionPhase::None:
        return "none";
    case MissionPhase::Uploading:
        return "uploading";
    case MissionPhase::Uploaded:
        return "uploaded";
    case MissionPhase::Running:
        return "running";
    case MissionPhase::Paused:
        return "paused";
    case MissionPhase::Completed:
        return "completed";
    case MissionPhase::Aborted:
        return "aborted";
    case MissionPhase::StoppedByEmergency:
        return "stopped by emergency";
    case MissionPhase::Lost:
        return "lost";
    case MissionPhase::Rejected:
        return "rejected";
    }
    return "none";
}

const char* nameFor(HandoffPhase p) {
    switch (p) {
    case HandoffPhase::None:
        return "none";
    case HandoffPhase::Requesting:
        return "requesting";
    case HandoffPhase::Queued:
        return "queued";
    case HandoffPhase::Granted:
        return "granted";
    case HandoffPhase::Completed:
        return "completed";
    case HandoffPhase::Denied:
        return "denied";
    case HandoffPhase::TimedOut:
        return "timed out";
    case HandoffPhase::Refused:
        return "refused";
    case HandoffPhase::Cancelled:
        return "cancelled";
    case HandoffPhase::Preempting:
        return "pre-empting";
    case HandoffPhase::Waiting:
        return "waiting";
    }
    return "none";
}

std::string toText(const GroupSocketProblem& p) {
    std::string t = "no group socket: ";
    if (p.heldByOther)
        t += "UDP port " + std::to_string(p.port) +
             " is held by another process that does not share it (bound without SO_REUSEADDR, e.g. a JAUS "
             "node manager; " +
             p.reason + ")";
    else
        t += p.reason;
    t += ", so nothing sent to " + p.group + " is received; working by unicast from UDP port " +
         std::to_string(p.unicastPort);
    if (p.unicastPortHeld != 0)
        t += " instead of " + std::to_string(p.unicastPortHeld) + " (held too)";
    t += ": static endpoints, and broadcasts such as QueryIdentification still go out to " + p.group +
         " (replies come back to port " + std::to_string(p.unicastPort) + ")";
    return t;
}

} // namespace ocu::jaus
