#include "tests/protocols/iso23725/foreign/ForeignAhs.h"

#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <regex>

namespace foreign {

namespace beast = boost::beast;
namespace websocket = boost::beast::websocket;
using tcp = boost::asio::ip::tcp;

struct ForeignAhs::Net {
    boost::asio::io_context io;
    tcp::acceptor acceptor{io};
    tcp::socket* current = nullptr; // the FMS's socket while one is connected (guarded by m_mu)
};

namespace {

// The header of §4.2 / §5 ("Protocol", "Version", "Timestamp" and, about one machine, "EquipmentId").
std::string header(const std::string& equipmentId, const std::string& time = "2025-03-14T02:20:30.000Z") {
    std::string h = R"("Protocol":"ISO23725","Version":1,"Timestamp":")" + time + "\"";
    if (!equipmentId.empty())
        h += R"(,"EquipmentId":")" + equipmentId + "\"";
    return h;
}

using Dialect = ForeignAhsOptions::Dialect;

// One production frame: `fields` are the members of the message body in the tables' order, each with
// whether the table marks it optional (sh / m). Minimal leaves the optional ones out, Extra adds unknown
// members (in the body and a whole unknown message next to it), Reordered writes the body's fields and the
// header's members in reverse order.
struct Field {
    std::string name;
    std::string json;
    bool optional = false;
};
std::string frame(Dialect d, const std::string& truck, const std::string& time, const std::string& message,
                  std::vector<Field> fields) {
    if (d == Dialect::Minimal)
        std::erase_if(fields, [](const Field& f) { return f.optional; });
    if (d == Dialect::Extra)
        fields.push_back({"VendorQuality", R"({"Grade":0.93,"Source":"lab"})", true});
    if (d == Dialect::Reordered)
        std::reverse(fields.begin(), fields.end());
    std::string body;
    for (const Field& f : fields)
        body += (body.empty() ? "" : ",") + ("\"" + f.name + "\":" + f.json);
    const std::string member = "\"" + message + "\":{" + body + "}";
    if (d == Dialect::Reordered)
        return "{" + member + R"(,"EquipmentId":")" + truck + R"(","Timestamp":")" + time +
               R"(","Version":1,"Protocol":"ISO23725"})";
    std::string out = "{" + header(truck, time) + "," + member;
    if (d == Dialect::Extra)
        out += R"(,"VendorTelemetryV7":{"TyreTemp":[61,63,60,62]})";
    return out + "}";
}

std::string q(const std::string& s) {
    return "\"" + s + "\"";
}

// One cycle (research note §6 examples 16-20, values in ForeignProduction): queued and loading at the shovel,
// the payload, hauling loaded, the dump, the cycle, and the truck driving empty again.
std::vector<std::string> productionCycle(Dialect d, const std::string& truck) {
    using P = ForeignProduction;
    const std::string load = q(P::loadAssignment), dump = q(P::dumpAssignment);
    auto state = [&](const std::string& time, const std::string& assignment, std::int64_t way,
                     const std::string& st) {
        return frame(d, truck, time, "HaulTruckProductionStateV2",
                     {{"AssignmentId", assignment},
                      {"WayId", std::to_string(way)},
                      {"AutonomyMode", q("Autonomous")},
                      {"ProductionState", q(st)}});
    };
    auto sensor = [&](const std::string& time, bool loaded, bool raised) {
        return frame(d, truck, time, "HaulTruckProductionStateSensorV1",
                     {{"Loaded", loaded ? "true" : "false", true},
                      {"BodyRaised", raised ? "true" : "false", true},
                      {"ParkBrake", "false", true},
                      {"PayloadWeight", std::to_string(loaded ? P::payload : 0), true}});
    };
    std::vector<std::string> out;
    out.push_back(state("2025-03-14T02:21:02.000Z", load, P::loadWay, "Queued"));
    out.push_back(state("2025-03-14T02:23:10.000Z", load, P::loadWay, "Loading"));
    out.push_back(frame(d, truck, "2025-03-14T02:25:30.000Z", "HaulTruckPayloadV1",
                        {{"PayloadWeight", std::to_string(P::payload)},
                         {"Accuracy", "4.5", true},
                         {"PayloadSourceId", q(P::loader), true}}));
    out.push_back(sensor("2025-03-14T02:25:31.000Z", true, false));
    out.push_back(state("2025-03-14T02:26:00.300Z", dump, P::haulWay, "Hauling"));
    out.push_back(state("2025-03-14T02:56:00.000Z", dump, P::dumpWay, "Dumping"));
    out.push_back(frame(d, truck, "2025-03-14T02:58:39.000Z", "HaulTruckDumpV1",
                        {{"AssignmentId", dump, true},
                         {"WayId", std::to_string(P::dumpWay)},
                         {"DumpedWeight", std::to_string(P::payload), true}}));
    out.push_back(
        frame(d, truck, "2025-03-14T02:58:40.000Z", "HaulTruckProductionCycleV1",
              {{"CycleId", q(P::cycleId)},
               {"AssignmentId", load, true},
               {"LoadWayId", std::to_string(P::loadWay)},
               {"DumpWayId", std::to_string(P::dumpWay)},
               {"LoaderEquipmentId", q(P::loader), true},
               {"PayloadWeight", std::to_string(P::payload), true},
               {"StateTimes",
                R"([{"ProductionState":"Queued","Start":"2025-03-14T02:21:02.000Z","Duration":128},)"
                R"({"ProductionState":"Loading","Start":"2025-03-14T02:23:10.000Z","Duration":140},)"
                R"({"ProductionState":"Hauling","Start":"2025-03-14T02:26:00.300Z","Duration":1800},)"
                R"({"ProductionState":"Dumping","Start":"2025-03-14T02:56:00.000Z","Duration":159}])",
                true}}));
    out.push_back(sensor("2025-03-14T02:58:41.000Z", false, false));
    out.push_back(state("2025-03-14T02:58:42.000Z", "null", P::haulWay, P::finalState));
    return out;
}

} // namespace

ForeignAhs::ForeignAhs(ForeignAhsOptions options)
    : m_opt(std::move(options)), m_net(std::make_unique<Net>()) {
    tcp::endpoint ep(boost::asio::ip::make_address("127.0.0.1"), 0);
    m_net->acceptor.open(ep.protocol());
    m_net->acceptor.set_option(tcp::acceptor::reuse_address(true));
    m_net->acceptor.bind(ep);
    m_net->acceptor.listen();
    m_port = m_net->acceptor.local_endpoint().port();
    m_thread = std::thread([this] { run(); });
}

ForeignAhs::~ForeignAhs() {
    {
        std::lock_guard lock(m_mu);
        m_stopping = true;
        boost::system::error_code ec;
        if (m_net->current)
            m_net->current->shutdown(tcp::socket::shutdown_both, ec);
    }
    // A blocked accept() is not woken by close() on Linux: wake it with a connection of our own.
    {
        boost::asio::io_context io;
        tcp::socket waker(io);
        boost::system::error_code ec;
        waker.connect(tcp::endpoint(boost::asio::ip::make_address("127.0.0.1"), m_port), ec);
        if (m_thread.joinable())
            m_thread.join();
    }
    boost::system::error_code ec;
    m_net->acceptor.close(ec);
}

std::vector<std::string> ForeignAhs::received() const {
    std::lock_guard lock(m_mu);
    return m_received;
}

bool ForeignAhs::connected() const {
    std::lock_guard lock(m_mu);
    return m_connected;
}

std::string ForeignAhs::waitFor(const std::string& needle, int timeoutMs) const {
    std::unique_lock lock(m_mu);
    std::string found;
    m_cv.wait_for(lock, std::chrono::milliseconds(timeoutMs), [&] {
        for (const auto& f : m_received)
            if (f.find(needle) != std::string::npos) {
                found = f;
                return true;
            }
        return false;
    });
    return found;
}

void ForeignAhs::run() {
    for (;;) {
        tcp::socket socket(m_net->io);
        boost::system::error_code ec;
        m_net->acceptor.accept(socket, ec);
        if (ec)
            return; // closed by the destructor
        {
            std::lock_guard lock(m_mu);
            if (m_stopping)
                return;
            m_net->current = &socket;
        }
        serve(&socket);
        std::lock_guard lock(m_mu);
        m_net->current = nullptr;
        m_connected = false;
        if (m_stopping)
            return;
    }
}

void ForeignAhs::serve(void* raw) {
    websocket::stream<tcp::socket&> ws(*static_cast<tcp::socket*>(raw));
    boost::system::error_code ec;
    ws.accept(ec);
    if (ec)
        return;
    {
        std::lock_guard lock(m_mu);
        m_connected = true;
    }
    ws.text(true);
    auto send = [&](const std::string& text) {
        ws.write(boost::asio::buffer(text), ec);
        return !ec;
    };
    const std::string& truck = m_opt.truckId;
    // "At Connection" (research note §10): FleetDefinitionV2 first, then the per-machine state, then
    // MapConnectivityV1 (row 10: a dump area, a road, a load area, and a bay nobody can drive into).
    send(
        "{" + header("") +
        R"(,"FleetDefinitionV2":{"AHSId":"7d1f3c2a-5b8e-4c61-9a0d-2e4f6b8c1a37","Equipment":[{"EquipmentId":")" +
        truck +
        R"(","HID":"HT01","Type":"HaulTruck","OEM":"Caterpillar","Model":"793F","Autonomous":true,"Length":12.9,"Width":7.6}]}})");
    send("{" + header("") + R"(,"MachineAllStopV1":{"ModeAllStop":"Off","ModeAllStopId":null}})");
    send("{" + header(truck) + R"(,"MachineAutonomyModeV1":{"AutonomyMode":"Autonomous"}})");
    if (!m_opt.custodian.empty())
        send("{" + header(truck) + R"(,"MachineDispatchAvailabilityV1":{"DispatchingCustodian":")" +
             m_opt.custodian + "\"}}");
    send("{" + header(truck) + R"(,"HaulTruckProductionStateV2":{"AssignmentId":null,"WayId":)" +
         std::to_string(m_opt.truckWayId) + R"(,"AutonomyMode":"Autonomous","ProductionState":"Parked"}})");
    send(
        "{" + header("") +
        R"(,"MapConnectivityV1":[)"
        R"({"WayId":4101,"WayType":"Area","AreaProperty":{"DefaultTask":"Offload","Name":"North Waste Dump"},"Connection":[{"WayId":2001}]},)"
        R"({"WayId":2001,"WayType":"Road","RoadProperty":{"Length":1840.5,"Name":"North Ramp"},"Connection":[{"WayId":4101},{"WayId":4201}]},)"
        R"({"WayId":4201,"WayType":"Area","AreaProperty":{"DefaultTask":"Load","Name":"Pit 3 Bench 480"},"Connection":[{"WayId":2001}]},)"
        R"({"WayId":4301,"WayType":"Area","AreaProperty":{"DefaultTask":"Park","Name":"Closed Bay"},"Connection":[{"WayId":2001}]}]})");
    if (m_opt.production)
        for (const std::string& f : productionCycle(m_opt.dialect, truck))
            send(f);
    static const std::regex assignmentId(R"re("AssignmentId":"([0-9a-f-]{36})")re");
    for (;;) {
        beast::flat_buffer buffer;
        ws.read(buffer, ec);
        if (ec)
            return;
        std::string text = beast::buffers_to_string(buffer.data());
        {
            std::lock_guard lock(m_mu);
            m_received.push_back(text);
        }
        m_cv.notify_all();
        if (!m_opt.answerAssignments || text.find("\"HaulTruckAssignmentRequestV2\"") == std::string::npos)
            continue;
        // Row 22: one response item per request item; row 24: the first becomes Active.
        std::string items;
        std::string first;
        for (auto it = std::sregex_iterator(text.begin(), text.end(), assignmentId);
             it != std::sregex_iterator(); ++it) {
            if (first.empty())
                first = (*it)[1];
            items += std::string(items.empty() ? "" : ",") + R"({"AssignmentId":")" + (*it)[1].str() +
                     R"(","Response":"Accepted"})";
        }
        if (m_opt.answerDelayMs > 0)
            std::this_thread::sleep_for(std::chrono::milliseconds(m_opt.answerDelayMs));
        send("{" + header(truck) + R"(,"HaulTruckAssignmentResponseV1":[)" + items + "]}");
        if (!first.empty())
            send("{" + header(truck) + R"(,"HaulTruckAssignmentV1":{"AssignmentId":")" + first +
                 R"(","Status":"Active","Task":"Load","DestinationId":4201}})");
        if (!first.empty() &&
            !m_opt.unsolicitedReject.empty()) // row 22: an accepted task can no longer be done
            send("{" + header(truck, "2025-03-14T02:20:31.500Z") +
                 R"(,"HaulTruckAssignmentResponseV1":[{"AssignmentId":")" + first +
                 R"(","Response":"Rejected","Detail":")" + m_opt.unsolicitedReject + "\"}]}");
    }
}

} // namespace foreign
