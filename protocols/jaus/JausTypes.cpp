#include "protocols/jaus/JausTypes.h"

namespace ocu::jaus {

const char* toString(LinkState s) {
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
const char* toString(AccessState s) {
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
const char* toString(EventKind k) {
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
    }
    return "?";
}

} // namespace ocu::jaus
