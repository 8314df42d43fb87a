#pragma once
// An event or alarm raised by a bridge, the fleet model or the stop controller.
#include <QMetaType>
#include <QString>

namespace ocu {

enum class EventSeverity { Info, Warning, Alarm, Critical };
enum class EventKind {
    LinkLoss,
    Timeout,
    HealthFault,
    Diagnostic,
    Discrepancy, // fleet-definition discrepancies (ISO 23725)
    ControlLost, // JAUS access control lost / refused
    TextMessage, // OSYRIS text messages
    Audit,       // an operator or script action (stop, clear stop, control, drive)
    Info,
};

struct FleetEvent {
    qint64 timeMs = 0; // ms since the Unix epoch; 0 = stamp on arrival
    EventSeverity severity = EventSeverity::Info;
    EventKind kind = EventKind::Info;
    QString machineId; // empty for link- or site-wide events
    QString source;    // protocol, "gui", "headless", ...
    QString text;
    // Alarms (Warning and above by default) stay unacknowledged until an operator acknowledges them.
    bool requiresAck = false;
};

QString toText(EventSeverity s); // "info", "warning", "alarm", "critical"
QString toText(EventKind k);     // "link_loss", "timeout", ...
// A FleetEvent with requiresAck defaulting to severity >= Warning and time stamped now.
FleetEvent makeEvent(EventSeverity severity, EventKind kind, const QString& machineId, const QString& text,
                     const QString& source = {});

} // namespace ocu

Q_DECLARE_METATYPE(ocu::FleetEvent)
