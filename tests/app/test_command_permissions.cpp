// The permission table, command by command and role by role: what each role may issue through the gate as
// the panels call it and as headless JSON lines, that a refusal names the role needed and reaches no bridge,
// that STOP ALL and the stops pass for every role and on a locked console, and that every audit line names
// the operator, the role and the console.
#include "app/HeadlessCommands.h"
#include "app/ProtocolModule.h"
#include "models/AlarmModel.h"
#include "models/CommandGate.h"
#include "models/testing/CommandWait.h"
#include "models/testing/FakeFleetBridge.h"

#include <QDeadlineTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSet>
#include <QTest>

#include <map>

using namespace ocu;
using ocu::testing::gateResult;
using R = OperatorRole;

namespace {

MachineState machine(const QString& id) {
    MachineState m;
    m.id = id;
    m.protocol = protocolOfId(id);
    m.link = LinkState::Up;
    m.stop = StopState::None;
    return m;
}

// One sample of every command type, and the roles that may issue it (the specification, in docs/roles.md).
struct Row {
    OperatorCommand command;
    QSet<R> roles;
};

QSet<R> everyone() {
    return {kAllOperatorRoles.begin(), kAllOperatorRoles.end()};
}

std::vector<Row> specification() {
    const QString ugv = QStringLiteral("jaus:1"), truck = QStringLiteral("iso23725:1"),
                  station = QStringLiteral("osyris:1");
    const QSet<R> ugvRoles{R::UgvOperator, R::Supervisor, R::Admin};
    const QSet<R> dispatchRoles{R::Dispatcher, R::Supervisor, R::Admin};
    AssignTask task;
    task.task = QStringLiteral("Load");
    task.destinationId = 4201;
    return {
        {StopAll{}, everyone()},
        {StopMachine{truck}, everyone()},
        {ClearStop{truck, true, {}},
         {R::Dispatcher, R::SiteManager, R::UgvOperator, R::Supervisor, R::Admin}},
        {RequestControl{ugv}, ugvRoles},
        {ReleaseControl{ugv}, ugvRoles},
        {ReleaseAll{}, ugvRoles},
        {Management{ugv, ManagementAction::Resume}, ugvRoles},
        {Management{ugv, ManagementAction::Standby}, ugvRoles},
        {Management{ugv, ManagementAction::Reset}, ugvRoles},
        {Management{ugv, ManagementAction::Shutdown}, {R::Supervisor, R::Admin}},
        {DriveStart{ugv, {}}, ugvRoles},
        {DriveStop{ugv, QStringLiteral("test")}, everyone()},
        {TimedDrive{ugv, TimedDrive::Mode::Velocity, 0.5, 0, 1.0}, ugvRoles},
        {AllStopApply{{}, truck}, everyone()},
        {AllStopRemove{{}, truck}, dispatchRoles},
        {FetchMap{{}, truck}, everyone()},
        {Assign{truck, {task}}, dispatchRoles},
        {ResetAssignment{truck}, dispatchRoles},
        {SendText{station, QStringLiteral("rolled up to x=15 m")}, {R::SiteManager, R::Supervisor, R::Admin}},
        {PingStation{1}, everyone()},
        {MissionUpload{ugv, {MissionWaypoint{48.1, 11.5, 1.0, 0.5}}, std::nullopt}, ugvRoles},
        {MissionStart{ugv, 0}, ugvRoles},
        {MissionPause{ugv}, ugvRoles},
        {MissionResume{ugv}, ugvRoles},
        {MissionAbort{ugv}, ugvRoles},
        {GoTo{ugv, MissionWaypoint{48.1, 11.5, 1.0, 0.5}}, ugvRoles},
        {SetPlatformMode{ugv, 1}, ugvRoles},
        {SetPlatformState{ugv, 4}, ugvRoles},
        {SetLights{ugv, bitOf(JausLight::Headlights), bitOf(JausLight::Headlights)}, ugvRoles},
        {Odometry{ugv, true}, ugvRoles},
        {HandoffRequest{ugv, QStringLiteral("shift change"), false}, ugvRoles},
        {HandoffAnswer{ugv, 3, true}, ugvRoles},
    };
}

// A console of three fake protocol bridges, one machine each, with the modules' rows in its gate.
struct Console {
    AlarmModel alarms;
    CommandGate gate{&alarms};
    FakeFleetBridge jaus{Protocol::Jaus}, iso{Protocol::Iso23725}, osyris{Protocol::Osyris};
    QStringList audit;
    Console() {
        gate.setAnswerDeadlineMs(2000);
        for (FakeFleetBridge* b : {&jaus, &iso, &osyris}) {
            b->simulateMachines = false;
            gate.addBridge(b);
            b->setMachine(machine(protocolPrefix(b->protocol()) + QStringLiteral("1")));
        }
        for (const auto& m : makeProtocolModules())
            m->addPermissions(gate.permissions());
        QObject::connect(&gate, &CommandGate::audited, [this](const QString& line) { audit << line; });
        QCoreApplication::processEvents();
    }
    int calls() const { return int(jaus.calls().size() + iso.calls().size() + osyris.calls().size()); }
    void clearCalls() {
        for (FakeFleetBridge* b : {&jaus, &iso, &osyris})
            b->clearCalls();
        audit.clear();
    }
};

// The headless line of a command (the JSON parseOperatorCommand reads).
QJsonObject headlessLine(const OperatorCommand& command) {
    QJsonObject line = toJson(command);
    if (std::holds_alternative<ClearStop>(command))
        line[QStringLiteral("confirm")] = true;
    return line;
}

} // namespace

class TestCommandPermissions : public QObject {
    Q_OBJECT
private:
    // Checks one command by one role on one path; `issue` sends it and returns the final result.
    void check(Console& c, const Row& row, R role, const QString& path,
               const std::function<CommandResult()>& issue) {
        c.clearCalls();
        c.gate.setOperator({QStringLiteral("alice"), role, QStringLiteral("ocu-7")});
        const QString what =
            QStringLiteral("%1 by %2 (%3)").arg(commandName(row.command), roleDisplayName(role), path);
        const CommandResult r = issue();
        const bool allowed = row.roles.contains(role);
        QVERIFY2(r.ok == allowed, qPrintable(what + QStringLiteral(": ") + r.message));
        if (allowed) {
            QVERIFY2(c.calls() >= 1, qPrintable(what + QStringLiteral(" reached no bridge")));
        } else {
            QVERIFY2(c.calls() == 0, qPrintable(what + QStringLiteral(" reached a bridge")));
            QCOMPARE(r.targets.size(), 1);
            QCOMPARE(r.targets.first().cause, OutcomeReason::NotPermitted);
            const QString reason = QString::fromStdString(r.targets.first().reason);
            bool namesOne = false;
            for (R needed : row.roles)
                namesOne |= reason.contains(roleDisplayName(needed));
            QVERIFY2(namesOne, qPrintable(what + QStringLiteral(": ") + reason));
        }
        QVERIFY2(!c.audit.isEmpty(), qPrintable(what + QStringLiteral(" not audited")));
        const QJsonObject line = QJsonDocument::fromJson(c.audit.last().toUtf8()).object();
        QCOMPARE(line.value(QStringLiteral("operator")).toString(), QStringLiteral("alice"));
        QCOMPARE(line.value(QStringLiteral("role")).toString(), QString::fromLatin1(roleName(role).data()));
        QCOMPARE(line.value(QStringLiteral("console")).toString(), QStringLiteral("ocu-7"));
        QCOMPARE(line.value(QStringLiteral("action")).toString(), commandName(row.command));
    }

private slots:
    // The specification names every command type, and the table has a row for every one of them.
    void everyCommandTypeHasARow() {
        Console c;
        QSet<std::size_t> types;
        for (const Row& row : specification()) {
            types.insert(row.command.index());
            QVERIFY2(c.gate.permissions().hasRow(commandName(row.command)),
                     qPrintable(commandName(row.command)));
        }
        QCOMPARE(std::size_t(types.size()), std::variant_size_v<OperatorCommand>);
    }

    // The panels' path: CommandGate::command with the typed value.
    void guiPath() {
        Console c;
        for (const Row& row : specification())
            for (R role : kAllOperatorRoles)
                check(c, row, role, QStringLiteral("gui"), [&] {
                    OperatorCommand cmd = row.command;
                    if (auto* clear = std::get_if<ClearStop>(&cmd))
                        clear->token = c.gate.requestClearToken(clear->id); // the hold-to-confirm
                    return gateResult([&](auto h) { c.gate.command(cmd, QStringLiteral("gui"), h); });
                });
    }

    // The headless path: one JSON command line each, answered by its result line.
    void headlessPath() {
        Console c;
        for (const Row& row : specification())
            for (R role : kAllOperatorRoles)
                check(c, row, role, QStringLiteral("headless"), [&] {
                    std::optional<QJsonObject> result;
                    HeadlessCommands lines(
                        &c.gate, [&](const QByteArray& l) { result = QJsonDocument::fromJson(l).object(); });
                    lines.execute(headlessLine(row.command));
                    QDeadlineTimer deadline(5000);
                    while (!result && !deadline.hasExpired())
                        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
                    if (!result)
                        return CommandResult::failure(QStringLiteral("no result line"));
                    CommandResult r;
                    r.ok = result->value(QStringLiteral("ok")).toBool();
                    r.message = result->value(QStringLiteral("message")).toString();
                    const QJsonObject audited = QJsonDocument::fromJson(c.audit.last().toUtf8()).object();
                    for (const QJsonValue& t : audited.value(QStringLiteral("targets")).toArray()) {
                        TargetOutcome o;
                        o.sent = t.toObject().value(QStringLiteral("sent")).toBool();
                        o.cause = o.sent ? OutcomeReason::None : OutcomeReason::NotPermitted;
                        o.reason = t.toObject().value(QStringLiteral("reason")).toString().toStdString();
                        if (!o.sent && !r.message.contains(QString::fromStdString(o.reason)))
                            o.cause = OutcomeReason::Refused; // the line must say why
                        r.targets.push_back(o);
                    }
                    return r;
                });
    }

    // A locked console refuses everything but the stops, whatever the role; STOP ALL reaches every bridge.
    void lockedConsoleStopsOnly() {
        Console c;
        c.gate.setLocked(true);
        for (R role : kAllOperatorRoles) {
            c.gate.setOperator({QStringLiteral("bob"), role, QStringLiteral("ocu-7")});
            for (const Row& row : specification()) {
                c.clearCalls();
                OperatorCommand cmd = row.command;
                if (auto* clear = std::get_if<ClearStop>(&cmd))
                    clear->token = c.gate.requestClearToken(clear->id);
                const CommandResult r =
                    gateResult([&](auto h) { c.gate.command(cmd, QStringLiteral("gui"), h); });
                const bool stop = c.gate.permissions().isStop(commandName(cmd));
                QVERIFY2(r.ok == stop, qPrintable(commandName(cmd) + QStringLiteral(": ") + r.message));
                if (!stop) {
                    QCOMPARE(c.calls(), 0);
                    QVERIFY(
                        QString::fromStdString(r.targets.first().reason).contains(QStringLiteral("locked")));
                }
            }
            c.clearCalls();
            const CommandResult all = gateResult([&](auto h) { c.gate.stopAll(QStringLiteral("gui"), h); });
            QVERIFY(all.ok);
            for (FakeFleetBridge* b : {&c.jaus, &c.iso, &c.osyris}) {
                QCOMPARE(b->calls().size(), 1);
                QCOMPARE(b->calls().first().name, QStringLiteral("stop_all"));
            }
        }
    }

    // STOP ALL from a monitor on the headless path, and from a locked console's early stop path.
    void stopAllFromMonitor() {
        Console c;
        c.gate.setOperator({QStringLiteral("svc-ocu"), R::Monitor, QStringLiteral("ocu-7")});
        HeadlessCommands lines(&c.gate, {});
        c.gate.setLocked(true);
        const QByteArray line =
            lines.execute({{QStringLiteral("cmd"), QStringLiteral("stop_all")}}, c.gate.stopAllEarly());
        QTRY_COMPARE_WITH_TIMEOUT(c.calls(), 3, 5000);
        QTRY_VERIFY_WITH_TIMEOUT(!c.audit.isEmpty(), 5000);
        const QJsonObject audited = QJsonDocument::fromJson(c.audit.last().toUtf8()).object();
        QVERIFY(audited.value(QStringLiteral("ok")).toBool());
        QCOMPARE(audited.value(QStringLiteral("role")).toString(), QStringLiteral("monitor"));
        QCOMPARE(audited.value(QStringLiteral("operator")).toString(), QStringLiteral("svc-ocu"));
    }

    // The headless monitor's own actions (not machine commands) pass the same table and the lock: a refused
    // one does nothing; its queries answer every role.
    void headlessLocalActions() {
        Console c;
        int done = 0;
        HeadlessCommands lines(&c.gate, {});
        const auto answer = [&done](const QJsonObject&) {
            ++done;
            return QJsonObject{{QStringLiteral("ok"), true},
                               {QStringLiteral("message"), QStringLiteral("done")}};
        };
        lines.addLocal(QStringLiteral("auto_dispatch"), answer,
                       [](const QJsonObject& cmd) { return cmd.contains(QStringLiteral("on")); });
        for (const char* name : {"shift_report", "coverage_report"})
            lines.addLocal(QLatin1String(name), answer, HeadlessCommands::always);
        const QSet<R> dispatchRoles{R::Dispatcher, R::Supervisor, R::Admin};
        const struct {
            QJsonObject line;
            QSet<R> roles;
        } cases[] = {
            {{{QStringLiteral("cmd"), QStringLiteral("auto_dispatch")}, {QStringLiteral("on"), true}},
             dispatchRoles},
            {{{QStringLiteral("cmd"), QStringLiteral("auto_dispatch")}}, everyone()},
            {{{QStringLiteral("cmd"), QStringLiteral("shift_report")}},
             {R::Dispatcher, R::SiteManager, R::Supervisor, R::Admin}},
            {{{QStringLiteral("cmd"), QStringLiteral("coverage_report")}},
             {R::SiteManager, R::Supervisor, R::Admin}},
        };
        for (const auto& k : cases) {
            for (R role : kAllOperatorRoles) {
                c.gate.setOperator({QStringLiteral("bob"), role, QStringLiteral("ocu-7")});
                c.audit.clear();
                done = 0;
                const QJsonObject result = QJsonDocument::fromJson(lines.execute(k.line)).object();
                const bool allowed = k.roles.contains(role);
                const QString what = QString::fromUtf8(QJsonDocument(k.line).toJson(QJsonDocument::Compact)) +
                                     QLatin1Char(' ') + OperatorIdentity{{}, role, {}}.roleText();
                QVERIFY2(result.value(QStringLiteral("ok")).toBool() == allowed, qPrintable(what));
                QVERIFY2(done == (allowed ? 1 : 0), qPrintable(what));
                const bool acts =
                    k.line.contains(QStringLiteral("on")) ||
                    k.line.value(QStringLiteral("cmd")).toString() != QLatin1String("auto_dispatch");
                QCOMPARE(c.audit.size(), acts ? 1 : 0);
                if (acts)
                    QCOMPARE(QJsonDocument::fromJson(c.audit.first().toUtf8())
                                 .object()
                                 .value(QStringLiteral("ok"))
                                 .toBool(),
                             allowed);
            }
        }
        c.gate.setOperator({QStringLiteral("root"), R::Admin, QStringLiteral("ocu-7")});
        c.gate.setLocked(true);
        done = 0;
        QVERIFY(
            !QJsonDocument::fromJson(lines.execute({{QStringLiteral("cmd"), QStringLiteral("shift_report")}}))
                 .object()
                 .value(QStringLiteral("ok"))
                 .toBool());
        QCOMPARE(done, 0);
    }

    // No row can narrow a stop; a later row replaces an earlier one; the refusal text lists the roles.
    void tableRules() {
        CommandPermissions t;
        t.allow(QStringLiteral("stop_all"), {R::Admin});
        t.allow(QStringLiteral("stop"), {});
        for (R role : kAllOperatorRoles) {
            QVERIFY(t.permits(QStringLiteral("stop_all"), role));
            QVERIFY(t.permits(QStringLiteral("stop"), role));
        }
        t.allow(QStringLiteral("x"), {R::Admin});
        t.allow(QStringLiteral("x"), {R::Supervisor, R::Dispatcher});
        QVERIFY(!t.permits(QStringLiteral("x"), R::Admin));
        QCOMPARE(t.refusalText(QStringLiteral("x"), R::Monitor),
                 QStringLiteral("x needs the dispatcher or supervisor role (you are monitor)"));
        QVERIFY(t.refusalText(QStringLiteral("unknown"), R::Supervisor).contains(QStringLiteral("any role")));
        // No row: only an admin passes (a console without roles is run by an admin).
        Console c;
        c.gate.setOperator({QStringLiteral("a"), R::Supervisor, QStringLiteral("c")});
        QVERIFY(!c.gate.mayIssue(QStringLiteral("unknown")));
        c.gate.setOperator({QStringLiteral("a"), R::Admin, QStringLiteral("c")});
        QVERIFY(c.gate.mayIssue(QStringLiteral("unknown")));
        QCOMPARE((OperatorIdentity{QStringLiteral("a"), R::UgvOperator, QStringLiteral("c")}.byText()),
                 QStringLiteral("a (ugv_operator) @ c"));
    }
};

QTEST_MAIN(TestCommandPermissions)
#include "test_command_permissions.moc"
