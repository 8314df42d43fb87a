// Hostile peers for the other two protocols: a running console core (the three stacks together, as
// the headless site runs them: IsoStack against the simulated AHS with two trucks, JausStack against two
// simulated UGVs, OsyrisStack with a real roller) receives malformed ISO 23725 frames from the AHS's
// connection and malformed JUDP datagrams on the JAUS group, one at a time. After every single frame or
// datagram the console answers an OSYRIS PING within 100 ms and every real machine stays live (new data of
// each truck, UGV and the roller since the one before). test_osyris_hostile does the same for hostile OSYRIS
// datagrams.
//
// The bound is asserted, not slept for: the PING's round trip is measured from the send to the PONG. A shared
// build machine may deschedule this process for longer than 100 ms at any moment, so a PING that took longer
// is repeated (at most three PINGs, one Beat apart as the console answers one per requester and Beat) and the
// fastest must be under 100 ms; every first attempt is reported as measured.
#include "protocols/common/Log.h"
#include "protocols/common/Udp.h"
#include "protocols/iso23725/IsoStack.h"
#include "protocols/jaus/JausStack.h"
#include "protocols/jaus/JudpCodec.h"
#include "protocols/osyris/OsyrisCodec.h"
#include "protocols/osyris/OsyrisStack.h"
#include "sim/iso23725/SimulatedAhs.h"
#include "sim/jaus/JausDemo.h"

#include <QtTest>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/udp.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <map>
#include <mutex>
#include <optional>
#include <random>
#include <thread>

using namespace ocu;
using namespace std::chrono;
namespace asio = boost::asio;

namespace {

#if defined(__SANITIZE_THREAD__)
constexpr bool kUnderThreadSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
constexpr bool kUnderThreadSanitizer = true;
#else
constexpr bool kUnderThreadSanitizer = false;
#endif
#else
constexpr bool kUnderThreadSanitizer = false;
#endif
// Under ThreadSanitizer (scripts/test.sh --tsan: the whole process 5-15 times slower) the bound is not the
// product's: there the PONG must come at all (within 1 s); the figures are printed either way.
constexpr double kPongBoundMs = kUnderThreadSanitizer ? 1000 : 100;

constexpr const char* kOsyrisGroup = "239.255.14.6";
constexpr std::uint8_t kConsole = 200, kRoller = 1, kProbe = 50;
const std::string kTruckA = "0b3c1d2e-4f50-4a61-8b72-9c83d4e5f6a1";

// A plain UDP socket on a multicast group (loopback, TTL 0): the JAUS attacker and the OSYRIS PING probe.
class RawSocket {
public:
    RawSocket(const std::string& group, std::uint16_t port) : m_group(asio::ip::make_address(group), port) {
        UdpOptions o;
        o.bindAddress = group;
        o.port = port;
        o.multicastGroup = group;
        o.interfaceAddress = "127.0.0.1";
        o.multicastTtl = 0;
        openUdpSocket(m_socket, o);
        m_socket.non_blocking(true);
    }
    void send(const Bytes& b) { m_socket.send_to(asio::buffer(b), m_group); }
    // OSYRIS: sends a PING from `me` to the console and waits for its PONG; the round trip in ms, or nullopt.
    std::optional<double> ping(std::uint8_t me, milliseconds timeout) {
        std::array<std::uint8_t, 65536> buf{};
        asio::ip::udp::endpoint from;
        boost::system::error_code ec;
        while (m_socket.receive_from(asio::buffer(buf), from, 0, ec), !ec) {
        } // what came before the PING
        Bytes b;
        osyris::encodeRequest(b, me, kConsole, {osyris::RequestType::Ping, 0, 0, 1.f, 2.f});
        const auto t0 = steady_clock::now();
        send(b);
        while (steady_clock::now() - t0 < timeout) {
            const auto n = m_socket.receive_from(asio::buffer(buf), from, 0, ec);
            if (ec) {
                std::this_thread::sleep_for(microseconds(100));
                continue;
            }
            for (const auto& m : osyris::decodeDatagram(ByteSpan(buf.data(), n)).messages)
                if (const auto* r = std::get_if<osyris::CmRequest>(&m.body);
                    r && r->type == osyris::RequestType::Pong && m.header.who == kConsole &&
                    m.header.whose == me)
                    return duration<double, std::milli>(steady_clock::now() - t0).count();
        }
        return std::nullopt;
    }

private:
    asio::io_context m_io;
    asio::ip::udp::socket m_socket{m_io};
    asio::ip::udp::endpoint m_group;
};

struct IsoMachines : iso23725::IsoListener {
    std::mutex m;
    std::map<std::string, int> positions; // position updates per machine
    void onMachineChanged(const iso23725::IsoMachineSnapshot& s) override {
        std::lock_guard l(m);
        if (s.position)
            ++positions[s.equipmentId];
    }
    std::map<std::string, int> snapshot() {
        std::lock_guard l(m);
        return positions;
    }
};

struct JausQuiet : jaus::JausListener {
    void onSubsystemChanged(const jaus::SubsystemSnapshot&) override {}
    void onEvent(const jaus::JausEvent&) override {}
};

struct OsyrisShown : osyris::OsyrisListener {
    std::atomic<int> roller{0};
    void onMachinePosition(const osyris::MachineSnapshot& s) override {
        if (s.idx == kRoller)
            ++roller;
    }
};

osyris::OsyrisConfig osyrisConfig(std::uint16_t port, std::uint8_t idx, int active) {
    osyris::OsyrisConfig c;
    c.group = kOsyrisGroup;
    c.port = port;
    c.interfaceAddress = "127.0.0.1";
    c.multicastTtl = 0;
    c.beatMs = 100;
    c.sendPeriodMs = 2000;
    c.ttlBeats = 10;
    c.stationIndex = idx;
    c.active = active;
    c.machineNames = {{kRoller, "Roller 1"}};
    return c;
}

iso23725::IsoConfig isoConfig(const std::string& url) {
    iso23725::IsoConfig c;
    c.links.push_back(iso23725::IsoLinkConfig{"ahs", {}, {}});
    c.links[0].ws.url = url;
    c.links[0].ws.backoffMin = milliseconds(100);
    c.links[0].ws.backoffMax = milliseconds(400);
    return c;
}

Bytes hex(const char* s) {
    Bytes b;
    for (; s[0] && s[1]; s += 2)
        b.push_back(std::uint8_t(std::stoi(std::string(s, 2), nullptr, 16)));
    return b;
}

// Malformed ISO 23725 frames (text unless `binary`): broken JSON, wrong types and versions, out-of-standard
// protocol names, unknown members, absurd numbers, wrong direction, deep nesting and a large frame.
struct IsoFrame {
    std::string what, text;
    bool binary = false;
};
std::vector<IsoFrame> malformedIsoFrames() {
    const std::string head = R"({"Protocol":"ISO23725","Version":1,"Timestamp":"2026-11-23T20:00:00.000Z",)";
    const std::string eq = R"("EquipmentId":")" + kTruckA + R"(",)";
    std::vector<IsoFrame> f;
    f.push_back({"empty text frame", ""});
    f.push_back({"not JSON", "hello, console"});
    f.push_back({"truncated JSON", head});
    f.push_back({"JSON array", "[1,2,3]"});
    f.push_back({"JSON number", "1e999"});
    f.push_back(
        {"unknown version", R"({"Protocol":"ISO23725","Version":99,"Timestamp":"2026-11-23T20:00:00Z"})"});
    f.push_back(
        {"out-of-standard protocol name",
         R"({"Protocol":"ISO-23725-X","Version":1,"Timestamp":"2026-11-23T20:00:00Z","MachineAllStopV1":{}})"});
    f.push_back({"unknown member", head + eq + R"("MachineTeleportV9":{"Where":"Mars"}})"});
    f.push_back(
        {"position with absurd coordinates",
         head + eq +
             R"("MachinePositionV1":{"Timestamp":"2026-11-23T20:00:00Z","Latitude":1e308,"Longitude":-1e308,"Heading":720,"Speed":1e30}})"});
    f.push_back(
        {"position with strings for numbers",
         head + eq +
             R"("MachinePositionV1":{"Timestamp":"2026-11-23T20:00:00Z","Latitude":"north","Longitude":"east"}})"});
    f.push_back(
        {"equipment id not a GUID",
         head +
             R"("EquipmentId":"'; DROP TABLE machines; --","MachinePositionV1":{"Latitude":0,"Longitude":0}})"});
    f.push_back({"timestamp garbage", R"({"Protocol":"ISO23725","Version":1,"Timestamp":"yesterday"})"});
    f.push_back({"wrong direction (all-stop request from the AHS)",
                 head + R"("MachineAllStopRequestV1":{"AllStopActive":true}})"});
    f.push_back({"duplicate keys", head + eq + eq + R"("MachineAutonomyModeV1":{"AutonomyMode":1}})"});
    f.push_back({"invalid UTF-8", head + "\"EquipmentId\":\"\xff\xfe\xc0\x80\"}"});
    f.push_back({"5,000 levels of nesting", std::string(5000, '[') + std::string(5000, ']')});
    f.push_back({"200 kB string", head + R"("Padding":")" + std::string(200000, 'x') + "\"}"});
    f.push_back({"binary frame", std::string("\x00\x01\x02\xff garbage", 12), true});
    return f;
}

// Malformed JUDP datagrams on the JAUS group (jaus-wire.md §2, the codec test's malformed cases and more).
std::vector<std::pair<std::string, Bytes>> malformedJudpDatagrams() {
    std::vector<std::pair<std::string, Bytes>> d;
    d.push_back({"empty datagram", Bytes{}});
    d.push_back({"version byte only", hex("02")});
    d.push_back({"one byte missing", hex("0200100001c7017e0001010200022200")});
    d.push_back({"DataSize beyond the datagram", hex("0200ff0001c7017e000101020002220000")});
    d.push_back({"DataSize below 14", hex("0200050001c7017e000101020002220000")});
    d.push_back({"version 3", hex("0300100001c7017e000101020002220000")});
    d.push_back({"legacy v1", hex("0100000010000000000000000000000000000000")});
    d.push_back({"legacy OPC", Bytes{'J', 'A', 'U', 'S', '0', '1', '.', '0', 0, 0, 0, 0, 0, 0, 0, 0}});
    d.push_back({"header compression", hex("0240100001c7017e000101020002220000")});
    d.push_back({"message type", hex("0204100001c7017e000101020002220000")});
    // Well-formed headers from a subsystem nobody knows: fragments that never complete, bodies no decoder
    // accepts.
    auto msg = [](jaus::DataFlags flags, std::uint16_t seq, Bytes payload) {
        jaus::JudpHeader h;
        h.destination = jaus::JausId{0xFFFF, 0xFF, 0xFF};
        h.source = jaus::JausId{66, 1, 1};
        h.dataFlags = flags;
        h.sequence = seq;
        return jaus::encodeDatagram(h, payload);
    };
    d.push_back({"last fragment alone", msg(jaus::DataFlags::Last, 9, Bytes{0xAA, 0xBB})});
    d.push_back({"first fragment never completed", msg(jaus::DataFlags::First, 20, Bytes{0x03, 0x4B, 0x99})});
    d.push_back(
        {"ReportGlobalPose with a cut body", msg(jaus::DataFlags::Single, 30, Bytes{0x02, 0x44, 0x01})});
    d.push_back({"ReportServices with a huge count",
                 msg(jaus::DataFlags::Single, 31, Bytes{0x03, 0x4B, 0xFF, 0xFF, 0xFF, 0xFF})});
    d.push_back({"message without an ID", msg(jaus::DataFlags::Single, 32, Bytes{0x01})});
    std::mt19937 rng(14);
    Bytes noise(1400);
    for (auto& b : noise)
        b = std::uint8_t(rng());
    d.push_back({"1,400 random bytes", noise});
    noise[0] = 0x02;
    d.push_back({"1,400 random bytes after a good version byte", noise});
    return d;
}

} // namespace

class TestConsoleHostileFrames : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { setLogThreshold(LogLevel::Error); }

    void everyMalformedFrameLeavesTheConsoleAnsweringAndTheMachinesLive() {
        // ISO 23725: the simulated AHS with two trucks, the console's IsoStack connected to it.
        sim::SimulatedAhsConfig ahsCfg;
        ahsCfg.truckCount = 2;
        ahsCfg.positionRateHz = 20; // configurable: new data of every truck within a Beat or so
        ahsCfg.healthEvents = false;
        sim::SimulatedAhs ahs(ahsCfg);
        QVERIFY(ahs.start());
        IsoMachines iso;
        iso23725::IsoStack isoStack(isoConfig(ahs.url()), iso);
        QVERIFY(isoStack.start());
        // JAUS: two simulated UGVs and the console's JausStack.
        sim::JausDemo jausDemo;
        jaus::JausConfig jausCfg;
        jausCfg.subsystemId = 200;
        jausCfg.callSign = "OCU-200";
        jausCfg.authority = 205;
        jausCfg.poseRateHz = 20; // the UGVs' pose events as often as the roller's positions
        jausDemo.configure(jausCfg);
        JausQuiet jausQuiet;
        jaus::JausStack jausStack(jausCfg, jausQuiet);
        jausStack.start();
        // OSYRIS: the console and one real roller driving from its own thread.
        const std::uint16_t osyrisPort = findFreeUdpPort();
        OsyrisShown shown;
        osyris::OsyrisListener quiet;
        osyris::OsyrisStack console(osyrisConfig(osyrisPort, kConsole, 15), shown);
        osyris::OsyrisStack roller(osyrisConfig(osyrisPort, kRoller, 7), quiet);
        std::string err;
        QVERIFY2(console.start(&err), err.c_str());
        QVERIFY2(roller.start(&err), err.c_str());
        std::atomic<bool> driving{true};
        std::thread drive([&] {
            for (std::uint32_t i = 0; driving; ++i) {
                osyris::CmPos p;
                p.slot = i;
                p.x = float(i % 200) * 0.2f;
                p.y = float((i / 200) % 2) * 2.0f;
                p.dx = 2.1f;
                p.speed = 1.0;
                p.flags = osyris::kPosValid | osyris::kPosAccuracyHigh | osyris::kPosVibrating;
                roller.publishOwnPosition(p);
                std::this_thread::sleep_for(milliseconds(50));
            }
        });
        struct Stop {
            std::atomic<bool>& flag;
            std::thread& t;
            ~Stop() {
                flag = false;
                if (t.joinable())
                    t.join();
            }
        } stopDriving{driving, drive};

        RawSocket probe(kOsyrisGroup, osyrisPort);
        RawSocket judp("239.255.0.1", jausDemo.multicastPort()); // JausDemoOptions::multicastGroup

        // Every real machine is live before anything hostile: both trucks, both UGVs, the roller.
        auto ugvHeard = [&](std::uint16_t ss) {
            auto s = jausStack.snapshot(ss);
            return s ? s->lastMessage : TimePoint{};
        };
        QTRY_VERIFY_WITH_TIMEOUT(iso.snapshot().size() == 2, 30000);
        QTRY_VERIFY_WITH_TIMEOUT(ugvHeard(126) != TimePoint{} && ugvHeard(127) != TimePoint{}, 30000);
        QTRY_VERIFY_WITH_TIMEOUT(shown.roller > 0, 30000);

        std::vector<double> firstPing;
        int repeated = 0;
        auto lastPing = steady_clock::now() - seconds(1);
        auto pingAfter = [&](const std::string& what) {
            std::optional<double> best;
            for (int attempt = 0; attempt < 3 && !(best && *best < kPongBoundMs); ++attempt) {
                if (attempt > 0)
                    ++repeated;
                // One PING per requester and Beat is answered: a Beat since the last one.
                std::this_thread::sleep_until(lastPing + milliseconds(110));
                auto ms = probe.ping(kProbe, milliseconds(1000));
                lastPing = steady_clock::now();
                if (attempt == 0)
                    firstPing.push_back(ms.value_or(1000));
                if (ms && (!best || *ms < *best))
                    best = ms;
            }
            QVERIFY2(best && *best < kPongBoundMs,
                     qPrintable(QString::fromStdString("no PONG within 100 ms after " + what + " (best: ") +
                                (best ? QString::number(*best, 'f', 1) + " ms)" : QStringLiteral("none)"))));
        };
        auto machinesLiveAfter = [&](const std::string& what, const std::map<std::string, int>& isoBefore,
                                     TimePoint ugv126, TimePoint ugv127, int rollerBefore) {
            const QString after = QString::fromStdString(what);
            for (const auto& [id, n] : isoBefore)
                QTRY_VERIFY2_WITH_TIMEOUT(
                    iso.snapshot()[id] > n,
                    qPrintable("ISO truck " + QString::fromStdString(id) + " stale after " + after), 10000);
            QTRY_VERIFY2_WITH_TIMEOUT(ugvHeard(126) > ugv126, qPrintable("UGV 126 stale after " + after),
                                      10000);
            QTRY_VERIFY2_WITH_TIMEOUT(ugvHeard(127) > ugv127, qPrintable("UGV 127 stale after " + after),
                                      10000);
            QTRY_VERIFY2_WITH_TIMEOUT(shown.roller > rollerBefore, qPrintable("roller stale after " + after),
                                      10000);
        };
        auto oneInput = [&](const std::string& what, const std::function<void()>& send) {
            const auto isoBefore = iso.snapshot();
            const TimePoint u126 = ugvHeard(126), u127 = ugvHeard(127);
            const int r = shown.roller;
            std::this_thread::sleep_until(lastPing + milliseconds(110));
            send();
            pingAfter(what);
            if (QTest::currentTestFailed())
                return;
            machinesLiveAfter(what, isoBefore, u126, u127, r);
        };

        pingAfter("nothing yet");
        int inputs = 0;
        for (const auto& frame : malformedIsoFrames()) {
            oneInput("ISO 23725 frame: " + frame.what, [&] {
                if (frame.binary)
                    ahs.sendRawBinary(frame.text);
                else
                    ahs.sendRaw(frame.text);
            });
            if (QTest::currentTestFailed())
                return;
            ++inputs;
        }
        for (const auto& [what, datagram] : malformedJudpDatagrams()) {
            oneInput("JUDP datagram: " + what, [&] { judp.send(datagram); });
            if (QTest::currentTestFailed())
                return;
            ++inputs;
        }
        // The inputs were seen and counted as bad, not silently lost on the way.
        const auto isoRejected = isoStack.counters().sumPrefix("rx.rejected.");
        const auto jausRejected = jausStack.counters().sumPrefix("rx.rejected.");
        qInfo("counted as rejected: ISO 23725 %llu, JAUS %llu", qulonglong(isoRejected),
              qulonglong(jausRejected));
        QVERIFY(isoRejected >= 8);
        QVERIFY(jausRejected >= 10);
        std::sort(firstPing.begin(), firstPing.end());
        qInfo("%d malformed inputs (%zu ISO 23725 frames, %zu JUDP datagrams): OSYRIS PING answered after "
              "each; "
              "first PING round trip median %.2f ms, max %.2f ms; %d PINGs repeated after a first one of "
              "100 ms or more; every truck, UGV and the roller live after each",
              inputs, malformedIsoFrames().size(), malformedJudpDatagrams().size(),
              firstPing[firstPing.size() / 2], firstPing.back(), repeated);
        isoStack.stop();
        jausStack.stop();
        roller.stop();
        console.stop();
        ahs.stop();
        jausDemo.stop();
    }
};

QTEST_GUILESS_MAIN(TestConsoleHostileFrames)
#include "test_console_hostile_frames.moc"
