#pragma once
// The headless monitor: JSON lines on an output device (stdout) for machine changes
// (rate-limited per machine, default 1 Hz; stop/link/mode/control/health/staleness changes are printed at
// once), link changes and alarm/event entries; JSON-line commands on an input device (stdin) answered with
// one result line each. The command socket (app/HeadlessSocket.h) adds clients as further outputs and inputs. Role and authority are enforced by the bridges, exactly as for the GUI, and every
// command is audited by the CommandGate.
//
// Output lines:
//   {"type":"machine","id":"<protocol>:<id>","protocol":..,"name":..,"machine_type":..,"lat":..,"lon":..,"e":..,
//    "n":..,"u":..,"heading":..,"speed":..,"state":..,"mode":..,"stop":"none|stopped|unknown","stop_text":..,
//    "controller":..,"control":..,"health":..,"link":..,"stale":false,"age_ms":..,"status":..}
//   {"type":"machine_removed","id":..}
//   {"type":"link","protocol":..,"link":..,"state":..,"age_ms":..,"detail":..}
//   {"type":"event","time":..,"severity":..,"kind":..,"machine":..,"source":..,"text":..}
//   {"type":"result","cmd":..,"req":<echoed>,"id":<echoed>,"ok":true|false,"targets":[{"id":<machine>,
//    "sent":true},{"id":<link>,"sent":false,"reason":"link ... is down","cause":..}],"message":..}
//   Commands that reach the command gate carry "targets" (what went on the wire, per machine or link) and are
//   answered when final: once every stack reported, or after the gate's deadline ("stack did not answer").
//   "ok" only when there was a target and every target was sent.
// Commands ("cmd" or "command" key; optional "req" is echoed), in the table of app/HeadlessCommands.h:
//   {"cmd":"stop_all"}  {"cmd":"stop","id":..}  {"cmd":"clear_stop","id":..,"confirm":true}  {"cmd":"list"}
//   {"cmd":"counters"}: one result line with every stack's counters per link:
//     {"type":"result","cmd":"counters","ok":true,"message":"3 links","links":[{"protocol":..,
//      "link":..,"rejected_total":4,"rejected":{"rejected.too_short":3,
//      "implausible.speed":1},"counters":{"rx.datagrams":120,...}}, ...]}
//   and those the protocol modules register (ProtocolModule::registerHeadless; see app/modules/).
#include "app/HeadlessCommands.h"

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
    // Further devices (not owned) that get every line from now on: the command socket's clients.
    void addOutput(QIODevice* out);
    void removeOutput(QIODevice* out);
    // Per-machine minimum interval between routine lines (ms); 0 = every change. Default 1000.
    void setRateLimitMs(int ms);
    int rateLimitMs() const { return m_rateMs; }
    void addBridge(FleetBridge* bridge);
    // The command table (app/HeadlessCommands.h): modules add their commands and queries to it.
    HeadlessCommands& commands() { return m_commands; }

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
    int pendingResults() const { return m_commands.pendingResults(); }

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
    void writeRaw(const QByteArray& line); // one line with its newline
    void writeResultLine(const QByteArray& line);
    void consumeInput(const QByteArray& chunk);
    QJsonObject machineJson(const MachineState& m, bool stale, qint64 ageMs) const;
    QByteArray handleLine(const QByteArray& line, std::shared_ptr<EarlyStop> early);
    static bool isStopAll(const QByteArray& line);
    void maybeFinishInput();

    QPointer<FleetModel> m_fleet;
    QPointer<AlarmModel> m_alarms;
    QPointer<CommandGate> m_gate;
    QPointer<QIODevice> m_out;
    std::unique_ptr<QFile> m_stdout;
    QList<QPointer<QIODevice>> m_extraOutputs;
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
    QList<QPointer<FleetBridge>> m_bridges; // for {"cmd":"counters"}
    QByteArray m_inBuf;
    std::thread m_stdinThread;
    std::atomic<bool> m_stdinStop{false};
    bool m_inputEnded = false;
    bool m_finishedSignalled = false;
    HeadlessCommands m_commands;
};

} // namespace ocu
