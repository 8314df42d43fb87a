// CommandGate fan-out, confirmation tokens and audit; AlarmModel acknowledgement, filter and CSV export.
#include "models/AlarmModel.h"
#include "models/CommandGate.h"
#include "models/FleetModel.h"
#include "models/testing/CommandWait.h"
#include "models/testing/FakeFleetBridge.h"

#include <QBuffer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <thread>

using namespace ocu;
using ocu::testing::gateResult;

namespace {
bool hasTimeoutAlarm(const AlarmModel& alarms, const QString& machine) {
    for (int i = 0; i < alarms.rowCount(); ++i)
        if (alarms.eventAt(i).kind == EventKind::Timeout && alarms.eventAt(i).machineId == machine &&
            alarms.eventAt(i).severity == EventSeverity::Alarm)
            return true;
    return false;
}

MachineState machine(const QString& id) {
    MachineState m;
    m.id = id;
    m.protocol = protocolOfId(id);
    m.link = LinkState::Up;
    m.stop = StopState::None;
    return m;
}
// A bridge that confirms control commands through its machines' reports (commandReported), like JausBridge.
class ConfirmingBridge : public FakeFleetBridge {
public:
    using FakeFleetBridge::FakeFleetBridge;
    bool confirmsCommand(const QString& action) const override {
        return action == QLatin1String("request_control") || action == QLatin1String("clear_stop");
    }
    bool reportsConfirmed(const QString& action, const QString& target) const override {
        return action == QLatin1String("clear_stop") && target == QLatin1String("jaus:9"); // already clear
    }
};
} // namespace

class TestStopAlarms : public QObject {
    Q_OBJECT
private slots:
    void stopAllReachesEveryBridgeAndShowsWhatMachinesReport() {
        QTemporaryDir dir;
        FleetModel fleet;
        fleet.setRefreshIntervalMs(0);
        AlarmModel alarms;
        CommandGate stop(&alarms);
        stop.setAuditLogPath(dir.filePath(QStringLiteral("audit.jsonl")));
        FakeFleetBridge jaus(Protocol::Jaus), iso(Protocol::Iso23725), osy(Protocol::Osyris);
        for (FakeFleetBridge* b : {&jaus, &iso, &osy}) {
            fleet.addBridge(b);
            stop.addBridge(b);
            b->setMachine(machine(protocolPrefix(b->protocol()) + QStringLiteral("1")));
        }
        jaus.simulateMachines = false; // this machine does not react: its shown state must stay "none"
        QCoreApplication::processEvents();
        QCOMPARE(fleet.rowCount(), 3);

        const CommandResult r = gateResult([&](auto h) { stop.stopAll(QStringLiteral("test"), h); });
        QVERIFY(r.ok);
        for (FakeFleetBridge* b : {&jaus, &iso, &osy}) {
            QCOMPARE(b->calls().size(), 1);
            QCOMPARE(b->calls().first().name, QStringLiteral("stop_all"));
        }
        QCoreApplication::processEvents();
        QCOMPARE(fleet.machine(QStringLiteral("iso23725:1"))->stop, StopState::Stopped);
        QCOMPARE(fleet.machine(QStringLiteral("osyris:1"))->stop, StopState::Stopped);
        QCOMPARE(fleet.machine(QStringLiteral("jaus:1"))->stop, StopState::None); // not what we asked

        // One target per machine, each sent.
        QCOMPARE(r.targets.size(), 3);
        for (const TargetOutcome& t : r.targets)
            QVERIFY(t.sent);
        // Audited: an event-log entry and one JSON line in the audit file.
        QCOMPARE(alarms.eventAt(0).kind, EventKind::Audit);
        QVERIFY(alarms.eventAt(0).text.startsWith(QStringLiteral("stop_all by test")));
        QFile f(stop.auditLogPath());
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = f.readAll().trimmed().split('\n');
        QCOMPARE(lines.size(), 1);
        const QJsonObject o = QJsonDocument::fromJson(lines[0]).object();
        QCOMPARE(o.value(QStringLiteral("action")).toString(), QStringLiteral("stop_all"));
        QCOMPARE(o.value(QStringLiteral("origin")).toString(), QStringLiteral("test"));
        QCOMPARE(o.value(QStringLiteral("ok")).toBool(), true);
        QCOMPARE(o.value(QStringLiteral("targets")).toArray().size(), 3);
    }

    // The headless stdin reader's STOP ALL. stopAllEarly() on another thread calls at once the
    // bridges that send from the caller's thread (and only those); stopAll(origin, h, early) on the gate's
    // thread calls the others and records it all as one STOP ALL: every target, one audit line, no bridge
    // called twice. Bridges that send from the caller's thread come first in a plain stopAll too.
    void earlyStopFromAnotherThreadIsOneStopAll() {
        QTemporaryDir dir;
        AlarmModel alarms;
        CommandGate stop(&alarms);
        stop.setAuditLogPath(dir.filePath(QStringLiteral("audit.jsonl")));
        FakeFleetBridge iso(Protocol::Iso23725), jaus(Protocol::Jaus), osy(Protocol::Osyris);
        jaus.fromCallersThread = true;
        osy.fromCallersThread = true;
        for (FakeFleetBridge* b : {&iso, &jaus, &osy}) {
            stop.addBridge(b);
            b->setMachine(machine(protocolPrefix(b->protocol()) + QStringLiteral("1")));
        }
        std::shared_ptr<EarlyStop> early;
        std::thread::id reader;
        std::thread t([&] {
            reader = std::this_thread::get_id();
            early = stop.stopAllEarly();
        });
        t.join();
        QCOMPARE(jaus.calls().size(), 1);
        QCOMPARE(osy.calls().size(), 1);
        QVERIFY(jaus.stopAllThread() == reader);
        QVERIFY(osy.stopAllThread() == reader);
        QCOMPARE(iso.calls().size(), 0);                     // not thread-safe: the gate's thread calls it
        QCOMPARE(QFile::exists(stop.auditLogPath()), false); // recorded only with the rest

        const CommandResult r =
            gateResult([&](auto h) { stop.stopAll(QStringLiteral("headless"), h, early); });
        QVERIFY(r.ok);
        QCOMPARE(r.targets.size(), 3);
        for (FakeFleetBridge* b : {&iso, &jaus, &osy})
            QCOMPARE(b->calls().size(), 1); // none twice
        QVERIFY(iso.stopAllThread() == std::this_thread::get_id());
        QFile f(stop.auditLogPath());
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = f.readAll().trimmed().split('\n');
        QCOMPARE(lines.size(), 1);
        QCOMPARE(QJsonDocument::fromJson(lines[0]).object().value(QStringLiteral("targets")).toArray().size(),
                 3);

        // A plain STOP ALL: the caller's-thread bridges first, whatever the order they were added in.
        const CommandResult r2 = gateResult([&](auto h) { stop.stopAll(QStringLiteral("gui"), h); });
        QCOMPARE(r2.targets.size(), 3);
        QCOMPARE(targetId(r2.targets.last()), QStringLiteral("iso23725:1"));
    }

    void stopAllStillReachesOthersWhenOneRefuses() {
        AlarmModel alarms;
        CommandGate stop(&alarms);
        FakeFleetBridge a(Protocol::Jaus), b(Protocol::Iso23725);
        a.refusedCommands = {QStringLiteral("stop_all")};
        stop.addBridge(&a);
        stop.addBridge(&b);
        const CommandResult r = gateResult([&](auto h) { stop.stopAll(QStringLiteral("gui"), h); });
        QVERIFY(!r.ok);
        QVERIFY(r.message.contains(QStringLiteral("jaus")));
        QCOMPARE(b.calls().size(), 1);
        // A refused stop is an alarm that needs acknowledgement.
        QVERIFY(alarms.unacknowledgedCount() >= 1);
    }

    // A stack that never answers is a target not sent once the deadline passed, never a success.
    void silentStackIsNotSentAfterTheDeadline() {
        AlarmModel alarms;
        CommandGate stop(&alarms);
        stop.setAnswerDeadlineMs(200);
        FakeFleetBridge a(Protocol::Jaus), b(Protocol::Iso23725);
        a.silent = true;
        b.setMachine(machine(QStringLiteral("iso23725:1")));
        stop.addBridge(&a);
        stop.addBridge(&b);
        QCoreApplication::processEvents();
        QSignalSpy finished(&stop, &CommandGate::stopFinished);
        const CommandResult r = gateResult([&](auto h) { stop.stopAll(QStringLiteral("gui"), h); });
        QVERIFY(!r.ok);
        QCOMPARE(r.targets.size(), 2);
        QCOMPARE(targetId(r.targets[0]), QStringLiteral("jaus"));
        QVERIFY(!r.targets[0].sent);
        QVERIFY(reasonText(r.targets[0]).contains(QStringLiteral("did not answer")));
        QVERIFY(r.targets[1].sent);
        QCOMPARE(finished.count(), 1);
        QCOMPARE(stop.pendingCommands(), 0);
    }

    // No target at all is not a success either (nothing went on the wire).
    void noTargetIsNotOk() {
        CommandGate stop;
        FakeFleetBridge a(Protocol::Jaus); // no machines: its STOP ALL addresses nobody
        stop.addBridge(&a);
        const CommandResult r = gateResult([&](auto h) { stop.stopAll(QStringLiteral("gui"), h); });
        QVERIFY(!r.ok);
        QVERIFY(r.targets.isEmpty());
        QVERIFY(!r.message.isEmpty());
        CommandGate empty;
        QVERIFY(!gateResult([&](auto h) { empty.stopAll(QStringLiteral("gui"), h); }).ok);
    }

    // Confirmation comes from the machines' reports: logged with its latency; none in time raises an alarm.
    void stopConfirmationLatencyAndAlarm() {
        AlarmModel alarms;
        CommandGate stop(&alarms);
        stop.setConfirmTimeoutMs(2000);
        FakeFleetBridge jaus(Protocol::Jaus), iso(Protocol::Iso23725);
        for (FakeFleetBridge* b : {&jaus, &iso}) {
            stop.addBridge(b);
            b->setMachine(machine(protocolPrefix(b->protocol()) + QStringLiteral("1")));
        }
        jaus.simulateMachines = false; // never reports stopped
        QCoreApplication::processEvents();
        QSignalSpy confirmed(&stop, &CommandGate::stopConfirmed);
        QSignalSpy unconfirmed(&stop, &CommandGate::stopUnconfirmed);
        // The ISO fake reports its stop only later (queued), so it is watched, then confirmed.
        const CommandResult r = gateResult([&](auto h) { stop.stopAll(QStringLiteral("gui"), h); });
        QVERIFY(r.ok);
        QTRY_COMPARE_WITH_TIMEOUT(unconfirmed.count(), 1, 20000);
        QCOMPARE(unconfirmed.first().at(0).toString(), QStringLiteral("jaus:1"));
        QVERIFY(confirmed.count() >= 1);
        QCOMPARE(confirmed.first().at(0).toString(), QStringLiteral("iso23725:1"));
        QVERIFY(confirmed.first().at(1).toString().contains(QStringLiteral("ms after the command")));
        bool alarm = false;
        for (int i = 0; i < alarms.rowCount(); ++i)
            alarm = alarm || (alarms.eventAt(i).kind == EventKind::Timeout &&
                              alarms.eventAt(i).machineId == QStringLiteral("jaus:1") &&
                              alarms.eventAt(i).severity == EventSeverity::Alarm);
        QVERIFY(alarm);
        QVERIFY(stop.awaitingConfirmation().isEmpty());
    }

    // Confirmation beyond stops: a confirmed command is watched until the machine's own report answers it
    // (an event with the latency); none within the confirmation time raises a Timeout alarm. A command the
    // bridge does not confirm (drive_start) is not watched.
    void commandConfirmationLatencyAndAlarm() {
        AlarmModel alarms;
        CommandGate gate(&alarms);
        gate.setConfirmTimeoutMs(300);
        ConfirmingBridge jaus(Protocol::Jaus);
        gate.addBridge(&jaus);
        for (const char* id : {"jaus:1", "jaus:2", "jaus:9"})
            jaus.setMachine(machine(QString::fromLatin1(id)));
        QCoreApplication::processEvents();
        QSignalSpy confirmed(&gate, &CommandGate::commandConfirmed);
        QSignalSpy unconfirmed(&gate, &CommandGate::commandUnconfirmed);
        for (const char* id : {"jaus:1", "jaus:2"})
            QVERIFY(gateResult([&](auto h) {
                        gate.command(RequestControl{QString::fromLatin1(id)}, QStringLiteral("gui"), h);
                    }).ok);
        QVERIFY(gateResult([&](auto h) {
                    gate.command(DriveStart{QStringLiteral("jaus:1"), {}}, QStringLiteral("gui"), h);
                }).ok);
        QCOMPARE(gate.awaitingCommandConfirmation().size(), 2);
        emit jaus.commandReported(QStringLiteral("request_control"), QStringLiteral("jaus:1"),
                                  QStringLiteral("UGV-1 confirms control by this console"));
        QCOMPARE(confirmed.count(), 1);
        QCOMPARE(confirmed.first().at(1).toString(), QStringLiteral("jaus:1"));
        QVERIFY(confirmed.first().at(2).toString().startsWith(
            QStringLiteral("UGV-1 confirms control by this console ")));
        QVERIFY(confirmed.first().at(2).toString().endsWith(QStringLiteral("ms after the command")));
        // A report nobody waits for (another action, another machine) changes nothing.
        emit jaus.commandReported(QStringLiteral("release_control"), QStringLiteral("jaus:2"),
                                  QStringLiteral("x"));
        QCOMPARE(confirmed.count(), 1);
        QTRY_COMPARE_WITH_TIMEOUT(unconfirmed.count(), 1, 20000);
        QCOMPARE(unconfirmed.first().at(0).toString(), QStringLiteral("request_control"));
        QCOMPARE(unconfirmed.first().at(1).toString(), QStringLiteral("jaus:2"));
        QVERIFY(hasTimeoutAlarm(alarms, QStringLiteral("jaus:2")));
        QVERIFY(!hasTimeoutAlarm(alarms, QStringLiteral("jaus:1")));
        QVERIFY(gate.awaitingCommandConfirmation().isEmpty());
        // Already showing the effect: confirmed at once.
        QVERIFY(gateResult([&](auto h) {
                    gate.clearStop(QStringLiteral("jaus:9"), gate.requestClearToken(QStringLiteral("jaus:9")),
                                   QStringLiteral("gui"), h);
                }).ok);
        QCOMPARE(confirmed.count(), 2);
        QVERIFY(gate.awaitingCommandConfirmation().isEmpty());
    }

    void stopNeedsNoConfirmationButReleaseDoes() {
        AlarmModel alarms;
        CommandGate stop(&alarms);
        FakeFleetBridge jaus(Protocol::Jaus), iso(Protocol::Iso23725);
        stop.addBridge(&jaus);
        stop.addBridge(&iso);
        QVERIFY(gateResult([&](auto h) {
                    stop.stopMachine(QStringLiteral("iso23725:T1"), QStringLiteral("gui"), h);
                }).ok);
        QCOMPARE(iso.calls().size(), 1);
        QCOMPARE(iso.calls()[0].name, QStringLiteral("stop"));
        QCOMPARE(jaus.calls().size(), 0);

        // No token, wrong token, token for another machine: refused, bridge untouched.
        QVERIFY(!gateResult([&](auto h) {
                     stop.clearStop(QStringLiteral("iso23725:T1"), QString(), QStringLiteral("gui"), h);
                 }).ok);
        QVERIFY(!gateResult([&](auto h) {
                     stop.clearStop(QStringLiteral("iso23725:T1"), QStringLiteral("bogus"),
                                    QStringLiteral("gui"), h);
                 }).ok);
        const QString other = stop.requestClearToken(QStringLiteral("iso23725:T9"));
        QVERIFY(!gateResult([&](auto h) {
                     stop.clearStop(QStringLiteral("iso23725:T1"), other, QStringLiteral("gui"), h);
                 }).ok);
        QCOMPARE(iso.calls().size(), 1);

        const QString token = stop.requestClearToken(QStringLiteral("iso23725:T1"));
        QVERIFY(gateResult([&](auto h) {
                    stop.clearStop(QStringLiteral("iso23725:T1"), token, QStringLiteral("gui"), h);
                }).ok);
        QCOMPARE(iso.calls().size(), 2);
        QCOMPARE(iso.calls()[1].name, QStringLiteral("clear_stop"));
        // Single use.
        QVERIFY(!gateResult([&](auto h) {
                     stop.clearStop(QStringLiteral("iso23725:T1"), token, QStringLiteral("gui"), h);
                 }).ok);
        QCOMPARE(iso.calls().size(), 2);

        // A token expires on the gate's clock: valid until its lifetime has passed on it (the system clock
        // advances with steady time, whatever the wall clock does).
        auto clock = std::make_shared<ManualModelClock>(3'600'000);
        stop.setClock(clock);
        stop.setTokenLifetimeMs(10000);
        const QString aging = stop.requestClearToken(QStringLiteral("iso23725:T1"));
        clock->advance(10001);
        QVERIFY(!gateResult([&](auto h) {
                     stop.clearStop(QStringLiteral("iso23725:T1"), aging, QStringLiteral("gui"), h);
                 }).ok);
        QCOMPARE(iso.calls().size(), 2);
        const QString fresh = stop.requestClearToken(QStringLiteral("iso23725:T1"));
        clock->advance(9999);
        QVERIFY(gateResult([&](auto h) {
                    stop.clearStop(QStringLiteral("iso23725:T1"), fresh, QStringLiteral("gui"), h);
                }).ok);
        QCOMPARE(iso.calls().size(), 3);

        // Expired token.
        stop.setTokenLifetimeMs(-1);
        const QString expired = stop.requestClearToken(QStringLiteral("iso23725:T1"));
        QVERIFY(!gateResult([&](auto h) {
                     stop.clearStop(QStringLiteral("iso23725:T1"), expired, QStringLiteral("gui"), h);
                 }).ok);
        QCOMPARE(iso.calls().size(), 3);
    }

    void alarmStaysUntilAcknowledged() {
        AlarmModel alarms;
        QSignalSpy count(&alarms, &AlarmModel::unacknowledgedCountChanged);
        alarms.add(makeEvent(EventSeverity::Info, EventKind::Info, {}, QStringLiteral("hello")));
        QCOMPARE(alarms.unacknowledgedCount(), 0);
        alarms.add(makeEvent(EventSeverity::Alarm, EventKind::HealthFault, QStringLiteral("jaus:1"),
                             QStringLiteral("motor fault")));
        alarms.add(makeEvent(EventSeverity::Warning, EventKind::Timeout, QStringLiteral("jaus:2"),
                             QStringLiteral("no data")));
        QCOMPARE(alarms.unacknowledgedCount(), 2);
        // Trimming never drops unacknowledged alarms.
        alarms.setMaxEntries(1);
        alarms.add(makeEvent(EventSeverity::Info, EventKind::Info, {}, QStringLiteral("x")));
        QCOMPARE(alarms.rowCount(), 2);
        QCOMPARE(alarms.unacknowledgedCount(), 2);
        alarms.setMaxEntries(1000);
        // Still there after time passes and more events arrive.
        for (int i = 0; i < 50; ++i)
            alarms.add(
                makeEvent(EventSeverity::Info, EventKind::Info, {}, QStringLiteral("noise %1").arg(i)));
        QCOMPARE(alarms.unacknowledgedCount(), 2);
        alarms.acknowledge(0);
        QCOMPARE(alarms.unacknowledgedCount(), 1);
        QVERIFY(alarms.isAcknowledged(0));
        alarms.acknowledge(0); // idempotent
        QCOMPARE(alarms.unacknowledgedCount(), 1);
        alarms.acknowledgeAll();
        QCOMPARE(alarms.unacknowledgedCount(), 0);
        QCOMPARE(count.last().at(0).toInt(), 0);
    }

    void linkLossAndStaleAndHealthFaultRaiseAlarms() {
        FakeFleetBridge bridge(Protocol::Iso23725);
        FleetModel fleet;
        fleet.setRefreshIntervalMs(0);
        auto clock = std::make_shared<ManualModelClock>(5'000'000);
        fleet.setClock(clock);
        fleet.addBridge(&bridge);
        AlarmModel alarms;
        alarms.addBridge(&bridge);
        alarms.watchFleet(&fleet);

        bridge.publishLink(
            {QStringLiteral("ahs-1"), LinkState::Down, 12000, QStringLiteral("heartbeat timeout")});
        bridge.publishLink(
            {QStringLiteral("ahs-1"), LinkState::Down, 13000, QStringLiteral("heartbeat timeout")});
        QCoreApplication::processEvents();
        QCOMPARE(alarms.unacknowledgedCount(), 1); // coalesced + deduplicated
        QCOMPARE(alarms.eventAt(0).kind, EventKind::LinkLoss);

        MachineState m = machine(QStringLiteral("iso23725:T1"));
        m.lastDataMs = clock->nowMs();
        m.health = HealthLevel::Fault;
        m.healthText = QStringLiteral("tyre pressure");
        bridge.publishMachine(m);
        QCoreApplication::processEvents();
        QCOMPARE(alarms.unacknowledgedCount(), 2);
        QCOMPARE(alarms.eventAt(1).kind, EventKind::HealthFault);
        QCOMPARE(alarms.eventAt(1).machineId, m.id);
        bridge.publishMachine(m); // same fault again: no second alarm
        QCoreApplication::processEvents();
        QCOMPARE(alarms.unacknowledgedCount(), 2);

        clock->advance(60000);
        fleet.setRemoveAfterMs(0);
        fleet.refresh();
        QCOMPARE(alarms.unacknowledgedCount(), 3);
        QCOMPARE(alarms.eventAt(2).kind, EventKind::Timeout);

        // Bridge events pass through.
        FleetEvent ev =
            makeEvent(EventSeverity::Warning, EventKind::Discrepancy, {}, QStringLiteral("fleet differs"));
        bridge.publishEvent(ev);
        QCoreApplication::processEvents();
        QCOMPARE(alarms.eventAt(alarms.rowCount() - 1).kind, EventKind::Discrepancy);
        QCOMPARE(alarms.eventAt(alarms.rowCount() - 1).source, QStringLiteral("iso23725"));
    }

    void filterAndCsvExport() {
        AlarmModel alarms;
        FleetEvent a = makeEvent(EventSeverity::Alarm, EventKind::ControlLost, QStringLiteral("jaus:101"),
                                 QStringLiteral("control lost, \"timeout\", retry"));
        a.timeMs = 1700000000000;
        alarms.add(a);
        alarms.add(makeEvent(EventSeverity::Info, EventKind::TextMessage, QStringLiteral("osyris:3"),
                             QStringLiteral("paver ready")));
        AlarmFilterProxy proxy;
        proxy.setSourceModel(&alarms);
        QCOMPARE(proxy.rowCount(), 2);
        proxy.setMinimumSeverity(EventSeverity::Warning);
        QCOMPARE(proxy.rowCount(), 1);
        proxy.setMinimumSeverity(EventSeverity::Info);
        proxy.setText(QStringLiteral("paver"));
        QCOMPARE(proxy.rowCount(), 1);
        proxy.setText(QString());
        proxy.setUnacknowledgedOnly(true);
        QCOMPARE(proxy.rowCount(), 1);

        QBuffer buf;
        buf.open(QIODevice::WriteOnly);
        QVERIFY(alarms.exportCsv(&buf));
        const QList<QByteArray> lines = buf.data().split('\n');
        QCOMPARE(lines[0].trimmed(), QByteArray("time,severity,kind,machine,source,text,acknowledged"));
        QCOMPARE(lines[1].trimmed(), QByteArray("2023-11-14T22:13:20.000Z,alarm,control_lost,jaus:101,,"
                                                "\"control lost, \"\"timeout\"\", retry\",no"));
        QVERIFY(lines[2].startsWith(QByteArray()));
        QVERIFY(lines[2].contains(",info,text_message,osyris:3,,paver ready,n/a"));
    }
};

QTEST_GUILESS_MAIN(TestStopAlarms)
#include "test_command_gate.moc"
