#pragma once
// The automatic dispatcher: while the operator has it on, every idle haul truck
// the FMS dispatches gets its next task without the dispatcher's hand:
//  * idle = DispatchingCustodian FMS (as the truck reported it), link up (DispatchSource::assignRefusal
//  empty),
//    and no Pending/Active assignment, or the truck asks for work (the "needs assignment" cue);
//  * an empty truck goes to the load area (shovel) with the shortest queue, a loaded one
//  (DispatchTruck::loaded)
//    to the dump/crusher with the shortest queue; queue = trucks at the area + trucks assigned to it and
//    still on the way (as DispatchQueueModel counts them) + requests sent from here and not answered yet;
//    ties go to the shorter route, then to the area's name; an area the truck cannot reach (the source's
//    route says why) is skipped;
//  * every assignment goes through the CommandGate ("assign", origin "auto-dispatch": audited, with the
//    per-target result); a truck with a request out is left alone until it reports that assignment, answers
//    Rejected (then that area is not tried again for it for kRetryMs) or the answer is late
//    (kAnswerTimeoutMs);
//  * it never assigns while the link is down or the custodian is AHS, and sends nothing once switched off
//    (answers to what was already sent are still reported).
// What it does is said in lines (acted) and, with an AlarmModel, as events in the event log.
#include "models/DispatchSource.h"
#include "models/FleetBridge.h"
#include "models/FleetEvent.h"
#include "models/ModelClock.h"

#include <QHash>
#include <QPointer>
#include <QTimer>

#include <functional>

namespace ocu {

class AlarmModel;
class CommandGate;
struct CommandResult;

class AutoDispatcher : public QObject {
    Q_OBJECT
public:
    static constexpr int kAnswerTimeoutMs = 15000;
    static constexpr int kRetryMs = 30000;
    static constexpr int kMaxPerStep = 50; // assignments sent per step (a fleet switched on at once is paced)

    AutoDispatcher(DispatchSource* source, CommandGate* gate, QObject* parent = nullptr);

    void setAlarms(AlarmModel* alarms);
    // The clock of answer deadlines and retry back-offs (null: the system clock).
    void setClock(std::shared_ptr<const ModelClock> clock) { m_clock = clockOrSystem(std::move(clock)); }
    DispatchSource* source() const { return m_source; }

    bool isOn() const { return m_on; }
    // Switches on or off (origin "gui", "headless"...); an event says who did it.
    void setOn(bool on, const QString& origin = QStringLiteral("gui"));
    QString lastAction() const { return m_last; }
    int assignmentsSent() const { return m_sent; }

    struct Decision {
        QString truckId;
        QString truckName;
        QString task; // Load or Offload
        DispatchArea area;
        int queue = 0; // the area's queue before this truck
        double routeM = -1;
    };
    // What would be assigned now, without sending (the trucks in name order; at most kMaxPerStep).
    QVector<Decision> plan() const;

public slots:
    void step(); // decide and send now (does nothing while off)

signals:
    void stateChanged(bool on);
    void acted(const QString& line); // one line per decision, result or answer

private:
    struct InFlight {
        QString assignmentId;
        qint64 areaWay = 0;
        QString areaLink;
        qint64 sentMs = 0;
        bool answered = false; // the gate's result came (sent or not)
    };
    void schedule();
    void followAnswers(const QVector<DispatchTruck>& trucks);
    void onResult(const QString& truckId, const QString& what, const CommandResult& r);
    void say(const QString& line, EventSeverity severity = EventSeverity::Info, const QString& machine = {});
    QString key(const QString& truckId, const DispatchArea& a) const;

    QPointer<DispatchSource> m_source;
    QPointer<CommandGate> m_gate;
    QPointer<AlarmModel> m_alarms;
    std::shared_ptr<const ModelClock> m_clock = systemModelClock();
    bool m_on = false;
    QTimer m_soon;                       // coalesces the trucks' reports into one step
    QTimer m_every;                      // retries (back-off ends, late answers) while on
    QHash<QString, InFlight> m_inFlight; // truck id -> the request sent from here
    QHash<QString, qint64> m_avoidUntil; // "truck id|area" (rejected there) or truck id (not sent) -> until
    QString m_last;
    int m_sent = 0;
};

} // namespace ocu
