#pragma once
// The headless monitor: JSON lines on an output device (stdout) for machine changes
// (rate-limited per machine, default 1 Hz; stop/link/mode/control/health/staleness changes are printed at
// once), link changes and alarm/event entries; JSON-line commands on an input device (stdin) answered with
// one result line each. Role and authority are enforced by the bridges, exactly as for the GUI, and every
// command is audited by the CommandGate.
//
// Output lines:
//   {"type":"machine","id":"jaus:101","protocol":"jaus","name":..,"machine_type":..,"lat":..,"lon":..,"e":..,
//    "n":..,"u":..,"heading":..,"speed":..,"state":..,"mode":..,"stop":"none|stopped|unknown","stop_text":..,
//    "controller":..,"control":..,"health":..,"link":..,"stale":false,"age_ms":..,"status":..}
//   {"type":"machine_removed","id":..}
//   {"type":"link","protocol":..,"link":..,"state":..,"age_ms":..,"detail":..}
//   {"type":"event","time":..,"severity":..,"kind":..,"machine":..,"source":..,"text":..}
//   {"type":"result","cmd":..,"req":<echoed>,"ok":true|false,"targets":[{"id":"jaus:126","sent":true},
//    {"id":"iso23725 link ahs","sent":false,"reason":"link ahs is down"}],"message":..}
//   Commands that reach the command gate carry "targets" (what went on the wire, per machine or link) and are
//   answered when final: once every stack reported, or after the gate's deadline ("stack did not answer").
//   "ok" only when there was a target and every target was sent.
// Commands ("cmd" or "command" key; optional "req" is echoed):
//   {"cmd":"stop_all"}  {"cmd":"stop","id":..}  {"cmd":"clear_stop","id":..,"confirm":true}
//   {"cmd":"request_control","id":..}  {"cmd":"release_control","id":..}
//   {"cmd":"drive","id":..,"mode":"velocity|effort","linear":..,"angular":..,"duration":..}  {"cmd":"list"}
//   {"cmd":"drive_start","id":..}  {"cmd":"drive_stop","id":..,"reason":..} (JAUS drive session)
//   {"cmd":"assign","id":"iso23725:<guid>","tasks":[{"task":"Load","destination":4201,"route":[2001]},..]}
//   (or one task's keys at the top level; the result echoes "tasks" with their "assignment_id")
//   {"cmd":"reset_assignment","id":"iso23725:<guid>"}  {"cmd":"production"} (result "trucks": dispatch views)
//   {"cmd":"shift_report","pdf":"shift.pdf","csv":"shift.csv","plan_tonnes":30000} (either file may be left
//   out; result "written":{"pdf":true,"csv":true}, "loads", "tonnes", "cycles"; ok only when all were
//   written)
//   {"cmd":"auto_dispatch","on":true|false} (without "on": the state): the automatic dispatcher
//   (models/AutoDispatcher.h); result "on", "dispatchers":[{"bridge","on","sent","last"}]
//   {"cmd":"coverage_report","pdf":"c.pdf","csv":"c.csv","geotiff":"c.tif","area":"Lot 1","lift":-1}
//   (models/coverage/CompactionSession; result "written":{"pdf","csv","geotiff"}, "errors")
//   {"cmd":"counters"}: one result line with every stack's counters per link:
//     {"type":"result","cmd":"counters","ok":true,"message":"3 links","links":[{"protocol":"osyris",
//      "link":"osyris:239.255.0.1:5000","rejected_total":4,"rejected":{"rejected.too_short":3,
//      "implausible.speed":1},"counters":{"rx.datagrams":120,...}}, ...]}
#include "models/CommandGate.h"

#include <QByteArray>
#include <QElapsedTimer>
#include <QHash>
#include <QJsonObject>
#include <QList>
#include <QObject>
#include <QPointer>
#include <QSet>
#include <QStringList>
#include <QTimer>
#include <atomic>
#include <functional>
#include <memory>
#include <thread>

class QIODevice;
class QEvent;
class QFile;

namespace ocu {

class AlarmModel;
class FleetBridge;
class FleetContext;
class FleetModel;
struct LinkStatus;
struct FleetEvent;
struct MachineState;

class HeadlessMonitor : public QObject {
    Q_OBJECT
public:
    HeadlessMonitor(FleetModel* fleet, AlarmModel* alarms, CommandGate* stop, QObject* parent = nullptr);
    // A monitor over the context's models, connected to its bridges now and to those added later;
    // `out` = nullptr means stdout. Owned by the context.
    static HeadlessMonitor* attach(FleetContext* ctx, QIODevice* out = nullptr);
    ~HeadlessMonitor() override;

    // Output device (not owned); default stdout.
    void setOutput(QIODevice* out);
    // Per-machine minimum interval between routine lines (ms); 0 = every change. Default 1000.
    void setRateLimitMs(int ms);
    int rateLimitMs() const { return m_rateMs; }
    void addBridge(FleetBridge* bridge);
    // Commands answered by another part of the console (e.g. "coverage_report" by the compaction
    // session): f(cmd) returns the result's fields ("ok", "message", ...). GUI thread; remove when gone.
    using LocalCommand = std::function<QJsonObject(const QJsonObject&)>;
    static void setLocalCommand(const QString& name, LocalCommand f); // an empty f removes it
    // Commands a protocol module adds (e.g. JAUS request_control): routed to the bridge of the machine named
    // by "id" (or of the "protocol"), and answered with "missing \"id\"" when both are absent.
    void addProtocolCommands(const QStringList& names);

    // A read-only query a module answers itself (not through the command gate, not audited), e.g.
    // {"cmd":"video_status"}: the handler returns the result's fields ("ok", "message", ...); the monitor
    // adds "type", "cmd" and "req".
    using QueryHandler = std::function<QJsonObject(const QJsonObject& cmd)>;
    void addQuery(const QString& name, QueryHandler handler);

    // Read commands from stdin; inputFinished() at end of input. A reader thread (raised priority where the
    // console enabled it, ThreadPriority.h) hands what it reads to this object as high-priority events, so a
    // command (a stop_all above all) is handled ahead of the telemetry queued for the GUI thread, and the
    // thread is woken at once by the kernel instead of at the event loop's next poll.
    bool startStdin();
    // Ends the reader thread (within 100 ms); before the bridges go, as it may stop through them. Also done
    // by the destructor.
    void stopStdin();
    // Read commands from any device (not owned): readyRead + readChannelFinished.
    void setInput(QIODevice* in);

    // Executes one JSON command line. The result line is written (and commandHandled emitted) when final; it
    // is also returned when it was final at once (otherwise an empty array).
    QByteArray handleLine(const QByteArray& line);
    // Gate commands whose result line is not written yet.
    int pendingResults() const { return m_pendingResults; }

    // Prints one line for every machine now.
    void printAll();

protected:
    bool event(QEvent* e) override;

signals:
    // End of input, once every result line of it was written.
    void inputFinished();
    void commandHandled(const QByteArray& resultLine);

private:
    void onMachinesChanged(const QStringList& ids);
    void onLink(const LinkStatus& s);
    void onEvent(const FleetEvent& e);
    void flushPending();
    void printMachine(const QString& id);
    void writeLine(const QJsonObject& o);
    void consumeInput(const QByteArray& chunk);
    QJsonObject machineJson(const MachineState& m, bool stale, qint64 ageMs) const;
    QByteArray result(const QJsonObject& cmd, bool ok, const QString& message);
    // Assign, reset_assignment, production (ISO 23725 dispatch).
    QByteArray dispatchCommand(const QString& name, const QJsonObject& cmd);
    // An operator command through the gate, parsed here once (parseOperatorCommand).
    QByteArray operatorCommand(const QString& name, const QJsonObject& cmd);
    QByteArray result(const QJsonObject& cmd, const CommandResult& r, bool withTargets);
    QByteArray handleLine(const QByteArray& line, std::shared_ptr<EarlyStop> early);
    static bool isStopAll(const QByteArray& line);
    QByteArray viaGate(const QJsonObject& cmd, const std::function<void(CommandGate::ResultHandler)>& issue,
                       const QString& suffix = {});
    void maybeFinishInput();
    QByteArray countersResult(const QJsonObject& cmd);

    QPointer<FleetModel> m_fleet;
    QPointer<AlarmModel> m_alarms;
    QPointer<CommandGate> m_gate;
    QPointer<QIODevice> m_out;
    std::unique_ptr<QFile> m_stdout;
    int m_rateMs = 1000;
    QTimer m_flushTimer;
    QElapsedTimer m_clock;
    struct Printed {
        qint64 atMs = -1;  // m_clock time of the last line
        QString signature; // the fields whose change is printed at once
    };
    QHash<QString, Printed> m_printed;
    QSet<QString> m_pending;
    QHash<QString, QString> m_linkSig;
    QSet<QString> m_protocolCommands;
    QList<QPointer<FleetBridge>> m_bridges; // for {"cmd":"counters"}
    QByteArray m_inBuf;
    std::thread m_stdinThread;
    std::atomic<bool> m_stdinStop{false};
    int m_pendingResults = 0;
    bool m_inputEnded = false;
    bool m_finishedSignalled = false;
    QHash<QString, QueryHandler> m_queries;
};

} // namespace ocu
