#include "models/MachineState.h"

namespace ocu {

QString toText(Protocol p) {
    switch (p) {
    case Protocol::Jaus:
        return QStringLiteral("jaus");
    case Protocol::Iso23725:
        return QStringLiteral("iso23725");
    case Protocol::Osyris:
        return QStringLiteral("osyris");
    case Protocol::Other:
        break;
    }
    return QStringLiteral("other");
}

Protocol protocolFromString(const QString& s) {
    const QString l = s.toLower();
    if (l == QLatin1String("jaus"))
        return Protocol::Jaus;
    if (l == QLatin1String("iso23725") || l == QLatin1String("iso"))
        return Protocol::Iso23725;
    if (l == QLatin1String("osyris"))
        return Protocol::Osyris;
    return Protocol::Other;
}

QString protocolPrefix(Protocol p) {
    return toText(p) + QLatin1Char(':');
}

Protocol protocolOfId(const QString& id) {
    const int colon = id.indexOf(QLatin1Char(':'));
    return colon > 0 ? protocolFromString(id.left(colon)) : Protocol::Other;
}

QString toText(LinkState s) {
    switch (s) {
    case LinkState::Up:
        return QStringLiteral("up");
    case LinkState::Degraded:
        return QStringLiteral("degraded");
    case LinkState::Down:
        return QStringLiteral("down");
    case LinkState::Unknown:
        break;
    }
    return QStringLiteral("unknown");
}

QString toText(StopState s) {
    switch (s) {
    case StopState::None:
        return QStringLiteral("none");
    case StopState::Stopped:
        return QStringLiteral("stopped");
    case StopState::Unknown:
        break;
    }
    return QStringLiteral("unknown");
}

QString toText(HealthLevel h) {
    switch (h) {
    case HealthLevel::Ok:
        return QStringLiteral("ok");
    case HealthLevel::Warning:
        return QStringLiteral("warning");
    case HealthLevel::Fault:
        return QStringLiteral("fault");
    case HealthLevel::Unknown:
        break;
    }
    return QStringLiteral("unknown");
}

QString toText(ModeCategory m) {
    switch (m) {
    case ModeCategory::Manual:
        return QStringLiteral("manual");
    case ModeCategory::Autonomous:
        return QStringLiteral("autonomous");
    case ModeCategory::Remote:
        return QStringLiteral("remote");
    case ModeCategory::Idle:
        return QStringLiteral("idle");
    case ModeCategory::Transition:
        return QStringLiteral("transition");
    case ModeCategory::Stopped:
        return QStringLiteral("stopped");
    case ModeCategory::Fault:
        return QStringLiteral("fault");
    case ModeCategory::Shutdown:
        return QStringLiteral("shutdown");
    case ModeCategory::Unknown:
        break;
    }
    return QStringLiteral("unknown");
}

QString toText(ControlState c) {
    switch (c) {
    case ControlState::Monitoring:
        return QStringLiteral("monitoring");
    case ControlState::ControlledByMe:
        return QStringLiteral("me");
    case ControlState::ControlledByOther:
        return QStringLiteral("other");
    case ControlState::Denied:
        return QStringLiteral("denied");
    case ControlState::None:
        break;
    }
    return QStringLiteral("none");
}

QString toText(StatusCategory c) {
    switch (c) {
    case StatusCategory::Ok:
        return QStringLiteral("ok");
    case StatusCategory::Warning:
        return QStringLiteral("warning");
    case StatusCategory::FaultOrStopped:
        return QStringLiteral("fault");
    case StatusCategory::Stale:
        return QStringLiteral("stale");
    case StatusCategory::Autonomous:
        return QStringLiteral("autonomous");
    }
    return QStringLiteral("ok");
}

StatusCategory statusOf(const MachineState& m, bool stale) {
    if (stale || m.link == LinkState::Down || m.link == LinkState::Unknown)
        return StatusCategory::Stale;
    if (m.health == HealthLevel::Fault || m.stop == StopState::Stopped || m.mode == ModeCategory::Fault ||
        m.mode == ModeCategory::Stopped)
        return StatusCategory::FaultOrStopped;
    if (m.health == HealthLevel::Warning || m.link == LinkState::Degraded ||
        m.mode == ModeCategory::Transition)
        return StatusCategory::Warning;
    if (m.mode == ModeCategory::Autonomous || m.mode == ModeCategory::Remote)
        return StatusCategory::Autonomous;
    return StatusCategory::Ok;
}

QColor statusColor(StatusCategory c) {
    // Saturated enough to read on the map at 1 px outlines; FKIE/rmf-web semantics (§8.1).
    switch (c) {
    case StatusCategory::Ok:
        return QColor(0x2e, 0xb8, 0x2e);
    case StatusCategory::Warning:
        return QColor(0xfe, 0x9a, 0x2e);
    case StatusCategory::FaultOrStopped:
        return QColor(0xe0, 0x20, 0x20);
    case StatusCategory::Stale:
        return QColor(0xa9, 0xa9, 0xa9);
    case StatusCategory::Autonomous:
        return QColor(0x1e, 0x6f, 0xe8);
    }
    return Qt::black;
}

} // namespace ocu
