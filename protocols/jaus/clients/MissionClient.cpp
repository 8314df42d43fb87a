// Waypoint missions, the commands and the steps driven by time: control, upload parts, readiness,
// ExecuteList, the safety watch. The vehicle's answers are handled in MissionClientReports.cpp.
#include "protocols/jaus/clients/MissionClient.h"

#include <algorithm>
#include <string_view>

#include "protocols/jaus/clients/AccessControlClient.h"
#include "protocols/jaus/clients/EventsClient.h"

namespace ocu::jaus {

namespace {

constexpr auto kStepTimeout = std::chrono::seconds(3); // FKIE's client waits 3 s (jaus-autonomy.md §12)
constexpr auto kRetry = std::chrono::seconds(1);
constexpr int kTries = 3;
constexpr std::size_t kPartBytes = 1400; // below every public stack's fragment limit (§2.4)
constexpr double kDefaultSpeed = 1.0;    // m/s when neither the waypoint nor the vehicle says

// The last URI segment, whatever the namespace or version (public stacks disagree on both, §2.1, §5).
bool offersNamed(const std::vector<ServiceRecord>& services, std::string_view name) {
    return std::any_of(services.begin(), services.end(), [&](const ServiceRecord& s) {
        const auto pos = s.uri.rfind(':');
        return pos != std::string::npos && std::string_view(s.uri).substr(pos + 1) == name;
    });
}

} // namespace

std::string MissionClient::waypointWord(int index, std::size_t n) {
    return "waypoint " + std::to_string(index + 1) + " of " + std::to_string(n);
}

void MissionClient::onServicesKnown(RemoteSubsystem& r) {
    State& s = m_state[r.id()];
    s.drivers.located = false;
    locate(r, s);
}

void MissionClient::locate(RemoteSubsystem& r, State& s) {
    if (s.drivers.located)
        return;
    s.drivers = Drivers{};
    s.drivers.located = true;
    for (const NodeInfo& n : r.snap.services)
        for (const ComponentInfo& c : n.components) {
            const JausId id{r.id(), n.node, c.component};
            auto pick = [&](JausId& slot, std::string_view name) {
                if (!slot.subsystem && offersNamed(c.services, name))
                    slot = id;
            };
            pick(s.drivers.localList, "LocalWaypointListDriver");
            pick(s.drivers.globalList, "GlobalWaypointListDriver");
            pick(s.drivers.localSingle, "LocalWaypointDriver");
            pick(s.drivers.globalSingle, "GlobalWaypointDriver");
            pick(s.drivers.pathReporter, "PathReporter");
        }
}

std::optional<MissionClient::Step> MissionClient::step(std::uint16_t ss) const {
    auto it = m_state.find(ss);
    if (it == m_state.end())
        return std::nullopt;
    return it->second.step;
}

MissionClient::State* MissionClient::stateFor(std::uint16_t ss, const char* what) {
    if (!m_ctx.config().mayControl()) {
        m_ctx.refuse(ss, std::string("the monitor role may not ") + what, OutcomeReason::NotPermitted);
        return nullptr;
    }
    RemoteSubsystem* r = m_ctx.find(ss);
    if (!r || !r->components.known) {
        m_ctx.refuseNoTarget(ss, "a waypoint driver");
        return nullptr;
    }
    if (!r->reachable()) {
        m_ctx.refuse(ss, r->snap.callSign + ": link down, " + what + " not sent", OutcomeReason::LinkDown);
        return nullptr;
    }
    State& s = m_state[ss];
    locate(*r, s);
    return &s;
}

bool MissionClient::ownComponent(const RemoteSubsystem& r, const State& s) const {
    return s.status.driver.subsystem && !(s.status.driver == r.controlTarget());
}

bool MissionClient::haveControl(const RemoteSubsystem& r, const State& s) const {
    return ownComponent(r, s) ? s.control == OwnControl::Controlled : r.snap.controlledByUs;
}

bool MissionClient::askControl(RemoteSubsystem& r, State& s) {
    go(s, Step::Control);
    if (!ownComponent(r, s))
        return m_access.wantsControl(r.id()) || m_access.requestControl(r.id());
    s.control = OwnControl::Requested;
    s.lastControlRequest = m_ctx.now();
    if (!m_ctx.send(s.status.driver, encodeU8(msg::RequestControl, m_ctx.config().authority)))
        return m_ctx.sendFailed(r.id(), "RequestControl");
    return true;
}

std::optional<ManagementState> MissionClient::driverStatus(const RemoteSubsystem& r, const State& s) const {
    return s.status.driver == r.managementTarget() ? r.snap.management : s.driverStatus;
}

void MissionClient::go(State& s, Step step) {
    s.step = step;
    s.since = s.lastSent = m_ctx.now();
    s.tries = 0;
}

bool MissionClient::sendToDriver(State& s, const Bytes& payload) {
    s.lastSent = m_ctx.now();
    return m_ctx.send(s.status.driver, payload);
}

void MissionClient::setPhase(RemoteSubsystem& r, State& s, MissionPhase phase, std::string reason) {
    const bool changed = s.status.phase != phase;
    s.status.phase = phase;
    s.status.reason = std::move(reason);
    if (phase == MissionPhase::Completed || phase == MissionPhase::Aborted ||
        phase == MissionPhase::Rejected) {
        s.status.distanceToGoM.reset();
        s.status.etaS.reset();
        s.status.activeIndex = -1;
        if (ownComponent(r, s) && s.control != OwnControl::None) {
            m_ctx.send(s.status.driver, encodeEmpty(msg::ReleaseControl));
            s.control = OwnControl::None;
        }
    }
    r.snap.mission = s.status;
    if (changed) {
        std::string text = r.snap.callSign + " mission " + nameFor(phase);
        if (phase == MissionPhase::Running && s.status.activeIndex >= 0)
            text += ": " + waypointWord(s.status.activeIndex, s.status.waypoints.size());
        if (!s.status.reason.empty())
            text += " (" + s.status.reason + ")";
        const Severity sev = phase == MissionPhase::Rejected || phase == MissionPhase::Lost ||
                                     phase == MissionPhase::StoppedByEmergency
                                 ? Severity::Warning
                                 : Severity::Info;
        m_ctx.notify(sev, EventKind::MissionChanged, r.id(), text);
    }
    m_ctx.changed(r);
}

void MissionClient::fail(RemoteSubsystem& r, State& s, std::string reason) {
    go(s, Step::Idle);
    setPhase(r, s, MissionPhase::Rejected, std::move(reason));
}

double MissionClient::activePollHz() const {
    return std::max(1.0, m_ctx.config().statusPollHz);
}

double MissionClient::speedFor(const RemoteSubsystem& r, const State& s, int index) const {
    double v = kDefaultSpeed;
    if (index >= 0 && std::size_t(index) < s.status.waypoints.size() && s.status.waypoints[index].speed > 0)
        v = s.status.waypoints[index].speed;
    if (r.snap.platform && r.snap.platform->maxForwardSpeed && *r.snap.platform->maxForwardSpeed > 0)
        v = std::min(v, *r.snap.platform->maxForwardSpeed);
    return v;
}

// ---- commands -------------------------------------------------------------------------------------------

bool MissionClient::upload(std::uint16_t ss, const std::vector<MissionPoint>& points,
                           std::optional<bool> global) {
    State* sp = stateFor(ss, "upload a mission");
    if (!sp)
        return false;
    State& s = *sp;
    RemoteSubsystem& r = *m_ctx.find(ss);
    if (points.empty() || points.size() > 65534)
        return m_ctx.refuse(ss, "a mission needs 1 to 65534 waypoints", OutcomeReason::InvalidArgument);
    if (s.step != Step::Idle && s.step != Step::Control && s.step != Step::Clearing &&
        s.step != Step::Sending && s.step != Step::Verifying)
        return m_ctx.refuse(ss, r.snap.callSign + " is running a mission: abort it before uploading another");
    const bool useGlobal = global.value_or(s.drivers.globalList.subsystem != 0);
    const JausId driver = useGlobal ? s.drivers.globalList : s.drivers.localList;
    if (!driver.subsystem)
        return m_ctx.refuse(ss,
                            "no component of " + r.snap.callSign + " offers " +
                                (useGlobal ? "GlobalWaypointListDriver" : "LocalWaypointListDriver"),
                            OutcomeReason::NotSupported);
    s.frame.reset();
    if (!useGlobal) {
        if (r.snap.globalPose && r.snap.localPose)
            s.frame = MissionFrame::from(*r.snap.globalPose, *r.snap.localPose);
        if (!s.frame)
            return m_ctx.refuse(ss, r.snap.callSign +
                                        " has not reported both its global and its local position: local "
                                        "waypoints cannot be placed");
    }
    s.elements.clear();
    for (std::size_t i = 0; i < points.size(); ++i) {
        const MissionPoint& p = points[i];
        ListElement e;
        e.uid = std::uint16_t(i + 1);
        e.previous = std::uint16_t(i);
        e.next = i + 1 < points.size() ? std::uint16_t(i + 2) : 0;
        std::optional<double> tol;
        if (p.tolerance > 0)
            tol = std::min(p.tolerance, 100.0);
        if (useGlobal) {
            GlobalWaypoint w;
            w.lat = p.lat;
            w.lon = p.lon;
            w.waypointTolerance = tol;
            e.data = encode(w);
        } else {
            LocalWaypoint w;
            std::tie(w.x, w.y) = s.frame->toLocal(p.lat, p.lon);
            w.waypointTolerance = tol;
            e.data = encode(w);
        }
        s.elements.push_back(std::move(e));
    }
    s.status = MissionStatus{};
    s.status.waypoints = points;
    s.status.global = useGlobal;
    s.status.driver = driver;
    s.verified = false;
    s.active = 0;
    s.startAfterUpload = false;
    s.goal = Goal::Upload;
    // Progress on an on-change event where the driver offers it, else polled (EventsClient falls back).
    m_events.subscribe(r, driver, encodeEmpty(msg::QueryActiveElement), activePollHz(),
                       EventType::EveryChange);
    setPhase(r, s, MissionPhase::Uploading);
    if (haveControl(r, s)) {
        afterControl(r, s);
        return s.status.phase != MissionPhase::Rejected;
    }
    return askControl(r, s);
}

bool MissionClient::start(std::uint16_t ss, int fromIndex) {
    State* sp = stateFor(ss, "start a mission");
    if (!sp)
        return false;
    State& s = *sp;
    RemoteSubsystem& r = *m_ctx.find(ss);
    if (!s.verified || s.status.single)
        return m_ctx.refuse(ss, r.snap.callSign +
                                    " has no verified mission list from this console: upload first");
    if (fromIndex < 0 || std::size_t(fromIndex) >= s.status.waypoints.size())
        return m_ctx.refuse(ss, "start waypoint " + std::to_string(fromIndex + 1) + " is not in the mission",
                            OutcomeReason::InvalidArgument);
    if (s.step == Step::Readying || s.step == Step::Starting || s.step == Step::Running)
        return m_ctx.refuse(ss, r.snap.callSign + " is already running the mission");
    if (r.snap.emergency)
        return m_ctx.refuse(ss, r.snap.callSign + " is in EMERGENCY: clear the emergency first");
    s.startIndex = fromIndex;
    s.goal = Goal::Start;
    return afterGoal(r, s);
}

bool MissionClient::resume(std::uint16_t ss) {
    State* sp = stateFor(ss, "resume a mission");
    if (!sp)
        return false;
    State& s = *sp;
    RemoteSubsystem& r = *m_ctx.find(ss);
    const MissionPhase ph = s.status.phase;
    if (!s.verified ||
        (ph != MissionPhase::Paused && ph != MissionPhase::StoppedByEmergency && ph != MissionPhase::Lost))
        return m_ctx.refuse(ss, r.snap.callSign + " has no paused or stopped mission to resume");
    if (r.snap.emergency)
        return m_ctx.refuse(ss, r.snap.callSign + " is in EMERGENCY: clear the emergency first");
    s.startIndex = std::max(0, s.status.lastSeenIndex);
    s.goal = Goal::Resume;
    return afterGoal(r, s);
}

bool MissionClient::afterGoal(RemoteSubsystem& r, State& s) {
    // A list driver of its own takes the vehicle's primitive driver itself: the console lets go of it.
    if (ownComponent(r, s) && !s.status.single && (m_access.wantsControl(r.id()) || r.snap.controlledByUs)) {
        m_access.releaseControl(r.id());
        m_ctx.notify(Severity::Info, EventKind::MissionChanged, r.id(),
                     r.snap.callSign + ": control of the drive component released so that the list driver " +
                         s.status.driver.toString() + " can take it");
    }
    if (haveControl(r, s)) {
        beginReadying(r, s);
        return s.status.phase != MissionPhase::Rejected;
    }
    return askControl(r, s);
}

bool MissionClient::pause(std::uint16_t ss) {
    State* sp = stateFor(ss, "pause a mission");
    if (!sp)
        return false;
    State& s = *sp;
    RemoteSubsystem& r = *m_ctx.find(ss);
    if (s.step != Step::Running && s.step != Step::Starting && s.step != Step::Readying)
        return m_ctx.refuse(ss, r.snap.callSign + " is not running a mission");
    go(s, Step::Pausing);
    if (!sendToDriver(s, encodeEmpty(msg::Standby)))
        return m_ctx.sendFailed(ss, "Standby");
    sendToDriver(s, encodeEmpty(msg::QueryStatus));
    return true;
}

bool MissionClient::abort(std::uint16_t ss) {
    State* sp = stateFor(ss, "abort a mission");
    if (!sp)
        return false;
    State& s = *sp;
    RemoteSubsystem& r = *m_ctx.find(ss);
    if (s.status.phase == MissionPhase::None || !s.status.driver.subsystem)
        return m_ctx.refuse(ss, r.snap.callSign + " has no mission from this console");
    s.verified = false;
    go(s, Step::Aborting);
    s.requestId = m_nextRequestId++;
    if (m_nextRequestId == 0)
        m_nextRequestId = 1;
    bool sent = true;
    if (!s.status.single)
        sent = sendToDriver(s, encode(DeleteElement{s.requestId, {kAllUids}}));
    else
        sent = sendToDriver(s, encodeTravelSpeed(msg::SetTravelSpeed, 0));
    // The JTS example ignores DeleteElement: Standby stops it (jaus-autonomy.md §3.4).
    sent = sendToDriver(s, encodeEmpty(msg::Standby)) && sent;
    sendToDriver(s, encodeEmpty(msg::QueryStatus));
    if (!s.status.single)
        sendToDriver(s, encodeEmpty(msg::QueryActiveElement));
    if (!sent)
        return m_ctx.sendFailed(ss, "the abort");
    return true;
}

bool MissionClient::goTo(std::uint16_t ss, const MissionPoint& p) {
    State* sp = stateFor(ss, "send a vehicle to a point");
    if (!sp)
        return false;
    State& s = *sp;
    RemoteSubsystem& r = *m_ctx.find(ss);
    if (s.drivers.globalSingle.subsystem || s.drivers.localSingle.subsystem)
        return goToSingle(r, s, p);
    if (!upload(ss, {p}, std::nullopt))
        return false;
    s.startAfterUpload = true;
    return true;
}

bool MissionClient::goToSingle(RemoteSubsystem& r, State& s, const MissionPoint& p) {
    if (s.step != Step::Idle && s.step != Step::Paused)
        return m_ctx.refuse(r.id(), r.snap.callSign + " is busy with a mission: abort it first");
    const bool useGlobal = s.drivers.globalSingle.subsystem != 0;
    s.frame.reset();
    if (!useGlobal) {
        if (r.snap.globalPose && r.snap.localPose)
            s.frame = MissionFrame::from(*r.snap.globalPose, *r.snap.localPose);
        if (!s.frame)
            return m_ctx.refuse(r.id(), r.snap.callSign + " has not reported both its global and its local "
                                                          "position: a local waypoint cannot be placed");
    }
    s.status = MissionStatus{};
    s.status.waypoints = {p};
    s.status.global = useGlobal;
    s.status.single = true;
    s.status.driver = useGlobal ? s.drivers.globalSingle : s.drivers.localSingle;
    s.verified = false;
    s.startIndex = 0;
    s.goal = Goal::GoTo;
    setPhase(r, s, MissionPhase::Uploading);
    return afterGoal(r, s);
}

// ---- steps ----------------------------------------------------------------------------------------------

void MissionClient::afterControl(RemoteSubsystem& r, State& s) {
    if (s.goal != Goal::Upload) {
        beginReadying(r, s);
        return;
    }
    // Clear first: JTS replaces the list on SetElement anyway, JAUS++ and FKIE clear on 65535 (§2.4).
    go(s, Step::Clearing);
    s.requestId = m_nextRequestId++;
    if (m_nextRequestId == 0)
        m_nextRequestId = 1;
    if (!sendToDriver(s, encode(DeleteElement{s.requestId, {kAllUids}})))
        fail(r, s, "DeleteElement was not sent: " + m_ctx.lastSendError());
}

void MissionClient::sendNextPart(RemoteSubsystem& r, State& s) {
    if (s.sentUpTo >= s.elements.size()) {
        go(s, Step::Verifying);
        s.verify = Verify::Count;
        sendToDriver(s, encodeEmpty(msg::QueryElementCount));
        return;
    }
    SetElement m;
    std::size_t bytes = 4, end = s.sentUpTo;
    while (end < s.elements.size() && m.elements.size() < 255) {
        const std::size_t size = 9 + s.elements[end].data.size();
        if (!m.elements.empty() && bytes + size > kPartBytes)
            break;
        bytes += size;
        m.elements.push_back(s.elements[end++]);
    }
    // A part that stops before the tail ends with Next 0: never reference a UID the vehicle does not hold
    // yet (JAUS++ and FKIE reject it); the next part links to it through Previous and the vehicle patches.
    if (end < s.elements.size())
        m.elements.back().next = 0;
    s.partEnd = end;
    if (s.step != Step::Sending)
        go(s, Step::Sending);
    s.requestId = m_nextRequestId++;
    if (m_nextRequestId == 0)
        m_nextRequestId = 1;
    m.requestId = s.requestId;
    if (!sendToDriver(s, encode(m)))
        fail(r, s, "SetElement was not sent: " + m_ctx.lastSendError());
}

void MissionClient::beginReadying(RemoteSubsystem& r, State& s) {
    // A driver of its own may have left Ready since it last said so (control released, an emergency):
    // only a report after this Resume counts.
    if (ownComponent(r, s))
        s.driverStatus.reset();
    if (driverStatus(r, s) == ManagementState::Ready) {
        const std::uint16_t uid = std::uint16_t(s.startIndex + 1);
        sendExecute(r, s, uid);
        return;
    }
    go(s, Step::Readying);
    if (!sendToDriver(s, encodeEmpty(msg::Resume)))
        return fail(r, s, "Resume was not sent: " + m_ctx.lastSendError());
    sendToDriver(s, encodeEmpty(msg::QueryStatus));
}

void MissionClient::sendExecute(RemoteSubsystem& r, State& s, std::uint16_t uid) {
    const int index = int(uid) - 1;
    s.speed = speedFor(r, s, index);
    go(s, Step::Starting);
    s.active = 0;
    if (s.status.single) {
        // Single driver: waypoint, then speed (the first non-zero speed starts it, §4), then read it back.
        const MissionPoint& p = s.status.waypoints.front();
        std::optional<double> tol;
        if (p.tolerance > 0)
            tol = std::min(p.tolerance, 100.0);
        if (s.status.global) {
            GlobalWaypoint w;
            w.lat = p.lat;
            w.lon = p.lon;
            w.waypointTolerance = tol;
            sendToDriver(s, encode(w));
            sendToDriver(s, encodeTravelSpeed(msg::SetTravelSpeed, s.speed));
            sendToDriver(s, encodeU8(msg::QueryGlobalWaypoint, 0x3F));
        } else {
            LocalWaypoint w;
            std::tie(w.x, w.y) = s.frame->toLocal(p.lat, p.lon);
            w.waypointTolerance = tol;
            sendToDriver(s, encode(w));
            sendToDriver(s, encodeTravelSpeed(msg::SetTravelSpeed, s.speed));
            sendToDriver(s, encodeU8(msg::QueryLocalWaypoint, 0x3F));
        }
        return;
    }
    if (!sendToDriver(s, encode(ExecuteList{s.speed, uid})))
        return fail(r, s, "ExecuteList was not sent: " + m_ctx.lastSendError());
    sendToDriver(s, encodeEmpty(msg::QueryActiveElement));
}

void MissionClient::tickControl(RemoteSubsystem& r, State& s, TimePoint now) {
    if (!ownComponent(r, s) || s.control == OwnControl::None)
        return;
    const double timeout = m_ctx.config().accessTimeoutS;
    const Duration period = s.control == OwnControl::Controlled ? secondsD(timeout * 0.4) : kRetry;
    if (now - s.lastControlRequest >= period) {
        s.lastControlRequest = now;
        m_ctx.send(s.status.driver, encodeU8(msg::RequestControl, m_ctx.config().authority));
    }
    // No confirmation for a whole timeout: the control lapsed.
    if (s.control == OwnControl::Controlled && now - s.lastControlConfirm > secondsD(timeout)) {
        s.control = OwnControl::None;
        if (s.step == Step::Running || s.step == Step::Paused || s.step == Step::Starting) {
            s.status.lastSeenIndex = std::max(s.status.lastSeenIndex, s.status.activeIndex);
            go(s, Step::Idle);
            setPhase(r, s, MissionPhase::Lost,
                     "control of the list driver lapsed, last seen at " +
                         waypointWord(std::max(0, s.status.lastSeenIndex), s.status.waypoints.size()));
        }
    }
    // Its Management state: polled, as nobody else asks this component.
    if (s.step != Step::Idle && now - s.lastSent >= kRetry)
        sendToDriver(s, encodeEmpty(msg::QueryStatus));
}

void MissionClient::tick(RemoteSubsystem& r, TimePoint now) {
    auto it = m_state.find(r.id());
    if (it == m_state.end())
        return;
    State& s = it->second;
    tickControl(r, s, now);
    watchSafety(r, s);
    tickSteps(r, s, now);
    trail(r, s);
}

void MissionClient::watchSafety(RemoteSubsystem& r, State& s) {
    const bool active = s.step == Step::Readying || s.step == Step::Starting || s.step == Step::Running ||
                        s.step == Step::Pausing || s.step == Step::Paused;
    if (!active)
        return;
    const std::size_t n = s.status.waypoints.size();
    s.status.lastSeenIndex = std::max(s.status.lastSeenIndex, s.status.activeIndex);
    const std::string seen = s.status.lastSeenIndex >= 0
                                 ? ", last seen at " + waypointWord(s.status.lastSeenIndex, n)
                                 : std::string();
    if (r.snap.emergency || driverStatus(r, s) == ManagementState::Emergency) {
        go(s, Step::Idle);
        setPhase(r, s, MissionPhase::StoppedByEmergency, "emergency stop" + seen);
    } else if (!r.reachable()) {
        go(s, Step::Idle);
        setPhase(r, s, MissionPhase::Lost, "link down: progress unknown" + seen);
    } else if (!haveControl(r, s) && s.step != Step::Readying) {
        const bool other = !ownComponent(r, s) && r.snap.controller.subsystem && !r.snap.controlledByUs;
        s.status.ours = !other;
        go(s, Step::Idle);
        setPhase(r, s, MissionPhase::Lost,
                 std::string(other ? "another console controls the vehicle" : "control lost") +
                     ": progress unknown" + seen);
    }
}

void MissionClient::tickSteps(RemoteSubsystem& r, State& s, TimePoint now) {
    const Duration inStep = now - s.since;
    const bool retry = now - s.lastSent >= kRetry;
    switch (s.step) {
    case Step::Idle:
    case Step::Paused:
        return;
    case Step::Control:
        if (haveControl(r, s))
            return afterControl(r, s);
        if (inStep >= kStepTimeout + kStepTimeout)
            fail(r, s, "control of " + s.status.driver.toString() + " was not granted");
        return;
    case Step::Clearing:
        // Silence is an answer too: the JTS example never answers DeleteElement (§2.4).
        if (inStep >= kStepTimeout) {
            s.sentUpTo = 0;
            sendNextPart(r, s);
        }
        return;
    case Step::Sending:
        if (now - s.lastSent >= kStepTimeout) {
            if (++s.tries >= kTries)
                return fail(r, s,
                            "no ConfirmElementRequest for SetElement after " + std::to_string(kTries) +
                                " tries");
            const int tries = s.tries;
            sendNextPart(r, s); // the same part again, with a fresh RequestID
            s.tries = tries;
        }
        return;
    case Step::Verifying:
        if (retry) {
            if (++s.tries > kTries)
                return fail(r, s,
                            "the vehicle does not answer the list read-back: the upload is not verified");
            if (s.verify == Verify::Count)
                sendToDriver(s, encodeEmpty(msg::QueryElementCount));
            else if (s.verify == Verify::List)
                sendToDriver(s, encodeEmpty(msg::QueryElementList));
            else {
                s.lastSent = now;
                for (std::uint16_t uid : s.pendingElements)
                    m_ctx.send(s.status.driver, encodeU16(msg::QueryElement, uid));
            }
        }
        return;
    case Step::Readying:
        if (driverStatus(r, s) == ManagementState::Ready && haveControl(r, s))
            return sendExecute(r, s, std::uint16_t(s.startIndex + 1));
        if (retry) {
            if (++s.tries > kTries)
                return fail(r, s,
                            "the driver did not report Ready after Resume (drivers obey only in Ready)");
            sendToDriver(s, encodeEmpty(msg::Resume));
            sendToDriver(s, encodeEmpty(msg::QueryStatus));
        }
        return;
    case Step::Starting:
        if (now - s.lastSent >= std::chrono::milliseconds(500)) {
            if (s.status.single)
                sendToDriver(
                    s, encodeU8(s.status.global ? msg::QueryGlobalWaypoint : msg::QueryLocalWaypoint, 0x3F));
            else
                sendToDriver(s, encodeEmpty(msg::QueryActiveElement));
        }
        if (inStep >= kStepTimeout)
            fail(r, s,
                 s.status.single ? "the waypoint driver does not report the waypoint it was given"
                                 : "ExecuteList had no effect: the vehicle reports no active element");
        return;
    case Step::Running:
        // The active element at 1 Hz at least, whether or not the event arrives.
        if (!s.status.single && now - s.lastActiveQuery >= periodOf(activePollHz())) {
            s.lastActiveQuery = now;
            if (m_events.state(r.id(), msg::QueryActiveElement) != EventsClient::SubscriptionState::Active)
                sendToDriver(s, encodeEmpty(msg::QueryActiveElement));
        }
        progress(r, s);
        return;
    case Step::Pausing:
        if (driverStatus(r, s) == ManagementState::Standby) {
            go(s, Step::Paused);
            setPhase(r, s, MissionPhase::Paused);
        } else if (retry && ++s.tries <= kTries) {
            sendToDriver(s, encodeEmpty(msg::Standby));
            sendToDriver(s, encodeEmpty(msg::QueryStatus));
        }
        return;
    case Step::Aborting:
        if (driverStatus(r, s) == ManagementState::Standby ||
            driverStatus(r, s) == ManagementState::Emergency || (s.status.single && inStep >= kRetry)) {
            go(s, Step::Idle);
            setPhase(r, s, MissionPhase::Aborted, "aborted by the operator");
        } else if (retry && ++s.tries <= kTries) {
            sendToDriver(s, encodeEmpty(msg::Standby));
            sendToDriver(s, encodeEmpty(msg::QueryStatus));
        }
        return;
    }
}

} // namespace ocu::jaus
