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

QString toText(AlarmPriority p) {
    switch (p) {
    case AlarmPriority::Low:
        return QStringLiteral("low");
    case AlarmPriority::Medium:
        return QStringLiteral("medium");
    case AlarmPriority::High:
        return QStringLiteral("high");
    case AlarmPriority::Urgent:
        return QStringLiteral("urgent");
    case AlarmPriority::Auto:
        break;
    }
    return QStringLiteral("auto");
}

AlarmPriority effectivePriority(const FleetEvent& e) {
    if (e.priority != AlarmPriority::Auto)
        return e.priority;
    switch (e.severity) {
    case EventSeverity::Info:
    case EventSeverity::Warning:
        return AlarmPriority::Low;
    case EventSeverity::Alarm:
        return AlarmPriority::High;
    case EventSeverity::Critical:
        return AlarmPriority::Urgent;
    }
    return AlarmPriority::Low;
}

QString alarmKey(const FleetEvent& e) {
    QString cause = e.cause;
    if (cause.isEmpty()) {
        cause = toText(e.kind);
        if (e.kind == EventKind::Info || e.kind == EventKind::Diagnostic ||
            e.kind == EventKind::TextMessage || e.kind == EventKind::Audit)
            cause += QLatin1Char(':') + e.text;
    }
    return cause + QLatin1Char('|') + (e.group.isEmpty() ? e.machineId : e.group) + QLatin1Char('|') +
           e.source;
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
