// Who is where across the control room, against a throwaway PostgreSQL server: two consoles (an operator
// session, a command gate and a PgHistory each) publish their presence; the other console reads the sign-in,
// the lock and unlock, a switch of operator, a clean exit (the row is gone) and a console whose heartbeats
// stopped (its row goes stale: "not seen since"). Sign-in, sign-out, switch, lock and unlock are in the
// shared audit with the person and role.
#include "models/AlarmModel.h"
#include "models/CommandGate.h"
#include "models/ControlRoomModel.h"
#include "models/FleetModel.h"
#include "models/OperatorSession.h"
#include "models/history/PgHistory.h"
#include "tests/models/history/PgTestServer.h"

#include <QtTest>

#include <libpq-fe.h>

using namespace ocu;
using R = OperatorRole;

namespace {

OperatorIdentity identity(const QString& user, const QString& console) {
    const R role = user == QLatin1String("alice") ? R::UgvOperator
                   : user == QLatin1String("bob") ? R::Dispatcher
                                                  : R::Supervisor;
    return {user, role, console};
}

struct Console {
    FleetModel fleet;
    AlarmModel alarms;
    CommandGate gate{&alarms};
    std::unique_ptr<OperatorSession> session;
    std::unique_ptr<PgHistory> history;
    Console(const QString& name, const QString& user, const QStringList& addresses, const QString& conninfo,
            const QString& dir, int heartbeatMs) {
        // Every test person's password is their name with "-pass".
        session = std::make_unique<OperatorSession>(
            &gate, &fleet, &alarms,
            [](const QString& u, const QString& p) {
                return p == u + QStringLiteral("-pass") ? QString() : QStringLiteral("wrong password");
            },
            [name](const QString& u) { return identity(u, name); });
        session->setOperator(identity(user, name));
        PgHistoryConfig cfg{conninfo, name, dir + QLatin1Char('/') + name + QStringLiteral(".outbox"), 250};
        cfg.heartbeatMs = heartbeatMs;
        cfg.staleAfterMs = 1500;
        history = std::make_unique<PgHistory>(cfg);
        history->attach(&alarms);
        history->attachGate(&gate);
        history->attachSession(session.get(), addresses);
    }
};

std::optional<ConsolePresence> find(const QVector<ConsolePresence>& room, const QString& console) {
    for (const ConsolePresence& p : room)
        if (p.console == console)
            return p;
    return std::nullopt;
}

QString scalar(const QString& conninfo, const QString& sql) {
    PGconn* c = PQconnectdb(conninfo.toUtf8().constData());
    QString out;
    PGresult* r = PQexec(c, sql.toUtf8().constData());
    if (PQresultStatus(r) == PGRES_TUPLES_OK && PQntuples(r) == 1)
        out = QString::fromUtf8(PQgetvalue(r, 0, 0));
    else
        out = QStringLiteral("error: ") + QString::fromUtf8(PQerrorMessage(c));
    PQclear(r);
    PQfinish(c);
    return out;
}

} // namespace

class TestPgPresence : public QObject {
    Q_OBJECT
    ocu::testing::PgTestServer m_server;
    QTemporaryDir m_outboxes;

private slots:
    void initTestCase() {
        if (ocu::testing::PgTestServer::binDir().isEmpty())
            QSKIP(
                "no PostgreSQL server binaries (/usr/lib/postgresql/*/bin; scripts/install-deps.sh installs "
                "them)");
        const QString err = m_server.start();
        QVERIFY2(err.isEmpty(), qPrintable(err));
        QVERIFY(m_outboxes.isValid());
    }

    void theRoomFollowsSignInLockSwitchAndExit() {
        const QString info = m_server.conninfo();
        Console a(QStringLiteral("ugv-desk"), QStringLiteral("alice"), {QStringLiteral("jaus:3.1.1")}, info,
                  m_outboxes.path(), 300);
        auto b = std::make_unique<Console>(QStringLiteral("dispatch-desk"), QStringLiteral("bob"),
                                           QStringList{QStringLiteral("jaus:7.1.1")}, info, m_outboxes.path(),
                                           300);
        ControlRoomModel room;
        connect(a.history.get(), &PgHistory::roomChanged, &room, &ControlRoomModel::setRoom);
        const qint64 started = QDateTime::currentMSecsSinceEpoch();
        QVERIFY(a.history->start().isEmpty());
        QVERIFY(b->history->start().isEmpty());

        // Published: each console sees both, with operator, role, since and the controller addresses.
        QTRY_COMPARE_WITH_TIMEOUT(a.history->room().size(), 2, 30000);
        QTRY_COMPARE_WITH_TIMEOUT(b->history->room().size(), 2, 10000);
        auto bob = find(a.history->room(), QStringLiteral("dispatch-desk"));
        QVERIFY(bob);
        QCOMPARE(bob->operatorName, QStringLiteral("bob"));
        QCOMPARE(bob->role, QStringLiteral("dispatcher"));
        QVERIFY(!bob->locked);
        QVERIFY(!bob->stale);
        QCOMPARE(bob->controllerAddresses, QStringList{QStringLiteral("jaus:7.1.1")});
        QVERIFY(qAbs(bob->sinceMs - started) < 60000);
        QCOMPARE(find(b->history->room(), QStringLiteral("ugv-desk"))->operatorName, QStringLiteral("alice"));
        QCOMPARE(room.consoleControllingWith(QStringLiteral("jaus:7.1.1"))->operatorName,
                 QStringLiteral("bob"));

        // Lock and unlock at B reach A.
        b->session->lock();
        QTRY_VERIFY_WITH_TIMEOUT(find(a.history->room(), QStringLiteral("dispatch-desk"))->locked, 10000);
        QCOMPARE(ControlRoomModel::stateText(*find(a.history->room(), QStringLiteral("dispatch-desk"))),
                 QStringLiteral("locked"));
        QVERIFY(b->session->unlock(QStringLiteral("bob-pass")));
        QTRY_VERIFY_WITH_TIMEOUT(!find(a.history->room(), QStringLiteral("dispatch-desk"))->locked, 10000);

        // A switch of operator at B: the next person, their role, a new "since".
        const qint64 bobSince = find(a.history->room(), QStringLiteral("dispatch-desk"))->sinceMs;
        QVERIFY(QTest::qWaitFor([&] { return QDateTime::currentMSecsSinceEpoch() > bobSince + 5; }));
        QCOMPARE(b->session->switchTo(QStringLiteral("carol"), QStringLiteral("carol-pass"), {}),
                 OperatorSession::Switch::Switched);
        QTRY_COMPARE_WITH_TIMEOUT(find(a.history->room(), QStringLiteral("dispatch-desk"))->operatorName,
                                  QStringLiteral("carol"), 10000);
        const ConsolePresence carol = *find(a.history->room(), QStringLiteral("dispatch-desk"));
        QCOMPARE(carol.role, QStringLiteral("supervisor"));
        QVERIFY(carol.sinceMs > bobSince);
        QCOMPARE(carol.controllerAddresses, QStringList{QStringLiteral("jaus:7.1.1")});
        QCOMPARE(room.consoleControllingWith(QStringLiteral("jaus:7.1.1"))->operatorName,
                 QStringLiteral("carol"));

        // A clean exit leaves the room at once (no waiting for staleness).
        b->gate.auditSession(QStringLiteral("sign_out"), b->session->current(), true,
                             QStringLiteral("console closed"));
        b.reset();
        QTRY_COMPARE_WITH_TIMEOUT(a.history->room().size(), 1, 10000);
        QCOMPARE(a.history->room().first().console, QStringLiteral("ugv-desk"));
        QCOMPARE(scalar(info, QStringLiteral("SELECT count(*) FROM ocu_presence")), QStringLiteral("1"));
        QVERIFY(!room.consoleControllingWith(QStringLiteral("jaus:7.1.1")));

        // Every step of the person at B is in the shared audit with who and which role, the sign-out of
        // the exit included (sent at the exit, not at the next start).
        QTRY_COMPARE_WITH_TIMEOUT(
            scalar(info,
                   QStringLiteral("SELECT string_agg(details->>'action' || ' ' || (details->>'operator') "
                                  "|| ' ' || (details->>'role'), ', ' ORDER BY seq) FROM ocu_history "
                                  "WHERE console = 'dispatch-desk' AND kind = 'audit'")),
            QStringLiteral("lock bob dispatcher, unlock bob dispatcher, sign_out bob dispatcher, sign_in "
                           "carol supervisor, sign_out carol supervisor"),
            10000);
    }

    void aConsoleWhoseHeartbeatStopsGoesStale() {
        const QString info = m_server.conninfo();
        Console a(QStringLiteral("watcher"), QStringLiteral("alice"), {}, info, m_outboxes.path(), 300);
        // The other console publishes once and then beats no more within the test, as a console that
        // crashed or lost its network leaves its row.
        Console silent(QStringLiteral("crashed"), QStringLiteral("bob"), {QStringLiteral("jaus:9.1.1")}, info,
                       m_outboxes.path(), 3600 * 1000);
        QVERIFY(a.history->start().isEmpty());
        QVERIFY(silent.history->start().isEmpty());
        QTRY_VERIFY_WITH_TIMEOUT(find(a.history->room(), QStringLiteral("crashed")).has_value(), 30000);
        const auto fresh = find(a.history->room(), QStringLiteral("crashed"));
        QVERIFY(!fresh->stale);
        QVERIFY(!find(a.history->room(), QStringLiteral("watcher"))->stale);
        // Past the stale timeout (1.5 s here, 30 s by default): shown as not seen since its last heartbeat.
        QTRY_VERIFY_WITH_TIMEOUT(find(a.history->room(), QStringLiteral("crashed"))->stale, 10000);
        const ConsolePresence stale = *find(a.history->room(), QStringLiteral("crashed"));
        QCOMPARE(stale.heartbeatMs, fresh->heartbeatMs);
        QVERIFY(ControlRoomModel::stateText(stale).startsWith(QStringLiteral("not seen since ")));
        QVERIFY(!find(a.history->room(), QStringLiteral("watcher"))->stale); // its own heartbeat goes on
        // The console comes back (a new presence, a fresh heartbeat): no longer stale.
        silent.session->lock();
        QTRY_VERIFY_WITH_TIMEOUT(!find(a.history->room(), QStringLiteral("crashed"))->stale, 10000);
        QVERIFY(find(a.history->room(), QStringLiteral("crashed"))->locked);
    }
};

QTEST_GUILESS_MAIN(TestPgPresence)
#include "test_pg_presence.moc"
