#pragma once
// Display texts in the operator's language for the stable English keys of events, alarms, links and machine
// states ("event, alarm and link texts translated like the rest"). The stacks and toText() keep
// the English key for logs, recordings, CSV export and headless JSON; only what a person reads goes through
// here. Translation context: "ocu::DisplayText".
#include "models/FleetEvent.h"
#include "models/MachineState.h"

#include <QCoreApplication>
#include <QString>

namespace ocu {

class DisplayText {
    Q_DECLARE_TR_FUNCTIONS(ocu::DisplayText)
public:
    static QString severity(EventSeverity s); // "Info", "Warning", "Alarm", "Critical"
    static QString kind(EventKind k);         // "link loss", "timeout", ...
    static QString priority(AlarmPriority p); // "low" … "urgent" (Auto: resolve with effectivePriority first)
    static QString link(LinkState s);         // "up", "degraded", "down", "unknown"
    static QString stop(StopState s);
    static QString health(HealthLevel h);
    static QString mode(ModeCategory m);
    static QString control(ControlState c);
    static QString status(StatusCategory c);
};

} // namespace ocu
