// Signing in at a shared console, switching operator with JAUS control kept or released, lock and unlock,
// STOP ALL on a locked console: against a throwaway PAM service folder.
#include "models/AlarmModel.h"
#include "models/CommandGate.h"
#include "models/FleetModel.h"
#include "models/OperatorSession.h"
#include "models/testing/CommandWait.h"
#include "models/testing/FakeFleetBridge.h"
#include "protocols/site/PamAuthenticator.h"
#include "tests/support/ThrowawayPam.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QSignalSpy>
#include <QTest>

#include <memory>

using namespace ocu;
using ocu::testing::gateResult;
using R = OperatorRole;

namespace {
MachineState controlled(const QString& id) {
    MachineState m;
    m.id = id;
    m.protocol = protocolOfId(id);
    m.link = LinkState::Up;
    m.control = ControlState::ControlledByMe;
    return m;
}

struct Console {
    testing::ThrowawayPam pam{{{QStringLiteral("alice"), QStringLiteral("a-pass")},
                               {QStringLiteral("bob"), QStringLiteral("b-pass")},
                               {QStringLiteral("carol"), QStringLiteral("c-pass")}}};
    PamAuthenticator auth{"ocu", pam.confDir().toStdString()};
    FleetModel fleet;
    AlarmModel alarms;
    CommandGate gate{&alarms};
    FakeFleetBridge ugv{Protocol::Jaus};
    QStringList audit;
    std::unique_ptr<OperatorSession> session;
    Console() {
        fleet.setRefreshIntervalMs(0);
        fleet.addBridge(&ugv);
        gate.addBridge(&ugv);
        ugv.simulateMachines = false;
        ugv.setMachine(controlled(QStringLiteral("jaus:1")));
        const QVector<R> ugvRoles{R::UgvOperator, R::Supervisor, R::Admin};
        for (const char* name : {"request_control", "release_control"})
            gate.permissions().allow(QLatin1String(name), ugvRoles);
        QObject::connect(&gate, &CommandGate::audited, [this](const QString& l) { audit << l; });
        session = std::make_unique<OperatorSession>(
            &gate, &fleet, &alarms,
            [this](const QString& u, const QString& p) {
                return QString::fromStdString(auth.authenticate(u.toStdString(), p.toStdString()));
            },
            [](const QString& user) {
                const R role = user == QLatin1String("alice") ? R::UgvOperator
                               : user == QLatin1String("bob") ? R::Dispatcher
                                                              : R::Supervisor;
                return OperatorIdentity{user, role, QStringLiteral("ocu-3")};
            });
        session->setOperator({QStringLiteral("alice"), R::UgvOperator, QStringLiteral("ocu-3")});
        QCoreApplication::processEvents();
    }
};
} // namespace

class TestOperatorSession : public QObject {
    Q_OBJECT
private slots:
    void signInAndWrongPassword() {
        Console c;
        QSignalSpy changed(c.session.get(), &OperatorSession::operatorChanged);
        QString why;
        QCOMPARE(c.session->switchTo(QStringLiteral("carol"), QStringLiteral("nope"), {}, &why),
                 OperatorSession::Switch::WrongPassword);
        QCOMPARE(why, QStringLiteral("wrong user name or password"));
        QCOMPARE(c.session->current().user, QStringLiteral("alice"));
        QCOMPARE(changed.count(), 0);
        QCOMPARE(c.session->switchTo(QStringLiteral("carol"), QStringLiteral("c-pass"), {}, &why),
                 OperatorSession::Switch::Switched);
        QCOMPARE(c.session->current().user, QStringLiteral("carol"));
        QCOMPARE(c.session->current().role, R::Supervisor);
        QCOMPARE(c.alarms.operatorName(), QStringLiteral("carol (supervisor) @ ocu-3"));
        QCOMPARE(changed.count(), 1);
    }

    // The next person's role may control: the console keeps control, nothing is sent, nobody is asked.
    void switchKeepsControl() {
        Console c;
        bool asked = false;
        QCOMPARE(c.session->switchTo(QStringLiteral("carol"), QStringLiteral("c-pass"),
                                     [&](const QStringList&) { return asked = true; }),
                 OperatorSession::Switch::Switched);
        QVERIFY(!asked);
        QVERIFY(c.ugv.calls().isEmpty());
        QVERIFY(c.gate.mayIssue(QStringLiteral("request_control")));
    }

    // The next person's role may not: asked first; cancelled keeps everything, confirmed releases control
    // as the previous operator, then switches.
    void switchReleasesControlAfterConfirmation() {
        Console c;
        QStringList askedFor;
        QCOMPARE(c.session->switchTo(QStringLiteral("bob"), QStringLiteral("b-pass"),
                                     [&](const QStringList& ids) {
                                         askedFor = ids;
                                         return false;
                                     }),
                 OperatorSession::Switch::Cancelled);
        QCOMPARE(askedFor, QStringList{QStringLiteral("jaus:1")});
        QCOMPARE(c.session->current().user, QStringLiteral("alice"));
        QVERIFY(c.ugv.calls().isEmpty());

        QCOMPARE(c.session->switchTo(QStringLiteral("bob"), QStringLiteral("b-pass"),
                                     [](const QStringList&) { return true; }),
                 OperatorSession::Switch::Switched);
        QTRY_COMPARE(c.ugv.calls().size(), 1);
        QCOMPARE(c.ugv.calls().first().name, QStringLiteral("release_control"));
        QCOMPARE(c.ugv.calls().first().id, QStringLiteral("jaus:1"));
        QTRY_VERIFY(!c.audit.isEmpty());
        const QJsonObject line = QJsonDocument::fromJson(c.audit.first().toUtf8()).object();
        QCOMPARE(line.value(QStringLiteral("operator")).toString(), QStringLiteral("alice"));
        QCOMPARE(line.value(QStringLiteral("role")).toString(), QStringLiteral("ugv_operator"));
        QCOMPARE(c.session->current().user, QStringLiteral("bob"));
        QVERIFY(!c.gate.mayIssue(QStringLiteral("request_control")));
    }

    // The release's result comes after the switch (a stack answers later): its audit still names the
    // operator who issued it.
    void releaseAnsweredAfterTheSwitchIsTheirs() {
        Console c;
        c.ugv.silent = true;
        c.gate.setAnswerDeadlineMs(200);
        QCOMPARE(c.session->switchTo(QStringLiteral("bob"), QStringLiteral("b-pass"),
                                     [](const QStringList&) { return true; }),
                 OperatorSession::Switch::Switched);
        QCOMPARE(c.session->current().user, QStringLiteral("bob"));
        const auto releases = [&c] {
            QStringList out;
            for (const QString& l : std::as_const(c.audit))
                if (l.contains(QLatin1String("\"release_control\"")))
                    out << l;
            return out;
        };
        QVERIFY(releases().isEmpty());
        QTRY_VERIFY(!releases().isEmpty());
        const QJsonObject line = QJsonDocument::fromJson(releases().first().toUtf8()).object();
        QCOMPARE(line.value(QStringLiteral("action")).toString(), QStringLiteral("release_control"));
        QCOMPARE(line.value(QStringLiteral("operator")).toString(), QStringLiteral("alice"));
    }

    // A person switching at a locked console: the previous operator's control is released (refused while
    // locked otherwise) and the console is theirs, unlocked.
    void switchAtLockedConsole() {
        Console c;
        c.session->lock();
        QCOMPARE(c.session->switchTo(QStringLiteral("bob"), QStringLiteral("b-pass"),
                                     [](const QStringList&) { return true; }),
                 OperatorSession::Switch::Switched);
        QTRY_COMPARE(c.ugv.calls().size(), 1);
        QCOMPARE(c.ugv.calls().first().name, QStringLiteral("release_control"));
        QVERIFY(!c.session->isLocked());
        QCOMPARE(c.session->current().user, QStringLiteral("bob"));
    }

    // Locked: only stops pass (STOP ALL reaches the bridge); the operator's own password unlocks.
    void lockAndUnlock() {
        Console c;
        QSignalSpy locked(c.session.get(), &OperatorSession::lockedChanged);
        c.session->lock();
        QVERIFY(c.session->isLocked());
        QCOMPARE(locked.count(), 1);
        const CommandResult refused = gateResult([&](auto h) {
            c.gate.command(RequestControl{QStringLiteral("jaus:1")}, QStringLiteral("gui"), h);
        });
        QVERIFY(!refused.ok);
        QVERIFY(c.ugv.calls().isEmpty());
        const CommandResult stop = gateResult([&](auto h) { c.gate.stopAll(QStringLiteral("gui"), h); });
        QVERIFY(stop.ok);
        QCOMPARE(c.ugv.calls().size(), 1);
        QString why;
        QVERIFY(!c.session->unlock(QStringLiteral("c-pass"), &why)); // carol's password is not alice's
        QVERIFY(c.session->isLocked());
        QVERIFY(c.session->unlock(QStringLiteral("a-pass"), &why));
        QVERIFY(!c.session->isLocked());
        QCOMPARE(locked.count(), 2);
        // Another person signs in at a locked console: unlocked, as them.
        c.session->lock();
        QCOMPARE(c.session->switchTo(QStringLiteral("carol"), QStringLiteral("c-pass"), {}),
                 OperatorSession::Switch::Switched);
        QVERIFY(!c.session->isLocked());
    }

    // Who signed in, out, locked and unlocked, refusals included, each an audit record with the person's
    // name; a wrong password is information in the event log, never an alarm.
    void sessionEventsAreAudited() {
        Console c;
        c.audit.clear();
        const int alarmsBefore = c.alarms.unacknowledgedCount();
        QCOMPARE(c.session->switchTo(QStringLiteral("carol"), QStringLiteral("nope"), {}),
                 OperatorSession::Switch::WrongPassword);
        QCOMPARE(c.session->switchTo(QStringLiteral("carol"), QStringLiteral("c-pass"), {}),
                 OperatorSession::Switch::Switched);
        c.session->lock();
        QVERIFY(!c.session->unlock(QStringLiteral("a-pass")));
        QVERIFY(c.session->unlock(QStringLiteral("c-pass")));
        QStringList seen;
        for (const QString& line : std::as_const(c.audit)) {
            const QJsonObject o = QJsonDocument::fromJson(line.toUtf8()).object();
            seen << QStringLiteral("%1 %2 %3 %4")
                        .arg(o.value(QStringLiteral("action")).toString(),
                             o.value(QStringLiteral("operator")).toString(),
                             o.value(QStringLiteral("role")).toString(),
                             o.value(QStringLiteral("ok")).toBool() ? QStringLiteral("ok")
                                                                    : QStringLiteral("refused"));
        }
        QCOMPARE(seen, (QStringList{QStringLiteral("sign_in carol supervisor refused"),
                                    QStringLiteral("sign_out alice ugv_operator ok"),
                                    QStringLiteral("sign_in carol supervisor ok"),
                                    QStringLiteral("lock carol supervisor ok"),
                                    QStringLiteral("unlock carol supervisor refused"),
                                    QStringLiteral("unlock carol supervisor ok")}));
        QCOMPARE(c.alarms.unacknowledgedCount(), alarmsBefore);
    }

    void locksWhenIdle() {
        Console c;
        c.session->setIdleLockMs(100);
        QTest::qWait(60);
        c.session->activity(); // activity restarts the count
        QTest::qWait(60);
        QVERIFY(!c.session->isLocked());
        QTRY_VERIFY_WITH_TIMEOUT(c.session->isLocked(), 2000);
    }
};

QTEST_MAIN(TestOperatorSession)
#include "test_operator_session.moc"
