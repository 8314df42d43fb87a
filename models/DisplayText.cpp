#include "models/DisplayText.h"

namespace ocu {

QString DisplayText::severity(EventSeverity s) {
    switch (s) {
    case EventSeverity::Info:
        return tr("Info");
    case EventSeverity::Warning:
        return tr("Warning");
    case EventSeverity::Alarm:
        return tr("Alarm");
    case EventSeverity::Critical:
        return tr("Critical");
    }
    return tr("Info");
}

QString DisplayText::kind(EventKind k) {
    switch (k) {
    case EventKind::LinkLoss:
        return tr("link loss");
    case EventKind::Timeout:
        return tr("timeout");
    case EventKind::HealthFault:
        return tr("health fault");
    case EventKind::Diagnostic:
        return tr("diagnostic");
    case EventKind::Discrepancy:
        return tr("discrepancy");
    case EventKind::ControlLost:
        return tr("control lost");
    case EventKind::TextMessage:
        return tr("text message");
    case EventKind::Audit:
        return tr("operator action");
    case EventKind::Info:
        break;
    }
    return tr("info");
}

QString DisplayText::priority(AlarmPriority p) {
    switch (p) {
    case AlarmPriority::Low:
        return tr("low");
    case AlarmPriority::Medium:
        return tr("medium");
    case AlarmPriority::High:
        return tr("high");
    case AlarmPriority::Urgent:
        return tr("urgent");
    case AlarmPriority::Auto:
        break;
    }
    return tr("auto");
}

QString DisplayText::link(LinkState s) {
    switch (s) {
    case LinkState::Up:
        return tr("up");
    case LinkState::Degraded:
        return tr("degraded");
    case LinkState::Down:
        return tr("down");
    case LinkState::Unknown:
        break;
    }
    return tr("unknown");
}

QString DisplayText::stop(StopState s) {
    switch (s) {
    case StopState::None:
        return tr("running");
    case StopState::Stopped:
        return tr("stopped");
    case StopState::Unknown:
        break;
    }
    return tr("unknown");
}

QString DisplayText::health(HealthLevel h) {
    switch (h) {
    case HealthLevel::Ok:
        return tr("ok");
    case HealthLevel::Warning:
        return tr("warning");
    case HealthLevel::Fault:
        return tr("fault");
    case HealthLevel::Unknown:
        break;
    }
    return tr("unknown");
}

QString DisplayText::mode(ModeCategory m) {
    switch (m) {
    case ModeCategory::Manual:
        return tr("manual");
    case ModeCategory::Autonomous:
        return tr("autonomous");
    case ModeCategory::Remote:
        return tr("remote");
    case ModeCategory::Idle:
        return tr("idle");
    case ModeCategory::Transition:
        return tr("transition");
    case ModeCategory::Stopped:
        return tr("stopped");
    case ModeCategory::Fault:
        return tr("fault");
    case ModeCategory::Shutdown:
        return tr("shutdown");
    case ModeCategory::Unknown:
        break;
    }
    return tr("unknown");
}

QString DisplayText::control(ControlState c) {
    switch (c) {
    case ControlState::Monitoring:
        return tr("monitoring");
    case ControlState::ControlledByMe:
        return tr("this console");
    case ControlState::ControlledByOther:
        return tr("another console");
    case ControlState::Denied:
        return tr("denied");
    case ControlState::None:
        break;
    }
    return tr("none");
}

QString DisplayText::status(StatusCategory c) {
    switch (c) {
    case StatusCategory::Ok:
        return tr("ok");
    case StatusCategory::Warning:
        return tr("warning");
    case StatusCategory::FaultOrStopped:
        return tr("fault or stopped");
    case StatusCategory::Stale:
        return tr("stale");
    case StatusCategory::Autonomous:
        return tr("autonomous");
    }
    return tr("ok");
}

} // namespace ocu
