// The shared control-room history against a throwaway PostgreSQL server: two console cores
// (AlarmModel + PgHistory each); an acknowledgement and a shelving at one console reach the other through
// LISTEN/NOTIFY; the database stopped for OCU_PG_TEST_OUTAGE_S seconds (default 30) and restarted loses and
// duplicates nothing (rows counted per console against what each console recorded); a record sent twice
// (crash between COMMIT and the outbox delete) is stored once.
#include "models/AlarmModel.h"
#include "models/CommandGate.h"
#include "models/history/PgHistory.h"
#include "tests/models/history/PgTestServer.h"

#include <QElapsedTimer>
#include <QtTest>

#include <libpq-fe.h>
#include <sqlite3.h>

using namespace ocu;

namespace {

struct Console {
    AlarmModel alarms;
    std::unique_ptr<PgHistory> history;
    Console(const QString& name, const QString& conninfo, const QString& dir) {
        alarms.setOperatorName(name + QStringLiteral(" operator"));
        history = std::make_unique<PgHistory>(PgHistoryConfig{
            conninfo, name, dir + QStringLiteral("/") + name + QStringLiteral(".outbox"), 250});
        history->attach(&alarms);
    }
};

FleetEvent alarm(const QString& machine, const QString& text) {
    return makeEvent(EventSeverity::Alarm, EventKind::HealthFault, machine, text, QStringLiteral("jaus"));
}

// One value from the database (a separate connection, as a reporting tool would use).
QString scalar(const QString& conninfo, const QString& sql) {
    PGconn* c = PQconnectdb(conninfo.toUtf8().constData());
    QString out;
    if (PQstatus(c) == CONNECTION_OK) {
        PGresult* r = PQexec(c, sql.toUtf8().constData());
        if (PQresultStatus(r) == PGRES_TUPLES_OK && PQntuples(r) == 1)
            out = QString::fromUtf8(PQgetvalue(r, 0, 0));
        else
            out = QStringLiteral("error: ") + QString::fromUtf8(PQerrorMessage(c));
        PQclear(r);
    } else {
        out = QStringLiteral("error: ") + QString::fromUtf8(PQerrorMessage(c));
    }
    PQfinish(c);
    return out;
}

int outageSeconds() {
    bool ok = false;
    const int s = qEnvironmentVariableIntValue("OCU_PG_TEST_OUTAGE_S", &ok);
    return ok && s >= 0 ? s : 30;
}

} // namespace

class TestPgHistory : public QObject {
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

    void acknowledgementReachesTheOtherConsole() {
        Console a(QStringLiteral("dispatcher"), m_server.conninfo(), m_outboxes.path());
        Console b(QStringLiteral("site-manager"), m_server.conninfo(), m_outboxes.path());
        QVERIFY(a.history->start().isEmpty());
        QVERIFY(b.history->start().isEmpty());
        QTRY_VERIFY_WITH_TIMEOUT(a.history->isConnected() && b.history->isConnected(), 30000);
        // Both consoles see the same machine's fault: the same key on both.
        a.alarms.add(alarm(QStringLiteral("ugv-1"), QStringLiteral("motor overheat")));
        b.alarms.add(alarm(QStringLiteral("ugv-1"), QStringLiteral("motor overheat")));
        a.alarms.add(alarm(QStringLiteral("ugv-2"), QStringLiteral("battery low")));
        b.alarms.add(alarm(QStringLiteral("ugv-2"), QStringLiteral("battery low")));
        QCOMPARE(a.alarms.keyAt(0), b.alarms.keyAt(0));
        QSignalSpy remote(b.history.get(), &PgHistory::remoteAcknowledged);

        QElapsedTimer t;
        qint64 seenAfterMs = -1;
        connect(b.history.get(), &PgHistory::remoteAcknowledged, this, [&] { seenAfterMs = t.elapsed(); });
        t.start();
        a.alarms.acknowledge(0);
        QTRY_VERIFY_WITH_TIMEOUT(b.alarms.isAcknowledged(0), 10000);
        // The figure (the issue asks for < 1 s); not asserted on a loaded machine, printed for the report.
        qInfo("acknowledgement at console A applied at console B after %lld ms", seenAfterMs);
        QCOMPARE(b.alarms.acknowledgedByAt(0), QStringLiteral("dispatcher operator (dispatcher)"));
        QCOMPARE(remote.count(), 1);
        QVERIFY(!b.alarms.isAcknowledged(1));
        QCOMPARE(b.alarms.unacknowledgedCount(), 1);

        // Shelving travels the same way, with its expiry.
        t.restart();
        b.alarms.shelve(b.alarms.keyAt(1), 15 * 60 * 1000);
        QTRY_VERIFY_WITH_TIMEOUT(a.alarms.isShelved(1), 10000);
        qInfo("shelving at console B seen at console A after %lld ms", qint64(t.elapsed()));
        QCOMPARE(a.alarms.shelf(a.alarms.keyAt(1)).untilMs, b.alarms.shelf(b.alarms.keyAt(1)).untilMs);
        QCOMPARE(a.alarms.unacknowledgedCount(), 0);
        // No echo: the remote acknowledgement was not recorded again by B.
        QTRY_COMPARE_WITH_TIMEOUT(a.history->pendingCount() + b.history->pendingCount(), qint64(0), 10000);
        QCOMPARE(scalar(m_server.conninfo(),
                        QStringLiteral("SELECT count(*) FROM ocu_history WHERE kind = 'ack'")),
                 QStringLiteral("1"));
        QCOMPARE(scalar(m_server.conninfo(),
                        QStringLiteral("SELECT count(*) FROM ocu_history WHERE kind = 'shelve'")),
                 QStringLiteral("1"));

        // The command audit goes in whole (the gate's JSON line as jsonb), once.
        // It names the operator and role beside the console.
        CommandGate gate(&a.alarms);
        gate.setOperator({QStringLiteral("carol"), OperatorRole::Dispatcher, QStringLiteral("dispatcher")});
        a.history->attachGate(&gate);
        gate.stopMachine(QStringLiteral("no-such-machine"), QStringLiteral("test"));
        QTRY_COMPARE_WITH_TIMEOUT(
            scalar(m_server.conninfo(),
                   QStringLiteral(
                       "SELECT count(*) FROM ocu_history WHERE kind = 'audit' AND console = 'dispatcher' "
                       "AND details->>'action' = 'stop' AND details->>'target' = 'no-such-machine' AND "
                       "NOT (details->>'ok')::boolean AND details->>'operator' = 'carol' AND "
                       "details->>'role' = 'dispatcher'")),
            QStringLiteral("1"), 10000);
    }

    void outageLosesAndDuplicatesNothing() {
        const QString info = m_server.conninfo();
        const QString base = scalar(info, QStringLiteral("SELECT count(*) FROM ocu_history"));
        Console a(QStringLiteral("ugv-operator"), info, m_outboxes.path());
        Console b(QStringLiteral("planner"), info, m_outboxes.path());
        QVERIFY(a.history->start().isEmpty());
        QVERIFY(b.history->start().isEmpty());
        QTRY_VERIFY_WITH_TIMEOUT(a.history->isConnected() && b.history->isConnected(), 30000);
        for (int i = 0; i < 20; ++i) {
            a.alarms.add(alarm(QStringLiteral("m%1").arg(i), QStringLiteral("before")));
            b.alarms.add(alarm(QStringLiteral("m%1").arg(i), QStringLiteral("before")));
        }
        QTRY_COMPARE_WITH_TIMEOUT(a.history->pendingCount() + b.history->pendingCount(), qint64(0), 20000);

        QVERIFY(m_server.stopServer());
        QTRY_VERIFY_WITH_TIMEOUT(!a.history->isConnected() && !b.history->isConnected(), 20000);
        // The consoles keep working: alarms, acknowledgements, events go on while the database is away.
        for (int i = 0; i < 50; ++i) {
            a.alarms.add(makeEvent(EventSeverity::Info, EventKind::Info, {},
                                   QStringLiteral("during %1").arg(i), QStringLiteral("gui")));
            b.alarms.add(alarm(QStringLiteral("n%1").arg(i), QStringLiteral("during")));
        }
        a.alarms.acknowledge(3); // m3 at A, made during the outage: B learns it on the return
        const QString ackedKey = a.alarms.keyAt(3);
        QTRY_VERIFY_WITH_TIMEOUT(a.history->pendingCount() >= 51 && b.history->pendingCount() >= 50, 20000);
        QTest::qWait(outageSeconds() * 1000);
        QVERIFY(!a.history->isConnected());
        QCOMPARE(b.alarms.isAcknowledged(b.alarms.rowOfKey(ackedKey)), false);

        const QString err = m_server.startServer();
        QVERIFY2(err.isEmpty(), qPrintable(err));
        QTRY_VERIFY_WITH_TIMEOUT(a.history->isConnected() && b.history->isConnected(), 30000);
        QTRY_COMPARE_WITH_TIMEOUT(a.history->pendingCount() + b.history->pendingCount(), qint64(0), 30000);
        QTRY_VERIFY_WITH_TIMEOUT(b.alarms.isAcknowledged(b.alarms.rowOfKey(ackedKey)), 10000);

        // Every record once: per console exactly what it recorded, no key twice.
        QCOMPARE(
            scalar(info, QStringLiteral("SELECT count(*) FROM ocu_history WHERE console = 'ugv-operator'")),
            QString::number(a.history->recordedCount()));
        QCOMPARE(scalar(info, QStringLiteral("SELECT count(*) FROM ocu_history WHERE console = 'planner'")),
                 QString::number(b.history->recordedCount()));
        QCOMPARE(a.history->recordedCount(), qint64(20 + 50 + 1));
        QCOMPARE(b.history->recordedCount(), qint64(20 + 50));
        QCOMPARE(scalar(info, QStringLiteral("SELECT count(*) - count(DISTINCT (console, origin, seq)) FROM "
                                             "ocu_history")),
                 QStringLiteral("0"));
        QCOMPARE(scalar(info, QStringLiteral("SELECT count(*) FROM ocu_history")).toLongLong(),
                 base.toLongLong() + 20 + 50 + 1 + 20 + 50);
        // The order of a console's records is its sequence.
        QCOMPARE(
            scalar(info, QStringLiteral("SELECT count(*) FROM ocu_history WHERE console = 'ugv-operator' AND "
                                        "kind = 'event' AND text LIKE 'during %'")),
            QStringLiteral("50"));
    }

    void recordSentTwiceIsStoredOnce() {
        const QString info = m_server.conninfo();
        const QString outbox = m_outboxes.path() + QStringLiteral("/replay.outbox");
        {
            Console a(QStringLiteral("replay"), info, m_outboxes.path());
            QVERIFY(a.history->start().isEmpty());
            QTRY_VERIFY(a.history->isConnected());
            a.alarms.add(alarm(QStringLiteral("x"), QStringLiteral("once")));
            QTRY_COMPARE_WITH_TIMEOUT(a.history->pendingCount(), qint64(0), 10000);
        }
        QCOMPARE(scalar(info, QStringLiteral("SELECT count(*) FROM ocu_history WHERE console = 'replay'")),
                 QStringLiteral("1"));
        // As if the console died after COMMIT and before deleting the row from its outbox: put it back.
        sqlite3* db = nullptr;
        QCOMPARE(sqlite3_open(outbox.toUtf8().constData(), &db), SQLITE_OK);
        QCOMPARE(sqlite3_exec(
                     db,
                     "INSERT INTO outbox(seq, kind, at_ms, alarm_key, text) VALUES "
                     "((SELECT seq FROM sqlite_sequence WHERE name = 'outbox'), 'alarm', 0, 'k', 'again')",
                     nullptr, nullptr, nullptr),
                 SQLITE_OK);
        sqlite3_close(db);
        Console again(QStringLiteral("replay"), info, m_outboxes.path());
        QVERIFY(again.history->start().isEmpty());
        QCOMPARE(again.history->pendingCount(), qint64(1));
        QTRY_COMPARE_WITH_TIMEOUT(again.history->pendingCount(), qint64(0), 20000);
        QCOMPARE(scalar(info, QStringLiteral("SELECT count(*) FROM ocu_history WHERE console = 'replay'")),
                 QStringLiteral("1"));
        QCOMPARE(scalar(info, QStringLiteral("SELECT text FROM ocu_history WHERE console = 'replay'")),
                 QStringLiteral("once"));
    }

    void unreachableDatabaseKeepsTheConsoleWorking() {
        // A conninfo that cannot work: the console runs on its outbox and says so once.
        AlarmModel alarms;
        PgHistory h(PgHistoryConfig{
            QStringLiteral("host=%1/nonexistent port=1 user=ocu dbname=postgres").arg(m_outboxes.path()),
            QStringLiteral("offline"), m_outboxes.path() + QStringLiteral("/offline.outbox"), 200});
        h.attach(&alarms);
        QSignalSpy down(&h, &PgHistory::connectionChanged);
        QVERIFY(h.start().isEmpty());
        QTRY_VERIFY_WITH_TIMEOUT(down.count() >= 1, 10000);
        QCOMPARE(down.first()[0].toBool(), false);
        alarms.add(alarm(QStringLiteral("y"), QStringLiteral("kept")));
        QTRY_COMPARE_WITH_TIMEOUT(h.pendingCount(), qint64(1), 10000);
        QTest::qWait(1000);
        QCOMPARE(down.count(), 1); // retries are silent
        // A bad outbox path is a clear error at start.
        PgHistory bad(PgHistoryConfig{QStringLiteral("host=/nonexistent"), QStringLiteral("bad"),
                                      QStringLiteral("/nonexistent-dir/x.outbox"), 200});
        const QString err = bad.start();
        QVERIFY2(err.contains(QStringLiteral("outbox")), qPrintable(err));
    }
};

QTEST_GUILESS_MAIN(TestPgHistory)
#include "test_pg_history.moc"
