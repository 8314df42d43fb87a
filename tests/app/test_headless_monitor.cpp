// HeadlessMonitor: machine/link/event lines, per-machine rate limit, commands and their results.
#include "app/HeadlessMonitor.h"
#include "app/ProtocolModule.h"
#include "models/AlarmModel.h"
#include "models/CommandGate.h"
#include "models/FleetContext.h"
#include "models/FleetModel.h"
#include "models/testing/CommandWait.h"
#include "models/testing/FakeFleetBridge.h"

#include <QBuffer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSignalSpy>
#include <QTest>
#include <unistd.h>

using namespace ocu;

namespace {
MachineState machine(const QString& id, double e) {
    MachineState m;
    m.id = id;
    m.protocol = protocolOfId(id);
    m.name = QStringLiteral("M-") + id;
    m.link = LinkState::Up;
    m.hasPosition = true;
    m.e = e;
    m.lat = 48.1;
    m.lon = 11.5;
    m.stop = StopState::None;
    m.modeText = QStringLiteral("AUTONOMOUS");
    m.mode = ModeCategory::Autonomous;
    return m;
}

// A bridge with two links whose stacks counted rejects.
struct CountingBridge : FakeFleetBridge {
    using FakeFleetBridge::FakeFleetBridge;
    Counters first, second;
    QVector<LinkCounters> linkCounters() const override {
        return {LinkCounters::of(QStringLiteral("iso23725:ahs-1"), first),
                LinkCounters::of(QStringLiteral("iso23725:ahs-2"), second)};
    }
};

// A protocol module with one query and one gate command, registered as the real modules do.
class FakeModule final : public ProtocolModule {
public:
    QString displayName() const override { return QStringLiteral("FAKE"); }
    Protocol protocol() const override { return Protocol::Jaus; }
    QString start(const ModuleStart&) override { return {}; }
    void stop() override {}
    FleetBridge* bridge() const override { return nullptr; }
    void registerHeadless(HeadlessCommands& table) override {
        table.addLocal(QStringLiteral("fake_status"), [this](const QJsonObject& cmd) {
            ++queries;
            return QJsonObject{{QStringLiteral("ok"), true},
                               {QStringLiteral("message"), QStringLiteral("fine")},
                               {QStringLiteral("asked"), cmd.value(QStringLiteral("what"))}};
        });
        // km/h in, a typed one-second drive at m/s to the bridge; refused without a speed.
        table.addGateCommand(QStringLiteral("fake_move"), [](const QJsonObject& cmd) {
            HeadlessCommands::GateRequest r;
            if (!cmd.contains(QStringLiteral("kmh"))) {
                r.refusal = QStringLiteral("missing \"kmh\"");
                return r;
            }
            TimedDrive drive;
            drive.id = cmd.value(QStringLiteral("id")).toString();
            drive.linear = cmd.value(QStringLiteral("kmh")).toDouble() / 3.6;
            r.command = drive;
            r.echo[QStringLiteral("mps")] = drive.linear;
            return r;
        });
        // Without a prepare step the JSON is read as the operator command of that name.
        table.addGateCommand(QStringLiteral("request_control"));
    }
    int queries = 0;
};

struct Rig {
    FleetModel fleet;
    AlarmModel alarms;
    CommandGate stop{&alarms};
    HeadlessMonitor monitor{&fleet, &alarms, &stop};
    FakeFleetBridge jaus{Protocol::Jaus}, iso{Protocol::Iso23725}, osy{Protocol::Osyris};
    QBuffer out;
    qsizetype readPos = 0;

    Rig() {
        fleet.setRefreshIntervalMs(0);
        out.open(QIODevice::ReadWrite);
        monitor.setOutput(&out);
        for (FakeFleetBridge* b : {&jaus, &iso, &osy}) {
            fleet.addBridge(b);
            alarms.addBridge(b);
            stop.addBridge(b);
            monitor.addBridge(b);
        }
    }
    // Lines written since the last call.
    QList<QJsonObject> take() {
        QList<QJsonObject> lines;
        const QByteArray all = out.data().mid(readPos);
        readPos = out.data().size();
        for (const QByteArray& l : all.split('\n')) {
            if (l.trimmed().isEmpty())
                continue;
            QJsonParseError err{};
            const QJsonDocument d = QJsonDocument::fromJson(l, &err);
            if (err.error != QJsonParseError::NoError)
                qFatal("not JSON: %s", l.constData());
            lines.push_back(d.object());
        }
        return lines;
    }
    static QList<QJsonObject> ofType(const QList<QJsonObject>& lines, const QString& type) {
        QList<QJsonObject> r;
        for (const auto& o : lines)
            if (o.value(QStringLiteral("type")).toString() == type)
                r.push_back(o);
        return r;
    }
};
} // namespace

class TestHeadlessMonitor : public QObject {
    Q_OBJECT
private slots:
    void printsMachineLinesWithTheIssueFields() {
        Rig rig;
        rig.jaus.setMachine(machine(QStringLiteral("jaus:101"), 12.5));
        rig.iso.setMachine(machine(QStringLiteral("iso23725:HT1"), 3));
        QCoreApplication::processEvents();
        const auto machines = Rig::ofType(rig.take(), QStringLiteral("machine"));
        QCOMPARE(machines.size(), 2);
        const QJsonObject& o = machines[0];
        QCOMPARE(o.value(QStringLiteral("id")).toString(), QStringLiteral("jaus:101"));
        QCOMPARE(o.value(QStringLiteral("protocol")).toString(), QStringLiteral("jaus"));
        QCOMPARE(o.value(QStringLiteral("name")).toString(), QStringLiteral("M-jaus:101"));
        QCOMPARE(o.value(QStringLiteral("e")).toDouble(), 12.5);
        QCOMPARE(o.value(QStringLiteral("lat")).toDouble(), 48.1);
        QCOMPARE(o.value(QStringLiteral("state")).toString(), QStringLiteral("AUTONOMOUS"));
        QCOMPARE(o.value(QStringLiteral("stop")).toString(), QStringLiteral("none"));
        for (const char* key : {"lon", "n", "heading", "speed", "controller", "age_ms"})
            QVERIFY2(o.contains(QLatin1String(key)), key);
        QCOMPARE(machines[1].value(QStringLiteral("protocol")).toString(), QStringLiteral("iso23725"));
    }

    void rateLimitsRoutineChangesButNotStopChanges() {
        Rig rig;
        rig.monitor.setRateLimitMs(1000);
        MachineState m = machine(QStringLiteral("osyris:3"), 0);
        rig.osy.setMachine(m);
        QCoreApplication::processEvents();
        QCOMPARE(Rig::ofType(rig.take(), QStringLiteral("machine")).size(), 1);
        // 20 position updates at once: no line yet (rate limit), then one line with the latest value.
        for (int i = 1; i <= 20; ++i) {
            m.e = i;
            rig.osy.setMachine(m);
            QCoreApplication::processEvents();
        }
        QCOMPARE(Rig::ofType(rig.take(), QStringLiteral("machine")).size(), 0);
        QList<QJsonObject> late;
        QTRY_VERIFY_WITH_TIMEOUT(
            (late += Rig::ofType(rig.take(), QStringLiteral("machine")), !late.isEmpty()), 4000);
        QCOMPARE(late.size(), 1);
        QCOMPARE(late[0].value(QStringLiteral("e")).toDouble(), 20.0); // the latest value
        // The stop state change is printed at once.
        rig.readPos = rig.out.data().size();
        m.stop = StopState::Stopped;
        rig.osy.setMachine(m);
        QCoreApplication::processEvents();
        const auto lines = Rig::ofType(rig.take(), QStringLiteral("machine"));
        QCOMPARE(lines.size(), 1);
        QCOMPARE(lines[0].value(QStringLiteral("stop")).toString(), QStringLiteral("stopped"));
    }

    void latestValueIsPrintedAfterTheRateInterval() {
        Rig rig;
        rig.monitor.setRateLimitMs(200);
        MachineState m = machine(QStringLiteral("jaus:5"), 0);
        rig.jaus.setMachine(m);
        QCoreApplication::processEvents();
        rig.take();
        m.e = 77;
        rig.jaus.setMachine(m);
        QCoreApplication::processEvents();
        QList<QJsonObject> lines;
        QTRY_VERIFY_WITH_TIMEOUT(
            (lines += Rig::ofType(rig.take(), QStringLiteral("machine")), !lines.isEmpty()), 2000);
        QCOMPARE(lines.last().value(QStringLiteral("e")).toDouble(), 77.0);
    }

    void stopAllCommandReachesEveryBridgeAndMachinesReportIt() {
        Rig rig;
        rig.jaus.setMachine(machine(QStringLiteral("jaus:1"), 0));
        rig.iso.setMachine(machine(QStringLiteral("iso23725:A"), 0));
        rig.osy.setMachine(machine(QStringLiteral("osyris:2"), 0));
        QCoreApplication::processEvents();
        rig.take();
        const QByteArray res = rig.monitor.handleLine(R"({"cmd":"stop_all","req":17})");
        const QJsonObject r = QJsonDocument::fromJson(res).object();
        QCOMPARE(r.value(QStringLiteral("type")).toString(), QStringLiteral("result"));
        QCOMPARE(r.value(QStringLiteral("ok")).toBool(), true);
        QCOMPARE(r.value(QStringLiteral("req")).toInt(), 17);
        // One target per machine the fakes stopped, each sent.
        const QJsonArray targets = r.value(QStringLiteral("targets")).toArray();
        QCOMPARE(targets.size(), 3);
        for (const auto& t : targets)
            QVERIFY(t.toObject().value(QStringLiteral("sent")).toBool());
        for (FakeFleetBridge* b : {&rig.jaus, &rig.iso, &rig.osy})
            QCOMPARE(b->calls().size(), 1);
        QCoreApplication::processEvents();
        const auto all = rig.take();
        const auto machines = Rig::ofType(all, QStringLiteral("machine"));
        QCOMPARE(machines.size(), 3);
        for (const auto& o : machines)
            QCOMPARE(o.value(QStringLiteral("stop")).toString(), QStringLiteral("stopped"));
        // Audited: an event line with kind audit.
        const auto events = Rig::ofType(all, QStringLiteral("event"));
        QVERIFY(std::any_of(events.begin(), events.end(), [](const QJsonObject& e) {
            return e.value(QStringLiteral("kind")).toString() == QStringLiteral("audit");
        }));
    }

    void clearStopNeedsConfirmTrue() {
        Rig rig;
        rig.iso.setMachine(machine(QStringLiteral("iso23725:A"), 0));
        QCoreApplication::processEvents();
        QJsonObject r =
            QJsonDocument::fromJson(rig.monitor.handleLine(R"({"cmd":"clear_stop","id":"iso23725:A"})"))
                .object();
        QCOMPARE(r.value(QStringLiteral("ok")).toBool(), false);
        QVERIFY(r.value(QStringLiteral("message")).toString().contains(QStringLiteral("confirm")));
        QCOMPARE(rig.iso.calls().size(), 0);
        r = QJsonDocument::fromJson(
                rig.monitor.handleLine(R"({"cmd":"clear_stop","id":"iso23725:A","confirm":true})"))
                .object();
        QCOMPARE(r.value(QStringLiteral("ok")).toBool(), true);
        QCOMPARE(rig.iso.calls().size(), 1);
        QCOMPARE(rig.iso.calls()[0].name, QStringLiteral("clear_stop"));
    }

    void protocolCommandsAreRoutedAndRefusalsReported() {
        Rig rig;
        QJsonObject r =
            QJsonDocument::fromJson(
                rig.monitor.handleLine(
                    R"({"cmd":"drive","id":"jaus:101","mode":"velocity","linear":0.5,"angular":0.1,"duration":2})"))
                .object();
        QCOMPARE(r.value(QStringLiteral("ok")).toBool(), true);
        QCOMPARE(rig.jaus.calls().size(), 1);
        QCOMPARE(rig.jaus.calls()[0].name, QStringLiteral("drive"));
        QCOMPARE(rig.jaus.calls()[0].args.value(QStringLiteral("linear")).toDouble(), 0.5);
        QCOMPARE(rig.iso.calls().size(), 0);

        rig.jaus.refusedCommands = {QStringLiteral("request_control")};
        r = QJsonDocument::fromJson(rig.monitor.handleLine(R"({"cmd":"request_control","id":"jaus:101"})"))
                .object();
        QCOMPARE(r.value(QStringLiteral("ok")).toBool(), false);
        QVERIFY(
            r.value(QStringLiteral("message")).toString().contains(QStringLiteral("insufficient authority")));
        QCOMPARE(r.value(QStringLiteral("targets"))
                     .toArray()
                     .first()
                     .toObject()
                     .value(QStringLiteral("reason"))
                     .toString(),
                 QStringLiteral("insufficient authority"));

        r = QJsonDocument::fromJson(rig.monitor.handleLine(R"({"cmd":"request_control","id":"nope:1"})"))
                .object();
        QCOMPARE(r.value(QStringLiteral("ok")).toBool(), false);
        // Stack-wide commands name the protocol instead of a machine.
        r = QJsonDocument::fromJson(rig.monitor.handleLine(R"({"cmd":"release_all","protocol":"jaus"})"))
                .object();
        QCOMPARE(r.value(QStringLiteral("ok")).toBool(), true);
        QCOMPARE(rig.jaus.calls().last().name, QStringLiteral("release_all"));
        QCOMPARE(rig.iso.calls().size(), 0);
        r = QJsonDocument::fromJson(rig.monitor.handleLine(R"({"cmd":"fly"})")).object();
        QCOMPARE(r.value(QStringLiteral("ok")).toBool(), false);
        r = QJsonDocument::fromJson(rig.monitor.handleLine(R"({"cmd": "stop_all")")).object();
        QCOMPARE(r.value(QStringLiteral("ok")).toBool(), false);
        QVERIFY(r.value(QStringLiteral("message")).toString().startsWith(QStringLiteral("invalid JSON")));
    }

    void moduleRegisteredCommandsAndQueriesWorkThroughTheMonitor() {
        Rig rig;
        FakeModule module;
        module.registerHeadless(rig.monitor.commands());
        // The query: answered here, not through the gate, in the one result-line shape.
        QJsonObject r =
            QJsonDocument::fromJson(
                rig.monitor.handleLine(R"({"cmd":"fake_status","req":"a","what":"all","id":"jaus:7"})"))
                .object();
        QCOMPARE(module.queries, 1);
        QCOMPARE(r.value(QStringLiteral("type")).toString(), QStringLiteral("result"));
        QCOMPARE(r.value(QStringLiteral("cmd")).toString(), QStringLiteral("fake_status"));
        QCOMPARE(r.value(QStringLiteral("req")).toString(), QStringLiteral("a"));
        QCOMPARE(r.value(QStringLiteral("id")).toString(), QStringLiteral("jaus:7"));
        QCOMPARE(r.value(QStringLiteral("ok")).toBool(), true);
        QCOMPARE(r.value(QStringLiteral("asked")).toString(), QStringLiteral("all"));
        QCOMPARE(rig.jaus.calls().size(), 0);
        // The gate command: prepared, forwarded to the machine's bridge, audited, answered with its targets.
        QSignalSpy handled(&rig.monitor, &HeadlessMonitor::commandHandled);
        r = QJsonDocument::fromJson(
                rig.monitor.handleLine(R"({"command":"fake_move","id":"jaus:7","kmh":18,"req":2})"))
                .object();
        QCOMPARE(handled.size(), 1);
        QCOMPARE(r.value(QStringLiteral("cmd")).toString(), QStringLiteral("fake_move"));
        QCOMPARE(r.value(QStringLiteral("ok")).toBool(), true);
        QCOMPARE(r.value(QStringLiteral("req")).toInt(), 2);
        QCOMPARE(r.value(QStringLiteral("id")).toString(), QStringLiteral("jaus:7"));
        QCOMPARE(r.value(QStringLiteral("mps")).toDouble(), 5.0);
        QCOMPARE(r.value(QStringLiteral("targets")).toArray().size(), 1);
        QCOMPARE(rig.jaus.calls().size(), 1);
        QCOMPARE(rig.jaus.calls()[0].name, QStringLiteral("drive"));
        QCOMPARE(rig.jaus.calls()[0].args.value(QStringLiteral("linear")).toDouble(), 5.0);
        // Refused by its prepare step: nothing sent, the result says why.
        r = QJsonDocument::fromJson(rig.monitor.handleLine(R"({"cmd":"fake_move","id":"jaus:7"})")).object();
        QCOMPARE(r.value(QStringLiteral("ok")).toBool(), false);
        QCOMPARE(r.value(QStringLiteral("message")).toString(), QStringLiteral("missing \"kmh\""));
        QCOMPARE(rig.jaus.calls().size(), 1);
        // A gate command without a prepare step asks for the machine.
        QCOMPARE(rig.monitor.handleLine(R"({"cmd":"request_control"})"),
                 QByteArray("{\"cmd\":\"request_control\",\"message\":\"missing "
                            "\\\"id\\\"\",\"ok\":false,\"type\":\"result\"}"));
        QCOMPARE(rig.jaus.calls().size(), 1);
        // Another monitor has its own table: the module's commands are unknown there.
        Rig other;
        QCOMPARE(QJsonDocument::fromJson(other.monitor.handleLine(R"({"cmd":"fake_status"})"))
                     .object()
                     .value(QStringLiteral("message"))
                     .toString(),
                 QStringLiteral("unknown command fake_status"));
    }

    // The JAUS module's hand-off commands: typed, forwarded to the vehicle's bridge with their arguments, and
    // a malformed answer refused before anything is sent.
    void jausHandoffCommandsReachTheBridge() {
#if OCU_TEST_WITH_JAUS
        Rig rig;
        for (const auto& m : makeProtocolModules())
            if (m->aboutName().startsWith(QLatin1String("JAUS")))
                m->registerHeadless(rig.monitor.commands());
        QJsonObject r =
            QJsonDocument::fromJson(
                rig.monitor.handleLine(R"({"cmd":"handoff_request","id":"jaus:7","reason":"shift change"})"))
                .object();
        QVERIFY(r.value(QStringLiteral("ok")).toBool());
        QCOMPARE(rig.jaus.calls().size(), 1);
        QCOMPARE(rig.jaus.calls()[0].name, QStringLiteral("handoff_request"));
        QCOMPARE(rig.jaus.calls()[0].args.value(QStringLiteral("reason")).toString(),
                 QStringLiteral("shift change"));
        r = QJsonDocument::fromJson(
                rig.monitor.handleLine(
                    R"({"cmd":"handoff_answer","id":"jaus:7","request":3,"accept":false})"))
                .object();
        QVERIFY(r.value(QStringLiteral("ok")).toBool());
        QCOMPARE(rig.jaus.calls().size(), 2);
        QCOMPARE(rig.jaus.calls()[1].name, QStringLiteral("handoff_answer"));
        QCOMPARE(rig.jaus.calls()[1].args.value(QStringLiteral("request")).toInt(), 3);
        QCOMPARE(rig.jaus.calls()[1].args.value(QStringLiteral("accept")).toBool(), false);
        r = QJsonDocument::fromJson(
                rig.monitor.handleLine(R"({"cmd":"handoff_answer","id":"jaus:7","request":3})"))
                .object();
        QVERIFY(!r.value(QStringLiteral("ok")).toBool());
        QVERIFY(r.value(QStringLiteral("message")).toString().contains(QStringLiteral("\"accept\"")));
        QCOMPARE(rig.jaus.calls().size(), 2);
        // WAIT: the request stays with the holder's answer "wait".
        r = QJsonDocument::fromJson(
                rig.monitor.handleLine(R"({"cmd":"handoff_answer","id":"jaus:7","request":3,"wait":true})"))
                .object();
        QVERIFY(r.value(QStringLiteral("ok")).toBool());
        QCOMPARE(rig.jaus.calls().size(), 3);
        QCOMPARE(rig.jaus.calls()[2].args.value(QStringLiteral("wait")).toBool(), true);
#else
        QSKIP("built without JAUS");
#endif
    }

    void unknownCommandGivesTheSameErrorLineAsBefore() {
        Rig rig;
        const QByteArray expected =
            R"({"cmd":"fly","id":"nope:1","message":"unknown command fly","ok":false,"req":5,"type":"result"})";
        QCOMPARE(rig.monitor.handleLine(R"({"cmd":"fly","req":5,"id":"nope:1"})"), expected);
        QCOMPARE(rig.take().size(), 1);
        QCOMPARE(rig.monitor.handleLine(R"({"req":1})"),
                 QByteArray("{\"cmd\":\"\",\"message\":\"missing "
                            "\\\"cmd\\\"\",\"ok\":false,\"req\":1,\"type\":\"result\"}"));
        QCOMPARE(rig.monitor.handleLine("[1]"),
                 QByteArray(
                     R"({"cmd":"","message":"a command must be a JSON object","ok":false,"type":"result"})"));
    }

    void linkAndAlarmEventsArePrinted() {
        Rig rig;
        rig.iso.publishLink({QStringLiteral("ahs-1"), LinkState::Down, 9000, QStringLiteral("timeout")});
        QCoreApplication::processEvents();
        const auto lines = rig.take();
        const auto links = Rig::ofType(lines, QStringLiteral("link"));
        QCOMPARE(links.size(), 1);
        QCOMPARE(links[0].value(QStringLiteral("protocol")).toString(), QStringLiteral("iso23725"));
        QCOMPARE(links[0].value(QStringLiteral("state")).toString(), QStringLiteral("down"));
        const auto events = Rig::ofType(lines, QStringLiteral("event"));
        QCOMPARE(events.size(), 1);
        QCOMPARE(events[0].value(QStringLiteral("kind")).toString(), QStringLiteral("link_loss"));
    }

    void countersCommandAnswersRejectsPerLinkAndReason() {
        Rig rig;
        CountingBridge extra(Protocol::Iso23725);
        rig.monitor.addBridge(&extra);
        extra.first.add("rx.rejected.invalid_json", 3);
        extra.first.add("rx.unknown_member");
        extra.first.add("rx.frames", 10);
        extra.second.add("rx.frames", 5);
        rig.take();
        const QByteArray line = rig.monitor.handleLine(R"({"cmd":"counters","req":7})");
        QVERIFY(!line.isEmpty());
        const auto lines = rig.take();
        QCOMPARE(lines.size(), 1); // one line answers it all
        const QJsonObject r = lines[0];
        QCOMPARE(QJsonDocument(r).toJson(QJsonDocument::Compact), line);
        QCOMPARE(r.value(QStringLiteral("type")).toString(), QStringLiteral("result"));
        QCOMPARE(r.value(QStringLiteral("cmd")).toString(), QStringLiteral("counters"));
        QCOMPARE(r.value(QStringLiteral("req")).toInt(), 7);
        QVERIFY(r.value(QStringLiteral("ok")).toBool());
        const QJsonArray links = r.value(QStringLiteral("links")).toArray();
        QCOMPARE(links.size(), 2); // the fake bridges without a stack have no links to count
        const QJsonObject a = links[0].toObject();
        QCOMPARE(a.value(QStringLiteral("protocol")).toString(), QStringLiteral("iso23725"));
        QCOMPARE(a.value(QStringLiteral("link")).toString(), QStringLiteral("iso23725:ahs-1"));
        QCOMPARE(a.value(QStringLiteral("rejected_total")).toInt(), 4);
        const QJsonObject rej = a.value(QStringLiteral("rejected")).toObject();
        QCOMPARE(rej.size(), 2);
        QCOMPARE(rej.value(QStringLiteral("rejected.invalid_json")).toInt(), 3);
        QCOMPARE(rej.value(QStringLiteral("unknown_member")).toInt(), 1);
        QCOMPARE(a.value(QStringLiteral("counters")).toObject().value(QStringLiteral("rx.frames")).toInt(),
                 10);
        const QJsonObject b = links[1].toObject();
        QCOMPARE(b.value(QStringLiteral("link")).toString(), QStringLiteral("iso23725:ahs-2"));
        QCOMPARE(b.value(QStringLiteral("rejected_total")).toInt(), 0);
        QVERIFY(b.value(QStringLiteral("rejected")).toObject().isEmpty());
        // The counts are live: a later reject shows in the next answer.
        extra.second.add("rx.rejected.header");
        const QJsonObject again =
            QJsonDocument::fromJson(rig.monitor.handleLine(R"({"cmd":"counters"})")).object();
        QCOMPARE(again.value(QStringLiteral("links"))
                     .toArray()[1]
                     .toObject()
                     .value(QStringLiteral("rejected_total"))
                     .toInt(),
                 1);
    }

    void fleetContextWiresBridgesToEverything() {
        FleetContext ctx;
        ctx.fleet()->setRefreshIntervalMs(0);
        QBuffer out;
        out.open(QIODevice::ReadWrite);
        FakeFleetBridge early(Protocol::Jaus), late(Protocol::Osyris);
        ctx.addBridge(&early);
        HeadlessMonitor::attach(&ctx, &out);
        ctx.addBridge(&late);
        ctx.addBridge(&late); // idempotent
        QCOMPARE(ctx.bridges().size(), 2);
        early.setMachine(machine(QStringLiteral("jaus:1"), 1));
        late.setMachine(machine(QStringLiteral("osyris:1"), 2));
        late.publishLink({QStringLiteral("osyris"), LinkState::Down, 5000, {}});
        QCoreApplication::processEvents();
        QCOMPARE(ctx.fleet()->rowCount(), 2);
        QCOMPARE(ctx.alarms()->unacknowledgedCount(), 1); // link loss
        QVERIFY(ocu::testing::gateResult([&](auto h) { ctx.gate()->stopAll(QStringLiteral("gui"), h); }).ok);
        QCOMPARE(early.calls().size(), 1);
        QCOMPARE(late.calls().size(), 1);
        const QByteArray text = out.data();
        QVERIFY(text.contains("\"id\":\"jaus:1\""));
        QVERIFY(text.contains("\"type\":\"link\""));
        QCOMPARE(text.count("\"type\":\"link\""), 1);
    }

    void readsCommandsFromStdin() {
        int fds[2];
        QCOMPARE(::pipe(fds), 0);
        const int savedStdin = ::dup(STDIN_FILENO);
        QVERIFY(::dup2(fds[0], STDIN_FILENO) >= 0);
        ::close(fds[0]);
        {
            Rig rig;
            QVERIFY(rig.monitor.startStdin());
            QSignalSpy finished(&rig.monitor, &HeadlessMonitor::inputFinished);
            const QByteArray input =
                "{\"cmd\":\"stop\",\"id\":\"osyris:4\",\"req\":1}\n{\"cmd\":\"list\",\"req\":2}";
            QCOMPARE(::write(fds[1], input.constData(), size_t(input.size())), ssize_t(input.size()));
            ::close(fds[1]); // EOF: the unterminated last line is still executed
            QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 5000);
            const auto results = Rig::ofType(rig.take(), QStringLiteral("result"));
            QCOMPARE(results.size(), 2);
            QCOMPARE(results[0].value(QStringLiteral("req")).toInt(), 1);
            QCOMPARE(results[0].value(QStringLiteral("ok")).toBool(), true);
            QCOMPARE(results[1].value(QStringLiteral("req")).toInt(), 2);
            QCOMPARE(rig.osy.calls().size(), 1);
        }
        ::dup2(savedStdin, STDIN_FILENO);
        ::close(savedStdin);
    }
};

QTEST_GUILESS_MAIN(TestHeadlessMonitor)
#include "test_headless_monitor.moc"
