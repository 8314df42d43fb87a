// The simulated UGV's waypoint services (jaus-autonomy.md §13): ListManager core 1.1 with the Local and
// Global Waypoint List Drivers and the single Local/Global Waypoint Drivers on the Core Mobility Component,
// the PathReporter on the sensor component; the route is driven by the same kinematics as teleop.
// List rules (§2.3): one head, one tail (or circular), references that exist, no self-references; an
// existing UID is updated; elements of one SetElement in any order; the neighbours' links patched on
// insert; RequestID echoed; codes 1-7 on rejection (the list rolled back). ExecuteList only from the
// controller in Ready (UID = start, 0 = head, none or 65535 = speed only); leaving Ready stops and zeroes
// the speed, the active element is kept (Resume does not move until a new ExecuteList).
#include <algorithm>
#include <cmath>
#include <set>

#include "protocols/common/Log.h"
#include "sim/jaus/UgvCore.h"
#include "sim/jaus/UgvSupport.h"

namespace ocu::sim {

using namespace ocu::jaus;
using ugv::kLog;

namespace {

constexpr double kDefaultToleranceM = 1.0; // capture radius when the waypoint gives none
constexpr double kPathStepM = 0.25;        // one historical path point per 0.25 m (FKIE's server)
constexpr std::size_t kPathPoints = 1000;

bool supportedElement(const ListElement& e) {
    const std::uint16_t id = peekMessageId(e.data);
    return e.format == 0 && (id == msg::SetLocalWaypoint || id == msg::SetGlobalWaypoint);
}

// The list's order from its head; empty when the links do not form one valid list (0 = valid).
std::uint8_t validate(const std::map<std::uint16_t, ListElement>& list) {
    if (list.empty())
        return 0;
    std::uint16_t head = 0;
    int heads = 0;
    for (const auto& [uid, e] : list) {
        if (e.previous == uid || e.next == uid)
            return std::uint8_t(ElementRejection::InvalidElementId);
        if (e.previous != 0 && !list.count(e.previous))
            return std::uint8_t(ElementRejection::InvalidPrevious);
        if (e.next != 0 && !list.count(e.next))
            return std::uint8_t(ElementRejection::InvalidNext);
        if (e.previous == 0) {
            head = uid;
            ++heads;
        }
    }
    if (heads > 1)
        return std::uint8_t(ElementRejection::InvalidPrevious);
    if (heads == 0)
        head = list.begin()->first; // circular: every element has a previous one
    std::set<std::uint16_t> seen;
    for (std::uint16_t u = head; u != 0 && !seen.count(u); u = list.at(u).next) {
        seen.insert(u);
        const ListElement& e = list.at(u);
        if (e.next != 0 && list.at(e.next).previous != u)
            return std::uint8_t(ElementRejection::InvalidNext);
    }
    return seen.size() == list.size() ? 0 : std::uint8_t(ElementRejection::Unspecified);
}

std::uint16_t headOf(const std::map<std::uint16_t, ListElement>& list) {
    for (const auto& [uid, e] : list)
        if (e.previous == 0)
            return uid;
    return list.empty() ? 0 : list.begin()->first;
}

} // namespace

void UgvCore::registerWaypoints() {
    const JausId mob = mobility(), sen = sensors();
    m_table.onCommand(msg::SetElement, mob,
                      [this](const JausId&, const JausId& src, ByteSpan p) { setElement(src, p); });
    m_table.onCommand(msg::DeleteElement, mob,
                      [this](const JausId&, const JausId& src, ByteSpan p) { deleteElement(src, p); });
    m_table.onCommand(msg::ExecuteList, mob,
                      [this](const JausId&, const JausId& src, ByteSpan p) { executeList(src, p); });
    for (std::uint16_t id : {msg::SetLocalWaypoint, msg::SetGlobalWaypoint})
        m_table.onCommand(
            id, mob, [this](const JausId&, const JausId& src, ByteSpan p) { setSingleWaypoint(src, p); });
    m_table.onCommand(msg::SetTravelSpeed, mob,
                      [this](const JausId&, const JausId& src, ByteSpan p) { setTravelSpeed(src, p); });
    m_table.onQuery(msg::QueryElement, mob, [this](const JausId&, ByteSpan q) -> std::optional<Bytes> {
        auto uid = decodeU16(q, msg::QueryElement);
        if (!uid)
            return std::nullopt;
        const std::uint16_t u = *uid == kHeadUid ? headOf(m_route.list) : *uid;
        auto it = m_route.list.find(u);
        if (it == m_route.list.end())
            return std::nullopt; // answered only if the element exists (§2.1)
        return encode(it->second);
    });
    m_table.onQuery(msg::QueryElementList, mob, [this](const JausId&, ByteSpan) {
        ReportElementList r; // in list order
        std::set<std::uint16_t> seen;
        for (std::uint16_t u = headOf(m_route.list); u != 0 && seen.insert(u).second;
             u = m_route.list.at(u).next)
            r.uids.push_back(u);
        return encode(r);
    });
    m_table.onQuery(msg::QueryElementCount, mob, [this](const JausId&, ByteSpan) {
        return encodeU16(msg::ReportElementCount, std::uint16_t(m_route.list.size()));
    });
    m_table.onQuery(msg::QueryActiveElement, mob, [this](const JausId&, ByteSpan) {
        return encodeU16(msg::ReportActiveElement, m_route.active);
    });
    m_table.onQuery(msg::QueryTravelSpeed, mob, [this](const JausId&, ByteSpan) {
        return encodeTravelSpeed(msg::ReportTravelSpeed, m_route.speed);
    });
    m_table.onQuery(msg::QueryLocalWaypoint, mob,
                    [this](const JausId&, ByteSpan) { return reportWaypoint(msg::ReportLocalWaypoint); });
    m_table.onQuery(msg::QueryGlobalWaypoint, mob,
                    [this](const JausId&, ByteSpan) { return reportWaypoint(msg::ReportGlobalWaypoint); });
    m_table.onQuery(msg::QueryPathReporterCapabilities, sen, [](const JausId&, ByteSpan) {
        ReportPathReporterCapabilities caps;
        for (std::uint8_t t :
             {std::uint8_t(PathType::HistoricalGlobal), std::uint8_t(PathType::HistoricalLocal)}) {
            PathCapability c;
            c.pathType = t;
            c.maximumPoints = std::uint16_t(kPathPoints);
            caps.paths.push_back(c);
        }
        return encode(caps);
    });
    m_table.onQuery(msg::QueryPath, sen, [this](const JausId&, ByteSpan q) -> std::optional<Bytes> {
        auto m = decodeQueryPath(q);
        if (!m || (m->pathType != 0 && m->pathType != 1))
            return std::nullopt; // an unsupported path type gets no reply (jaus-services-extra.md §3.3)
        return reportPath(q);
    });
}

void UgvCore::setElement(const JausId& src, ByteSpan p) {
    auto m = decodeSetElement(p);
    if (!m)
        return rejectMalformed(m.error());
    if (!isController(src)) {
        m_counters.add("rx.refused.not_controller");
        return;
    }
    auto reject = [&](ElementRejection code) {
        send(mobility(), src, encode(RejectElementRequest{m->requestId, std::uint8_t(code)}));
    };
    auto list = m_route.list;
    for (const ListElement& e : m->elements) {
        if (e.uid == 0 || e.uid == kAllUids)
            return reject(ElementRejection::InvalidElementId);
        if (!supportedElement(e))
            return reject(ElementRejection::UnsupportedType);
        if (list.size() >= 20000 && !list.count(e.uid))
            return reject(ElementRejection::OutOfMemory);
        list[e.uid] = e;
    }
    // The neighbours' links follow the new elements (an insert or an append, §2.3).
    for (const ListElement& e : m->elements) {
        if (e.previous != 0 && list.count(e.previous))
            list[e.previous].next = e.uid;
        if (e.next != 0 && list.count(e.next))
            list[e.next].previous = e.uid;
    }
    if (const std::uint8_t code = validate(list))
        return reject(ElementRejection(code)); // rolled back: the old list stays
    m_route.list = std::move(list);
    send(mobility(), src, encodeU8(msg::ConfirmElementRequest, m->requestId));
}

void UgvCore::deleteElement(const JausId& src, ByteSpan p) {
    auto m = decodeDeleteElement(p);
    if (!m)
        return rejectMalformed(m.error());
    if (!isController(src)) {
        m_counters.add("rx.refused.not_controller");
        return;
    }
    auto list = m_route.list;
    for (std::uint16_t uid : m->uids) {
        if (uid == kAllUids) {
            list.clear();
            continue;
        }
        auto it = list.find(uid);
        if (it == list.end())
            return send(mobility(), src,
                        encode(RejectElementRequest{m->requestId, std::uint8_t(ElementRejection::NotFound)}));
        const ListElement e = it->second;
        if (e.previous && list.count(e.previous))
            list[e.previous].next = e.next;
        if (e.next && list.count(e.next))
            list[e.next].previous = e.previous;
        list.erase(it);
    }
    m_route.list = std::move(list);
    // Deleting the list (or the active element) stops its execution (§13 item 2).
    if (m_route.active && !m_route.list.count(m_route.active)) {
        m_route.active = 0;
        m_route.speed = 0;
    }
    send(mobility(), src, encodeU8(msg::ConfirmElementRequest, m->requestId));
}

void UgvCore::executeList(const JausId& src, ByteSpan p) {
    auto m = decodeExecuteList(p);
    if (!m)
        return rejectMalformed(m.error());
    // Controlled and Ready, else dropped silently (§3.3).
    if (!isController(src) || m_s.management != ManagementState::Ready) {
        m_counters.add("rx.refused.execute_list");
        return;
    }
    m_route.speed = std::clamp(m->speed, 0.0, m_cfg.maxForwardSpeed);
    if (!m->startUid || *m->startUid == kAllUids)
        return; // a speed change only
    const std::uint16_t uid = *m->startUid == kHeadUid ? headOf(m_route.list) : *m->startUid;
    if (!m_route.list.count(uid)) {
        m_counters.add("rx.refused.execute_list");
        return;
    }
    m_route.single.reset();
    m_route.active = uid;
    m_routeManagement = ManagementState::Ready;
}

void UgvCore::setSingleWaypoint(const JausId& src, ByteSpan p) {
    if (!isController(src)) {
        m_counters.add("rx.refused.not_controller");
        return;
    }
    const std::uint16_t id = peekMessageId(p);
    const bool ok =
        id == msg::SetGlobalWaypoint ? bool(decodeGlobalWaypoint(p)) : bool(decodeLocalWaypoint(p));
    if (!ok)
        return rejectMalformed("value: " + std::string(messageName(id)) + " does not decode");
    m_route.single = ListElement{0, 0, 0, 0, Bytes(p.begin(), p.end())};
    m_route.singleArrived = false;
    m_route.active = 0;
}

void UgvCore::setTravelSpeed(const JausId& src, ByteSpan p) {
    auto v = decodeTravelSpeed(p, msg::SetTravelSpeed);
    if (!v)
        return rejectMalformed(v.error());
    // Only in Ready and only once a waypoint exists (§4).
    if (!isController(src) || m_s.management != ManagementState::Ready || !m_route.single) {
        m_counters.add("rx.refused.travel_speed");
        return;
    }
    m_route.speed = std::clamp(*v, 0.0, m_cfg.maxForwardSpeed);
    m_routeManagement = ManagementState::Ready;
}

std::optional<std::pair<double, double>> UgvCore::targetOf(const ListElement& e, double* tolerance) const {
    *tolerance = kDefaultToleranceM;
    if (peekMessageId(e.data) == msg::SetGlobalWaypoint) {
        auto w = decodeGlobalWaypoint(e.data);
        if (!w)
            return std::nullopt;
        if (w->waypointTolerance && *w->waypointTolerance > 0)
            *tolerance = *w->waypointTolerance;
        const EnuPoint enu = m_geo.toLocal(GeoPoint{w->lat, w->lon, m_cfg.origin.alt});
        return std::pair{enu.n, enu.e}; // local x north, y east
    }
    auto w = decodeLocalWaypoint(e.data);
    if (!w)
        return std::nullopt;
    if (w->waypointTolerance && *w->waypointTolerance > 0)
        *tolerance = *w->waypointTolerance;
    return std::pair{w->x, w->y};
}

std::optional<Bytes> UgvCore::reportWaypoint(std::uint16_t reportId) const {
    const ListElement* e = nullptr;
    if (m_route.active && m_route.list.count(m_route.active))
        e = &m_route.list.at(m_route.active);
    else if (m_route.single)
        e = &*m_route.single;
    if (!e)
        return std::nullopt; // answered only while a waypoint exists (§4)
    if (reportId == msg::ReportGlobalWaypoint) {
        if (peekMessageId(e->data) == msg::SetGlobalWaypoint)
            return encode(*decodeGlobalWaypoint(e->data), reportId);
        double tol = 0;
        const auto xy = targetOf(*e, &tol);
        const GeoPoint g = m_geo.toGeodetic(EnuPoint{xy->second, xy->first, 0});
        GlobalWaypoint w;
        w.lat = g.lat;
        w.lon = g.lon;
        w.waypointTolerance = tol;
        return encode(w, reportId);
    }
    double tol = 0;
    const auto xy = targetOf(*e, &tol);
    if (!xy)
        return std::nullopt;
    LocalWaypoint w;
    w.x = xy->first;
    w.y = xy->second;
    w.waypointTolerance = tol;
    return encode(w, reportId);
}

void UgvCore::followRoute(TimePoint now) {
    const bool ready = m_s.management == ManagementState::Ready && m_s.controller.subsystem != 0;
    // Leaving Ready (Standby, Emergency, control lost): stop, speed 0, the active element kept (§3.3).
    if (!ready) {
        if (m_routeManagement == ManagementState::Ready) {
            m_route.speed = 0;
            m_cmdV = m_cmdW = 0;
        }
        m_routeManagement = m_s.management;
        return;
    }
    m_routeManagement = ManagementState::Ready;
    const ListElement* e = nullptr;
    const bool single = !m_route.active && m_route.single && !m_route.singleArrived;
    if (m_route.active && m_route.list.count(m_route.active))
        e = &m_route.list.at(m_route.active);
    else if (single)
        e = &*m_route.single;
    if (!e || m_route.speed <= 0)
        return;
    double tol = kDefaultToleranceM;
    const auto target = targetOf(*e, &tol);
    if (!target)
        return;
    const double dx = target->first - m_s.x, dy = target->second - m_s.y;
    if (std::hypot(dx, dy) <= tol) {
        ++m_route.captured;
        if (single) {
            m_route.singleArrived = true;
            m_route.speed = 0;
        } else {
            // Advance to the next element; at the tail the list stays and nothing is active (§13 item 4).
            m_route.active = e->next;
            if (!m_route.active)
                m_route.speed = 0;
        }
        m_cmdV = m_cmdW = 0;
        m_brake = 0;
        m_lastDrive = now;
        m_haveDrive = true;
        return;
    }
    // Turn towards the target (x north, y east, yaw clockwise from north), slow while pointing away.
    const double err = ugv::wrapAngle(std::atan2(dy, dx) - m_s.yaw);
    m_cmdW = std::clamp(m_cfg.headingGain * err, -m_cfg.maxYawRate, m_cfg.maxYawRate);
    m_cmdV = std::min(m_route.speed, m_cfg.maxForwardSpeed) * std::max(0.0, std::cos(err));
    m_brake = 0;
    m_velocityMode = true;
    m_lastDrive = now; // the route is the drive demand: no drive timeout while it runs
    m_haveDrive = true;
    if (m_s.driveTimedOut)
        m_s.driveTimedOut = false;
}

void UgvCore::recordPath() {
    auto& path = m_route.path;
    if (!path.empty() && std::hypot(path.back().first - m_s.x, path.back().second - m_s.y) < kPathStepM)
        return;
    path.emplace_back(m_s.x, m_s.y);
    if (path.size() > kPathPoints)
        path.erase(path.begin());
}

Bytes UgvCore::reportPath(ByteSpan query) const {
    const auto q = *decodeQueryPath(query);
    ReportPath r;
    r.pathType = q.pathType;
    std::size_t n = m_route.path.size();
    if (q.maximumPoints)
        n = std::min<std::size_t>(n, *q.maximumPoints);
    for (std::size_t i = m_route.path.size() - n; i < m_route.path.size(); ++i) {
        const auto [x, y] = m_route.path[i];
        PathPoint pt;
        if (q.pathType == std::uint8_t(PathType::HistoricalGlobal)) {
            const GeoPoint g = m_geo.toGeodetic(EnuPoint{y, x, 0});
            pt.lat = g.lat;
            pt.lon = g.lon;
        } else {
            pt.x = x;
            pt.y = y;
        }
        r.points.push_back(pt);
    }
    return encode(r);
}

} // namespace ocu::sim
