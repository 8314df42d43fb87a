#pragma once
// An event or alarm raised by a bridge, the fleet model or the stop controller.
#include <QMetaType>
#include <QString>
#include <QStringList>

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

// Alarm priority (ISA-18.2 §10, EEMUA 191 §3.3): how fast the operator must respond. Auto = derived from the
// severity (Warning -> Low, Alarm -> High, Critical -> Urgent).
enum class AlarmPriority { Auto, Low, Medium, High, Urgent };

struct FleetEvent {
    qint64 timeMs = 0; // ms since the Unix epoch; 0 = stamp on arrival
    EventSeverity severity = EventSeverity::Info;
    EventKind kind = EventKind::Info;
    QString machineId; // empty for link- or site-wide events
    QString source;    // protocol, "gui", "headless", ...
    QString text;
    // Alarms (Warning and above by default) stay unacknowledged until an operator acknowledges them.
    bool requiresAck = false;
    // Alarm identity and grouping. cause: stable identifier of what went wrong
    // ("fleet.not_in_fms"); empty = the kind. group: the machine or group the cause applies to (a link, a
    // fleet); empty = machineId. One cause of one group from one source is one alarm: repeats update it.
    QString cause;
    QString group;
    QStringList details; // the grouped items (one line each), e.g. the 1,000 machines
    int itemCount = 1;   // how many items the alarm groups
    AlarmPriority priority = AlarmPriority::Auto;
};

QString toText(EventSeverity s); // "info", "warning", "alarm", "critical"
QString toText(EventKind k);     // "link_loss", "timeout", ...
QString toText(AlarmPriority p); // "low", "medium", "high", "urgent" (Auto resolved by effectivePriority)
AlarmPriority effectivePriority(const FleetEvent& e);
// The alarm's stable key, the same on every console that sees the same cause: cause|group|source, where
// kinds without a cause of their own (info, diagnostic, text message) use their text as the cause.
QString alarmKey(const FleetEvent& e);
// A FleetEvent with requiresAck defaulting to severity >= Warning and time stamped now.
FleetEvent makeEvent(EventSeverity severity, EventKind kind, const QString& machineId, const QString& text,
                     const QString& source = {});

} // namespace ocu

Q_DECLARE_METATYPE(ocu::FleetEvent)
