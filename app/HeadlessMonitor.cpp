#include "app/HeadlessMonitor.h"
#include "app/ShiftReportCommand.h"
#include "models/MachineJson.h"

#include "models/AlarmModel.h"
#include "models/AutoDispatcher.h"
#include "models/CommandGate.h"

#include "models/FleetBridge.h"
#include "models/FleetContext.h"
#include "models/FleetModel.h"
#include <QJsonArray>

#include <QCoreApplication>
#include <QDateTime>
#include <QEvent>
#include <QFile>
#include <QJsonDocument>
#include <QJsonParseError>
#include <QSocketNotifier>
#include <QUuid>

#include "protocols/common/ThreadPriority.h"

#include <cerrno>
#include <poll.h>
#include <unistd.h>

namespace ocu {

HeadlessMonitor::HeadlessMonitor(FleetModel* fleet, AlarmModel* alarms, CommandGate* stop, QObject* parent)
    : QObject(parent), m_fleet(fleet), m_alarms(alarms), m_gate(stop) {
    m_clock.start();
    if (fleet) {
        connect(fleet, &FleetModel::machinesChanged, this, &HeadlessMonitor::onMachinesChanged);
        connect(fleet, &FleetModel::machineStaleChanged, this,
                [this](const QString& id, bool) { onMachinesChanged({id}); });
        connect(fleet, &FleetModel::machineRemoved, this, [this](const QString& id) {
            m_printed.remove(id);
            m_pending.remove(id);
            QJsonObject o;
            o[QStringLiteral("type")] = QStringLiteral("machine_removed");
            o[QStringLiteral("id")] = id;
            writeLine(o);
        });
    }
    if (alarms)
        connect(alarms, &AlarmModel::eventAdded, this, &HeadlessMonitor::onEvent);
    connect(&m_flushTimer, &QTimer::timeout, this, &HeadlessMonitor::flushPending);
    setRateLimitMs(1000);
}

namespace {

// One line the stdin reader thread read (with the STOP ALL it already sent for it), a line that was too long,
// or the end of input, for the monitor's thread.
struct StdinEvent : QEvent {
    enum What { Line, TooLong, End };
    static QEvent::Type kind() {
        static const auto t = QEvent::Type(QEvent::registerEventType());
        return t;
    }
    StdinEvent(What w, QByteArray d = {}, std::shared_ptr<EarlyStop> e = {})
        : QEvent(kind()), what(w), line(std::move(d)), early(std::move(e)) {}
    What what;
    QByteArray line;
    std::shared_ptr<EarlyStop> early;
};

} // namespace

HeadlessMonitor::~HeadlessMonitor() {
    stopStdin();
}

void HeadlessMonitor::stopStdin() {
    m_stdinStop = true;
    if (m_stdinThread.joinable())
        m_stdinThread.join(); // within one poll period (100 ms)
}

HeadlessMonitor* HeadlessMonitor::attach(FleetContext* ctx, QIODevice* out) {
    auto* mon = new HeadlessMonitor(ctx->fleet(), ctx->alarms(), ctx->gate(), ctx);
    for (FleetBridge* b : ctx->bridges())
        mon->addBridge(b);
    connect(ctx, &FleetContext::bridgeAdded, mon, &HeadlessMonitor::addBridge);
    if (out)
        mon->setOutput(out);
    return mon;
}

void HeadlessMonitor::setOutput(QIODevice* out) {
    m_out = out;
}

void HeadlessMonitor::setRateLimitMs(int ms) {
    m_rateMs = std::max(0, ms);
    // Pending lines are checked at a quarter of the interval (bounded), so a line is at most ~25 % late.
    m_flushTimer.start(std::clamp(m_rateMs / 4, 20, 250));
}

void HeadlessMonitor::addBridge(FleetBridge* bridge) {
    connect(bridge, &FleetBridge::linkChanged, this, &HeadlessMonitor::onLink);
    m_bridges.append(bridge);
}

void HeadlessMonitor::writeLine(const QJsonObject& o) {
    QByteArray line = QJsonDocument(o).toJson(QJsonDocument::Compact);
    line += '\n';
    QIODevice* out = m_out.data();
    if (!out) {
        if (!m_stdout) {
            m_stdout = std::make_unique<QFile>();
            if (!m_stdout->open(STDOUT_FILENO, QIODevice::WriteOnly | QIODevice::Unbuffered))
                return;
        }
        out = m_stdout.get();
    }
    out->write(line);
    if (auto* f = qobject_cast<QFile*>(out))
        f->flush();
}

QJsonObject HeadlessMonitor::machineJson(const MachineState& m, bool stale, qint64 ageMs) const {
    QJsonObject o = machineStateJson(m); // shared with the recording's export (models/MachineJson.h)
    o[QStringLiteral("stale")] = stale;
    o[QStringLiteral("status")] = toText(statusOf(m, stale));
    o[QStringLiteral("age_ms")] = double(ageMs);
    return o;
}

static QString signatureOf(const MachineState& m, bool stale) {
    return QStringLiteral("%1|%2|%3|%4|%5|%6|%7")
        .arg(int(m.stop))
        .arg(int(m.link))
        .arg(m.modeText)
        .arg(int(m.control))
        .arg(int(m.health))
        .arg(stale ? 1 : 0)
        .arg(m.controller);
}

void HeadlessMonitor::printMachine(const QString& id) {
    if (!m_fleet)
        return;
    const int row = m_fleet->rowOf(id);
    if (row < 0)
        return;
    const MachineState& m = m_fleet->machineAt(row);
    const bool stale = m_fleet->isStaleAt(row);
    writeLine(machineJson(m, stale, m_fleet->ageMsAt(row)));
    Printed& p = m_printed[id];
    p.atMs = m_clock.elapsed();
    p.signature = signatureOf(m, stale);
    m_pending.remove(id);
}

void HeadlessMonitor::onMachinesChanged(const QStringList& ids) {
    if (!m_fleet)
        return;
    const qint64 now = m_clock.elapsed();
    for (const QString& id : ids) {
        const int row = m_fleet->rowOf(id);
        if (row < 0)
            continue;
        auto it = m_printed.constFind(id);
        const bool important = it == m_printed.constEnd() ||
                               it->signature != signatureOf(m_fleet->machineAt(row), m_fleet->isStaleAt(row));
        if (important || m_rateMs == 0 || now - it->atMs >= m_rateMs)
            printMachine(id);
        else
            m_pending.insert(id);
    }
}

void HeadlessMonitor::flushPending() {
    if (m_pending.isEmpty())
        return;
    const qint64 now = m_clock.elapsed();
    const QSet<QString> pending = m_pending;
    for (const QString& id : pending) {
        const Printed p = m_printed.value(id);
        if (now - p.atMs >= m_rateMs)
            printMachine(id);
    }
}

void HeadlessMonitor::printAll() {
    if (!m_fleet)
        return;
    for (const QString& id : m_fleet->ids())
        printMachine(id);
}

void HeadlessMonitor::onLink(const LinkStatus& s) {
    const QString sig = toText(s.state) + QLatin1Char('|') + s.detail;
    if (m_linkSig.value(s.link) == sig)
        return;
    m_linkSig.insert(s.link, sig);
    auto* bridge = qobject_cast<FleetBridge*>(sender());
    QJsonObject o;
    o[QStringLiteral("type")] = QStringLiteral("link");
    o[QStringLiteral("protocol")] = bridge ? toText(bridge->protocol()) : QString();
    o[QStringLiteral("link")] = s.link;
    o[QStringLiteral("state")] = toText(s.state);
    o[QStringLiteral("age_ms")] = double(s.dataAgeMs);
    o[QStringLiteral("detail")] = s.detail;
    writeLine(o);
}

void HeadlessMonitor::onEvent(const FleetEvent& e) {
    QJsonObject o;
    o[QStringLiteral("type")] = QStringLiteral("event");
    o[QStringLiteral("time")] = QDateTime::fromMSecsSinceEpoch(e.timeMs, Qt::UTC).toString(Qt::ISODateWithMs);
    o[QStringLiteral("severity")] = toText(e.severity);
    o[QStringLiteral("kind")] = toText(e.kind);
    o[QStringLiteral("machine")] = e.machineId;
    o[QStringLiteral("source")] = e.source;
    o[QStringLiteral("text")] = e.text;
    o[QStringLiteral("requires_ack")] = e.requiresAck;
    writeLine(o);
}

QByteArray HeadlessMonitor::result(const QJsonObject& cmd, bool ok, const QString& message) {
    CommandResult r;
    r.ok = ok;
    r.message = message;
    return result(cmd, r, false);
}

QByteArray HeadlessMonitor::result(const QJsonObject& cmd, const CommandResult& r, bool withTargets) {
    QJsonObject o;
    o[QStringLiteral("type")] = QStringLiteral("result");
    QString name = cmd.value(QStringLiteral("cmd")).toString();
    if (name.isEmpty())
        name = cmd.value(QStringLiteral("command")).toString();
    o[QStringLiteral("cmd")] = name;
    if (cmd.contains(QStringLiteral("req")))
        o[QStringLiteral("req")] = cmd.value(QStringLiteral("req"));
    if (cmd.contains(QStringLiteral("id")))
        o[QStringLiteral("id")] = cmd.value(QStringLiteral("id"));
    if (cmd.value(QStringLiteral("tasks")).isArray()) // assign: the tasks with their AssignmentIds
        o[QStringLiteral("tasks")] = cmd.value(QStringLiteral("tasks"));
    o[QStringLiteral("ok")] = r.ok;
    if (withTargets) {
        // What went on the wire, per target.
        o[QStringLiteral("targets")] = targetsToJson(r.targets);
    }
    o[QStringLiteral("message")] = r.message;
    writeLine(o);
    QByteArray line = QJsonDocument(o).toJson(QJsonDocument::Compact);
    emit commandHandled(line);
    return line;
}

QByteArray HeadlessMonitor::viaGate(const QJsonObject& cmd,
                                    const std::function<void(CommandGate::ResultHandler)>& issue,
                                    const QString& suffix) {
    // The gate answers when every stack reported its outcome (or its deadline passed): the result line is
    // written then. When every bridge decided at once, the line is also returned here.
    struct Call {
        bool inCall = true;
        QByteArray line;
    };
    auto call = std::make_shared<Call>();
    ++m_pendingResults;
    QPointer<HeadlessMonitor> self(this);
    issue([self, call, cmd, suffix](const CommandResult& r) {
        if (!self)
            return;
        CommandResult shown = r;
        if (!r.ok && !suffix.isEmpty())
            shown.message += suffix;
        const QByteArray line = self->result(cmd, shown, true);
        if (call->inCall)
            call->line = line;
        --self->m_pendingResults;
        self->maybeFinishInput();
    });
    call->inCall = false;
    return call->line;
}

void HeadlessMonitor::maybeFinishInput() {
    if (m_inputEnded && m_pendingResults == 0 && !m_finishedSignalled) {
        m_finishedSignalled = true;
        emit inputFinished();
    }
}

bool HeadlessMonitor::isStopAll(const QByteArray& raw) {
    // The same reading as handleLine's: a JSON object whose "cmd" (or "command") is "stop_all".
    const QJsonDocument doc = QJsonDocument::fromJson(raw.trimmed());
    if (!doc.isObject())
        return false;
    const QJsonObject cmd = doc.object();
    QString name = cmd.value(QStringLiteral("cmd")).toString();
    if (name.isEmpty())
        name = cmd.value(QStringLiteral("command")).toString();
    return name == QLatin1String("stop_all");
}

// Commands of other parts of the console, by name.
static QHash<QString, HeadlessMonitor::LocalCommand>& localCommands() {
    static QHash<QString, HeadlessMonitor::LocalCommand> commands;
    return commands;
}

void HeadlessMonitor::setLocalCommand(const QString& name, LocalCommand f) {
    if (f)
        localCommands().insert(name, std::move(f));
    else
        localCommands().remove(name);
}

QByteArray HeadlessMonitor::handleLine(const QByteArray& raw) {
    return handleLine(raw, nullptr);
}

QByteArray HeadlessMonitor::handleLine(const QByteArray& raw, std::shared_ptr<EarlyStop> early) {
    if (early && !isStopAll(raw))
        early.reset(); // cannot happen (the reader asked the same question): never attach it elsewhere
    const QByteArray line = raw.trimmed();
    if (line.isEmpty())
        return {};
    QJsonParseError err{};
    const QJsonDocument doc = QJsonDocument::fromJson(line, &err);
    if (err.error != QJsonParseError::NoError || !doc.isObject())
        return result({}, false,
                      err.error != QJsonParseError::NoError
                          ? QStringLiteral("invalid JSON: %1").arg(err.errorString())
                          : QStringLiteral("a command must be a JSON object"));
    const QJsonObject cmd = doc.object();
    QString name = cmd.value(QStringLiteral("cmd")).toString();
    if (name.isEmpty())
        name = cmd.value(QStringLiteral("command")).toString();
    const QString id = cmd.value(QStringLiteral("id")).toString();
    if (name == QLatin1String("list")) {
        printAll();
        return result(cmd, true, QStringLiteral("%1 machines").arg(m_fleet ? m_fleet->rowCount() : 0));
    }
    if (name == QLatin1String("counters")) // rejects per link and reason
        return countersResult(cmd);
    if (auto q = m_queries.constFind(name); q != m_queries.constEnd()) { // module queries
        QJsonObject o = (*q)(cmd);
        o[QStringLiteral("type")] = QStringLiteral("result");
        o[QStringLiteral("cmd")] = name;
        if (cmd.contains(QStringLiteral("req")))
            o[QStringLiteral("req")] = cmd.value(QStringLiteral("req"));
        writeLine(o);
        QByteArray out = QJsonDocument(o).toJson(QJsonDocument::Compact);
        emit commandHandled(out);
        return out;
    }
    if (!m_gate)
        return result(cmd, false, QStringLiteral("no stop controller"));
    const QString origin = QStringLiteral("headless");
    CommandGate* gate = m_gate;
    if (name == QLatin1String("stop_all"))
        return viaGate(cmd,
                       [&](CommandGate::ResultHandler h) { gate->stopAll(origin, std::move(h), early); });
    if (name == QLatin1String("stop")) {
        if (id.isEmpty())
            return result(cmd, false, QStringLiteral("missing \"id\""));
        return viaGate(cmd,
                       [&](CommandGate::ResultHandler h) { gate->stopMachine(id, origin, std::move(h)); });
    }
    if (name == QLatin1String("clear_stop")) {
        if (id.isEmpty())
            return result(cmd, false, QStringLiteral("missing \"id\""));
        // The scripted equivalent of the GUI's deliberate hold: an explicit "confirm": true.
        if (cmd.value(QStringLiteral("confirm")).toBool(false) != true)
            return viaGate(
                cmd,
                [&](CommandGate::ResultHandler h) { gate->clearStop(id, QString(), origin, std::move(h)); },
                QStringLiteral(" (add \"confirm\": true)")); // audited refusal
        return viaGate(cmd, [&](CommandGate::ResultHandler h) {
            gate->clearStop(id, gate->requestClearToken(id), origin, std::move(h));
        });
    }
    if (name == QLatin1String("assign") || name == QLatin1String("reset_assignment") ||
        name == QLatin1String("production"))
        return dispatchCommand(name, cmd);
    // Commands answered in this process (no gate round trip): the result line as the command's reply.
    const auto localResult = [&](QJsonObject o) {
        o[QStringLiteral("type")] = QStringLiteral("result");
        o[QStringLiteral("cmd")] = name;
        if (cmd.contains(QStringLiteral("req")))
            o[QStringLiteral("req")] = cmd.value(QStringLiteral("req"));
        writeLine(o);
        QByteArray line = QJsonDocument(o).toJson(QJsonDocument::Compact);
        emit commandHandled(line);
        return line;
    };
    if (name == QLatin1String("auto_dispatch")) // models/AutoDispatcher.h
        return localResult(AutoDispatcher::command(m_gate->bridges(), cmd, origin));
    if (const auto local = localCommands().find(name); local != localCommands().end())
        return localResult(local.value()(cmd));
    if (name == QLatin1String("shift_report")) { // app/ShiftReportCommand.h
        ShiftReportRequest r{cmd.value(QStringLiteral("pdf")).toString(),
                             cmd.value(QStringLiteral("csv")).toString(), std::nullopt,
                             cmd.value(QStringLiteral("site")).toString()};
        if (cmd.contains(QStringLiteral("plan_tonnes")))
            r.planTonnes = cmd.value(QStringLiteral("plan_tonnes")).toDouble();
        QJsonObject o = writeShiftReport(m_gate->bridges(), m_fleet, r);
        o[QStringLiteral("type")] = QStringLiteral("result");
        o[QStringLiteral("cmd")] = name;
        if (cmd.contains(QStringLiteral("req")))
            o[QStringLiteral("req")] = cmd.value(QStringLiteral("req"));
        writeLine(o);
        QByteArray line = QJsonDocument(o).toJson(QJsonDocument::Compact);
        emit commandHandled(line);
        return line;
    }
    return operatorCommand(name, cmd);
}

// Every other operator command is read into its typed value here, once (models/commands/OperatorCommand.h):
// the gate checks, sends and audits that value, and the result line names the command as read.
QByteArray HeadlessMonitor::operatorCommand(const QString& name, const QJsonObject& cmd) {
    ParsedCommand parsed = parseOperatorCommand(name, cmd);
    CommandGate* gate = m_gate;
    const QString origin = QStringLiteral("headless");
    if (!parsed.command) {
        if (parsed.target.isEmpty())
            return result(cmd, false, parsed.error);
        // A malformed argument of a command naming a machine: audited as not sent to it.
        return viaGate(cmd, [&](CommandGate::ResultHandler h) {
            gate->refuse(name, parsed.target, OutcomeReason::InvalidArgument, parsed.error, origin,
                         std::move(h));
        });
    }
    // Every assignment task gets its AssignmentId here, so the result line names them.
    if (auto* assign = std::get_if<Assign>(&*parsed.command))
        for (AssignTask& t : assign->tasks)
            if (t.assignmentId.isEmpty())
                t.assignmentId = QUuid::createUuid().toString(QUuid::WithoutBraces);
    const OperatorCommand command = *parsed.command;
    QJsonObject shown = toJson(command);
    if (cmd.contains(QStringLiteral("req")))
        shown[QStringLiteral("req")] = cmd.value(QStringLiteral("req"));
    return viaGate(shown,
                   [&](CommandGate::ResultHandler h) { gate->command(command, origin, std::move(h)); });
}

// ---- Dispatch (ISO 23725 haul trucks) ----
// assign / reset_assignment go through the gate to the bridge owning "id" (audited; the result lists the
// truck as its target, sent only when the socket took the request). production answers from the bridges'
// dispatch views (what the trucks reported), without touching the wire.
QByteArray HeadlessMonitor::dispatchCommand(const QString& name, const QJsonObject& cmd) {
    const QString id = cmd.value(QStringLiteral("id")).toString();
    if (name == QLatin1String("production")) {
        QJsonArray trucks;
        int sources = 0;
        for (FleetBridge* b : m_gate->bridges()) {
            QJsonArray part;
            if (!b || b->metaObject()->indexOfMethod("productionJson()") < 0 ||
                !QMetaObject::invokeMethod(b, "productionJson", Qt::DirectConnection,
                                           Q_RETURN_ARG(QJsonArray, part)))
                continue;
            ++sources;
            for (const auto& t : part)
                if (id.isEmpty() || t.toObject().value(QStringLiteral("id")).toString() == id)
                    trucks << t;
        }
        QJsonObject o;
        o[QStringLiteral("type")] = QStringLiteral("result");
        o[QStringLiteral("cmd")] = name;
        if (cmd.contains(QStringLiteral("req")))
            o[QStringLiteral("req")] = cmd.value(QStringLiteral("req"));
        o[QStringLiteral("ok")] = sources > 0;
        o[QStringLiteral("trucks")] = trucks;
        o[QStringLiteral("message")] = sources > 0 ? QStringLiteral("%1 trucks").arg(trucks.size())
                                                   : QStringLiteral("no ISO 23725 bridge in this console");
        writeLine(o);
        QByteArray line = QJsonDocument(o).toJson(QJsonDocument::Compact);
        emit commandHandled(line);
        return line;
    }
    return operatorCommand(name, cmd); // assign, reset_assignment
}

// ---- {"cmd":"counters"} ----
QByteArray HeadlessMonitor::countersResult(const QJsonObject& cmd) {
    QJsonArray links;
    for (const QPointer<FleetBridge>& b : std::as_const(m_bridges)) {
        if (!b)
            continue;
        for (const LinkCounters& c : b->linkCounters()) {
            QJsonObject rejected;
            for (auto it = c.rejected.begin(); it != c.rejected.end(); ++it)
                rejected[it.key()] = double(it.value());
            QJsonObject all;
            for (auto it = c.all.begin(); it != c.all.end(); ++it)
                all[it.key()] = double(it.value());
            QJsonObject l;
            l[QStringLiteral("protocol")] = toText(b->protocol());
            l[QStringLiteral("link")] = c.link;
            l[QStringLiteral("rejected_total")] = double(c.rejectedTotal());
            l[QStringLiteral("rejected")] = rejected;
            l[QStringLiteral("counters")] = all;
            links.append(l);
        }
    }
    QJsonObject o;
    o[QStringLiteral("type")] = QStringLiteral("result");
    o[QStringLiteral("cmd")] = QStringLiteral("counters");
    if (cmd.contains(QStringLiteral("req")))
        o[QStringLiteral("req")] = cmd.value(QStringLiteral("req"));
    o[QStringLiteral("ok")] = true;
    o[QStringLiteral("message")] = QStringLiteral("%1 links").arg(links.size());
    o[QStringLiteral("links")] = links;
    writeLine(o);
    const QByteArray line = QJsonDocument(o).toJson(QJsonDocument::Compact);
    emit commandHandled(line);
    return line;
}

void HeadlessMonitor::consumeInput(const QByteArray& chunk) {
    m_inBuf += chunk;
    int nl;
    while ((nl = int(m_inBuf.indexOf('\n'))) >= 0) {
        const QByteArray line = m_inBuf.left(nl);
        m_inBuf.remove(0, nl + 1);
        handleLine(line);
    }
    if (m_inBuf.size() > 1 << 20) { // a runaway line without newline: drop it, say so
        m_inBuf.clear();
        result({}, false, QStringLiteral("input line too long (over 1 MiB), dropped"));
    }
}

void HeadlessMonitor::addProtocolCommands(const QStringList& names) {
    for (const QString& n : names)
        m_protocolCommands.insert(n);
}

bool HeadlessMonitor::startStdin() {
    if (m_stdinThread.joinable())
        return true;
    CommandGate* gate = m_gate.data(); // lives as long as the bridges; the thread ends before they go
    m_stdinThread = std::thread([this, gate] {
        if (stopPathPriorityEnabled())
            raiseThreadPriority("headless stdin reader");
        // High priority: ahead of the queued telemetry events; among themselves in order of reading.
        auto post = [this](StdinEvent::What w, QByteArray line = {}, std::shared_ptr<EarlyStop> early = {}) {
            QCoreApplication::postEvent(this, new StdinEvent(w, std::move(line), std::move(early)),
                                        Qt::HighEventPriority);
        };
        auto line = [&](const QByteArray& l) {
            // A stop_all leaves from here at once on the stacks that can send from any thread; the monitor's
            // thread sends the rest and records it all as this command (CommandGate::stopAllEarly).
            post(StdinEvent::Line, l, gate && isStopAll(l) ? gate->stopAllEarly() : nullptr);
        };
        QByteArray pending;
        char buf[4096];
        while (!m_stdinStop) {
            pollfd p{STDIN_FILENO, POLLIN, 0};
            const int r = ::poll(&p, 1, 100); // wakes at once on input; checks m_stdinStop every 100 ms
            if (r == 0 || (r < 0 && errno == EINTR))
                continue;
            const ssize_t n = r > 0 ? ::read(STDIN_FILENO, buf, sizeof buf) : -1;
            if (n < 0 && (errno == EINTR || errno == EAGAIN))
                continue;
            if (n <= 0) {
                if (!pending.trimmed().isEmpty())
                    line(pending); // the unterminated last line is still executed
                post(StdinEvent::End);
                return;
            }
            pending.append(buf, int(n));
            int nl;
            while ((nl = int(pending.indexOf('\n'))) >= 0) {
                line(pending.left(nl));
                pending.remove(0, nl + 1);
            }
            if (pending.size() > 1 << 20) { // a runaway line without newline: drop it, say so
                pending.clear();
                post(StdinEvent::TooLong);
            }
        }
    });
    return true;
}

bool HeadlessMonitor::event(QEvent* e) {
    if (e->type() != StdinEvent::kind())
        return QObject::event(e);
    auto* in = static_cast<StdinEvent*>(e);
    switch (in->what) {
    case StdinEvent::Line:
        handleLine(in->line, std::move(in->early));
        break;
    case StdinEvent::TooLong:
        result({}, false, QStringLiteral("input line too long (over 1 MiB), dropped"));
        break;
    case StdinEvent::End:
        m_inputEnded = true;
        maybeFinishInput();
        break;
    }
    return true;
}

void HeadlessMonitor::setInput(QIODevice* in) {
    connect(in, &QIODevice::readyRead, this, [this, in] { consumeInput(in->readAll()); });
    connect(in, &QIODevice::readChannelFinished, this, [this, in] {
        consumeInput(in->readAll());
        if (!m_inBuf.isEmpty())
            consumeInput("\n");
        m_inputEnded = true;
        maybeFinishInput();
    });
}

void HeadlessMonitor::addQuery(const QString& name, QueryHandler handler) {
    m_queries.insert(name, std::move(handler));
}

} // namespace ocu
