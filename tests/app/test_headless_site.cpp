// `ocu --headless` on the built-in simulated site: machines of all three protocols
// are printed, and a stop_all line on stdin leads to the simulated machines reporting their stop (measured
// and printed; the goal is 2 s).
#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSet>
#include <QTemporaryDir>
#include <QtTest>

#include "tests/protocols/jaus/foreign/ForeignJausVehicle.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

namespace {
// A port nobody listens on, at or above `min` (bound once to pick it, then released).
int freePort(int type, int min = 1024) {
    for (int port = min + int(::getpid() % 5000);; ++port) {
        const int fd = ::socket(AF_INET, type, 0);
        sockaddr_in a{};
        a.sin_family = AF_INET;
        a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        a.sin_port = htons(std::uint16_t(port));
        const bool ok = ::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0;
        ::close(fd);
        if (ok)
            return port;
    }
}
} // namespace

class TestHeadlessSite : public QObject {
    Q_OBJECT

    QProcess m_p;
    QByteArray m_buffer;
    QVector<QJsonObject> m_lines;

    void pump(int ms) {
        QElapsedTimer t;
        t.start();
        while (t.elapsed() < ms) {
            m_p.waitForReadyRead(50);
            m_buffer += m_p.readAllStandardOutput();
            int nl;
            while ((nl = m_buffer.indexOf('\n')) >= 0) {
                const QByteArray line = m_buffer.left(nl);
                m_buffer.remove(0, nl + 1);
                QJsonParseError err;
                const QJsonDocument d = QJsonDocument::fromJson(line, &err);
                QVERIFY2(err.error == QJsonParseError::NoError && d.isObject(), line.constData());
                m_lines.push_back(d.object());
            }
        }
    }
    template <class Pred> bool waitFor(Pred pred, int ms) {
        QElapsedTimer t;
        t.start();
        while (t.elapsed() < ms) {
            if (pred())
                return true;
            pump(50);
        }
        return pred();
    }
    // The latest line per machine id.
    QHash<QString, QJsonObject> machines() const {
        QHash<QString, QJsonObject> out;
        for (const auto& o : m_lines)
            if (o.value("type") == "machine")
                out.insert(o.value("id").toString(), o);
        return out;
    }
    int machinesOf(const QString& protocol) const {
        int n = 0;
        for (const auto& o : machines())
            n += o.value("protocol") == protocol;
        return n;
    }
    QJsonObject result(int req) const {
        for (const auto& o : m_lines)
            if (o.value("type") == "result" && o.value("req").toInt() == req)
                return o;
        return {};
    }
    void send(const QByteArray& line) { m_p.write(line + "\n"); }

private slots:
    void initTestCase() {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove("DISPLAY");
        m_p.setProcessEnvironment(env);
        m_p.start(OCU_BINARY, {"--headless", "--duration", "60"});
        QVERIFY(m_p.waitForStarted(10000));
    }
    void machinesOfAllThreeProtocols() {
        QVERIFY2(waitFor(
                     [&] {
                         return machinesOf("jaus") >= 2 && machinesOf("iso23725") >= 6 &&
                                machinesOf("osyris") >= 3;
                     },
                     20000),
                 qPrintable(QString("jaus %1 iso %2 osyris %3")
                                .arg(machinesOf("jaus"))
                                .arg(machinesOf("iso23725"))
                                .arg(machinesOf("osyris"))));
        // Every machine line carries the documented fields.
        for (const auto& o : machines())
            for (const char* k : {"id", "protocol", "name", "lat", "lon", "e", "n", "heading", "speed",
                                  "state", "stop", "controller", "age_ms"})
                QVERIFY2(o.contains(k), qPrintable(o.value("id").toString() + " lacks " + k));
    }
    void clearStopNeedsConfirmation() {
        send(R"({"cmd":"clear_stop","id":"jaus:126","req":10})");
        QVERIFY(waitFor([&] { return !result(10).isEmpty(); }, 20000));
        QCOMPARE(result(10).value("ok").toBool(), false);
    }
    // "list" gives each UGV's mission beside its machine fields: state, active waypoint k of n, distance.
    void listShowsTheMissionOfEachUgv() {
        const QJsonObject ugv = machines().value("jaus:126");
        QVERIFY(!ugv.isEmpty());
        QJsonArray points;
        for (int i = 1; i <= 5; ++i)
            points << QJsonArray{ugv.value("lat").toDouble() + 0.00003 * i, ugv.value("lon").toDouble()};
        send(QJsonDocument(
                 QJsonObject{
                     {"cmd", "mission_upload"}, {"id", "jaus:126"}, {"req", 20}, {"waypoints", points}})
                 .toJson(QJsonDocument::Compact));
        QVERIFY(waitFor([&] { return !result(20).isEmpty(); }, 20000));
        QVERIFY2(result(20).value("ok").toBool(), QJsonDocument(result(20)).toJson().constData());
        auto listed = [&](int req) {
            m_lines.clear();
            send(QStringLiteral(R"({"cmd":"list","req":%1})").arg(req).toUtf8());
            waitFor([&] { return !result(req).isEmpty(); }, 10000);
            return machines();
        };
        auto missionOf = [&](const QHash<QString, QJsonObject>& m, const QString& id) {
            return m.value(id).value("mission").toObject();
        };
        QJsonObject mission;
        QVERIFY(waitFor(
            [&] {
                mission = missionOf(listed(21), "jaus:126");
                return mission.value("state") == "uploaded";
            },
            20000));
        QCOMPARE(mission.value("waypoints").toInt(), 5);
        send(R"({"cmd":"mission_start","id":"jaus:126","from_index":0,"req":22})");
        int req = 23;
        QVERIFY2(waitFor(
                     [&] {
                         mission = missionOf(listed(req++), "jaus:126");
                         return mission.value("state") == "running" && mission.contains("active_waypoint");
                     },
                     20000),
                 QJsonDocument(mission).toJson().constData());
        QCOMPARE(mission.value("waypoints").toInt(), 5);
        QVERIFY(mission.value("active_waypoint").toInt() >= 1 &&
                mission.value("active_waypoint").toInt() <= 5);
        QVERIFY(mission.contains("distance_to_go_m"));
        QVERIFY(mission.value("ours").toBool());
        // A UGV without a mission has no "mission" field.
        QVERIFY(missionOf(listed(req++), "jaus:127").isEmpty());
        send(R"({"cmd":"mission_abort","id":"jaus:126","req":90})");
        QVERIFY(waitFor([&] { return !result(90).isEmpty(); }, 20000));
    }
    // The platform services' commands reach the simulated UGV with results per target; the console's own
    // refusals name their reason.
    void platformCommandsPerTarget() {
        send(R"({"cmd":"lights","id":"jaus:126","headlights":true,"req":940})");
        send(R"({"cmd":"odometry","id":"jaus:126","req":941})");
        send(R"({"cmd":"platform_mode","id":"jaus:126","mode":"training","req":942})");
        send(R"({"cmd":"lights","id":"jaus:126","visible_light":true,"req":943})");
        QVERIFY(waitFor(
            [&] {
                return !result(940).isEmpty() && !result(941).isEmpty() && !result(942).isEmpty() &&
                       !result(943).isEmpty();
            },
            20000));
        for (int req : {940, 941, 942}) {
            const QJsonObject r = result(req);
            QVERIFY2(r.value("ok").toBool(), QJsonDocument(r).toJson().constData());
            const QJsonArray targets = r.value("targets").toArray();
            QCOMPARE(targets.size(), 1);
            QCOMPARE(targets[0].toObject().value("id").toString(), QStringLiteral("jaus:126"));
            QVERIFY(targets[0].toObject().value("sent").toBool());
        }
        // The read's note says what the vehicle last reported.
        QVERIFY2(QJsonDocument(result(941)).toJson().contains("odometer"),
                 QJsonDocument(result(941)).toJson().constData());
        QCOMPARE(result(943).value("ok").toBool(), false);
        QVERIFY2(QJsonDocument(result(943)).toJson().contains("9.2.2"),
                 QJsonDocument(result(943)).toJson().constData());
    }
    void stopAllStopsEveryMachineWithinTwoSeconds() {
        // STOP ALL reaches every discovered JAUS vehicle, controlled by this console or not, so
        // no control is taken here. Both vehicles must be known first.
        QVERIFY(waitFor(
            [&] {
                const auto m = machines();
                return m.value("jaus:126").value("link") == "up" && m.value("jaus:127").value("link") == "up";
            },
            20000));
        // ISO 23725 machines must be known (not UNKNOWN) before the stop, so the change is visible.
        QVERIFY(waitFor(
            [&] {
                for (const auto& o : machines())
                    if (o.value("protocol") == "iso23725" && o.value("stop") != "none")
                        return false;
                return true;
            },
            20000));
        const int before = m_lines.size();
        QElapsedTimer t;
        t.start();
        send(R"({"cmd":"stop_all","req":3})");
        auto stoppedAfter = [&](const QString& id) {
            for (int i = before; i < m_lines.size(); ++i)
                if (m_lines[i].value("type") == "machine" && m_lines[i].value("id") == id &&
                    m_lines[i].value("stop") == "stopped")
                    return true;
            return false;
        };
        QStringList targets;
        for (const auto& o : machines())
            if (o.value("protocol") != "osyris") // OSYRIS carries no stop: the machines are manned
                targets << o.value("id").toString();
        QVERIFY(targets.size() >= 8);
        // The 2 s stop target is a figure to report, not to assert (a busy CI machine must not fail
        // the suite on a scheduler delay): wait generously, print the measured time.
        QVERIFY2(waitFor([&] { return std::all_of(targets.begin(), targets.end(), stoppedAfter); }, 20000),
                 qPrintable(QString("not stopped after %1 ms").arg(t.elapsed())));
        qInfo("every JAUS and ISO 23725 machine reported its stop %lld ms after stop_all (goal: 2,000 ms)",
              t.elapsed());
        QVERIFY(waitFor([&] { return !result(3).isEmpty(); }, 20000));
        const QJsonObject r = result(3);
        QVERIFY2(r.value("ok").toBool(), QJsonDocument(r).toJson().constData());
        // The result names what went on the wire: both UGVs, the AHS link and the OSYRIS group, all sent.
        QSet<QString> ids;
        for (const auto& v : r.value("targets").toArray()) {
            QVERIFY(v.toObject().value("sent").toBool());
            ids.insert(v.toObject().value("id").toString());
        }
        QVERIFY2(ids.contains("jaus:126") && ids.contains("jaus:127"), QJsonDocument(r).toJson().constData());
        QVERIFY2(std::any_of(ids.begin(), ids.end(),
                             [](const QString& i) { return i.startsWith("iso23725 link "); }),
                 QJsonDocument(r).toJson().constData());
        QVERIFY2(std::any_of(ids.begin(), ids.end(),
                             [](const QString& i) { return i.startsWith("osyris group "); }),
                 QJsonDocument(r).toJson().constData());
        // Confirmation from the vehicles' own reports, with its latency.
        QVERIFY(waitFor(
            [&] {
                int n = 0;
                for (const auto& o : m_lines)
                    n += o.value("type") == "event" &&
                         o.value("text").toString().contains("reports EMERGENCY") &&
                         o.value("text").toString().contains("ms after the command");
                return n >= 2;
            },
            20000));
    }
    // Every link down -> "ok": false, one target per link, a reason each.
    // With every link down, stop_all answers ok:false with one target per machine /
    // link, each saying what happened. JAUS names every vehicle it knows: FOREIGN-126 (a foreign vehicle
    // heard, then out of range: SetEmergency still goes to its last address, sent, with a note that its
    // confirmation is pending) and subsystem 127 (a static endpoint never heard: sent to the configured
    // address, noted); the ISO 23725 link and the OSYRIS group are not sent, each with its reason.
    void stopAllWithEveryLinkDownSaysSoPerTarget() {
        QTemporaryDir dir;
        const int jausPort = freePort(SOCK_DGRAM, 40000), osyPort = freePort(SOCK_DGRAM, 50000),
                  ahsPort = freePort(SOCK_STREAM, 40000), silentPort = freePort(SOCK_DGRAM, 45000);
        foreign::VehicleOptions vo;
        vo.subsystem = 126;
        foreign::ForeignJausVehicle vehicle(vo);
        const QString cfg = dir.filePath("down.json");
        QFile f(cfg);
        QVERIFY(f.open(QIODevice::WriteOnly));
        const QJsonObject origin{{"latitude", -23.3601}, {"longitude", 119.7310}, {"altitude", 550}};
        const QJsonObject config{
            {"site", QJsonObject{{"name", "down"}, {"origin", origin}}},
            {"fleet", QJsonObject{{"audit_log", dir.filePath("audit.jsonl")}}},
            {"jaus", QJsonObject{{"subsystem_id", 150},
                                 {"call_sign", "OCU-DOWN"},
                                 {"role", "primary_operator"},
                                 {"authority", 205},
                                 {"port", 0},
                                 {"multicast_port", jausPort},
                                 {"multicast_group", "239.255.42.99"},
                                 {"interface_address", "127.0.0.1"},
                                 {"link_lost_s", 1.0},
                                 {"static_endpoints", QJsonArray{QJsonObject{{"subsystem", 126},
                                                                             {"address", "127.0.0.1"},
                                                                             {"port", int(vehicle.port())}},
                                                                 QJsonObject{{"subsystem", 127},
                                                                             {"address", "127.0.0.1"},
                                                                             {"port", silentPort}}}}}},
            {"iso23725",
             QJsonObject{{"links", QJsonArray{QJsonObject{
                                       {"name", "ahs"},
                                       {"url", QString("ws://127.0.0.1:%1/iso23725").arg(ahsPort)}}}}}},
            {"osyris", QJsonObject{{"group", "239.255.42.98"},
                                   {"port", osyPort},
                                   {"interface", "127.0.0.1"},
                                   {"sqliteFile", dir.filePath("osyris.sqlite")},
                                   {"originLat", -23.3601},
                                   {"originLon", 119.7310}}}};
        f.write(QJsonDocument(config).toJson());
        f.close();
        QProcess p;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove("DISPLAY");
        p.setProcessEnvironment(env);
        p.start(OCU_BINARY, {"--config", cfg, "--no-sim", "--headless", "--duration", "90"});
        QVERIFY(p.waitForStarted(10000));
        QByteArray buf;
        auto readUntil = [&](auto pred, int ms) {
            QElapsedTimer t;
            t.start();
            while (t.elapsed() < ms && p.state() == QProcess::Running) {
                p.waitForReadyRead(100);
                buf += p.readAllStandardOutput();
                int nl;
                while ((nl = buf.indexOf('\n')) >= 0) {
                    const QJsonObject o = QJsonDocument::fromJson(buf.left(nl)).object();
                    buf.remove(0, nl + 1);
                    if (pred(o))
                        return o;
                }
            }
            return QJsonObject();
        };
        auto machineLink = [](const char* link) {
            return [link](const QJsonObject& o) {
                return o.value("type") == "machine" && o.value("id") == "jaus:126" && o.value("link") == link;
            };
        };
        // The vehicle is heard (through the static endpoint), then goes out of range: its link goes down.
        QVERIFY2(!readUntil(machineLink("up"), 30000).isEmpty(), "FOREIGN-126 never came up");
        vehicle.setOffline(true);
        QVERIFY2(!readUntil(machineLink("down"), 30000).isEmpty(), "FOREIGN-126 never went down");
        p.write(R"({"cmd":"stop_all","req":99})"
                "\n");
        const QJsonObject r = readUntil(
            [](const QJsonObject& o) { return o.value("type") == "result" && o.value("req").toInt() == 99; },
            30000);
        p.terminate();
        p.waitForFinished(10000);
        QVERIFY2(!r.isEmpty(), p.readAllStandardError().constData());
        const QByteArray text = QJsonDocument(r).toJson();
        QCOMPARE(r.value("ok").toBool(), false);
        QMap<QString, QJsonObject> byId;
        for (const auto& v : r.value("targets").toArray())
            byId.insert(v.toObject().value("id").toString(), v.toObject());
        QCOMPARE(byId.keys(), QStringList({"iso23725 link ahs", "jaus:126", "jaus:127",
                                           QString("osyris group 239.255.42.98:%1").arg(osyPort)}));
        for (const QString& id : {QString("iso23725 link ahs"), byId.lastKey()}) {
            QVERIFY2(!byId[id].value("sent").toBool(), text.constData());
            QVERIFY2(!byId[id].value("reason").toString().isEmpty(), text.constData());
        }
        QVERIFY2(byId["jaus:126"].value("sent").toBool(), text.constData());
        QVERIFY2(byId["jaus:126"].value("note").toString().contains("link down"), text.constData());
        QVERIFY2(byId["jaus:126"].value("note").toString().contains("confirmation pending"),
                 text.constData());
        QVERIFY2(byId["jaus:127"].value("sent").toBool(), text.constData());
        QVERIFY2(byId["jaus:127"].value("note").toString().contains("never heard"), text.constData());
        // The audit log records the same truth; the monitor's end (terminated above) is its sign-out.
        QFile audit(dir.filePath("audit.jsonl"));
        QVERIFY(audit.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = audit.readAll().trimmed().split('\n');
        QVERIFY(lines.size() >= 2);
        QCOMPARE(QJsonDocument::fromJson(lines.last()).object().value("action").toString(),
                 QString("sign_out"));
        const QJsonObject a = QJsonDocument::fromJson(lines.at(lines.size() - 2)).object();
        QCOMPARE(a.value("action").toString(), QString("stop_all"));
        QCOMPARE(a.value("ok").toBool(), false);
        QCOMPARE(a.value("targets").toArray().size(), 4);
        QCOMPARE(a.value("targets").toArray(), r.value("targets").toArray());
    }
    void cleanupTestCase() {
        m_p.closeWriteChannel();
        m_p.terminate();
        m_p.waitForFinished(10000);
    }
};

QTEST_GUILESS_MAIN(TestHeadlessSite)
#include "test_headless_site.moc"
