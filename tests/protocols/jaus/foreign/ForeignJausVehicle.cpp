#include "tests/protocols/jaus/foreign/ForeignJausVehicle.h"

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/udp.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/steady_timer.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <set>
#include <thread>

namespace foreign {

namespace asio = boost::asio;
using asio::ip::udp;
using Clock = std::chrono::steady_clock;

namespace {

// Message IDs (AS5710A core, jaus-wire.md §3.1).
enum : std::uint16_t {
    SetEmergency = 0x0006,
    ClearEmergency = 0x0007,
    Standby = 0x0003,
    Resume = 0x0004,
    RequestControl = 0x000D,
    ReleaseControl = 0x000E,
    ConfirmControl = 0x000F,
    RejectControl = 0x0010,
    QueryStatus = 0x2002,
    QueryTimeout = 0x2003,
    QueryControl = 0x200D,
    QueryIdentification = 0x2B00,
    QueryServices = 0x2B03,
    ReportStatus = 0x4002,
    ReportTimeout = 0x4003,
    ReportControl = 0x400D,
    ReportIdentification = 0x4B00,
    ReportServices = 0x4B03,
    RegisterServices = 0x0B00,
    QueryConfiguration = 0x2B01,
    QueryGlobalPose = 0x2402,
    QueryLocalPose = 0x2403,
    QueryVelocityState = 0x2404,
    ReportGlobalPose = 0x4402,
    ReportLocalPose = 0x4403,
    ReportVelocityState = 0x4404,
    // IOP Digital Resource Discovery 1.1 (jaus-services-extra.md §1.1)
    QueryDigitalResourceEndpoint = 0xE702,
    ReportDigitalResourceEndpoint = 0xF702,
};

// AS6009 scaled integers: value in [lo, hi] over the whole unsigned range (jaus-wire.md §3.4).
std::uint32_t scaled32(double v, double lo, double hi) {
    return std::uint32_t((v - lo) / (hi - lo) * 4294967295.0 + 0.5);
}
std::uint16_t scaled16(double v, double lo, double hi) {
    return std::uint16_t((v - lo) / (hi - lo) * 65535.0 + 0.5);
}

// One AS5669A general-transport-header message (no header compression, single fragment).
struct Message {
    std::uint8_t props = 0; // priority bits 0-1, broadcast 2-3, ACK/NAK 4-5, data flags 6-7
    std::uint32_t destination = 0, source = 0;
    Buf payload; // message ID + body
    std::uint16_t sequence = 0;
};

// Datagram = version 0x02, then messages of [type u8][size u16 = 14 + payload][props][dst u32][src u32]
// [payload][seq u16], all little-endian (jaus-wire.md §2.1). False when the bytes break that layout.
bool parse(const std::uint8_t* d, std::size_t n, std::vector<Message>& out) {
    if (n < 1 || d[0] != 0x02)
        return false;
    std::size_t i = 1;
    while (i < n) {
        if (n - i < 3 || d[i] != 0) // type 0 = normal, no header compression
            return false;
        const std::size_t size = get16(d + i + 1);
        if (size < 14 || i + size > n)
            return false;
        Message m;
        m.props = d[i + 3];
        m.destination = get32(d + i + 4);
        m.source = get32(d + i + 8);
        m.payload.assign(d + i + 12, d + i + size - 2);
        m.sequence = get16(d + i + size - 2);
        if ((m.props >> 6) != 0) // fragments: a console never needs them for what we answer
            return false;
        out.push_back(std::move(m));
        i += size;
    }
    return true;
}

Buf frame(std::uint8_t props, std::uint32_t dst, std::uint32_t src, const Buf& payload, std::uint16_t seq) {
    Buf b;
    put8(b, 0x02);
    put8(b, 0);
    put16(b, std::uint16_t(14 + payload.size()));
    put8(b, props);
    put32(b, dst);
    put32(b, src);
    b.insert(b.end(), payload.begin(), payload.end());
    put16(b, seq);
    return b;
}

Buf withId(std::uint16_t id) {
    Buf b;
    put16(b, id);
    return b;
}

} // namespace

struct ForeignJausVehicle::Impl {
    explicit Impl(VehicleOptions o) : opt(std::move(o)), socket(io), timer(io) {
        socket.open(udp::v4());
        socket.bind(udp::endpoint(asio::ip::make_address_v4("127.0.0.1"), opt.port));
        self = id(opt.subsystem, opt.node, opt.component);
        comps.push_back(Comp{opt.component, opt.services, opt.management, opt.accessControl, opt.pose});
        for (const ExtraComponent& e : opt.extraComponents)
            comps.push_back(Comp{e.component, e.services, e.management, e.accessControl, e.pose});
        if (opt.listDriverComponent) {
            ownList = opt.listDriverComponent != opt.component;
            list = std::make_unique<WaypointListDriver>(
                opt.listDriver, id(opt.subsystem, opt.node, opt.listDriverComponent),
                ownList ? listController : controller, ownList ? listStatus : status, controller);
        }
        if (opt.platformServicesComponent)
            platform = std::make_unique<PlatformServices>(controller, status, beforeEmergency);
        if (opt.handoffComponent)
            eac = std::make_unique<EnhancedAccessControl>(
                opt.handoff, controller, controllerAuthority,
                [this, from = id(opt.subsystem, opt.node, opt.handoffComponent)](
                    std::uint32_t to, const Buf& b) { reply(to, b, from); });
        lat0 = opt.latitude;
        lon0 = opt.longitude;
        x0 = opt.localX;
        y0 = opt.localY;
        started = Clock::now();
        receive();
        tick();
        thread = std::thread([this] { io.run(); });
    }
    ~Impl() {
        io.stop();
        if (thread.joinable())
            thread.join();
    }

    struct Comp {
        std::uint8_t component = 1;
        std::vector<std::string> services;
        bool management = false, accessControl = false, pose = false;
    };
    std::uint32_t idOf(const Comp& c) const { return id(opt.subsystem, opt.node, c.component); }

    bool forComp(std::uint32_t dst, const Comp& c) const {
        const std::uint16_t ss = std::uint16_t(dst >> 16);
        const std::uint8_t node = std::uint8_t(dst >> 8), comp = std::uint8_t(dst);
        return (ss == 0xFFFF || ss == opt.subsystem) && (node == 0xFF || node == opt.node) &&
               (comp == 0xFF || comp == c.component);
    }

    void receive() {
        socket.async_receive_from(asio::buffer(buffer), from,
                                  [this](boost::system::error_code ec, std::size_t n) {
                                      if (ec == asio::error::operation_aborted)
                                          return;
                                      if (!ec && !offline)
                                          onDatagram(n);
                                      receive();
                                  });
    }

    void onDatagram(std::size_t n) {
        std::vector<Message> msgs;
        std::lock_guard lock(mutex);
        if (!parse(buffer.data(), n, msgs)) {
            ++malformed;
            return;
        }
        for (Message& m : msgs) {
            bool counted = false;
            for (const Comp& c : comps) {
                if (!forComp(m.destination, c))
                    continue;
                endpoints[m.source] = from;
                if (((m.props >> 4) & 3) == 1 && m.destination == idOf(c)) // ACK requested: ACK it (same seq)
                    send(from, frame(std::uint8_t(0x30 | (m.props & 3)), m.source, idOf(c), {}, m.sequence),
                         false);
                if (m.payload.size() < 2)
                    continue;
                const std::uint16_t mid = get16(m.payload.data());
                if (!counted) {
                    counted = true;
                    ++counts[mid];
                    ++countsFrom[{mid, m.source}];
                }
                ++countsBy[{mid, c.component}];
                handle(c, mid, m.source, m.payload.data() + 2, m.payload.size() - 2);
            }
        }
    }

    void reply(std::uint32_t to, const Buf& payload, std::uint32_t from = 0) {
        auto it = endpoints.find(to);
        if (it == endpoints.end())
            return;
        send(it->second, frame(0x01, to, from ? from : self, payload, seq++), true);
    }

    // ReportServices: one node with the given components (none: "0 components").
    Buf reportServices(const std::vector<const Comp*>& list) const {
        Buf b = withId(ReportServices);
        put8(b, 1); // nodes
        put8(b, opt.node);
        put8(b, std::uint8_t(list.size()));
        for (const Comp* c : list) {
            put8(b, c->component);
            put8(b, 0); // instance
            put8(b, std::uint8_t(c->services.size()));
            for (auto& uri : c->services) {
                putStr8(b, uri);
                put8(b, 1);
                put8(b, 1);
            }
        }
        return b;
    }

    // The components a QueryServices names: {node u8; list u8 x component u8}, 255 = all (AS5710A).
    std::vector<const Comp*> named(const std::uint8_t* body, std::size_t len, bool& wildcard) const {
        std::vector<const Comp*> out;
        wildcard = false;
        if (len < 1)
            return out;
        std::size_t i = 1;
        for (int n = 0; n < body[0] && i + 2 <= len; ++n) {
            const std::uint8_t node = body[i], count = body[i + 1];
            i += 2;
            for (int k = 0; k < count && i < len; ++k, ++i) {
                const std::uint8_t comp = body[i];
                if (node == 0xFF || comp == 0xFF)
                    wildcard = true;
                for (const Comp& c : comps)
                    if ((node == 0xFF || node == opt.node) && (comp == 0xFF || comp == c.component))
                        out.push_back(&c);
            }
        }
        return out;
    }

    Buf registration(const Comp& c) const {
        Buf b = withId(RegisterServices);
        put8(b, std::uint8_t(c.services.size()));
        for (auto& uri : c.services) {
            putStr8(b, uri);
            put8(b, 1);
            put8(b, 1);
        }
        return b;
    }

    void send(const udp::endpoint& to, Buf datagram, bool delayed) {
        if (offline)
            return;
        if (!delayed || opt.replyDelayMs <= 0) {
            boost::system::error_code ec;
            socket.send_to(asio::buffer(datagram), to, 0, ec);
            return;
        }
        auto t = std::make_shared<asio::steady_timer>(io, std::chrono::milliseconds(opt.replyDelayMs));
        t->async_wait([this, t, to, d = std::move(datagram)](boost::system::error_code ec) {
            if (ec || offline)
                return;
            socket.send_to(asio::buffer(d), to, 0, ec);
        });
    }

    void handle(const Comp& c, std::uint16_t mid, std::uint32_t src, const std::uint8_t* body,
                std::size_t len) {
        const bool first = &c == &comps.front(); // the Discovery component (platform manager)
        const std::uint32_t me = idOf(c);
        if (list && c.component == opt.listDriverComponent) {
            if (ownList && handleOwnControl(mid, src, body, len, me))
                return;
            std::vector<Buf> replies;
            if (list->handle(mid, src, body, len, replies)) {
                for (const Buf& r : replies)
                    reply(src, r, me);
                return;
            }
        }
        if (platform && c.component == opt.platformServicesComponent) {
            std::vector<Buf> replies;
            if (platform->handle(mid, src, body, len, replies)) {
                for (const Buf& r : replies)
                    reply(src, r, me);
                return;
            }
        }
        if (eac && c.component == opt.handoffComponent && eac->handle(mid, src, body, len))
            return;
        switch (mid) {
        case QueryIdentification: {
            if (len < 1 || (!first && !opt.everyComponentIdentifies))
                return;
            Buf b = withId(ReportIdentification);
            put8(b, body[0]);
            put16(b, body[0] == 2 ? 10001 : body[0] == 3 ? 40001 : 60001); // VEHICLE, NODE, COMPONENT
            putStr8(b, opt.callSign);
            return reply(src, b, me);
        }
        case QueryServices: {
            bool wildcard = false;
            std::vector<const Comp*> list = named(body, len, wildcard);
            switch (opt.servicesDialect) {
            case ServicesDialect::Report:
                if (!first)
                    return;
                return reply(src, reportServices(list), me);
            case ServicesDialect::EmptyWildcardRegister:
                registerTo.insert(src);
                if (wildcard) // "all" answered with nothing, from the Discovery component only
                    return first ? reply(src, reportServices({}), me) : void();
                // A named query: answered by the Discovery component and by the named component itself.
                if (first || std::find(list.begin(), list.end(), &c) != list.end())
                    return reply(src, reportServices(list), me);
                return;
            case ServicesDialect::Silent:
                if (first && wildcard)
                    return reply(src, reportServices({}), me);
                return;
            }
            return;
        }
        case QueryGlobalPose:
        case QueryLocalPose:
        case QueryVelocityState:
            if (c.pose)
                reply(src, poseReport(mid), me);
            return;
        case RequestControl: {
            if (!c.accessControl || len < 1)
                return;
            const std::uint8_t authority = body[0];
            auto confirm = [&](std::uint8_t code) {
                Buf b = withId(ConfirmControl);
                put8(b, code);
                reply(src, b, me);
            };
            if (controller == 0 || controller == src) {
                controller = src;
                controlComponent = me;
                controllerAuthority = authority;
                lastRequest = Clock::now();
                return confirm(0);
            }
            if (authority > controllerAuthority) { // pre-emption (AS5710A AccessControl)
                const std::uint32_t old = controller;
                controller = src;
                controlComponent = me;
                controllerAuthority = authority;
                lastRequest = Clock::now();
                if (opt.tellOldController)
                    rejectTo(old, 0, me);
                if (opt.rejectThenConfirm)
                    rejectTo(src, 0, me);
                return confirm(0);
            }
            return confirm(2); // INSUFFICIENT_AUTHORITY
        }
        case ReleaseControl:
            if (c.accessControl && src == controller) {
                controller = 0;
                controllerAuthority = 0;
                rejectTo(src, 0, me); // CONTROL_RELEASED
            }
            return;
        case QueryControl:
            if (c.accessControl && opt.answerQueryControl) {
                Buf b = withId(ReportControl);
                put16(b, std::uint16_t(controller >> 16));
                put8(b, std::uint8_t(controller >> 8));
                put8(b, std::uint8_t(controller));
                put8(b, controllerAuthority);
                reply(src, b, me);
            }
            return;
        case QueryTimeout:
            if (c.accessControl && opt.answerQueryTimeout) {
                Buf b = withId(ReportTimeout);
                put8(b, opt.accessTimeoutS);
                reply(src, b, me);
            }
            return;
        case SetEmergency: // from any client (AS5710A Management)
            if (c.management && len >= 2 && status != 5) {
                beforeEmergency = status;
                status = 5;
                if (list)
                    list->emergency();
            }
            return;
        case ClearEmergency:
            if (c.management && len >= 2 && status == 5)
                status = beforeEmergency;
            return;
        case Resume:
        case Standby:
            if (c.management && src == controller && status != 5)
                status = mid == Resume ? 1 : 2;
            return;
        case QueryStatus:
            if (c.management) {
                Buf b = withId(ReportStatus);
                put8(b, status);
                put32(b, 0);
                reply(src, b, me);
            }
            return;
        case QueryDigitalResourceEndpoint: {
            if (Clock::now() - started < std::chrono::milliseconds(opt.drdSilentFirstMs))
                return; // still "starting up": silently ignored, the client must retry
            // count u8, then {PV u8; ServerType u8; URL str8; [JAUS_ID u32]; [ResourceID u16]}
            Buf b = withId(ReportDigitalResourceEndpoint);
            put8(b, std::uint8_t(opt.streams.size()));
            for (const AnnouncedStream& st : opt.streams) {
                put8(b, std::uint8_t((st.withHost ? 1 : 0) | (st.withResourceId ? 2 : 0)));
                put8(b, st.serverType);
                putStr8(b, st.url);
                if (st.withHost)
                    put32(b, me);
                if (st.withResourceId)
                    put16(b, st.resourceId);
            }
            return reply(src, b, me);
        }
        default:
            return; // CreateEvent, QueryHeartbeatPulse, Visual Sensor ...: not offered, not answered
        }
    }

    // The list driver's own access control and Management state (a component of its own).
    bool handleOwnControl(std::uint16_t mid, std::uint32_t src, const std::uint8_t*, std::size_t len,
                          std::uint32_t me) {
        switch (mid) {
        case RequestControl: {
            if (len < 1)
                return true;
            Buf b = withId(ConfirmControl);
            const bool ok = listController == 0 || listController == src;
            if (ok)
                listController = src;
            put8(b, ok ? 0 : 2);
            reply(src, b, me);
            return true;
        }
        case ReleaseControl:
            if (src == listController) {
                listController = 0;
                if (listStatus == 1)
                    listStatus = 2;
                rejectTo(src, 0, me);
            }
            return true;
        case Resume:
        case Standby:
            if (src == listController && status != 5)
                listStatus = mid == Resume ? 1 : 2;
            return true;
        case QueryStatus: {
            Buf b = withId(ReportStatus);
            put8(b, status == 5 ? 5 : listStatus);
            put32(b, 0);
            reply(src, b, me);
            return true;
        }
        default:
            return false;
        }
    }

    // The list driver drives the pose: local x north, y east; the global pose follows on the WGS84
    // ellipsoid's radii of curvature at the start.
    void drive(double dt) {
        if (!list)
            return;
        list->step(dt, status == 5, opt.localX, opt.localY);
        constexpr double a = 6378137.0, e2 = 6.69437999014e-3, rad = 3.14159265358979 / 180;
        const double s = std::sin(lat0 * rad), w = 1 - e2 * s * s;
        const double meridian = a * (1 - e2) / std::pow(w, 1.5), normal = a / std::sqrt(w);
        opt.latitude = lat0 + (opt.localX - x0) / meridian / rad;
        opt.longitude = lon0 + (opt.localY - y0) / (normal * std::cos(lat0 * rad)) / rad;
        if (list->executing() && controller == id(opt.subsystem, opt.node, opt.listDriverComponent))
            lastRequest = Clock::now(); // it holds the drive component while it drives
    }

    void rejectTo(std::uint32_t to, std::uint8_t code, std::uint32_t from = 0) {
        Buf b = withId(RejectControl);
        put8(b, code);
        reply(to, b, from ? from : controlComponent);
    }

    // The pose reports with every field the query may ask for; peers often ignore the presence vector
    // (jaus-wire.md §6), and so does this one.
    Buf poseReport(std::uint16_t query) const {
        if (query == QueryGlobalPose) {
            Buf b = withId(ReportGlobalPose);
            put16(b, 0x0043); // latitude, longitude, yaw
            put32(b, scaled32(opt.latitude, -90, 90));
            put32(b, scaled32(opt.longitude, -180, 180));
            put16(b, scaled16(opt.yaw, -3.14159265358979, 3.14159265358979));
            return b;
        }
        if (query == QueryLocalPose) {
            Buf b = withId(ReportLocalPose);
            put16(b, 0x0043); // x, y, yaw
            put32(b, scaled32(opt.localX, -100000, 100000));
            put32(b, scaled32(opt.localY, -100000, 100000));
            put16(b, scaled16(opt.yaw, -3.14159265358979, 3.14159265358979));
            return b;
        }
        Buf b = withId(ReportVelocityState);
        put16(b, 0x0001); // velocity x
        put32(b, scaled32(0.0, -327.68, 327.67));
        return b;
    }

    void tick() {
        timer.expires_after(std::chrono::milliseconds(50));
        timer.async_wait([this](boost::system::error_code ec) {
            if (ec)
                return;
            {
                std::lock_guard lock(mutex);
                drive(0.05);
                if (eac)
                    eac->tick(Clock::now());
                // Each component (re-)registers its services with every console that asked (AS5710A
                // RegisterServices; public stacks repeat it until their registration is verified).
                if (opt.servicesDialect == ServicesDialect::EmptyWildcardRegister && opt.pushRegistrations &&
                    Clock::now() - lastRegistration > std::chrono::milliseconds(500)) {
                    lastRegistration = Clock::now();
                    for (std::uint32_t to : registerTo)
                        for (const Comp& c : comps)
                            reply(to, registration(c), idOf(c));
                }
                if (controller != 0 &&
                    Clock::now() - lastRequest > std::chrono::seconds(opt.accessTimeoutS)) {
                    if (opt.tellOldController)
                        rejectTo(controller, 0);
                    controller = 0;
                    controllerAuthority = 0;
                }
            }
            tick();
        });
    }

    VehicleOptions opt;
    asio::io_context io;
    udp::socket socket;
    asio::steady_timer timer;
    std::thread thread;
    std::array<std::uint8_t, 65536> buffer{};
    udp::endpoint from;
    std::uint32_t self = 0;
    Clock::time_point started{};
    std::atomic<bool> offline{false};

    mutable std::mutex mutex; // everything below
    std::map<std::uint32_t, udp::endpoint> endpoints;
    std::map<std::uint16_t, int> counts;
    std::map<std::pair<std::uint16_t, std::uint32_t>, int> countsFrom;
    std::map<std::pair<std::uint16_t, std::uint8_t>, int> countsBy;
    std::vector<Comp> comps;
    std::set<std::uint32_t> registerTo;
    Clock::time_point lastRegistration{};
    std::uint32_t controlComponent = 0; // the component that confirmed the current control
    int malformed = 0;
    std::uint16_t seq = 0;
    std::uint32_t controller = 0;
    std::uint8_t controllerAuthority = 0;
    Clock::time_point lastRequest{};
    std::uint8_t status = 2; // STANDBY
    std::uint8_t beforeEmergency = 2;
    // The waypoint list driver (listDriverComponent): its own control and state when on its own component.
    std::unique_ptr<WaypointListDriver> list;
    bool ownList = false;
    std::uint32_t listController = 0;
    std::uint8_t listStatus = 2;
    std::unique_ptr<PlatformServices> platform; // platformServicesComponent
    std::unique_ptr<EnhancedAccessControl> eac; // handoffComponent
    double lat0 = 0, lon0 = 0, x0 = 0, y0 = 0;
};

ForeignJausVehicle::ForeignJausVehicle(VehicleOptions options)
    : m_impl(std::make_unique<Impl>(std::move(options))) {}
ForeignJausVehicle::~ForeignJausVehicle() = default;

std::uint16_t ForeignJausVehicle::port() const {
    return m_impl->socket.local_endpoint().port();
}
void ForeignJausVehicle::setOffline(bool offline) {
    m_impl->offline = offline;
}
std::uint32_t ForeignJausVehicle::controller() const {
    std::lock_guard lock(m_impl->mutex);
    return m_impl->controller;
}
std::uint32_t ForeignJausVehicle::lights() const {
    std::lock_guard lock(m_impl->mutex);
    return m_impl->platform ? m_impl->platform->lights() : 0;
}
std::uint8_t ForeignJausVehicle::status() const {
    std::lock_guard lock(m_impl->mutex);
    return m_impl->status;
}
int ForeignJausVehicle::received(std::uint16_t mid) const {
    std::lock_guard lock(m_impl->mutex);
    auto it = m_impl->counts.find(mid);
    return it == m_impl->counts.end() ? 0 : it->second;
}
int ForeignJausVehicle::receivedFrom(std::uint16_t mid, std::uint32_t src) const {
    std::lock_guard lock(m_impl->mutex);
    auto it = m_impl->countsFrom.find({mid, src});
    return it == m_impl->countsFrom.end() ? 0 : it->second;
}
int ForeignJausVehicle::receivedBy(std::uint16_t mid, std::uint8_t component) const {
    std::lock_guard lock(m_impl->mutex);
    auto it = m_impl->countsBy.find({mid, component});
    return it == m_impl->countsBy.end() ? 0 : it->second;
}
std::uint16_t ForeignJausVehicle::activeElement() const {
    std::lock_guard lock(m_impl->mutex);
    return m_impl->list ? m_impl->list->active() : 0;
}
std::pair<double, double> ForeignJausVehicle::localPosition() const {
    std::lock_guard lock(m_impl->mutex);
    return {m_impl->opt.localX, m_impl->opt.localY};
}
std::size_t ForeignJausVehicle::handoffsQueued() const {
    std::lock_guard lock(m_impl->mutex);
    return m_impl->eac ? m_impl->eac->queued() : 0;
}
int ForeignJausVehicle::handoffsGranted() const {
    std::lock_guard lock(m_impl->mutex);
    return m_impl->eac ? m_impl->eac->granted() : 0;
}
int ForeignJausVehicle::malformed() const {
    std::lock_guard lock(m_impl->mutex);
    return m_impl->malformed;
}

} // namespace foreign
