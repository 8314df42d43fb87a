// The simulated AHS seen from a bare WebSocket client (no IsoStack) over loopback: production-state sensor
// messages (at connection and on change, consistent with HaulTruckProductionStateV2), periodic and on-error
// InterfaceDiagnosticV1, and the map service on its own socket (research note Q10).
#include "sim/iso23725/SimulatedAhs.h"

#include "protocols/iso23725/Messages.h"
#include "protocols/iso23725/WsEndpoint.h"

#include "protocols/common/Counters.h"
#include "protocols/common/IoThread.h"

#include <QTemporaryDir>
#include <QtTest>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

using namespace ocu::iso23725;
using namespace ocu::sim;
using namespace std::chrono_literals;

namespace {

// Polls pred every 10 ms until true or timeout (every wait ends by itself). Generous: on an idle machine
// every condition holds within a fraction of it.
bool waitFor(const std::function<bool()>& pred, std::chrono::milliseconds timeout = 20000ms) {
    auto end = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < end) {
        if (pred())
            return true;
        std::this_thread::sleep_for(10ms);
    }
    return pred();
}

// One WsEndpoint client on its own io_context thread, recording every text frame in arrival order.
class Client : public WsHandler {
public:
    explicit Client(const std::string& url, const std::string& caFile = {}) : m_io("test-client") {
        WsOptions o;
        o.role = WsRole::Client;
        o.url = url;
        o.tls.caFile = caFile;
        o.backoffMin = 100ms;
        o.backoffMax = 200ms;
        m_io.start();
        m_ok = m_io.call([&] {
            m_ep = std::make_unique<WsEndpoint>(m_io.context(), o, *this, m_counters);
            return m_ep->start().ok();
        });
    }
    ~Client() override { stop(); }

    bool started() const { return m_ok; }
    void stop() {
        if (!m_io.running())
            return;
        m_io.call([&] {
            if (m_ep)
                m_ep->stop();
        });
        m_io.stop();
        m_ep.reset();
    }
    bool open() const {
        std::lock_guard l(m_mu);
        return m_session.has_value();
    }
    bool closed() const {
        std::lock_guard l(m_mu);
        return m_closed;
    }
    void sendText(std::string text) {
        m_io.post([this, text = std::move(text)] {
            std::optional<SessionId> s;
            {
                std::lock_guard l(m_mu);
                s = m_session;
            }
            if (s)
                m_ep->send(*s, text);
        });
    }
    void send(const Body& b, std::optional<Guid> eq = std::nullopt) { sendText(encodeMessage(b, eq)); }
    std::vector<std::string> frames() const {
        std::lock_guard l(m_mu);
        return m_frames;
    }

    void onOpen(SessionId id, const std::string&) override {
        std::lock_guard l(m_mu);
        m_session = id;
    }
    void onText(SessionId, std::string text) override {
        std::lock_guard l(m_mu);
        m_frames.push_back(std::move(text));
    }
    void onClose(SessionId, const std::string&) override {
        std::lock_guard l(m_mu);
        m_session.reset();
        m_closed = true;
    }

private:
    ocu::IoThread m_io;
    ocu::Counters m_counters;
    std::unique_ptr<WsEndpoint> m_ep;
    bool m_ok = false;
    mutable std::mutex m_mu;
    std::optional<SessionId> m_session;
    bool m_closed = false;
    std::vector<std::string> m_frames;
};

// A decoded frame: envelope (JSON) or raw XML map chunk.
struct Frame {
    std::optional<Envelope> env;
    std::string raw;
    bool xml() const { return !env && !raw.empty() && raw.front() == '<'; }
    template <class T> const T* get() const { return env ? env->find<T>() : nullptr; }
};

std::vector<Frame> decodeAll(const std::vector<std::string>& texts) {
    std::vector<Frame> v;
    for (auto& t : texts) {
        Frame f;
        f.raw = t;
        if (auto e = decodeMessage(t))
            f.env = std::move(*e);
        v.push_back(std::move(f));
    }
    return v;
}

template <class T> int countOf(const std::vector<Frame>& frames) {
    int n = 0;
    for (auto& f : frames)
        n += f.get<T>() ? 1 : 0;
    return n;
}

SimulatedAhsConfig baseConfig() {
    SimulatedAhsConfig c;
    c.truckCount = 6;
    c.positionRateHz = 10;
    c.healthEvents = false;
    c.pingInterval = 500ms;
    c.deadAfter = 3000ms;
    return c;
}

FleetDefinitionV2 fmsFleet() {
    return FleetDefinitionV2{"1b9e6a40-3c2d-4f87-8e15-6a7b9c0d2e41", {}};
}

// A count measurement's value; -1 when missing (so QCOMPARE prints both numbers on failure).
double measurement(const InterfaceDiagnosticV1& d, const std::string& name) {
    for (auto& m : d.measurement)
        if (m.name == name && m.unit == "count" && m.value)
            return *m.value;
    return -1;
}

// Periodic diagnostics (measurements only) with the frame index they arrived at.
std::vector<std::pair<std::size_t, InterfaceDiagnosticV1>> periodic(const std::vector<Frame>& frames) {
    std::vector<std::pair<std::size_t, InterfaceDiagnosticV1>> v;
    for (std::size_t i = 0; i < frames.size(); ++i)
        if (auto* d = frames[i].get<InterfaceDiagnosticV1>(); d && !d->measurement.empty())
            v.emplace_back(i, *d);
    return v;
}

std::vector<DiagMessage> diagMessages(const std::vector<Frame>& frames) {
    std::vector<DiagMessage> v;
    for (auto& f : frames)
        if (auto* d = f.get<InterfaceDiagnosticV1>())
            v.insert(v.end(), d->message.begin(), d->message.end());
    return v;
}

const DiagMessage* findCode(const std::vector<DiagMessage>& v, const std::string& code) {
    for (auto& m : v)
        if (m.code == code)
            return &m;
    return nullptr;
}

} // namespace

class TestSimAhsServices : public QObject {
    Q_OBJECT
private slots:
    // (a) HaulTruckProductionStateSensorV1: one per truck in the connection snapshot, then only on change,
    // always consistent with the production state last reported for that truck.
    void productionSensor() {
        auto cfg = baseConfig();
        cfg.timeScale = 40; // a full load-haul-dump cycle in a few wall seconds
        SimulatedAhs ahs(cfg);
        QVERIFY2(ahs.start(), ahs.lastError().c_str());
        Client fms(ahs.url());
        QVERIFY(fms.started());
        QVERIFY(waitFor([&] { return fms.open(); }));
        fms.send(fmsFleet());
        const auto fleet = ahs.fleet();
        QCOMPARE(int(fleet.size()), 6);

        struct Seen {
            int sensors = 0, areaSensors = 0, checkedHauling = 0, checkedLoading = 0;
            std::string failure;
        };
        // Replays the frames in order: the latest production state per truck, each sensor checked against it.
        auto check = [&](const std::vector<Frame>& frames) {
            Seen s;
            std::map<Guid, std::string> state;
            std::map<Guid, HaulTruckProductionStateSensorV1> last;
            for (auto& f : frames) {
                if (!f.env || !f.env->header.equipmentId)
                    continue;
                const Guid& eq = *f.env->header.equipmentId;
                if (auto* p = f.get<HaulTruckProductionStateV2>())
                    state[eq] = p->productionState;
                auto* v = f.get<HaulTruckProductionStateSensorV1>();
                if (!v)
                    continue;
                auto fail = [&](const std::string& why) {
                    if (s.failure.empty())
                        s.failure = "truck " + eq + " in " + state[eq] + ": " + why + " (" + f.raw + ")";
                };
                if (!v->loaded || !v->bodyRaised || !v->parkBrake || !v->payloadWeight || !v->inLoadArea ||
                    !v->inDumpArea)
                    fail("a member is missing");
                else if (last.count(eq) && last[eq] == *v)
                    fail("sent again without a change");
                else if (*v->loaded != (*v->payloadWeight > 0))
                    fail("Loaded disagrees with PayloadWeight");
                else if (*v->inLoadArea && *v->inDumpArea)
                    fail("in the load and the dump area at once");
                else if (state[eq] == "Hauling" && !(*v->loaded && !*v->bodyRaised && !*v->inLoadArea))
                    fail("hauling needs Loaded, body down, out of the load area");
                else if (state[eq] == "Loading" && !(*v->inLoadArea && !*v->loaded && !*v->bodyRaised))
                    fail("loading needs InLoadArea, not yet Loaded, body down");
                else if (state[eq] == "Dumping" && !(*v->inDumpArea && *v->bodyRaised && *v->loaded))
                    fail("dumping needs InDumpArea, BodyRaised, Loaded");
                else if (state[eq] == "Driving" && (*v->loaded || *v->inLoadArea || *v->inDumpArea))
                    fail("driving empty outside the areas");
                else if (*v->bodyRaised && !*v->inDumpArea)
                    fail("body raised outside a dump area");
                if (state[eq].empty())
                    fail("sensor before any production state");
                s.checkedHauling += state[eq] == "Hauling";
                s.checkedLoading += state[eq] == "Loading";
                s.areaSensors += (*v->inLoadArea || *v->inDumpArea) ? 1 : 0;
                last[eq] = *v;
                ++s.sensors;
            }
            return s;
        };

        // At connection: one sensor per truck, inside the snapshot (before MapConnectivityV1).
        QVERIFY(waitFor([&] { return countOf<MapConnectivityV1>(decodeAll(fms.frames())) == 1; }));
        {
            auto frames = decodeAll(fms.frames());
            std::map<Guid, int> perTruck;
            for (auto& f : frames) {
                if (f.get<MapConnectivityV1>())
                    break;
                if (f.get<HaulTruckProductionStateSensorV1>())
                    ++perTruck[*f.env->header.equipmentId];
            }
            QCOMPARE(int(perTruck.size()), 6);
            for (auto& e : fleet)
                QCOMPARE(perTruck[e.equipmentId], 1);
        }

        // On change: trucks arrive at shovels and dumps, load and leave loaded.
        QVERIFY(waitFor(
            [&] {
                auto s = check(decodeAll(fms.frames()));
                return !s.failure.empty() || (s.sensors >= 12 && s.areaSensors >= 1 &&
                                              s.checkedHauling >= 1 && s.checkedLoading >= 1);
            },
            30000ms));
        auto s = check(decodeAll(fms.frames()));
        QVERIFY2(s.failure.empty(), s.failure.c_str());
        QVERIFY(s.sensors >= 12);
        QVERIFY(ahs.counters().get("sim.tx.sensor") >= std::uint64_t(s.sensors - 6)); // more may follow
        // Sensor messages are events, not a stream: far fewer than positions.
        const int positions = countOf<MachinePositionV1>(decodeAll(fms.frames()));
        qInfo("%d positions, %d sensor messages", positions, s.sensors);
        QVERIFY2(positions > 3 * s.sensors,
                 qPrintable(QString("%1 positions, %2 sensor messages").arg(positions).arg(s.sensors)));

        // All-stop: every truck ends up at rest with the park brake on.
        fms.send(MachineAllStopRequestV1{"Apply", newGuid()});
        QVERIFY(waitFor([&] {
            auto frames = decodeAll(fms.frames());
            std::map<Guid, bool> brake;
            for (auto& f : frames)
                if (auto* v = f.get<HaulTruckProductionStateSensorV1>())
                    brake[*f.env->header.equipmentId] = v->parkBrake.value_or(false);
            return std::count_if(brake.begin(), brake.end(), [](auto& b) { return b.second; }) == 6;
        }));
        s = check(decodeAll(fms.frames()));
        QVERIFY2(s.failure.empty(), s.failure.c_str());
        QCOMPARE(ahs.counters().get("sim.rx.rejected"), 0u);
        fms.stop();
    }

    // (b) InterfaceDiagnosticV1: periodic counts per session, and an Error diagnostic per rejected frame.
    void interfaceDiagnostic() {
        auto cfg = baseConfig();
        cfg.interfaceDiagnosticPeriod = 300ms;
        SimulatedAhs ahs(cfg);
        QVERIFY2(ahs.start(), ahs.lastError().c_str());
        Client fms(ahs.url());
        QVERIFY(waitFor([&] { return fms.open(); }));
        fms.send(fmsFleet());

        QVERIFY(waitFor([&] { return periodic(decodeAll(fms.frames())).size() >= 2; }));
        {
            auto frames = decodeAll(fms.frames());
            auto p = periodic(frames);
            auto [at, first] = p[0];
            QCOMPARE(int(first.measurement.size()), 3);
            QVERIFY(first.message.empty());
            // Every frame the AHS sent before this one was received by us, in order.
            QCOMPARE(measurement(first, "MessagesSent"), double(at));
            QVERIFY(at >= 6 * 5 + 4);                              // at least the connection snapshot
            QCOMPARE(measurement(first, "MessagesReceived"), 1.0); // our fleet
            QCOMPARE(measurement(first, "MessagesRejected"), 0.0);
            auto [at2, second] = p[1];
            QCOMPARE(measurement(second, "MessagesSent"), double(at2));
            QVERIFY(at2 > at + 3); // positions at 10 Hz for 6 trucks in between
            QVERIFY(frames[at].env && frames[at2].env);
            auto gap = *frames[at2].env->header.timestamp.unixMs - *frames[at].env->header.timestamp.unixMs;
            QVERIFY2(gap >= 250 && gap <= 1000, std::to_string(gap).c_str());
        }
        QVERIFY(diagMessages(decodeAll(fms.frames())).empty());

        // Invalid JSON: an Error with nothing to refer to.
        fms.sendText("{not json");
        QVERIFY(waitFor([&] { return findCode(diagMessages(decodeAll(fms.frames())), "InvalidJson"); }));
        {
            auto m = *findCode(diagMessages(decodeAll(fms.frames())), "InvalidJson");
            QCOMPARE(m.severity, std::string("Error"));
            QVERIFY(!m.refMember && !m.refTimestamp);
            QVERIFY(m.detail && m.detail->find("invalid JSON") != std::string::npos);
        }
        // A member only the AHS sends, and a member failing validation: named, with the frame's timestamp.
        const std::string ts = "2025-03-14T02:17:42.210Z";
        fms.sendText(R"({"Protocol":"ISO23725","Version":1,"Timestamp":")" + ts + R"(","EquipmentId":")" +
                     ahs.fleet()[0].equipmentId + R"(","MachineAutonomyModeV1":{"AutonomyMode":"Manual"}})");
        fms.sendText(R"({"Protocol":"ISO23725","Version":1,"Timestamp":")" + ts +
                     R"(","MapCommandV1":{"Method":"PUT","Scope":"/"}})");
        QVERIFY(waitFor([&] {
            auto v = diagMessages(decodeAll(fms.frames()));
            return findCode(v, "WrongDirection") && findCode(v, "InvalidMember");
        }));
        auto v = diagMessages(decodeAll(fms.frames()));
        QCOMPARE(int(v.size()), 3);
        for (const char* code : {"WrongDirection", "InvalidMember"}) {
            auto m = *findCode(v, code);
            QCOMPARE(m.severity, std::string("Error"));
            QVERIFY(m.refTimestamp);
            QCOMPARE(m.refTimestamp->text, ts);
        }
        QCOMPARE(findCode(v, "WrongDirection")->refMember,
                 std::optional<std::string>("MachineAutonomyModeV1"));
        QCOMPARE(findCode(v, "InvalidMember")->refMember, std::optional<std::string>("MapCommandV1"));
        QCOMPARE(ahs.counters().get("sim.rx.rejected"), 3u);
        QCOMPARE(ahs.counters().get("sim.tx.interface_diagnostic.error"), 3u);
        // The autonomy mode was not taken from the FMS: no map was sent for the rejected command either.
        QCOMPARE(ahs.counters().get("sim.map.sent"), 0u);

        // The next periodic report counts the four frames received and three rejected.
        const auto before = periodic(decodeAll(fms.frames())).size();
        QVERIFY(waitFor([&] { return periodic(decodeAll(fms.frames())).size() > before; }));
        auto last = periodic(decodeAll(fms.frames())).back().second;
        QCOMPARE(measurement(last, "MessagesReceived"), 4.0);
        QCOMPARE(measurement(last, "MessagesRejected"), 3.0);
        QVERIFY(ahs.counters().get("sim.tx.interface_diagnostic") >= 3);
        fms.stop();
    }

    // (c) The map service on its own socket: identification first, summary and chunks there; the main
    // socket keeps MapConnectivityV1 and points MapCommandV1 elsewhere.
    void separateMapService() {
        auto cfg = baseConfig();
        cfg.separateMapService = true;
        SimulatedAhs ahs(cfg);
        QVERIFY2(ahs.start(), ahs.lastError().c_str());
        const auto mapUrl = ahs.mapUrl();
        QVERIFY(ahs.mapPort() != 0 && ahs.mapPort() != ahs.port());
        QCOMPARE(mapUrl, "ws://127.0.0.1:" + std::to_string(ahs.mapPort()) + "/map");

        Client fms(ahs.url());
        QVERIFY(waitFor([&] { return fms.open(); }));
        fms.send(fmsFleet());
        QVERIFY(waitFor([&] { return countOf<MapConnectivityV1>(decodeAll(fms.frames())) == 1; }));
        fms.send(MapCommandV1{"GET", "/"});
        QVERIFY(
            waitFor([&] { return findCode(diagMessages(decodeAll(fms.frames())), "MapServiceElsewhere"); }));
        {
            auto m = *findCode(diagMessages(decodeAll(fms.frames())), "MapServiceElsewhere");
            QCOMPARE(m.severity, std::string("Warning"));
            QVERIFY(m.detail && m.detail->find(mapUrl) != std::string::npos);
            QCOMPARE(m.refMember, std::optional<std::string>("MapCommandV1"));
        }

        // The map client sends nothing first: the service identifies itself, then the summary.
        Client map(mapUrl);
        QVERIFY(waitFor([&] { return map.frames().size() >= 2; }));
        auto mf = decodeAll(map.frames());
        QVERIFY(mf[0].get<MapServiceV1>());
        QCOMPARE(mf[0].get<MapServiceV1>()->api, std::int64_t(1));
        QVERIFY(mf[0].raw.find("\"MapServiceV1\"") != std::string::npos);
        QVERIFY(mf[1].get<MapSummaryV1>());
        const auto first = *mf[1].get<MapSummaryV1>();
        QVERIFY(first.documentCount >= 3);
        QCOMPARE(ahs.stats().mapSessions, std::size_t(1));

        // GET "/": summary, then DocumentCount raw XML chunks.
        map.send(MapCommandV1{"GET", "/"});
        const std::size_t want = 2 + 1 + std::size_t(first.documentCount);
        QVERIFY(waitFor([&] { return map.frames().size() >= want; }));
        mf = decodeAll(map.frames());
        QVERIFY(mf[2].get<MapSummaryV1>());
        QCOMPARE(*mf[2].get<MapSummaryV1>(), first);
        for (std::size_t i = 3; i < want; ++i) {
            QVERIFY(mf[i].xml());
            QVERIFY(mf[i].raw.find("sequence=\"" + std::to_string(i - 2) + "\"") != std::string::npos);
        }
        map.send(MapCommandV1{"GET", "/summary"});
        QVERIFY(waitFor([&] { return countOf<MapSummaryV1>(decodeAll(map.frames())) == 3; }));

        // A map edit: a new summary on the map service only.
        ahs.bumpMapChangeSet();
        QVERIFY(waitFor([&] { return countOf<MapSummaryV1>(decodeAll(map.frames())) == 4; }));
        mf = decodeAll(map.frames());
        QCOMPARE(mf.back().get<MapSummaryV1>()->changeSetMap, first.changeSetMap + 1);
        QCOMPARE(countOf<MapServiceV1>(mf), 1);

        // Give a wrongly routed summary time to show up on the main socket, then check it never did.
        std::this_thread::sleep_for(200ms);
        auto main = decodeAll(fms.frames());
        QCOMPARE(countOf<MapServiceV1>(main), 0);
        QCOMPARE(countOf<MapSummaryV1>(main), 0);
        QVERIFY(std::none_of(main.begin(), main.end(), [](const Frame& f) { return f.xml(); }));
        QCOMPARE(countOf<MapConnectivityV1>(main), 1);
        QVERIFY(countOf<FleetDefinitionV2>(main) == 1 && main.front().get<FleetDefinitionV2>());
        QCOMPARE(ahs.counters().get("sim.rx.rejected"), 0u);

        // stop() closes both services.
        ahs.stop();
        QVERIFY(waitFor([&] { return fms.closed() && map.closed(); }));
        QVERIFY(!ahs.running());
        map.stop();
        fms.stop();
    }

    // wss://: the map service uses the main service's certificate (a test CA made here with openssl).
    void separateMapServiceTls() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const std::string d = dir.path().toStdString();
        auto run = [](const std::string& cmd) {
            return std::system((cmd + " >/dev/null 2>&1").c_str()) == 0;
        };
        const std::string ec = "openssl req -newkey ec -pkeyopt ec_paramgen_curve:prime256v1 -nodes ";
        std::ofstream(d + "/server.ext") << "subjectAltName=IP:127.0.0.1\nextendedKeyUsage=serverAuth\n"
                                         << "basicConstraints=CA:FALSE\n";
        QVERIFY(run(ec +
                    "-x509 -days 2 -subj /CN=ca -addext basicConstraints=critical,CA:TRUE -addext "
                    "keyUsage=critical,keyCertSign,cRLSign -keyout " +
                    d + "/ca.key -out " + d + "/ca.pem"));
        QVERIFY(run(ec + "-subj /CN=server -keyout " + d + "/server.key -out " + d + "/server.csr"));
        QVERIFY(run("openssl x509 -req -days 2 -in " + d + "/server.csr -CA " + d + "/ca.pem -CAkey " + d +
                    "/ca.key -CAcreateserial -extfile " + d + "/server.ext -out " + d + "/server.pem"));

        auto cfg = baseConfig();
        cfg.truckCount = 2;
        cfg.tls = true;
        cfg.certFile = d + "/server.pem";
        cfg.keyFile = d + "/server.key";
        cfg.separateMapService = true;
        SimulatedAhs ahs(cfg);
        QVERIFY2(ahs.start(), ahs.lastError().c_str());
        QCOMPARE(ahs.mapUrl(), "wss://127.0.0.1:" + std::to_string(ahs.mapPort()) + "/map");
        Client map(ahs.mapUrl(), d + "/ca.pem");
        QVERIFY(waitFor([&] { return map.frames().size() >= 2; }));
        auto mf = decodeAll(map.frames());
        QVERIFY(mf[0].get<MapServiceV1>());
        QVERIFY(mf[1].get<MapSummaryV1>());
        map.send(MapCommandV1{"GET", "/"});
        const auto want = 2 + 1 + std::size_t(mf[1].get<MapSummaryV1>()->documentCount);
        QVERIFY(waitFor([&] { return map.frames().size() >= want; }));
        QVERIFY(decodeAll(map.frames())[want - 1].xml());
        // A plain ws:// client gets nothing from the wss:// map service.
        Client plain("ws://127.0.0.1:" + std::to_string(ahs.mapPort()) + "/map");
        std::this_thread::sleep_for(300ms);
        QVERIFY(!plain.open() && plain.frames().empty());
        plain.stop();
        map.stop();
    }

    // With the map on the main socket (default), nothing changed: identification and summary in the
    // snapshot, GET "/" answered there.
    void sharedMapServiceUnchanged() {
        auto cfg = baseConfig();
        SimulatedAhs ahs(cfg);
        QVERIFY2(ahs.start(), ahs.lastError().c_str());
        QCOMPARE(ahs.mapPort(), std::uint16_t(0));
        Client fms(ahs.url());
        QVERIFY(waitFor([&] { return fms.open(); }));
        QVERIFY(waitFor([&] { return countOf<MapSummaryV1>(decodeAll(fms.frames())) == 1; }));
        fms.send(MapCommandV1{"GET", "/"});
        QVERIFY(waitFor([&] {
            auto f = decodeAll(fms.frames());
            return std::count_if(f.begin(), f.end(), [](const Frame& x) { return x.xml(); }) >= 3;
        }));
        auto f = decodeAll(fms.frames());
        QCOMPARE(countOf<MapServiceV1>(f), 1);
        QCOMPARE(countOf<MapSummaryV1>(f), 2);
        QVERIFY(diagMessages(f).empty());
        fms.stop();
    }
};

QTEST_GUILESS_MAIN(TestSimAhsServices)
#include "test_sim_ahs_services.moc"
