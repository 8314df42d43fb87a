// The hostile station over real loopback multicast (group joined and sent on 127.0.0.1, free
// port, TTL 0): two real rollers (OsyrisStack stations publishing a fixed track) and the console
// (OsyrisStack), twice side by side over two ports: once alone and once with a hostile station written here
// from the spec (§6 layouts through the codec only, no simulator code) sending phantom ranges, absurd
// positions, huge drums, request floods, garbage and datagrams from more unknown stations than the cap.
// Every slot of the rollers arrives, the console's pass counts equal those of the quiet run, the console
// answers a PING after every single hostile datagram within 100 ms (measured round trip; the fastest of at
// most three PINGs, so that a descheduled test process does not fail it) and keeps both rollers live, and the
// longest io-thread handler is measured and printed (the 10 ms is reported, a generous 0.5 s
// asserted, so the test holds on a loaded machine).
#include "protocols/osyris/OsyrisCodec.h"
#include "protocols/osyris/OsyrisStack.h"
#include "protocols/osyris/RibbonStore.h"

#include "protocols/common/Udp.h"

#include <QtTest>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/udp.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <optional>
#include <random>
#include <thread>

using namespace ocu;
using namespace ocu::osyris;
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

constexpr const char* kGroup = "239.255.14.5";
constexpr std::uint8_t kConsole = 200, kHostile = 9, kProbe = 50;
constexpr std::uint32_t kTrack = 240; // positions per roller
constexpr std::uint32_t kGood = kPosValid | kPosAccuracyHigh | kPosVibrating;

struct Console : OsyrisListener {
    std::mutex m;
    std::map<int, int> positions; // plausible positions shown, per machine
    int implausible = 0;
    void onMachinePosition(const MachineSnapshot& s) override {
        std::lock_guard l(m);
        if (s.implausible.empty())
            ++positions[s.idx];
        else
            ++implausible;
    }
    int shown(int idx) {
        std::lock_guard l(m);
        return positions[idx];
    }
};

OsyrisConfig stationConfig(std::uint16_t port, std::uint8_t idx, int active) {
    OsyrisConfig c;
    c.group = kGroup;
    c.port = port;
    c.interfaceAddress = "127.0.0.1";
    c.multicastTtl = 0;
    c.beatMs = 100;
    c.sendPeriodMs = 2000;
    c.ttlBeats = 10;
    c.stationIndex = idx;
    c.active = active;
    c.machineNames = {{1, "Roller 1"}, {2, "Roller 2"}};
    return c;
}

// Roller k's i-th position: 80-position lanes back and forth, so cells are passed several times.
CmPos trackPosition(int roller, std::uint32_t i) {
    const std::uint32_t lane = i / 80, k = i % 80;
    const bool forward = lane % 2 == 0;
    CmPos p;
    p.x = static_cast<float>((forward ? k : 79 - k) * 0.25);
    p.y = static_cast<float>(roller * 1.5);
    p.dx = 2.0f;
    p.speed = 1.0;
    p.flags = kGood | (forward ? kPosForward : kPosBackward);
    return p;
}

// A plain UDP socket on the group: the hostile station and the operator's PING probe. Shares no code with
// OsyrisTransport beyond the socket options helper.
class RawStation {
public:
    explicit RawStation(std::uint16_t port) : m_group(asio::ip::make_address(kGroup), port) {
        UdpOptions o;
        o.bindAddress = kGroup;
        o.port = port;
        o.multicastGroup = kGroup;
        o.interfaceAddress = "127.0.0.1";
        o.multicastTtl = 0;
        openUdpSocket(m_socket, o);
        m_socket.non_blocking(true);
    }
    void send(const Bytes& b) { m_socket.send_to(asio::buffer(b), m_group); }
    // Sends a PING from `me` to the console and waits for its PONG; the milliseconds it took, or nullopt.
    std::optional<double> ping(std::uint8_t me, milliseconds timeout) {
        drain();
        Bytes b;
        encodeRequest(b, me, kConsole, {RequestType::Ping, 0, 0, 1.f, 2.f});
        const auto t0 = steady_clock::now();
        send(b);
        std::array<std::uint8_t, 65536> buf{};
        while (steady_clock::now() - t0 < timeout) {
            asio::ip::udp::endpoint from;
            boost::system::error_code ec;
            const auto n = m_socket.receive_from(asio::buffer(buf), from, 0, ec);
            if (ec) {
                std::this_thread::sleep_for(microseconds(200));
                continue;
            }
            for (const auto& m : decodeDatagram(ByteSpan(buf.data(), n)).messages)
                if (const auto* r = std::get_if<CmRequest>(&m.body);
                    r && r->type == RequestType::Pong && m.header.who == kConsole && m.header.whose == me)
                    return duration<double, std::milli>(steady_clock::now() - t0).count();
        }
        return std::nullopt;
    }

private:
    void drain() {
        std::array<std::uint8_t, 65536> buf{};
        boost::system::error_code ec;
        asio::ip::udp::endpoint from;
        while (!ec)
            m_socket.receive_from(asio::buffer(buf), from, 0, ec);
    }
    asio::io_context m_ctx;
    asio::ip::udp::socket m_socket{m_ctx};
    asio::ip::udp::endpoint m_group;
};

// The hostile station's repertoire: one datagram each, every one at most MaxLen (1400) bytes.
std::vector<std::pair<std::string, Bytes>> hostileDatagrams() {
    std::vector<std::pair<std::string, Bytes>> out;
    auto add = [&](std::string what, Bytes b) {
        if (b.size() > 1400)
            qFatal("hostile datagram larger than MaxLen");
        out.emplace_back(std::move(what), std::move(b));
    };
    auto request = [](std::uint8_t who, std::uint8_t whose, CmRequest r) {
        Bytes b;
        encodeRequest(b, who, whose, r);
        return b;
    };
    auto flood = [](std::uint8_t whose, CmRequest r) {
        Bytes b;
        while (b.size() + kRequestSize <= 1400)
            encodeRequest(b, kHostile, whose, r);
        return b;
    };
    auto position = [](std::uint8_t who, std::uint32_t slot, float x, float dx) {
        CmPos p = trackPosition(0, 0);
        p.slot = slot;
        p.x = x;
        p.dx = dx;
        Bytes b;
        encodePos(b, who, who, p);
        return b;
    };
    const float nan = std::numeric_limits<float>::quiet_NaN();
    add("phantom ALIVE 0..0xFFFFFFFE",
        request(kHostile, kHostile, {RequestType::Alive, 0, 0xFFFFFFFEu, 0, 0}));
    add("phantom ALIVE of roller 1 far ahead",
        request(kHostile, 1, {RequestType::Alive, 0, 3'000'000u, 0, 0}));
    add("wide ALIVE 0..2^22-2", request(kHostile, kHostile, {RequestType::Alive, 0, (1u << 22) - 2, 0, 0}));
    add("CmPos x = NaN", position(kHostile, 0, nan, 2.0f));
    add("CmPos x = 1e30 m", position(kHostile, 1, 1e30f, 2.0f));
    add("CmPos drum 1e6 m", position(kHostile, 2, 5.0f, 1e6f));
    add("CmPos drum 1e5 m", position(kHostile, 3, 5.0f, 1e5f));
    add("CmPos slot 0xFFFFFFF0", position(kHostile, 0xFFFFFFF0u, 5.0f, 2.0f));
    add("80 x ALL", flood(kIdxAll, {RequestType::All, 0, kSlotLast, 0, 0}));
    add("80 x PING", flood(kConsole, {RequestType::Ping, 0, 0, 1, 1}));
    add("80 x NAK roller 1 [0, max]", flood(1, {RequestType::Nak, 0, kSlotLast - 1, 0, 0}));
    add("80 x NAK roller 2 [0, last]", flood(2, {RequestType::Nak, 0, kSlotLast, 0, 0}));
    add("80 x NAK of the phantom ribbon", flood(kHostile, {RequestType::Nak, 0, kSlotLast - 1, 0, 0}));
    {
        Bytes b;
        for (int i = 0; b.size() + 3 * kRequestSize <= 1400; ++i) {
            encodeRequest(b, kHostile, kIdxAll, {RequestType::All, 0, 0, 0, 0});
            encodeRequest(b, kHostile, kConsole, {RequestType::Ping, 0, 0, 1, 1});
            encodeRequest(b, kHostile, std::uint8_t(1 + i % 2),
                          {RequestType::Nak, std::uint32_t(i), kSlotLast, 0, 0});
        }
        add("ALL + PING + NAK mixed", b);
    }
    {
        CmPos p = trackPosition(0, 0);
        p.slot = 10;
        Bytes b;
        encodePos(b, kHostile, kHostile, p);
        std::vector<PosProp> props((1400 - b.size() - kHeaderSize) / kPosPropSize);
        encodePosProps(b, kHostile, kHostile, props);
        add("CmPos with a datagram of properties", b);
    }
    {
        Bytes b;
        encodePos(b, kHostile, kHostile, trackPosition(0, 1));
        encodePos(b, 77, 77, trackPosition(0, 2));
        add("another IdxWho inside the datagram", b);
    }
    {
        std::mt19937 rng(14);
        Bytes b(1400);
        for (auto& x : b)
            x = static_cast<std::uint8_t>(rng());
        add("1400 random bytes", b);
        Bytes header;
        encodeRequest(header, kHostile, kHostile, {RequestType::Nak, 0, 1, 0, 0});
        header[2] = 0xFF; // WLen beyond the end
        header[3] = 0xFF;
        add("WLen beyond the datagram", header);
    }
    for (std::uint8_t who = 100; who < 120; ++who) // 20 more unknown stations than anyone needs
        add("unknown station " + std::to_string(who), position(who, 0, nan, 2.0f));
    return out;
}

struct RunResult {
    std::vector<TileSnapshot> tiles;
    std::map<std::pair<std::int32_t, std::int32_t>, int> counted; // cells with a count
    std::vector<std::pair<double, double>> incomplete;            // centres of the cells marked incomplete
    std::map<std::uint8_t, std::vector<SlotRange>> givenUp;
    double cellSize = 0;
    double maxPingMs = 0, medianPingMs = 0;
    double maxHandlerMs = 0;
    std::size_t hostileDatagrams = 0;
    std::uint64_t rejected = 0, implausible = 0, limited = 0;
};

// The console's defaults, gap give-up included, except that a gap is also given up after 6 s instead of
// 2 min: what is asserted is what a given-up gap does, and its 5 unanswered NAKs (in rounds of 3 s that the
// rollers' own NAKs for the same gap often hold back) took 5-25 s. 6 s is longer than a NAK round, its
// back-off and the answer's TTL, so a roller's gap is repaired before (and recounted if not).
OsyrisConfig consoleConfig(std::uint16_t port) {
    OsyrisConfig c = stationConfig(port, kConsole, 15);
    c.gapGiveUpMs = 6000;
    return c;
}

// One site over its own port: the console and two rollers driving their tracks from a thread of the test.
struct Site {
    explicit Site(std::uint16_t p)
        : port(p), ocu(consoleConfig(p), console), roller1(stationConfig(p, 1, 7), quiet),
          roller2(stationConfig(p, 2, 7), quiet) {}
    ~Site() {
        if (drive.joinable())
            drive.join();
    }
    std::uint16_t port;
    Console console;
    OsyrisListener quiet;
    // The hostile station's own ribbon has a gap nobody answers (slots 4-9) before a plausible position
    // (slot 10), so it is given up and marks cells incomplete; the rollers' counts must not change for it.
    OsyrisStack ocu;
    OsyrisStack roller1, roller2;
    std::atomic<std::uint32_t> published{0};
    std::thread drive;
};

} // namespace

class TestOsyrisHostile : public QObject {
    Q_OBJECT

    void start(Site& site) {
        std::string err;
        QVERIFY2(site.ocu.start(&err), err.c_str());
        QVERIFY2(site.roller1.start(&err), err.c_str());
        QVERIFY2(site.roller2.start(&err), err.c_str());
        // The rollers drive at 25 positions/s each, from their own thread, through the whole attack.
        site.drive = std::thread([&site] {
            for (std::uint32_t i = 0; i < kTrack; ++i) {
                site.roller1.publishOwnPosition(trackPosition(1, i));
                site.roller2.publishOwnPosition(trackPosition(2, i));
                site.published = i + 1;
                std::this_thread::sleep_for(milliseconds(40));
            }
        });
        QTRY_VERIFY_WITH_TIMEOUT(site.console.shown(1) > 0 && site.console.shown(2) > 0, 20000);
    }

    void attack(Site& site, RunResult& out) {
        OsyrisStack& ocu = site.ocu;
        Console& console = site.console;
        const auto& published = site.published;
        RawStation probe(site.port);
        RawStation attacker(site.port);
        std::vector<double> pings;
        ocu.resetMaxHandlerDuration();
        auto before = std::make_pair(console.shown(1), console.shown(2));
        // The probe first (a PING before anything hostile), then right after each hostile datagram (a
        // PONG within 100 ms: the console keeps answering under attack). The round trip is measured, not
        // slept for; a shared build machine may deschedule this process for 100 ms at any moment, so a
        // PING over the bound is repeated (at most three, one Beat apart: one PING per requester and Beat
        // is answered) and the fastest must be under 100 ms. The first attempts are the figures reported.
        auto lastPing = steady_clock::now() - seconds(1);
        // Under ThreadSanitizer (scripts/test.sh --tsan: the whole process 5-15 times slower) the bound
        // is not the product's: there the PONG must come at all (within 1 s), the figures are printed.
        const double boundMs = kUnderThreadSanitizer ? 1000 : 100;
        auto answered = [&](const std::string& after) {
            std::optional<double> best;
            for (int attempt = 0; attempt < 3 && !(best && *best < boundMs); ++attempt) {
                std::this_thread::sleep_until(lastPing + milliseconds(110));
                const auto ms = probe.ping(kProbe, milliseconds(1000));
                lastPing = steady_clock::now();
                if (attempt == 0)
                    pings.push_back(ms.value_or(1000));
                if (ms && (!best || *ms < *best))
                    best = ms;
            }
            if (!(best && *best < boundMs))
                qWarning("no PONG within 100 ms after: %s (best %.1f ms)", after.c_str(), best.value_or(-1));
            return best && *best < boundMs;
        };
        QVERIFY(answered("nothing yet"));
        for (const auto& [what, datagram] : hostileDatagrams()) {
            std::this_thread::sleep_until(lastPing + milliseconds(110)); // the PING may follow at once
            attacker.send(datagram);
            ++out.hostileDatagrams;
            QVERIFY2(answered(what),
                     qPrintable(QString::fromStdString("no PONG within 100 ms after " + what)));
            // Both rollers stay live: new positions of each arrived since the previous hostile datagram
            // (unless the drive is over).
            if (published < kTrack) {
                QTRY_VERIFY2_WITH_TIMEOUT(console.shown(1) > before.first || published >= kTrack,
                                          qPrintable(QString::fromStdString("roller 1 stale after " + what)),
                                          5000);
                QTRY_VERIFY2_WITH_TIMEOUT(console.shown(2) > before.second || published >= kTrack,
                                          qPrintable(QString::fromStdString("roller 2 stale after " + what)),
                                          5000);
            }
            before = std::make_pair(console.shown(1), console.shown(2));
        }
        std::sort(pings.begin(), pings.end());
        out.maxPingMs = pings.back();
        out.medianPingMs = pings[pings.size() / 2];
    }

    void finish(Site& site, RunResult& out, bool hostile) {
        OsyrisStack& ocu = site.ocu;
        site.drive.join();
        // Every slot of both rollers arrives.
        for (std::uint8_t r : {1, 2})
            QTRY_VERIFY_WITH_TIMEOUT(ocu.store()->held(r).containsAll(0, kTrack - 1), 30000);
        QCOMPARE(ocu.store()->count(1), std::uint64_t(kTrack));
        QCOMPARE(ocu.store()->count(2), std::uint64_t(kTrack));
        // The counts are final once the grid has advanced over every slot of both rollers with none of
        // their slots given up: the grid is a function of the ribbons alone (PassCountGrid.h), and only a
        // given-up gap can change it afterwards (its slots recounted when they arrive, at most once per
        // StationCore::kRecountGap). updateGrid() advances over every held slot now instead of at the next
        // Beat; under load a roller's gap may have been given up, and then this waits for its recount. The
        // attacked console also waits for the hostile station's gap to be given up (at the latest after
        // gapGiveUpMs), so that what it marks incomplete is checked on every run.
        std::shared_ptr<const PassCountSnapshot> snap;
        QTRY_VERIFY_WITH_TIMEOUT(
            [&] {
                ocu.withCore([](StationCore& core) { core.updateGrid(); });
                snap = ocu.passCounts();
                return !snap->givenUp().count(1) && !snap->givenUp().count(2) &&
                       (!hostile || snap->givenUp().count(kHostile));
            }(),
            60000);
        out.tiles = snap->tileValues();
        out.cellSize = snap->cellSize();
        snap->forEachCell(-1, [&](std::int32_t cx, std::int32_t cy, int count, bool inc) {
            if (count > 0)
                out.counted[{cx, cy}] = count;
            if (inc)
                out.incomplete.emplace_back((cx + 0.5) * out.cellSize, (cy + 0.5) * out.cellSize);
        });
        out.givenUp = snap->givenUp();
        out.maxHandlerMs = duration<double, std::milli>(ocu.maxHandlerDuration()).count();
        ocu.withCore([&](StationCore& core) {
            for (const auto& [name, value] : core.counters().snapshot()) {
                if (name.rfind("rx.rejected.", 0) == 0)
                    out.rejected += value;
                if (name.rfind("rx.implausible.", 0) == 0)
                    out.implausible += value;
                if (name.rfind("rx.limited.", 0) == 0)
                    out.limited += value;
            }
        });
        site.roller1.stop();
        site.roller2.stop();
        ocu.stop();
    }

private slots:
    // The quiet run and the attacked one side by side, each over its own port: the same drive at the same
    // pace, so the quiet run's counts are what the attacked console must show.
    void hostileStationChangesNothingReal() {
        RunResult quiet, attacked;
        const std::uint16_t quietPort = findFreeUdpPort();
        Site quietSite(quietPort);
        start(quietSite);
        if (QTest::currentTestFailed())
            return;
        std::uint16_t attackedPort = findFreeUdpPort();
        while (attackedPort == quietPort)
            attackedPort = findFreeUdpPort();
        Site attackedSite(attackedPort);
        start(attackedSite);
        if (QTest::currentTestFailed())
            return;
        attack(attackedSite, attacked);
        if (QTest::currentTestFailed())
            return;
        finish(quietSite, quiet, false);
        if (QTest::currentTestFailed())
            return;
        finish(attackedSite, attacked, true);
        if (QTest::currentTestFailed())
            return;
        qInfo("hostile station: %zu datagrams; console answered PING after each: median %.1f ms, max %.1f ms "
              "(bound 100 ms); longest io-thread handler during the attack %.2f ms (bound 10 ms); "
              "counted: %llu rejected, %llu implausible, %llu rate-limited; its own unanswered gap given up: "
              "%s "
              "(%zu cells marked incomplete)",
              attacked.hostileDatagrams, attacked.medianPingMs, attacked.maxPingMs, attacked.maxHandlerMs,
              qulonglong(attacked.rejected), qulonglong(attacked.implausible), qulonglong(attacked.limited),
              attacked.givenUp.empty() ? "no" : "yes", attacked.incomplete.size());
        QVERIFY(!quiet.counted.empty());
        QVERIFY2(attacked.counted == quiet.counted,
                 "pass counts differ from the run without the hostile station");
        // Nothing of the rollers stays given up (a gap of theirs given up under load is recounted once its
        // slots arrive); the quiet run marks nothing incomplete.
        QVERIFY(quiet.givenUp.empty());
        QVERIFY(quiet.incomplete.empty());
        for (const auto& [machine, ranges] : attacked.givenUp) {
            QCOMPARE(int(machine), int(kHostile));
            QCOMPARE(ranges, (std::vector<SlotRange>{{4, 9}}));
        }
        // What the hostile station's own given-up gap marks incomplete is the footprint of its first position
        // after the gap (slot 10 at (0, 0), a 2 m drum; late-join rule of PassCountGrid::advance), no more.
        QVERIFY(!attacked.givenUp.empty());
        QVERIFY(!attacked.incomplete.empty());
        for (const auto& [x, y] : attacked.incomplete)
            QVERIFY2(std::abs(x) <= 1 + attacked.cellSize && std::abs(y) <= 1 + attacked.cellSize,
                     qPrintable(QString("cell (%1, %2) marked incomplete").arg(x).arg(y)));
        QVERIFY(attacked.rejected >= 10);   // phantom ranges, mixed sender, garbage, station cap
        QVERIFY(attacked.implausible >= 4); // NaN, 1e30 m, 1e6 m and 1e5 m drums
        QVERIFY(attacked.limited >= 1);     // the floods
        // Generous bounds (a loaded build machine); the measured figures are printed above.
        // Each datagram's PONG within 100 ms is asserted above (the fastest of at most three PINGs).
        if (!kUnderThreadSanitizer) // a wall-clock figure: meaningless 5-15 times slowed down, printed only
            QVERIFY2(attacked.maxHandlerMs < 500, "no io-thread handler of 0.5 s or more");
    }
};

QTEST_APPLESS_MAIN(TestOsyrisHostile)
#include "test_osyris_hostile.moc"
