// Typed operator commands: every command survives its JSON (parse -> toJson -> parse), malformed and unknown
// commands say what is wrong, a bridge refuses what it does not support as NotSupported, and the outcome
// collector calls `done` exactly once with the outcomes of every thread.
#include "models/CommandGate.h"
#include "models/FleetBridge.h"
#include "models/commands/OperatorCommand.h"
#include "models/testing/CommandWait.h"
#include "protocols/common/OutcomeCollector.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QtTest>

#include <atomic>
#include <thread>

using namespace ocu;

namespace {

QJsonObject json(const char* text) {
    return QJsonDocument::fromJson(QByteArray(text)).object();
}

// A bridge that implements only the base class's command(): it must refuse every command.
class BareBridge : public FleetBridge {
public:
    using FleetBridge::FleetBridge;
    void stopAll(OutcomeCallback done) override { done({}); }
    void stopMachine(const QString&, OutcomeCallback done) override { done({}); }
    void clearStop(const QString&, OutcomeCallback done) override { done({}); }
};

} // namespace

class TestOperatorCommand : public QObject {
    Q_OBJECT
private slots:
    void roundTrip_data() {
        QTest::addColumn<QString>("line");
        QTest::newRow("stop_all") << R"({"cmd":"stop_all"})";
        QTest::newRow("stop") << R"({"cmd":"stop","id":"jaus:126"})";
        QTest::newRow("clear_stop") << R"({"cmd":"clear_stop","id":"iso23725:A","confirm":true})";
        QTest::newRow("request_control") << R"({"cmd":"request_control","id":"jaus:126"})";
        QTest::newRow("release_control") << R"({"cmd":"release_control","id":"jaus:126"})";
        QTest::newRow("release_all") << R"({"cmd":"release_all","protocol":"jaus"})";
        QTest::newRow("resume") << R"({"cmd":"resume","id":"jaus:126"})";
        QTest::newRow("standby") << R"({"cmd":"standby","id":"jaus:126"})";
        QTest::newRow("shutdown") << R"({"cmd":"shutdown","id":"jaus:126"})";
        QTest::newRow("reset") << R"({"cmd":"reset","id":"jaus:126"})";
        QTest::newRow("drive_start") << R"({"cmd":"drive_start","id":"jaus:126","reason":"teleop input"})";
        QTest::newRow("drive_stop") << R"({"cmd":"drive_stop","id":"jaus:126","reason":"keys released"})";
        QTest::newRow("drive")
            << R"({"cmd":"drive","id":"jaus:101","mode":"effort","linear":40,"angular":-5,)"
               R"("duration":2.5})";
        QTest::newRow("all_stop_apply") << R"({"cmd":"all_stop_apply","link":"ahs"})";
        QTest::newRow("all_stop_remove") << R"({"cmd":"all_stop_remove","id":"iso23725:A"})";
        QTest::newRow("fetch_map") << R"({"cmd":"fetch_map","link":"ahs"})";
        QTest::newRow("assign")
            << R"({"cmd":"assign","id":"iso23725:A","tasks":[{"task":"Load","destination":4201,)"
               R"("equipment":"shovel-1","spot":3,"route":[2001,2002],"assignment_id":"a-1"},)"
               R"({"task":"Offload","destination":4300}]})";
        QTest::newRow("assign shorthand")
            << R"({"cmd":"assign","id":"iso23725:A","task":"Park","destination":7})";
        QTest::newRow("reset_assignment") << R"({"cmd":"reset_assignment","id":"iso23725:A"})";
        QTest::newRow("send_text to one") << R"({"cmd":"send_text","id":"osyris:4","text":"lift 2 next"})";
        QTest::newRow("send_text to all") << R"({"cmd":"send_text","protocol":"osyris","text":"break"})";
        QTest::newRow("ping") << R"({"cmd":"ping","idx":7})";
        QTest::newRow("mission_upload")
            << R"({"cmd":"mission_upload","id":"jaus:126","global":false,"waypoints":[)"
               R"({"lat":48.1,"lon":11.5,"speed":1.5,"tolerance":2},{"lat":48.1001,"lon":11.5002,"speed":0,)"
               R"("tolerance":0}]})";
        QTest::newRow("mission_upload, driver chosen by the vehicle")
            << R"({"cmd":"mission_upload","id":"jaus:126","waypoints":[[48.1,11.5],[48.2,11.6]]})";
        QTest::newRow("mission_start") << R"({"cmd":"mission_start","id":"jaus:126","from_index":2})";
        QTest::newRow("mission_pause") << R"({"cmd":"mission_pause","id":"jaus:126"})";
        QTest::newRow("mission_resume") << R"({"cmd":"mission_resume","id":"jaus:126"})";
        QTest::newRow("mission_abort") << R"({"cmd":"mission_abort","id":"jaus:126"})";
        QTest::newRow("goto")
            << R"({"cmd":"goto","id":"jaus:126","lat":48.1,"lon":11.5,"speed":1,"tolerance":0.5})";
        QTest::newRow("platform_mode") << R"({"cmd":"platform_mode","id":"jaus:126","mode":"training"})";
        QTest::newRow("platform_mode, program mode")
            << R"({"cmd":"platform_mode","id":"jaus:126","mode":180})";
        QTest::newRow("platform_state") << R"({"cmd":"platform_state","id":"jaus:126","state":"emergency"})";
        QTest::newRow("lights")
            << R"({"cmd":"lights","id":"jaus:126","headlights":true,"left_turn_signal":false,"ir_light":true})";
        QTest::newRow("odometry read") << R"({"cmd":"odometry","id":"jaus:126"})";
        QTest::newRow("odometry reset") << R"({"cmd":"odometry","id":"jaus:126","reset_trip":true})";
        QTest::newRow("handoff_request")
            << R"({"cmd":"handoff_request","id":"jaus:126","reason":"shift change"})";
        QTest::newRow("handoff_request, withdrawn")
            << R"({"cmd":"handoff_request","id":"jaus:126","cancel":true})";
        QTest::newRow("handoff_answer")
            << R"({"cmd":"handoff_answer","id":"jaus:126","request":3,"accept":true})";
        QTest::newRow("handoff_answer, wait")
            << R"({"cmd":"handoff_answer","id":"jaus:126","request":3,"wait":true})";
    }
    // The platform commands' arguments: what reaches the bridge, and what is refused at the edge.
    void platformCommands() {
        auto parse = [](const char* line) {
            const QJsonObject in = json(line);
            return parseOperatorCommand(in.value(QStringLiteral("cmd")).toString(), in);
        };
        const ParsedCommand lights =
            parse(R"({"cmd":"lights","id":"jaus:1","headlights":true,"brake_lights":false})");
        QVERIFY(lights.command);
        const auto& l = std::get<SetLights>(*lights.command);
        QCOMPARE(l.mask, bitOf(JausLight::Headlights) | bitOf(JausLight::BrakeLights));
        QCOMPARE(l.on, bitOf(JausLight::Headlights));
        QCOMPARE(std::get<SetPlatformMode>(
                     *parse(R"({"cmd":"platform_mode","id":"jaus:1","mode":"maintenance"})").command)
                     .mode,
                 2);
        // Never the whole vehicle's visible-light source; at least one light; booleans only.
        QVERIFY(parse(R"({"cmd":"lights","id":"jaus:1","visible_light":true})").error.contains("§9.2.2"));
        QVERIFY(!parse(R"({"cmd":"lights","id":"jaus:1"})").command);
        QVERIFY(!parse(R"({"cmd":"lights","id":"jaus:1","headlights":1})").command);
        QVERIFY(!parse(R"({"cmd":"platform_mode","id":"jaus:1","mode":"racing"})").command);
        QVERIFY(!parse(R"({"cmd":"platform_mode","id":"jaus:1","mode":100})").command);
        QVERIFY(!parse(R"({"cmd":"platform_state","id":"jaus:1","state":"asleep"})").command);
        QVERIFY(!parse(R"({"cmd":"odometry","id":"jaus:1","reset_trip":"yes"})").command);
        const ParsedCommand noId = parse(R"({"cmd":"odometry"})");
        QVERIFY(!noId.command);
        QCOMPARE(noId.error, QStringLiteral("missing \"id\""));
    }
    void roundTrip() {
        QFETCH(QString, line);
        const QJsonObject in = json(line.toUtf8().constData());
        const QString name = in.value(QStringLiteral("cmd")).toString();
        const ParsedCommand first = parseOperatorCommand(name, in);
        QVERIFY2(first.command, qPrintable(first.error));
        QCOMPARE(commandName(*first.command), name);
        QVERIFY(isOperatorCommand(name));
        const QJsonObject out = toJson(*first.command);
        QCOMPARE(out.value(QStringLiteral("cmd")).toString(), name);
        const ParsedCommand second = parseOperatorCommand(name, out);
        QVERIFY2(second.command, qPrintable(second.error));
        QVERIFY2(*second.command == *first.command,
                 qPrintable(QString::fromUtf8(QJsonDocument(out).toJson(QJsonDocument::Compact))));
        QCOMPARE(toJson(*second.command), out);
    }

    void everyCommandHasItsName() {
        // One name per alternative of the variant, and each of them parses.
        const std::vector<OperatorCommand> all{StopAll{},
                                               StopMachine{QStringLiteral("a:1")},
                                               ClearStop{},
                                               RequestControl{},
                                               ReleaseControl{},
                                               ReleaseAll{},
                                               Management{},
                                               DriveStart{},
                                               DriveStop{},
                                               TimedDrive{},
                                               AllStopApply{},
                                               AllStopRemove{},
                                               FetchMap{},
                                               Assign{},
                                               ResetAssignment{},
                                               SendText{},
                                               PingStation{},
                                               MissionUpload{},
                                               MissionStart{},
                                               MissionPause{},
                                               MissionResume{},
                                               MissionAbort{},
                                               GoTo{},
                                               SetPlatformMode{},
                                               SetPlatformState{},
                                               SetLights{},
                                               Odometry{},
                                               HandoffRequest{},
                                               HandoffAnswer{}};
        QCOMPARE(all.size(), std::variant_size_v<OperatorCommand>);
        QSet<QString> names;
        for (const OperatorCommand& c : all) {
            names.insert(commandName(c));
            QVERIFY(isOperatorCommand(commandName(c)));
        }
        QCOMPARE(names.size(), int(all.size()));
    }

    void routes() {
        QVERIFY(commandRoute(StopAll{}).everyBridge);
        QCOMPARE(commandRoute(RequestControl{QStringLiteral("jaus:1")}).machine, QStringLiteral("jaus:1"));
        QCOMPARE(commandRoute(ReleaseAll{}).protocol, std::optional<Protocol>(Protocol::Jaus));
        QCOMPARE(commandRoute(SendText{{}, QStringLiteral("x")}).protocol,
                 std::optional<Protocol>(Protocol::Osyris));
        QCOMPARE(commandRoute(SendText{QStringLiteral("osyris:2"), QStringLiteral("x")}).machine,
                 QStringLiteral("osyris:2"));
        QCOMPARE(commandRoute(MissionUpload{QStringLiteral("jaus:7"), {}, {}}).machine,
                 QStringLiteral("jaus:7"));
        QCOMPARE(commandRoute(FetchMap{QStringLiteral("ahs"), {}}).protocol,
                 std::optional<Protocol>(Protocol::Iso23725));
    }

    void malformedAndUnknownCommandsSayWhy() {
        ParsedCommand p = parseOperatorCommand(QStringLiteral("fly"), json(R"({"cmd":"fly","id":"jaus:1"})"));
        QVERIFY(!p.command);
        QCOMPARE(p.error, QStringLiteral("unknown command fly"));
        QVERIFY(p.target.isEmpty());
        QVERIFY(!isOperatorCommand(QStringLiteral("fly")));

        p = parseOperatorCommand({}, QJsonObject{});
        QCOMPARE(p.error, QStringLiteral("missing \"cmd\""));

        p = parseOperatorCommand(QStringLiteral("request_control"), json(R"({"cmd":"request_control"})"));
        QVERIFY(!p.command);
        QCOMPARE(p.error, QStringLiteral("missing \"id\""));

        p = parseOperatorCommand(QStringLiteral("request_control"), json(R"({"id":126})"));
        QVERIFY(!p.command);
        QVERIFY2(p.error.contains(QStringLiteral("\"id\" must be a string")), qPrintable(p.error));

        p = parseOperatorCommand(QStringLiteral("drive"), json(R"({"id":"jaus:1","mode":"warp"})"));
        QVERIFY(!p.command);
        QVERIFY2(p.error.contains(QStringLiteral("\"velocity\" or \"effort\"")), qPrintable(p.error));
        QCOMPARE(p.target, QStringLiteral("jaus:1")); // audited against the machine it named

        p = parseOperatorCommand(QStringLiteral("drive"), json(R"({"id":"jaus:1","linear":"fast"})"));
        QVERIFY(!p.command);
        QVERIFY2(p.error.contains(QStringLiteral("\"linear\" must be a number")), qPrintable(p.error));

        p = parseOperatorCommand(QStringLiteral("assign"),
                                 json(R"({"id":"iso23725:A","task":"Load","destination":"north"})"));
        QVERIFY(!p.command);
        QVERIFY2(p.error.contains(QStringLiteral("\"destination\" must be a way id")), qPrintable(p.error));
        QCOMPARE(p.target, QStringLiteral("iso23725:A"));

        p = parseOperatorCommand(QStringLiteral("ping"), json(R"({"idx":300})"));
        QVERIFY(!p.command);
        QVERIFY2(p.error.contains(QStringLiteral("0-253")), qPrintable(p.error));

        p = parseOperatorCommand(QStringLiteral("mission_upload"), json(R"({"id":"jaus:1","waypoints":[]})"));
        QVERIFY(!p.command);
        QVERIFY2(p.error.contains(QStringLiteral("\"waypoints\"")), qPrintable(p.error));
        p = parseOperatorCommand(
            QStringLiteral("mission_upload"),
            json(R"({"id":"jaus:1","waypoints":[{"lat":48,"lon":11},{"lat":95,"lon":11}]})"));
        QVERIFY(!p.command);
        QVERIFY2(p.error.contains(QStringLiteral("waypoint 2")) && p.error.contains(QStringLiteral("±90")),
                 qPrintable(p.error));
        QCOMPARE(p.target, QStringLiteral("jaus:1"));
        p = parseOperatorCommand(QStringLiteral("goto"),
                                 json(R"({"id":"jaus:1","lat":48,"lon":11,"speed":-1})"));
        QVERIFY(!p.command);
        QVERIFY2(p.error.contains(QStringLiteral("\"speed\"")), qPrintable(p.error));
        p = parseOperatorCommand(QStringLiteral("mission_start"), json(R"({"id":"jaus:1","from_index":-1})"));
        QVERIFY(!p.command);

        p = parseOperatorCommand(QStringLiteral("handoff_answer"), json(R"({"id":"jaus:1","request":3})"));
        QVERIFY(!p.command);
        QVERIFY2(p.error.contains(QStringLiteral("\"accept\"")), qPrintable(p.error));
        p = parseOperatorCommand(QStringLiteral("handoff_answer"),
                                 json(R"({"id":"jaus:1","request":3,"wait":true})"));
        QVERIFY(p.command); // WAIT needs no "accept"
        QVERIFY(std::get<HandoffAnswer>(*p.command).wait && !std::get<HandoffAnswer>(*p.command).accept);
        p = parseOperatorCommand(QStringLiteral("handoff_answer"),
                                 json(R"({"id":"jaus:1","request":300,"accept":false})"));
        QVERIFY(!p.command);
        QVERIFY2(p.error.contains(QStringLiteral("\"request\"")), qPrintable(p.error));

        p = parseOperatorCommand(QStringLiteral("clear_stop"), json(R"({"id":"jaus:1","confirm":"yes"})"));
        QVERIFY(!p.command);
        QVERIFY2(p.error.contains(QStringLiteral("\"confirm\"")), qPrintable(p.error));
    }

    // The token of a release is never written out: it would let a reader of the audit log release a stop.
    void clearStopTokenStaysOutOfJson() {
        const QJsonObject o = toJson(ClearStop{QStringLiteral("jaus:1"), true, QStringLiteral("secret")});
        QVERIFY(!QJsonDocument(o).toJson().contains("secret"));
    }

    void defaultBridgeRefusesAsNotSupported() {
        BareBridge bridge(Protocol::Osyris);
        std::vector<TargetOutcome> got;
        int calls = 0;
        bridge.command(RequestControl{QStringLiteral("osyris:3")}, [&](std::vector<TargetOutcome> o) {
            ++calls;
            got = std::move(o);
        });
        QCOMPARE(calls, 1);
        QCOMPARE(got.size(), size_t(1));
        QVERIFY(!got[0].sent);
        QCOMPARE(got[0].cause, OutcomeReason::NotSupported);
        QCOMPARE(got[0].target, std::string("osyris:3"));
        QVERIFY(QString::fromStdString(got[0].reason).contains(QStringLiteral("request_control")));

        // Through the gate: the result is not ok, and the headless JSON names the cause.
        CommandGate gate;
        gate.addBridge(&bridge);
        const CommandResult r =
            testing::gateResult([&](auto h) { gate.command(PingStation{1}, QStringLiteral("test"), h); });
        QVERIFY(!r.ok);
        QCOMPARE(r.targets.size(), 1);
        QCOMPARE(r.targets[0].cause, OutcomeReason::NotSupported);
        QCOMPARE(targetsToJson(r.targets)[0].toObject().value(QStringLiteral("cause")).toString(),
                 QStringLiteral("not_supported"));
    }

    void gateAuditsTheTypedCommand() {
        BareBridge bridge(Protocol::Jaus);
        CommandGate gate;
        gate.addBridge(&bridge);
        QStringList lines;
        connect(&gate, &CommandGate::audited, this, [&](const QString& l) { lines << l; });
        TimedDrive d;
        d.id = QStringLiteral("jaus:5");
        d.linear = 0.5;
        (void)testing::gateResult([&](auto h) { gate.command(d, QStringLiteral("test"), h); });
        QCOMPARE(lines.size(), 1);
        const QJsonObject a = QJsonDocument::fromJson(lines[0].toUtf8()).object();
        QCOMPARE(a.value(QStringLiteral("action")).toString(), QStringLiteral("drive"));
        QCOMPARE(a.value(QStringLiteral("target")).toString(), QStringLiteral("jaus:5"));
        QCOMPARE(a.value(QStringLiteral("command")).toObject(), toJson(d));
    }

    void collectorCallsDoneOnceWithEveryThreadsOutcomes() {
        for (int round = 0; round < 200; ++round) {
            std::atomic<int> calls{0};
            std::vector<TargetOutcome> got;
            auto collector = OutcomeCollector::create(2, [&](std::vector<TargetOutcome> o) {
                ++calls;
                got = std::move(o);
            });
            OutcomeCallback a = collector->part(), b = collector->part();
            std::thread t1([a] { a({TargetOutcome::sentTo("one")}); });
            std::thread t2([b] {
                b({TargetOutcome::refused("two", OutcomeReason::LinkDown, "link down"),
                   TargetOutcome::sentTo("three")});
            });
            t1.join();
            t2.join();
            a({TargetOutcome::sentTo("again")});             // a part answering twice counts once
            collector->add({TargetOutcome::sentTo("late")}); // beyond the expected count: ignored
            QCOMPARE(calls.load(), 1);
            QCOMPARE(got.size(), size_t(3));
            std::vector<std::string> names;
            for (const auto& o : got)
                names.push_back(o.target);
            std::sort(names.begin(), names.end());
            QCOMPARE(names, (std::vector<std::string>{"one", "three", "two"}));
        }
        // Nothing expected: done at once, with no outcome.
        int calls = 0;
        auto none = OutcomeCollector::create(0, [&](std::vector<TargetOutcome> o) {
            ++calls;
            QVERIFY(o.empty());
        });
        QCOMPARE(calls, 1);
    }

    void outcomeCauses() {
        QCOMPARE(TargetOutcome::sentTo("x").cause, OutcomeReason::None);
        QCOMPARE(TargetOutcome("x", false, "why").cause, OutcomeReason::Refused);
        QCOMPARE(std::string(nameFor(OutcomeReason::LinkDown)), std::string("link_down"));
        QCOMPARE(std::string(nameFor(OutcomeReason::NotSupported)), std::string("not_supported"));
    }
};

QTEST_MAIN(TestOperatorCommand)
#include "test_operator_command.moc"
