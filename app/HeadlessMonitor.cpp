#include "app/HeadlessMonitor.h"

#include "models/AlarmModel.h"
#include "models/FleetBridge.h"
#include "models/FleetContext.h"
#include "models/FleetModel.h"
#include "models/MachineJson.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QEvent>
#include <QFile>
#include <QJsonDocument>
#include <QJsonParseError>

#include "protocols/common/ThreadPriority.h"

#include <cerrno>
#include <poll.h>
#include <unistd.h>

namespace ocu {

HeadlessMonitor::HeadlessMonitor(FleetModel* fleet, AlarmModel* alarms, CommandGate* stop, QObject* parent)
    : QObject(parent), m_fleet(fleet), m_alarms(alarms), m_gate(stop),
      m_commands(stop, [this](const QByteArray& line) { writeResultLine(line); }) {
    m_clock.start();
    m_commands.setSettledHandler([this] { maybeFinishInput(); });
    m_commands.addLocal(QStringLiteral("list"), [this](const QJsonObject&) {
        printAll();
        return QJsonObject{{QStringLiteral("ok"), true},
                           {QStringLiteral("message"),
                            QStringLiteral("%1 machines").arg(m_fleet ? m_fleet->rowCount() : 0)}};
    });
    m_commands.setMachineRefresh([this](const QString& id, bool atOnce) {
        if (atOnce)
            printMachine(id);
        else
            onMachinesChanged({id});
    });
    // Rejects per link and reason.
    m_commands.addLocal(QStringLiteral("counters"),
                        [this](const QJsonObject&) { return linkCountersFields(m_bridges); });
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
    writeRaw(QJsonDocument(o).toJson(QJsonDocument::Compact) + '\n');
}

void HeadlessMonitor::writeRaw(const QByteArray& line) {
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
    for (const QPointer<QIODevice>& extra : std::as_const(m_extraOutputs)) {
        if (!extra || !extra->isOpen())
            continue;
        // A client that stopped reading is dropped rather than buffered without end.
        if (extra->bytesToWrite() > (16 << 20))
            extra->close();
        else
            extra->write(line);
    }
}

void HeadlessMonitor::addOutput(QIODevice* out) {
    m_extraOutputs.append(out);
}

void HeadlessMonitor::removeOutput(QIODevice* out) {
    m_extraOutputs.removeAll(out);
}

void HeadlessMonitor::writeResultLine(const QByteArray& line) {
    writeRaw(line + '\n');
    emit commandHandled(line);
}

QJsonObject HeadlessMonitor::machineJson(const MachineState& m, bool stale, qint64 ageMs) const {
    QJsonObject o = machineStateJson(m); // shared with the recording's export (models/MachineJson.h)
    o[QStringLiteral("stale")] = stale;
    o[QStringLiteral("status")] = toText(statusOf(m, stale));
    o[QStringLiteral("age_ms")] = double(ageMs);
    m_commands.machineFields(m.id, o); // the modules' own (a vehicle's mission)
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

void HeadlessMonitor::maybeFinishInput() {
    if (m_inputEnded && m_commands.pendingResults() == 0 && !m_finishedSignalled) {
        m_finishedSignalled = true;
        emit inputFinished();
    }
}

bool HeadlessMonitor::isStopAll(const QByteArray& raw) {
    // The same reading as handleLine's: a JSON object whose "cmd" (or "command") is "stop_all".
    const QJsonDocument doc = QJsonDocument::fromJson(raw.trimmed());
    if (!doc.isObject())
        return false;
    return HeadlessCommands::nameOf(doc.object()) == QLatin1String("stop_all");
}

QByteArray HeadlessMonitor::handleLine(const QByteArray& raw) {
    return handleLine(raw, nullptr);
}

QByteArray HeadlessMonitor::handleLine(const QByteArray& raw, std::shared_ptr<EarlyStop> early) {
    const QByteArray line = raw.trimmed();
    if (line.isEmpty())
        return {};
    QJsonParseError err{};
    const QJsonDocument doc = QJsonDocument::fromJson(line, &err);
    if (err.error != QJsonParseError::NoError || !doc.isObject())
        return m_commands.refuse({}, err.error != QJsonParseError::NoError
                                         ? QStringLiteral("invalid JSON: %1").arg(err.errorString())
                                         : QStringLiteral("a command must be a JSON object"));
    return m_commands.execute(doc.object(), std::move(early));
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
        m_commands.refuse({}, QStringLiteral("input line too long (over 1 MiB), dropped"));
    }
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
        m_commands.refuse({}, QStringLiteral("input line too long (over 1 MiB), dropped"));
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

} // namespace ocu
