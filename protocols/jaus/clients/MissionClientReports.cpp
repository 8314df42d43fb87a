// Waypoint missions, the vehicle's answers: element confirmations and rejections, the read-back, the active
// element, the single waypoint drivers' reports, the PathReporter, and the progress drawn from the pose.
#include <algorithm>
#include <cmath>

#include "protocols/jaus/clients/EventsClient.h"
#include "protocols/jaus/clients/MissionClient.h"

namespace ocu::jaus {

namespace {

constexpr std::size_t kReadBackWindow = 8; // QueryElements outstanding at once
constexpr std::size_t kTrailPoints = 5000;
constexpr double kTrailStepM = 0.5;
constexpr double kDefaultToleranceM = 1.0; // the simulated UGV's default capture radius

} // namespace

void MissionClient::registerMessages(MessageTable& table) {
    auto on = [&](std::uint16_t id,
                  void (MissionClient::*handler)(RemoteSubsystem&, const JausId&, ByteSpan)) {
        table.onVehicleMessage(id, [this, handler](RemoteSubsystem& r, const JausId& src, ByteSpan p) {
            (this->*handler)(r, src, p);
        });
    };
    on(msg::ConfirmElementRequest, &MissionClient::onConfirm);
    on(msg::RejectElementRequest, &MissionClient::onReject);
    on(msg::ReportElementCount, &MissionClient::onCount);
    on(msg::ReportElementList, &MissionClient::onList);
    on(msg::ReportElement, &MissionClient::onElement);
    on(msg::ReportActiveElement, &MissionClient::onActive);
    on(msg::ReportPathReporterCapabilities, &MissionClient::onPathCapabilities);
    on(msg::ReportPath, &MissionClient::onPath);
    // The single waypoint drivers' read-back: the waypoint exists, so the driver took it.
    for (std::uint16_t id : {msg::ReportGlobalWaypoint, msg::ReportLocalWaypoint})
        table.onVehicleMessage(id, [this, id](RemoteSubsystem& r, const JausId& src, ByteSpan p) {
            auto it = m_state.find(r.id());
            if (it == m_state.end() || !(src == it->second.status.driver))
                return;
            State& s = it->second;
            const bool ok = id == msg::ReportGlobalWaypoint ? bool(decodeGlobalWaypoint(p, id))
                                                            : bool(decodeLocalWaypoint(p, id));
            if (!ok)
                return m_ctx.rejected(src, "value: " + std::string(messageName(id)) + " does not decode");
            if (s.step == Step::Starting && s.status.single) {
                go(s, Step::Running);
                s.status.activeIndex = 0;
                setPhase(r, s, MissionPhase::Running);
            }
        });
    table.onVehicleMessage(msg::ReportTravelSpeed, [](RemoteSubsystem&, const JausId&, ByteSpan) {});
}

bool MissionClient::handleControlMessage(RemoteSubsystem& r, const JausId& src, std::uint16_t id,
                                         ByteSpan p) {
    auto it = m_state.find(r.id());
    if (it == m_state.end())
        return false;
    State& s = it->second;
    if (!(src == s.status.driver) || !ownComponent(r, s))
        return false;
    auto code = decodeU8(p, id);
    if (!code) {
        m_ctx.rejected(src, code.error());
        return true;
    }
    if (id == msg::ConfirmControl) {
        if (*code == std::uint8_t(ConfirmControlCode::Accepted)) {
            if (s.control == OwnControl::None) {
                m_ctx.send(src, encodeEmpty(msg::ReleaseControl)); // late: we no longer want it
                return true;
            }
            s.control = OwnControl::Controlled;
            s.lastControlConfirm = m_ctx.now();
            if (s.step == Step::Control)
                afterControl(r, s);
        } else {
            s.control = OwnControl::None;
            if (s.step == Step::Control)
                fail(r, s,
                     "control of the list driver " + src.toString() + " refused (" +
                         (*code == std::uint8_t(ConfirmControlCode::NotAvailable)
                              ? "not available"
                              : "insufficient authority") +
                         ")");
        }
    } else if (id == msg::RejectControl && s.control != OwnControl::None) {
        s.control = OwnControl::None; // watchSafety shows a running mission Lost
    }
    return true;
}

bool MissionClient::handleStatus(RemoteSubsystem& r, const JausId& src, ByteSpan p) {
    auto it = m_state.find(r.id());
    if (it == m_state.end())
        return false;
    State& s = it->second;
    if (!(src == s.status.driver) || src == r.managementTarget())
        return false;
    auto m = decodeReportStatus(p);
    if (!m) {
        m_ctx.rejected(src, m.error());
        return true;
    }
    s.driverStatus = m->status;
    return true;
}

void MissionClient::onConfirm(RemoteSubsystem& r, const JausId& src, ByteSpan p) {
    auto id = decodeU8(p, msg::ConfirmElementRequest);
    if (!id)
        return m_ctx.rejected(src, id.error());
    auto it = m_state.find(r.id());
    if (it == m_state.end())
        return;
    State& s = it->second;
    // RequestID 0 is the JTS example's answer to every request; only one is outstanding at a time.
    if (*id != s.requestId && *id != 0)
        return;
    if (s.step == Step::Clearing) {
        s.sentUpTo = 0;
        sendNextPart(r, s);
    } else if (s.step == Step::Sending) {
        s.sentUpTo = s.partEnd;
        sendNextPart(r, s);
    }
}

void MissionClient::onReject(RemoteSubsystem& r, const JausId& src, ByteSpan p) {
    auto m = decodeRejectElementRequest(p);
    if (!m)
        return m_ctx.rejected(src, m.error());
    auto it = m_state.find(r.id());
    if (it == m_state.end())
        return;
    State& s = it->second;
    const std::string what =
        std::string(nameFor(ElementRejection(m->code))) + " (code " + std::to_string(m->code) + ")";
    if (s.step == Step::Clearing && (m->requestId == s.requestId || m->requestId == 0)) {
        s.sentUpTo = 0; // an empty list cannot be cleared on some stacks: go on
        sendNextPart(r, s);
    } else if (s.step == Step::Sending && (m->requestId == s.requestId || m->requestId == 0)) {
        const std::size_t first = s.sentUpTo + 1, last = s.partEnd;
        fail(r, s,
             "the vehicle refused waypoints " + std::to_string(first) + "-" + std::to_string(last) + " of " +
                 std::to_string(s.elements.size()) + ": " + what);
    } else if (s.step == Step::Starting || s.step == Step::Running) {
        // FKIE's list driver answers a failed ExecuteList with RequestID 0 (§3.4).
        fail(r, s, "the vehicle refused ExecuteList: " + what);
    }
}

void MissionClient::onCount(RemoteSubsystem& r, const JausId& src, ByteSpan p) {
    auto n = decodeU16(p, msg::ReportElementCount);
    if (!n)
        return m_ctx.rejected(src, n.error());
    auto it = m_state.find(r.id());
    if (it == m_state.end() || it->second.step != Step::Verifying)
        return;
    State& s = it->second;
    if (s.verify == Verify::Elements) {
        // FKIE answers QueryElement with ReportElementCount: the elements cannot be read back one by one;
        // the count and the list were equal.
        return verified(r, s);
    }
    if (s.verify != Verify::Count)
        return;
    if (*n != s.elements.size())
        return fail(r, s,
                    "read-back: the vehicle holds " + std::to_string(*n) + " waypoints, not " +
                        std::to_string(s.elements.size()));
    s.verify = Verify::List;
    s.tries = 0;
    sendToDriver(s, encodeEmpty(msg::QueryElementList));
}

void MissionClient::onList(RemoteSubsystem& r, const JausId& src, ByteSpan p) {
    auto m = decodeReportElementList(p);
    if (!m)
        return m_ctx.rejected(src, m.error());
    auto it = m_state.find(r.id());
    if (it == m_state.end() || it->second.step != Step::Verifying || it->second.verify == Verify::Elements)
        return;
    State& s = it->second;
    // As a set: JAUS++ reports in ascending UID order, others in list order (§2.4).
    std::vector<std::uint16_t> got = m->uids;
    std::sort(got.begin(), got.end());
    bool same = got.size() == s.elements.size();
    for (std::size_t i = 0; same && i < got.size(); ++i)
        same = got[i] == s.elements[i].uid;
    if (!same)
        return fail(r, s,
                    "read-back: the vehicle's list (" + std::to_string(got.size()) +
                        " UIDs) differs from the " + std::to_string(s.elements.size()) + " uploaded");
    s.verify = Verify::Elements;
    s.tries = 0;
    s.pendingElements.clear();
    s.nextElement = 0;
    queryElements(s);
}

void MissionClient::queryElements(State& s) {
    while (s.pendingElements.size() < kReadBackWindow && s.nextElement < s.elements.size()) {
        const std::uint16_t uid = s.elements[s.nextElement++].uid;
        s.pendingElements.insert(uid);
        sendToDriver(s, encodeU16(msg::QueryElement, uid));
    }
}

bool MissionClient::sameElement(const State& s, const ListElement& a, const ListElement& b) const {
    if (a.uid != b.uid || a.previous != b.previous || a.next != b.next)
        return false;
    auto close = [](const std::optional<double>& x, const std::optional<double>& y, double eps) {
        return x.has_value() == y.has_value() && (!x || std::abs(*x - *y) <= eps);
    };
    // Within a few LSB: truncating peers differ by one (jaus-wire.md §3).
    if (s.status.global) {
        auto x = decodeGlobalWaypoint(a.data), y = decodeGlobalWaypoint(b.data);
        return x && y && std::abs(x->lat - y->lat) < 1e-6 && std::abs(x->lon - y->lon) < 1e-6 &&
               close(x->waypointTolerance, y->waypointTolerance, 0.01);
    }
    auto x = decodeLocalWaypoint(a.data), y = decodeLocalWaypoint(b.data);
    return x && y && std::abs(x->x - y->x) < 1e-3 && std::abs(x->y - y->y) < 1e-3 &&
           close(x->waypointTolerance, y->waypointTolerance, 0.01);
}

void MissionClient::onElement(RemoteSubsystem& r, const JausId& src, ByteSpan p) {
    auto m = decodeListElement(p);
    if (!m)
        return m_ctx.rejected(src, m.error());
    auto it = m_state.find(r.id());
    if (it == m_state.end() || it->second.step != Step::Verifying || it->second.verify != Verify::Elements)
        return;
    State& s = it->second;
    if (!s.pendingElements.erase(m->uid))
        return;
    if (m->uid == 0 || m->uid > s.elements.size() || !sameElement(s, s.elements[m->uid - 1], *m))
        return fail(r, s,
                    "read-back: waypoint " + std::to_string(m->uid) + " on the vehicle differs from ours");
    s.tries = 0;
    s.lastSent = m_ctx.now();
    queryElements(s);
    if (s.pendingElements.empty() && s.nextElement >= s.elements.size())
        verified(r, s);
}

void MissionClient::verified(RemoteSubsystem& r, State& s) {
    s.verified = true;
    go(s, Step::Idle);
    setPhase(r, s, MissionPhase::Uploaded);
    if (s.startAfterUpload) {
        s.startAfterUpload = false;
        s.startIndex = 0;
        s.goal = Goal::Start;
        afterGoal(r, s);
    }
}

void MissionClient::onActive(RemoteSubsystem& r, const JausId& src, ByteSpan p) {
    auto uid = decodeU16(p, msg::ReportActiveElement);
    if (!uid)
        return m_ctx.rejected(src, uid.error());
    auto it = m_state.find(r.id());
    if (it == m_state.end() || !(src == it->second.status.driver) || it->second.status.single)
        return;
    State& s = it->second;
    const std::size_t n = s.status.waypoints.size();
    const bool known = *uid >= 1 && *uid <= n;
    if (s.step == Step::Starting && known) {
        go(s, Step::Running);
        s.active = *uid;
        s.status.activeIndex = *uid - 1;
        s.status.lastSeenIndex = std::max(s.status.lastSeenIndex, s.status.activeIndex);
        progress(r, s);
        return setPhase(r, s, MissionPhase::Running);
    }
    if (s.step == Step::Aborting && *uid == 0) {
        go(s, Step::Idle);
        return setPhase(r, s, MissionPhase::Aborted, "aborted by the operator");
    }
    if (s.step != Step::Running)
        return;
    if (*uid == 0) {
        // Back to idle: the end of the list, or the vehicle ended it early.
        go(s, Step::Idle);
        const int last = int(n) - 1;
        if (s.status.lastSeenIndex >= last)
            return setPhase(r, s, MissionPhase::Completed);
        return setPhase(r, s, MissionPhase::Aborted,
                        "the vehicle ended the list at " + waypointWord(s.status.lastSeenIndex, n));
    }
    if (!known || *uid == s.active)
        return;
    s.active = *uid;
    s.status.activeIndex = *uid - 1;
    s.status.lastSeenIndex = std::max(s.status.lastSeenIndex, s.status.activeIndex);
    // A waypoint with a speed of its own: ExecuteList from the active element carries it (§3.4).
    const double v = speedFor(r, s, s.status.activeIndex);
    if (std::abs(v - s.speed) > 0.01) {
        s.speed = v;
        sendToDriver(s, encode(ExecuteList{v, *uid}));
    }
    progress(r, s);
    r.snap.mission = s.status;
    m_ctx.changed(r);
}

void MissionClient::progress(RemoteSubsystem& r, State& s) {
    const auto& g = r.snap.globalPose;
    const int k = s.status.activeIndex;
    if (!g || !g->lat || !g->lon || k < 0 || std::size_t(k) >= s.status.waypoints.size())
        return;
    const auto& w = s.status.waypoints;
    double d = groundDistance(*g->lat, *g->lon, w[k].lat, w[k].lon);
    const double toActive = d;
    for (std::size_t i = std::size_t(k) + 1; i < w.size(); ++i)
        d += groundDistance(w[i - 1].lat, w[i - 1].lon, w[i].lat, w[i].lon);
    double v = s.speed;
    if (r.snap.velocity && r.snap.velocity->vx && std::abs(*r.snap.velocity->vx) > 0.1)
        v = std::abs(*r.snap.velocity->vx);
    const bool changed = !s.status.distanceToGoM || std::abs(*s.status.distanceToGoM - d) > 0.05;
    s.status.distanceToGoM = d;
    s.status.etaS = v > 0.01 ? std::optional<double>(d / v) : std::nullopt;
    // A single waypoint is reached when the pose is within its tolerance (the driver reports no progress).
    if (s.status.single && s.step == Step::Running &&
        toActive <= (w[k].tolerance > 0 ? w[k].tolerance : kDefaultToleranceM)) {
        go(s, Step::Idle);
        return setPhase(r, s, MissionPhase::Completed);
    }
    if (changed) {
        r.snap.mission = s.status;
        m_ctx.changed(r);
    }
}

void MissionClient::trail(RemoteSubsystem& r, State& s) {
    const bool moving = s.step == Step::Starting || s.step == Step::Running || s.step == Step::Pausing ||
                        s.step == Step::Paused;
    if (!moving)
        return;
    const TimePoint now = m_ctx.now();
    if (s.drivers.pathReporter.subsystem) {
        if (!s.pathCapsKnown && now - s.lastPathQuery >= std::chrono::seconds(3)) {
            s.lastPathQuery = now;
            m_ctx.send(s.drivers.pathReporter, encodeEmpty(msg::QueryPathReporterCapabilities));
        } else if (s.pathType && now - s.lastPathQuery >= std::chrono::seconds(1)) {
            s.lastPathQuery = now;
            QueryPath q;
            q.pathType = *s.pathType;
            q.maximumPoints = 1000;
            m_ctx.send(s.drivers.pathReporter, encode(q));
        }
        if (s.pathType)
            return;
    }
    const auto& g = r.snap.globalPose;
    if (!g || !g->lat || !g->lon)
        return;
    auto& path = s.status.drivenPath;
    if (!path.empty() &&
        groundDistance(path.back().first, path.back().second, *g->lat, *g->lon) < kTrailStepM)
        return;
    path.emplace_back(*g->lat, *g->lon);
    if (path.size() > kTrailPoints)
        path.erase(path.begin(), path.begin() + std::ptrdiff_t(path.size() - kTrailPoints));
    s.status.pathSource = "pose trail";
    r.snap.mission = s.status;
    m_ctx.changed(r);
}

void MissionClient::onPathCapabilities(RemoteSubsystem& r, const JausId& src, ByteSpan p) {
    auto m = decodeReportPathReporterCapabilities(p);
    if (!m)
        return m_ctx.rejected(src, m.error());
    auto it = m_state.find(r.id());
    if (it == m_state.end())
        return;
    State& s = it->second;
    s.pathCapsKnown = true;
    s.pathType.reset();
    // The historical global path draws directly on the map; a local one needs the vehicle's frame.
    for (const PathCapability& c : m->paths)
        if (c.pathType == std::uint8_t(PathType::HistoricalGlobal))
            s.pathType = c.pathType;
    if (!s.pathType && s.frame)
        for (const PathCapability& c : m->paths)
            if (c.pathType == std::uint8_t(PathType::HistoricalLocal))
                s.pathType = c.pathType;
}

void MissionClient::onPath(RemoteSubsystem& r, const JausId& src, ByteSpan p) {
    auto m = decodeReportPath(p);
    if (!m)
        return m_ctx.rejected(src, m.error());
    auto it = m_state.find(r.id());
    if (it == m_state.end() || !it->second.pathType || *it->second.pathType != m->pathType)
        return;
    State& s = it->second;
    std::vector<std::pair<double, double>> path;
    for (const PathPoint& pt : m->points) {
        if (pt.lat && pt.lon)
            path.emplace_back(*pt.lat, *pt.lon);
        else if (pt.x && pt.y && s.frame)
            path.push_back(s.frame->toGlobal(*pt.x, *pt.y));
    }
    s.status.drivenPath = std::move(path);
    s.status.pathSource = "path reporter";
    r.snap.mission = s.status;
    m_ctx.changed(r);
}

} // namespace ocu::jaus
