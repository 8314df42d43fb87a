// Crew messages both ways over loopback multicast (interface 127.0.0.1) against the simulated
// rollers: the console's message through the command gate (audited; the result names what went on the wire)
// to one machine reaches only that machine's driver, to all reaches every driver, and their answers and their
// own reports come back as events with the sender. A foreign OSYRIS peer (raw socket, its own encoding, CmMsg
// numbered WType 3 as a vendor that resolved the table's clash would) exchanges CmMsg with the console too.
#include "models/AlarmModel.h"
#include "models/CommandGate.h"
#include "models/bridges/OsyrisBridge.h"
#include "models/testing/CommandWait.h"
#include "protocols/common/Udp.h"
#include "protocols/osyris/OsyrisStack.h"
#include "sim/osyris/OsyrisDemo.h"

#include <QtTest>

#include <boost/asio/io_context.hpp>

using namespace ocu;

namespace {

const GeoPoint kOrigin{48.137154, 11.576124, 520};

struct Received {
    QString fromId, fromName, text;
};

// A foreign OSYRIS station: written from the specification (§6 CmHeader + CmMsg, 80-byte NUL-padded text),
// sharing no code with the project's codec.
class ForeignPeer {
public:
    ForeignPeer(const std::string& group, std::uint16_t port) : m_socket(m_io), m_port(port) {
        UdpOptions o;
        o.bindAddress = group;
        o.port = port;
        o.multicastGroup = group;
        o.interfaceAddress = "127.0.0.1";
        o.multicastTtl = 0;
        openUdpSocket(m_socket, o);
        m_socket.non_blocking(true);
        m_group = boost::asio::ip::udp::endpoint(boost::asio::ip::make_address(group), port);
    }
    void sendMsg(std::uint8_t who, std::uint8_t whose, const std::string& text) {
        std::vector<std::uint8_t> b(88, 0);
        b[2] = 88; // WLen, little-endian
        b[4] = 3;  // WType 3 = CmMsg in this vendor's numbering
        b[6] = who;
        b[7] = whose;
        for (std::size_t i = 0; i < text.size() && i < 79; ++i)
            b[8 + i] = static_cast<std::uint8_t>(text[i]);
        m_socket.send_to(boost::asio::buffer(b), m_group);
    }
    // Texts of CmMsg (WType 3 or 4) from station `from` received so far.
    std::vector<std::string> textsFrom(std::uint8_t from) {
        std::uint8_t buf[65536];
        boost::system::error_code ec;
        for (;;) {
            boost::asio::ip::udp::endpoint sender;
            const std::size_t n = m_socket.receive_from(boost::asio::buffer(buf), sender, 0, ec);
            if (ec)
                break;
            for (std::size_t at = 0; at + 8 <= n;) {
                const std::size_t len = buf[at + 2] | (buf[at + 3] << 8);
                const int type = buf[at + 4] | (buf[at + 5] << 8);
                if (len < 8 || at + len > n)
                    break;
                if ((type == 3 || type == 4) && buf[at + 6] == from) {
                    std::string t;
                    for (std::size_t i = at + 8; i < at + len && buf[i]; ++i)
                        t.push_back(static_cast<char>(buf[i]));
                    m_texts.push_back(t);
                }
                at += len;
            }
        }
        return m_texts;
    }

private:
    boost::asio::io_context m_io;
    boost::asio::ip::udp::socket m_socket;
    boost::asio::ip::udp::endpoint m_group;
    std::uint16_t m_port;
    std::vector<std::string> m_texts;
};

} // namespace

class TestOsyrisCrewMessages : public QObject {
    Q_OBJECT
private slots:
    void bothWaysWithTheSimulatedRollers() {
        sim::osyris::OsyrisDemoOptions opts;
        opts.rollers = 2;
        opts.paver = false;
        opts.relay = false;
        opts.speedUp = 10;
        opts.crewMessageEveryS = 20; // a driver's own report every 2 s of real time
        sim::osyris::OsyrisDemo demo(opts);
        std::string err;
        QVERIFY2(demo.start(&err), err.c_str());
        osyris::OsyrisConfig cfg = demo.ocuConfig();
        cfg.originLat = kOrigin.lat;
        cfg.originLon = kOrigin.lon;
        cfg.originAlt = kOrigin.alt;
        OsyrisBridge bridge(cfg, GeoFrame(kOrigin));
        QList<Received> received;
        connect(&bridge, &OsyrisBridge::textReceived, this,
                [&](const QString& id, const QString& name, const QString& text) {
                    received << Received{id, name, text};
                });
        QList<FleetEvent> events;
        connect(&bridge, &FleetBridge::eventRaised, this, [&](const FleetEvent& e) { events << e; });
        CommandGate gate;
        gate.addBridge(&bridge);
        QStringList audit;
        connect(&gate, &CommandGate::audited, this, [&](const QString& line) { audit << line; });
        QVERIFY(bridge.start().isEmpty());
        const auto has = [&](const QString& from, const QString& part) {
            for (const auto& r : received)
                if (r.fromId == from && r.text.contains(part))
                    return true;
            return false;
        };
        const QString r1 = QStringLiteral("osyris:%1").arg(demo.machines()[0].idx);
        const QString r2 = QStringLiteral("osyris:%1").arg(demo.machines()[1].idx);

        // The rollers report by themselves (an event with the sender).
        QTRY_VERIFY_WITH_TIMEOUT(has(r1, QStringLiteral("Roller 1: rolled up to x=")), 30000);
        QVERIFY(std::any_of(events.begin(), events.end(), [&](const FleetEvent& e) {
            return e.kind == EventKind::TextMessage && e.machineId == r1 &&
                   e.text.contains(QStringLiteral("Roller 1"));
        }));

        // To one machine: only its driver gets it and answers; the result names that machine.
        const CommandResult one = testing::gateResult([&](auto done) {
            gate.command(SendText{r2, QStringLiteral("lift 2 next")}, QStringLiteral("test"), done);
        });
        QVERIFY2(one.ok, qPrintable(one.message));
        QCOMPARE(one.targets.size(), 1);
        QCOMPARE(targetId(one.targets[0]), r2);
        QTRY_VERIFY_WITH_TIMEOUT(has(r2, QStringLiteral("Roller 2: OK, lift 2 next")), 30000);
        QCOMPARE(received.last().fromName, QStringLiteral("Roller 2"));
        QTest::qWait(500);
        QCOMPARE(demo.crewMessagesReceived(0), 0);
        QCOMPARE(demo.crewMessagesReceived(1), 1);
        QVERIFY(std::any_of(audit.begin(), audit.end(), [&](const QString& l) {
            return l.contains(QStringLiteral("send_text")) && l.contains(r2);
        }));

        // To all: every driver answers.
        const CommandResult all = testing::gateResult([&](auto done) {
            gate.command(SendText{{}, QStringLiteral("break at 12:00")}, QStringLiteral("test"), done);
        });
        QVERIFY2(all.ok, qPrintable(all.message));
        QVERIFY(targetId(all.targets[0]).startsWith(QStringLiteral("osyris group")));
        QTRY_VERIFY_WITH_TIMEOUT(has(r1, QStringLiteral("Roller 1: OK, break at 12:00")) &&
                                     has(r2, QStringLiteral("Roller 2: OK, break at 12:00")),
                                 30000);

        // Refused with the reason, nothing sent: too long, not an OSYRIS station.
        const CommandResult tooLong = testing::gateResult([&](auto done) {
            gate.command(SendText{r1, QString(80, QLatin1Char('x'))}, QStringLiteral("test"), done);
        });
        QVERIFY(!tooLong.ok);
        QVERIFY2(tooLong.message.contains(QStringLiteral("79 bytes")), qPrintable(tooLong.message));

        // The foreign peer: its message (WType 3) arrives with its sender, and it receives the console's.
        ForeignPeer peer(cfg.group, cfg.port);
        peer.sendMsg(77, 255, "asphalt truck 4 arriving");
        QTRY_VERIFY_WITH_TIMEOUT(has(QStringLiteral("osyris:77"), QStringLiteral("asphalt truck 4 arriving")),
                                 30000);
        const CommandResult toPeer = testing::gateResult([&](auto done) {
            gate.command(SendText{{}, QStringLiteral("truck 4 to lane 2")}, QStringLiteral("test"), done);
        });
        QVERIFY2(toPeer.ok, qPrintable(toPeer.message));
        QTRY_VERIFY_WITH_TIMEOUT(
            [&] {
                auto t = peer.textsFrom(cfg.stationIndex);
                return std::find(t.begin(), t.end(), std::string("truck 4 to lane 2")) != t.end();
            }(),
            30000);
        bridge.stop();
        demo.stop();
    }

    // Crew text messages are messages, not alarms (EEMUA 191: an alarm needs an operator's action): 100 of
    // them from a machine reach the console as information events, and the alarm list, its unacknowledged
    // count and its flood indicator stay as they were.
    void hundredMessagesRaiseNoAlarm() {
        sim::osyris::OsyrisDemoOptions opts;
        opts.rollers = 1;
        opts.paver = false;
        opts.relay = false;
        opts.crewMessageEveryS = 0;
        sim::osyris::OsyrisDemo demo(opts);
        std::string err;
        QVERIFY2(demo.start(&err), err.c_str());
        osyris::OsyrisConfig cfg = demo.ocuConfig();
        OsyrisBridge bridge(cfg, GeoFrame(kOrigin));
        AlarmModel alarms;
        alarms.addBridge(&bridge);
        int texts = 0;
        QList<FleetEvent> events;
        connect(&bridge, &OsyrisBridge::textReceived, this, [&] { ++texts; });
        connect(&bridge, &FleetBridge::eventRaised, this, [&](const FleetEvent& e) {
            if (e.kind == EventKind::TextMessage)
                events << e;
        });
        QVERIFY(bridge.start().isEmpty());
        // A machine's station on the same group that sends the texts.
        osyris::OsyrisConfig machine = cfg;
        machine.stationIndex = 9;
        machine.sqlitePath.clear();
        osyris::OsyrisListener quiet;
        osyris::OsyrisStack sender(machine, quiet);
        QVERIFY2(sender.start(&err), err.c_str());
        for (int i = 0; i < 100; ++i)
            sender.sendText("lane " + std::to_string(i) + " done");
        QTRY_COMPARE_WITH_TIMEOUT(texts, 100, 60000);
        QTRY_COMPARE_WITH_TIMEOUT(events.size(), 100, 10000);
        for (const FleetEvent& e : std::as_const(events)) {
            QVERIFY(!e.requiresAck);
            QCOMPARE(e.severity, EventSeverity::Info);
        }
        QCOMPARE(alarms.unacknowledgedCount(), 0);
        QCOMPARE(alarms.alarmRate(), 0);
        QVERIFY(!alarms.isFlood());
        sender.stop();
        bridge.stop();
    }
};

QTEST_GUILESS_MAIN(TestOsyrisCrewMessages)
#include "test_osyris_crew_messages.moc"
