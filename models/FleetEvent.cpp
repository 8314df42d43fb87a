#include "models/FleetEvent.h"

#include <QDateTime>

namespace ocu {

QString toText(EventSeverity s) {
    switch (s) {
    case EventSeverity::Info:
        return QStringLiteral("info");
    case EventSeverity::Warning:
        return QStringLiteral("warning");
    case EventSeverity::Alarm:
        return QStringLiteral("alarm");
    case EventSeverity::Critical:
        return QStringLiteral("critical");
    }
    return QStringLiteral("info");
}

QString toText(EventKind k) {
    switch (k) {
    case EventKind::LinkLoss:
        return QStringLiteral("link_loss");
    case EventKind::Timeout:
        return QStringLiteral("timeout");
    case EventKind::HealthFault:
        return QStringLiteral("health_fault");
    case EventKind::Diagnostic:
        return QStringLiteral("diagnostic");
    case EventKind::Discrepancy:
        return QStringLiteral("discrepancy");
    case EventKind::ControlLost:
        return QStringLiteral("control_lost");
    case EventKind::TextMessage:
        return QStringLiteral("text_message");
    case EventKind::Audit:
        return QStringLiteral("audit");
    case EventKind::Info:
        break;
    }
    return QStringLiteral("info");
}

FleetEvent makeEvent(EventSeverity severity, EventKind kind, const QString& machineId, const QString& text,
                     const QString& source) {
    FleetEvent ev;
    ev.timeMs = QDateTime::currentMSecsSinceEpoch();
    ev.severity = severity;
    ev.kind = kind;
    ev.machineId = machineId;
    ev.text = text;
    ev.source = source;
    ev.requiresAck = severity >= EventSeverity::Warning;
    return ev;
}

} // namespace ocu
