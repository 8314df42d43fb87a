#include "protocols/osyris/StationCore.h"

#include "protocols/common/Log.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ocu::osyris {

namespace {

// The newest n slots of s.
IntervalSet newestOf(const IntervalSet& s, std::uint64_t n) {
    IntervalSet out;
    const auto ranges = s.ranges();
    for (auto r = ranges.rbegin(); r != ranges.rend() && n > 0; ++r) {
        const std::uint64_t take = std::min<std::uint64_t>(n, r->size());
        out.insert(static_cast<std::uint32_t>(std::uint64_t(r->to) + 1 - take), r->to);
        n -= take;
    }
    return out;
}

} // namespace

MachineSnapshot makeSnapshot(std::uint8_t idx, const CmPos& p, const GeoFrame* frame, const std::string& name,
                             const std::string& type) {
    MachineSnapshot s;
    s.idx = idx;
    s.name = name;
    s.type = type;
    s.x = p.x;
    s.y = p.y;
    s.z = p.z;
    s.yaw = p.yaw;
    double h = -p.yaw * 180.0 / std::numbers::pi; // yaw counter-clockwise from north -> compass
    h = std::fmod(h, 360.0);
    if (h < 0)
        h += 360.0;
    s.headingDeg = h;
    s.speed = p.speed;
    s.width = p.dx;
    s.flags = p.flags;
    s.valid = p.flags & kPosValid;
    s.vibrating = p.flags & kPosVibrating;
    s.forward = p.flags & kPosForward;
    s.backward = p.flags & kPosBackward;
    s.stopped = p.flags & kPosStop;
    s.gpsShadow = p.flags & kPosGpsShadow;
    s.accuracy = (p.flags & kPosAccuracyHigh)  ? 3
                 : (p.flags & kPosAccuracyMed) ? 2
                 : (p.flags & kPosAccuracyLow) ? 1
                                               : 0;
    s.timestampMs = p.time ? fileTimeToUnixMillis(p.time) : 0;
    s.slot = p.slot;
    if (frame) {
        auto g = frame->toGeodetic({p.x, p.y, p.z});
        s.lat = g.lat;
        s.lon = g.lon;
    }
    return s;
}

StationCore::StationCore(OsyrisConfig cfg, const Clock& clock, RibbonStore& store, PassCountGrid* grid,
                         OsyrisListener* listener, SendFn send, std::uint32_t seed)
    : m_cfg(std::move(cfg)), m_clock(clock), m_store(store), m_grid(grid), m_listener(listener),
      m_send(std::move(send)), m_rng(seed),
      m_frame(GeoPoint{m_cfg.originLat, m_cfg.originLon, m_cfg.originAlt}) {
    m_geo = m_cfg.originLat != 0 || m_cfg.originLon != 0;
    if (auto n = m_store.newest(idx()))
        m_nextOwnSlot = n->pos.slot + 1; // restart: continue our own ribbon
    m_configured.insert(idx());
    for (const auto& [i, name] : m_cfg.machineNames)
        m_configured.insert(i);
    for (const auto& [i, type] : m_cfg.machineTypes)
        m_configured.insert(i);
    for (auto owner : m_store.machines()) {
        m_configured.insert(owner);
        auto held = m_store.held(owner);
        auto& rs = m_ribbons[owner];
        rs.knownMin = held.min();
        rs.knownMax = held.max();
        m_gridDirty.insert(owner);
    }
}

Duration StationCore::beats(double n) const {
    return std::chrono::duration_cast<Duration>(std::chrono::duration<double, std::milli>(n * m_cfg.beatMs));
}

void StationCore::event(Severity s, const std::string& text) {
    if (m_listener)
        m_listener->onEvent(s, text);
}

void StationCore::reject(const std::string& reason, const std::string& text) {
    m_counters.add("rx.rejected." + reason);
    auto& n = m_rejectLogged[reason];
    if (n++ < 5 || n % 1000 == 0) // bounded logging: a noisy radio must not flood the log
        logWarning("osyris",
                   "station " + std::to_string(idx()) + ": datagram rejected (" + reason + "): " + text);
    // The operator sees it too: one warning per cause and minute, with the count since.
    auto [it, first] = m_rejectEventAt.try_emplace(reason, m_clock.now());
    if (!first && m_clock.now() - it->second < std::chrono::seconds(60))
        return;
    it->second = m_clock.now();
    event(Severity::Warning, "OSYRIS input rejected (" + reason + "): " + text + " (" + std::to_string(n) +
                                 " so far, counted in rx.rejected." + reason +
                                 "; at most one such warning per minute)");
}

bool StationCore::storeFull(std::uint8_t owner) const {
    return m_store.count(owner) >= m_cfg.maxRibbonSlots || m_store.totalCount() >= m_cfg.maxStoreSlots;
}

bool StationCore::admitted(std::uint8_t station) {
    if (station >= kIdxNobody)
        return false;
    if (m_configured.count(station) || m_unknown.count(station))
        return true;
    if (m_unknown.size() >= static_cast<std::size_t>(kMaxUnknownStations))
        return false;
    m_unknown.insert(station);
    event(Severity::Info, "OSYRIS station " + std::to_string(station) +
                              " is not in the configuration; admitted as unknown station " +
                              std::to_string(m_unknown.size()) + " of at most " +
                              std::to_string(kMaxUnknownStations));
    return true;
}

bool StationCore::charge(std::size_t bytes) {
    if (bytes > m_answerBudget) {
        m_counters.add("rx.limited.budget");
        return false;
    }
    m_answerBudget -= bytes;
    return true;
}

std::size_t StationCore::unitSize(const PositionRecord& rec) const {
    return kPosSize + (rec.props.empty() ? 0 : kHeaderSize + kPosPropSize * rec.props.size());
}

IntervalSet StationCore::chargeSlots(std::uint8_t owner, const IntervalSet& slots) {
    // Newest first, as the answers go out (§4); a slot no longer held costs nothing.
    IntervalSet out;
    const auto ranges = slots.ranges();
    for (auto r = ranges.rbegin(); r != ranges.rend(); ++r)
        for (std::uint64_t sl = r->to + std::uint64_t(1); sl-- > r->from;) {
            auto rec = m_store.get(owner, static_cast<std::uint32_t>(sl));
            if (!rec)
                continue;
            if (!charge(unitSize(*rec)))
                return out;
            out.insert(static_cast<std::uint32_t>(sl), static_cast<std::uint32_t>(sl));
        }
    return out;
}

void StationCore::start() {
    auto now = m_clock.now();
    m_lastAlive = now;
    auto machines = m_store.machines();
    bool haveOthers =
        std::any_of(machines.begin(), machines.end(), [this](std::uint8_t m) { return m != idx(); });
    // A station restarted on its site file already has the history: it asks only for the gap (NAK), which
    // ALIVE and live positions reveal. Only an empty station joins late with ALL (§4).
    if ((m_cfg.active & kActiveAskRequests) && !haveOthers) {
        enqueueRequest(kIdxAll, {RequestType::All, 0, kSlotLast, 0, 0});
        m_counters.add("tx.all");
        m_allRetries = 0;
        m_allRetryAt = now + beats(m_cfg.ttlBeats);
    }
    sendAlive();
    m_aliveSent = true;
    flush(now, true);
}

std::uint32_t StationCore::publishOwnPosition(CmPos p, std::vector<PosProp> props) {
    p.slot = m_nextOwnSlot++;
    PositionRecord rec{p, std::move(props)};
    m_store.put(idx(), rec);
    auto& rs = m_ribbons[idx()];
    if (!rs.knownMin)
        rs.knownMin = p.slot;
    rs.knownMax = std::max(rs.knownMax.value_or(0), p.slot);
    m_gridDirty.insert(idx());
    if (m_cfg.active & kActiveSendPositions) {
        enqueuePosition(idx(), rec, false);
        m_counters.add("tx.pos");
    }
    if (m_listener)
        m_listener->onMachinePosition(
            makeSnapshot(idx(), p, m_geo ? &m_frame : nullptr, nameOf(idx()), typeOf(idx())));
    return p.slot;
}

void StationCore::sendText(const std::string& text, std::uint8_t to) {
    // Sent now, as its own datagram, not at the next Beat: the operator's texts carry the console's STOP, and
    // the specification binds no message kind but Alive to the timer (OSYRIS communication spec §6: text
    // messages are sent "for operator communication", Alive "periodically"; concatenating messages into one
    // datagram is "recommended, but not required"). The queue keeps its Beat pacing (§7 Beat); a text carries
    // no slot, so leaving ahead of queued positions changes nothing for them. One datagram, so the caller's
    // send result is this text's.
    const Bytes b = textDatagram(text, to);
    textSent(b.size());
    m_send(b);
}

Bytes StationCore::textDatagram(const std::string& text, std::uint8_t to) const {
    Bytes b;
    encodeMsg(b, idx(), to, text, m_cfg.checksum);
    return b;
}

void StationCore::textSent(std::size_t bytes) {
    m_counters.add("tx.msg");
    m_counters.add("tx.datagrams");
    m_counters.add("tx.bytes", bytes);
}

void StationCore::ping(std::uint8_t target) {
    auto own = ownPosition();
    m_pings[target] = m_clock.now();
    enqueueRequest(target, {RequestType::Ping, 0, 0, own ? own->x : 0.f, own ? own->y : 0.f});
    m_counters.add("tx.ping");
}

void StationCore::pingNow(std::uint8_t target) {
    auto own = ownPosition();
    m_pings[target] = m_clock.now();
    Bytes b;
    encodeRequest(b, idx(), target, {RequestType::Ping, 0, 0, own ? own->x : 0.f, own ? own->y : 0.f},
                  m_cfg.checksum);
    m_counters.add("tx.ping");
    m_counters.add("tx.datagrams");
    m_counters.add("tx.bytes", b.size());
    m_send(b);
}

std::string StationCore::nameOf(std::uint8_t owner) const {
    auto it = m_cfg.machineNames.find(owner);
    return it == m_cfg.machineNames.end() ? std::string() : it->second;
}

std::string StationCore::typeOf(std::uint8_t owner) const {
    auto it = m_cfg.machineTypes.find(owner);
    return it == m_cfg.machineTypes.end() ? std::string() : it->second;
}

std::optional<CmPos> StationCore::ownPosition() const {
    if (auto n = m_store.newest(idx()))
        return n->pos;
    return std::nullopt;
}

std::optional<std::uint32_t> StationCore::knownMax(std::uint8_t owner) const {
    auto it = m_ribbons.find(owner);
    return it == m_ribbons.end() ? std::nullopt : it->second.knownMax;
}

std::uint64_t StationCore::missingCount() const {
    std::uint64_t n = 0;
    for (auto& [owner, rs] : m_ribbons) {
        if (!rs.knownMax)
            continue;
        auto held = m_store.held(owner);
        for (auto& g : held.gaps(rs.knownMin.value_or(0), *rs.knownMax))
            n += g.size();
    }
    return n;
}

std::set<std::uint8_t> StationCore::heardStations() const {
    std::set<std::uint8_t> s;
    for (auto& [i, t] : m_lastHeard)
        s.insert(i);
    return s;
}

// ---- sending ----

void StationCore::enqueue(Bytes unit, bool urgent) {
    m_queuedBytes += unit.size();
    m_queue.push_back({std::move(unit), m_clock.now(), urgent});
}

void StationCore::enqueuePosition(std::uint8_t owner, const PositionRecord& rec, bool urgent) {
    Bytes b;
    encodePos(b, idx(), owner, rec.pos, m_cfg.checksum);
    if (!rec.props.empty()) // CmPosProps immediately follows its position, in the same datagram
        encodePosProps(b, idx(), owner, rec.props, m_cfg.checksum);
    enqueue(std::move(b), urgent);
}

void StationCore::enqueueRequest(std::uint8_t whose, const CmRequest& r, bool urgent) {
    Bytes b;
    encodeRequest(b, idx(), whose, r, m_cfg.checksum);
    enqueue(std::move(b), urgent);
}

void StationCore::flush(TimePoint now, bool force) {
    if (m_queue.empty())
        return;
    bool urgent = std::any_of(m_queue.begin(), m_queue.end(), [](const Unit& u) { return u.urgent; });
    bool due = force || urgent || m_queuedBytes >= static_cast<std::size_t>(m_cfg.minLen) ||
               now - m_queue.front().queuedAt >= std::chrono::milliseconds(m_cfg.sendPeriodMs);
    if (!due)
        return;
    int datagrams = 0;
    const std::size_t maxLen = static_cast<std::size_t>(m_cfg.maxLen);
    while (!m_queue.empty() && datagrams < m_cfg.maxDatagramsPerBeat) {
        Bytes d;
        while (!m_queue.empty() && (d.empty() || d.size() + m_queue.front().bytes.size() <= maxLen)) {
            auto& u = m_queue.front();
            d.insert(d.end(), u.bytes.begin(), u.bytes.end());
            m_queuedBytes -= u.bytes.size();
            m_queue.pop_front();
        }
        m_counters.add("tx.datagrams");
        m_counters.add("tx.bytes", d.size());
        m_send(d);
        ++datagrams;
    }
}

void StationCore::sendAlive() {
    bool any = false;
    m_configured.insert(idx());
    for (const auto& [i, name] : m_cfg.machineNames)
        m_configured.insert(i);
    for (const auto& [i, type] : m_cfg.machineTypes)
        m_configured.insert(i);
    for (auto owner : m_store.machines()) {
        m_configured.insert(owner);
        auto held = m_store.held(owner);
        if (held.empty())
            continue;
        // ALIVE per ribbon held: the owner's range, or what this station can relay for others (§4 soft
        // relay).
        enqueueRequest(owner, {RequestType::Alive, held.min(), held.max(), 0, 0}, false);
        any = any || owner == idx();
        m_counters.add("tx.alive");
    }
    if (!any) {
        enqueueRequest(idx(), {RequestType::Alive, kSlotLast, 0, 0, 0}, false); // From > To: no own ribbon
        m_counters.add("tx.alive");
    }
}

// ---- receiving ----

void StationCore::receive(ByteSpan datagram) {
    auto now = m_clock.now();
    m_counters.add("rx.datagrams");
    auto d = decodeDatagram(datagram, m_cfg.checksum, static_cast<std::size_t>(std::max(m_cfg.maxLen, 1500)));
    if (!d.reason.empty())
        reject(d.reason, d.error);
    if (d.messages.empty())
        return;
    std::uint8_t who = d.messages.front().header.who;
    if (who == idx()) {
        m_counters.add("rx.own"); // our own multicast looped back
        return;
    }
    if (!admitted(who)) {
        reject("station_cap", "datagram from station " + std::to_string(who) + ": already " +
                                  std::to_string(kMaxUnknownStations) + " stations not in the configuration");
        return;
    }
    m_answerBudget =
        static_cast<std::size_t>(kAnswerBudgetDatagrams) * static_cast<std::size_t>(m_cfg.maxLen);
    if (m_cfg.maxRange > 0) {
        for (auto& m : d.messages)
            if (auto* p = std::get_if<CmPos>(&m.body); p && m.header.whose == who) {
                auto it = m_senderPos.find(who);
                if (it == m_senderPos.end() || it->second.slot < p->slot)
                    m_senderPos[who] = *p;
            }
        auto own = ownPosition();
        auto it = m_senderPos.find(who);
        if (own && it != m_senderPos.end() &&
            std::hypot(double(own->x) - it->second.x, double(own->y) - it->second.y) > m_cfg.maxRange) {
            m_counters.add("rx.dropped.range"); // §7 MaxRange: simulated range-limited transmission
            return;
        }
    }
    if (!m_lastHeard.count(who))
        event(Severity::Info, "OSYRIS station " + std::to_string(who) + " heard");
    m_lastHeard[who] = now;
    for (std::size_t i = 0; i < d.messages.size(); ++i) {
        const auto& m = d.messages[i];
        if (m.header.who != who) {
            // One datagram has one sender (§6 IdxWho); a message claiming another is not believed.
            reject("mixed_sender", "message from station " + std::to_string(m.header.who) +
                                       " in a datagram from station " + std::to_string(who));
            continue;
        }
        if (auto* p = std::get_if<CmPos>(&m.body)) {
            const std::vector<PosProp>* props = nullptr;
            if (i + 1 < d.messages.size() && d.messages[i + 1].header.whose == m.header.whose)
                if (auto* pp = std::get_if<CmPosProps>(&d.messages[i + 1].body)) {
                    props = &pp->props;
                    ++i;
                }
            handlePosition(m.header, *p, props, now);
        } else if (std::get_if<CmPosProps>(&m.body)) {
            m_counters.add("rx.props.orphan"); // no position before it: nothing to attach to
        } else if (auto* r = std::get_if<CmRequest>(&m.body)) {
            handleRequest(m.header, *r, now);
        } else if (auto* t = std::get_if<CmMsg>(&m.body)) {
            m_counters.add("rx.msg");
            if ((m_cfg.active & kActiveDisplayMessages) &&
                (m.header.whose == kIdxAll || m.header.whose == idx()) && m_listener)
                m_listener->onText(who, t->text);
        }
    }
    if (m_pongQueued) { // at most one PONG per requester and Beat (answerAllowed), within the answer budget
        m_pongQueued = false;
        flush(now, true);
    }
}

void StationCore::noteKnown(std::uint8_t owner, std::uint32_t from, std::uint32_t to) {
    auto& rs = m_ribbons[owner];
    rs.knownMin = rs.knownMin ? std::min(*rs.knownMin, from) : from;
    rs.knownMax = rs.knownMax ? std::max(*rs.knownMax, to) : to;
}

void StationCore::handlePosition(const CmHeader& h, const CmPos& p, const std::vector<PosProp>* props,
                                 TimePoint now) {
    std::uint8_t owner = h.whose;
    if (!admitted(owner)) {
        reject("station_cap", "position of station " + std::to_string(owner) + " from station " +
                                  std::to_string(h.who) + ": already " + std::to_string(kMaxUnknownStations) +
                                  " stations not in the configuration");
        return;
    }
    if (owner != idx() && storeFull(owner) && !m_store.has(owner, p.slot)) {
        // Bounded store: refused, never room made by dropping a held slot (it is counted).
        const bool ribbon = m_store.count(owner) >= m_cfg.maxRibbonSlots;
        reject(ribbon ? "ribbon_full" : "store_full",
               "position of slot " + std::to_string(p.slot) + " of station " + std::to_string(owner) +
                   " refused: " +
                   (ribbon ? "its ribbon holds " + std::to_string(m_cfg.maxRibbonSlots) + " positions"
                           : "the store holds " + std::to_string(m_cfg.maxStoreSlots) + " positions") +
                   " (the bound); what is held stays and its gaps are no longer asked for");
        return;
    }
    if (h.who == owner)
        m_ownerShown[owner] = std::max(m_ownerShown[owner], p.slot);
    PositionRecord rec{p, props ? *props : std::vector<PosProp>{}};
    bool isNew = m_store.put(owner, rec);
    if (!isNew && props)
        m_store.addProps(owner, p.slot, *props);
    auto& rs = m_ribbons[owner];
    bool newest = !rs.knownMax || p.slot > *rs.knownMax;
    bool repair = rs.knownMax && p.slot < *rs.knownMax;
    noteKnown(owner, p.slot, p.slot);
    if (isNew) {
        m_counters.add("rx.pos.new");
        m_receivedPositions = true;
        m_gridDirty.insert(owner);
        if (repair) {
            rs.lastRepair = now; // an answer is flowing: hold our own requests for this ribbon
            if (auto b = m_gridBlocks.find(owner); b != m_gridBlocks.end()) {
                b->second.naks = 0; // the ribbon is being repaired: its requests are answered
                b->second.since = now;
            }
        }
        if (m_grid && p.slot < m_grid->nextSlot(owner))
            m_gridRecount = true; // a slot given up as unobtainable came after all
    } else {
        m_counters.add("rx.pos.duplicate");
    }
    // Someone else answers this data: our pending answers for it are no longer needed (§5).
    for (auto& a : m_assets)
        if (a.owner == owner && a.pending.contains(p.slot)) {
            a.pending.erase(p.slot);
            a.othersAnswering = true;
        }
    // A retransmission was overheard: whoever answers this ribbon is alive, so a repeated NAK for the slot
    // means the answer was lost, not that nobody answers; push our relay wait further out.
    if (h.who != idx() && (!isNew || repair))
        if (auto ns = m_nakSeen.find(owner); ns != m_nakSeen.end())
            if (auto it = ns->second.find(p.slot); it != ns->second.end())
                it->second = NakSeen{now, 0, it->second.requester}; // count the repetitions afresh
    for (auto& s : m_suppressed)
        if (s.owner == owner && s.pending.contains(p.slot)) {
            s.pending.erase(p.slot);
            s.heard = true;
        }
    if (isNew && (newest || !rs.reported || p.slot > rs.lastReported)) {
        rs.reported = true;
        rs.lastReported = p.slot;
        // Implausible positions stay in the ribbon (the slot is complete for everyone's repair) but reach
        // neither the grid (PassCountGrid applies the same limits) nor a model.
        const PositionFault fault = checkPosition(p, m_cfg.passCount.plausibility);
        if (fault != PositionFault::None)
            implausible(owner, p, fault, now);
        if (m_listener) {
            if (fault == PositionFault::None) {
                m_listener->onMachinePosition(
                    makeSnapshot(owner, p, m_geo ? &m_frame : nullptr, nameOf(owner), typeOf(owner)));
            } else {
                MachineSnapshot bad;
                bad.idx = owner;
                bad.name = nameOf(owner);
                bad.type = typeOf(owner);
                bad.slot = p.slot;
                bad.flags = p.flags;
                bad.timestampMs = p.time ? fileTimeToUnixMillis(p.time) : 0;
                bad.implausible = std::string("implausible position ignored (") + toString(fault) + ")";
                m_listener->onMachinePosition(bad);
            }
        }
    } else if (isNew) {
        if (const PositionFault fault = checkPosition(p, m_cfg.passCount.plausibility);
            fault != PositionFault::None)
            implausible(owner, p, fault, now);
    }
}

bool StationCore::answerAllowed(std::uint8_t requester, std::uint8_t whose, RequestType type, TimePoint now) {
    // Amplification bound: one answer per requester, addressed ribbon and type per Beat. 50
    // ALLs in one datagram made the console send 206 messages; now one requester's datagram costs at most one
    // ALL answer for all ribbons (newest position + ALIVE per ribbon held) plus one per ribbon addressed
    // singly, i.e. at most 4 messages per ribbon held, and one PONG. Bounded table: 255 x 256 x 2 entries at
    // most.
    auto [it, first] = m_answeredAt.try_emplace({requester, whose, type}, now);
    if (!first && now - it->second < beats(1)) {
        m_counters.add(type == RequestType::All ? "rx.limited.all" : "rx.limited.ping");
        return false;
    }
    it->second = now;
    return true;
}

void StationCore::implausible(std::uint8_t owner, const CmPos& p, PositionFault fault, TimePoint now) {
    m_counters.add(std::string("rx.implausible.") + toString(fault));
    // Bounded: at most 254 owners x 4 causes.
    auto [it, first] = m_implausibleEventAt.try_emplace({owner, fault}, now);
    if (!first && now - it->second < kImplausibleEventGap)
        return;
    it->second = now;
    const auto& l = m_cfg.passCount.plausibility;
    std::string what;
    switch (fault) {
    case PositionFault::NonFinite:
        what = "a coordinate, speed or width is not a finite number";
        break;
    case PositionFault::OutsideExtent:
        what = "x/y/z beyond " + std::to_string(static_cast<long long>(l.extentM)) +
               " m from the worksite origin";
        break;
    case PositionFault::DrumWidth:
        what = "drum width " + std::to_string(p.dx) + " m outside " + std::to_string(l.minWidthM) + "-" +
               std::to_string(l.maxWidthM) + " m";
        break;
    case PositionFault::Speed:
        what = "speed " + std::to_string(p.speed) + " m/s above " + std::to_string(l.maxSpeedMps) + " m/s";
        break;
    case PositionFault::None:
        return;
    }
    const std::string name = nameOf(owner);
    event(Severity::Warning, "OSYRIS station " + std::to_string(owner) +
                                 (name.empty() ? "" : " (" + name + ")") + ": position of slot " +
                                 std::to_string(p.slot) + " ignored: " + what +
                                 " (counted in rx.implausible." + toString(fault) +
                                 "; one warning per machine and cause every 30 s)");
}

void StationCore::handleRequest(const CmHeader& h, const CmRequest& r, TimePoint now) {
    std::uint8_t who = h.who;
    switch (r.type) {
    case RequestType::Nak: {
        m_counters.add("rx.nak");
        std::uint8_t owner = h.whose;
        if (owner >= kIdxNobody)
            return;
        auto held = m_store.held(owner);
        std::uint32_t to = r.to == kSlotLast ? (held.empty() ? 0 : held.max()) : r.to;
        // Overheard: the answer will be multicast, so our own wish for the same slots waits (§5).
        if (m_cfg.active & kActiveAskRequests)
            if (auto it = m_ribbons.find(owner); it != m_ribbons.end() && r.from <= to)
                setHold(it->second, r.from, to, now + beats(m_cfg.ttlBeats));
        if (!(m_cfg.active & kActiveAnswerRequests) || r.from > to)
            return;
        IntervalSet have;
        for (auto& x : held.intersect(r.from, to))
            have.insert(x.from, x.to);
        if (auto rs = m_recentlySent.find(owner); rs != m_recentlySent.end()) {
            for (auto it = rs->second.lower_bound(r.from); it != rs->second.end() && it->first <= to; ++it)
                if (now - it->second < beats(m_cfg.answerHoldBeats)) {
                    have.erase(it->first);
                    m_counters.add("rx.nak.crossed");
                }
        }
        if (have.empty()) {
            m_counters.add("rx.nak.ignored"); // we hold none of it (§5)
            return;
        }
        const bool all = have.count() == std::uint64_t(to) - r.from + 1;
        // Bounded work: never look at more slots than the answer budget could pay for.
        have = newestOf(have, m_answerBudget / kPosSize + 1);
        if (owner != idx()) {
            // Soft relay (§5): a non-owner answers a NAK only when it is repeated after TTL/2, i.e. the owner
            // did not answer the first one. The first NAK is remembered (at most kMaxNakSeenPerRibbon slots).
            auto& seen = m_nakSeen[owner];
            const auto heard = m_lastHeard.find(owner);
            const int repeatsNeeded =
                heard != m_lastHeard.end() &&
                        now - heard->second < std::chrono::milliseconds(3 * m_cfg.sendPeriodMs)
                    ? 2
                    : 1;
            IntervalSet due;
            for (auto& x : have.ranges())
                for (std::uint64_t sl = x.from; sl <= x.to; ++sl) {
                    auto it = seen.find(static_cast<std::uint32_t>(sl));
                    if (it == seen.end()) {
                        if (seen.size() < kMaxNakSeenPerRibbon)
                            seen.emplace(static_cast<std::uint32_t>(sl), NakSeen{now, 0, who});
                        else
                            m_counters.add("rx.nak.unremembered");
                    } else if (it->second.requester != who) {
                        it->second = NakSeen{now, 0, who}; // another station's miss: its own count
                    } else if (now - it->second.at >= beats(m_cfg.ttlBeats / 2.0)) {
                        it->second.at = now;
                        if (++it->second.repeats >= repeatsNeeded)
                            due.insert(static_cast<std::uint32_t>(sl));
                    }
                }
            if (due.empty()) {
                m_counters.add("rx.nak.deferred");
                return;
            }
            have = std::move(due);
        }
        if (!charge(kRequestSize)) // the NCF
            return;
        have = chargeSlots(owner, have);
        if (have.empty())
            return;
        int prio;
        TimePoint nb;
        if (owner == idx()) {
            prio = kPrioOwner;
            nb = now;
        } else {
            prio = all ? kPrioAll : kPrioPartial;
            nb = now + beats((all ? 2.0 : 3.0) + rankFor(owner));
        }
        addAsset(owner, std::move(have), prio, nb);
        break;
    }
    case RequestType::Ncf: {
        m_counters.add("rx.ncf");
        std::uint8_t owner = h.whose;
        if (owner >= kIdxNobody || r.from > r.to)
            return;
        // Another station will answer: lower our answer for the same interval (suppressed until TTL)...
        for (auto& a : m_assets) {
            if (a.owner != owner || a.ncfSent)
                continue;
            IntervalSet moved;
            for (auto& x : a.pending.intersect(r.from, r.to))
                moved.insert(x.from, x.to);
            if (moved.empty())
                continue;
            a.pending.erase(r.from, r.to);
            m_counters.add("asset.suppressed");
            m_suppressed.push_back({owner, std::move(moved), now + beats(m_cfg.ttlBeats), false});
        }
        // ...and our own wish for it waits for the retransmission.
        if (auto it = m_ribbons.find(owner); it != m_ribbons.end())
            setHold(it->second, r.from, r.to, now + beats(m_cfg.ttlBeats));
        break;
    }
    case RequestType::All: {
        m_counters.add("rx.all");
        if (!(m_cfg.active & kActiveAnswerRequests))
            return;
        if (h.whose != kIdxAll && m_store.held(h.whose).empty())
            return; // a ribbon we do not hold: nothing to answer, and no rate-limit entry for it
        if (!answerAllowed(who, h.whose, RequestType::All, now))
            return;
        for (auto owner : m_store.machines()) {
            if (h.whose != kIdxAll && h.whose != owner)
                continue;
            auto held = m_store.held(owner);
            if (held.empty())
                continue;
            // Newest state first (§4 late join): the newest position of every ribbon, right away.
            auto n = m_store.newest(owner);
            if (!charge(kRequestSize + (n ? unitSize(*n) : 0)))
                break;
            if (n) {
                enqueuePosition(owner, *n, true);
                m_counters.add("tx.retx");
                m_counters.add("tx.retx.newest");
            }
            enqueueRequest(owner, {RequestType::Alive, held.min(), held.max(), 0, 0}, true);
            m_counters.add("tx.alive");
            if (owner == idx() && held.max() > held.min() && charge(kRequestSize)) {
                // Owner sends its tail (TailPos, default all), newest first, with an NCF: as much of it as
                // this datagram's answer budget pays for; the requester NAKs the rest, which ALIVE showed.
                std::uint32_t hi = held.max() - 1;
                std::uint32_t lo = held.min();
                if (m_cfg.tailPos > 0 && hi - lo + 1 > m_cfg.tailPos)
                    lo = hi - (m_cfg.tailPos - 1);
                IntervalSet tail;
                for (auto& x : held.intersect(lo, hi))
                    tail.insert(x.from, x.to);
                tail = chargeSlots(owner, newestOf(tail, m_answerBudget / kPosSize + 1));
                if (!tail.empty())
                    addAsset(owner, std::move(tail), kPrioOwner, now);
            }
        }
        break;
    }
    case RequestType::Ping: {
        m_counters.add("rx.ping");
        if (h.whose != idx() && h.whose != kIdxAll)
            return;
        if (!answerAllowed(who, h.whose, RequestType::Ping, now) || !charge(kRequestSize))
            return;
        auto own = ownPosition();
        enqueueRequest(who, {RequestType::Pong, 0, 0, own ? own->x : 0.f, own ? own->y : 0.f});
        m_counters.add("tx.pong");
        m_pongQueued = true; // answered at once, not at the next Beat: the round-trip time means something
        break;
    }
    case RequestType::Pong: {
        m_counters.add("rx.pong");
        if (h.whose != idx())
            return;
        auto it = m_pings.find(who);
        double rtt = -1;
        if (it != m_pings.end()) {
            rtt = std::chrono::duration<double, std::milli>(now - it->second).count();
            m_pings.erase(it);
        }
        if (m_listener)
            m_listener->onPong(who, rtt, r.x, r.y);
        event(Severity::Info,
              "PONG from station " + std::to_string(who) + " after " + std::to_string(int(rtt)) + " ms");
        break;
    }
    case RequestType::Alive: {
        m_counters.add("rx.alive");
        std::uint8_t owner = h.whose;
        bool hasRange = r.from <= r.to && r.to != kSlotLast;
        if (owner < kIdxNobody && hasRange && !admitted(owner)) {
            reject("station_cap", "ALIVE from " + std::to_string(who) + " about station " +
                                      std::to_string(owner) + ": already " +
                                      std::to_string(kMaxUnknownStations) +
                                      " stations not in the configuration");
            hasRange = false;
        }
        if (owner < kIdxNobody && hasRange) {
            // Phantom ranges: too wide to be a machine's ribbon, or (from a third station) far
            // beyond anything the owner itself showed. Ignored with a counter; NAKing them cost endless
            // datagrams.
            auto shown = m_ownerShown.find(owner);
            const bool tooWide = r.to - r.from >= kMaxAnnouncedSpan;
            const bool tooFarAhead = who != owner && shown != m_ownerShown.end() &&
                                     std::uint64_t(r.to) > std::uint64_t(shown->second) + kMaxAnnouncedAhead;
            if (tooWide || tooFarAhead) {
                reject(tooWide ? "alive_range_too_wide" : "alive_range_ahead",
                       "ALIVE from " + std::to_string(who) + " announces slots " + std::to_string(r.from) +
                           "-" + std::to_string(r.to) + " of station " + std::to_string(owner));
                hasRange = false;
            } else {
                if (who == owner)
                    m_ownerShown[owner] = std::max(m_ownerShown[owner], r.to);
                noteKnown(owner, r.from, r.to);
            }
        }
        if (owner == who && m_listener)
            m_listener->onStationAlive(who, hasRange ? std::optional<SlotRange>(SlotRange{r.from, r.to})
                                                     : std::nullopt);
        break;
    }
    }
}

// ---- the Beat ----

void StationCore::checkGridBlocks(TimePoint now) {
    // Counting a ribbon waits at its first missing slot; when the gap stays unobtainable (asked
    // for gapGiveUpNaks times without any answer for the ribbon and the last request's TTL passed, or for
    // gapGiveUpMs), it is given up: the
    // grid counts on after it, never across it, and marks the cells it may have covered incomplete.
    for (auto owner : m_store.machines()) {
        const std::uint32_t next = m_grid->nextSlot(owner);
        const IntervalSet held = m_store.held(owner);
        if (held.empty() || held.max() < next || held.contains(next)) {
            m_gridBlocks.erase(owner);
            continue;
        }
        auto [it, fresh] = m_gridBlocks.try_emplace(owner);
        GridBlock& b = it->second;
        if (fresh || b.slot != next) {
            b = {next, now, 0};
            continue;
        }
        // The last request had its TTL to be answered.
        const bool asked = m_cfg.gapGiveUpNaks > 0 && b.naks >= m_cfg.gapGiveUpNaks &&
                           now - b.lastNak >= beats(m_cfg.ttlBeats);
        const bool waited =
            m_cfg.gapGiveUpMs > 0 && now - b.since >= std::chrono::milliseconds(m_cfg.gapGiveUpMs);
        if (!asked && !waited)
            continue;
        std::uint32_t last = next;
        for (const auto& r : held.ranges())
            if (r.from > next) {
                last = r.from - 1;
                break;
            }
        m_grid->giveUp(owner, next, last);
        m_gridDirty.insert(owner);
        m_counters.add("grid.gap.given_up");
        m_counters.add("grid.gap.given_up.slots", std::uint64_t(last) - next + 1);
        const std::string name = nameOf(owner).empty() ? "station " + std::to_string(owner) : nameOf(owner);
        const std::string why =
            asked ? "asked for " + std::to_string(b.naks) + " times without an answer"
                  : "not obtained in " +
                        std::to_string(
                            std::chrono::duration_cast<std::chrono::seconds>(now - b.since).count()) +
                        " s";
        event(Severity::Warning, "OSYRIS: positions " + std::to_string(next) + "-" + std::to_string(last) +
                                     " of " + name + " are unobtainable (" + why +
                                     "): pass counts go on without them; the cells they may have covered are "
                                     "marked incomplete");
        m_gridBlocks.erase(it);
    }
}

void StationCore::setPassCountSettings(const PassCountSettings& s) {
    m_cfg.passCount = s;
    if (!m_grid)
        return;
    m_grid->setSettings(s);
    for (auto owner : m_store.machines())
        m_gridDirty.insert(owner);
    m_passCountsUnpublished = true;
    m_nextPassCountPublish = {};
    updateGrid();
}

void StationCore::updateGrid() {
    if (!m_grid)
        return;
    if (m_gridRecount && m_clock.now() >= m_nextRecount) {
        m_gridRecount = false;
        m_nextRecount = m_clock.now() + kRecountGap;
        m_grid->recount(m_store);
        m_gridDirty.clear();
        m_passCountsUnpublished = true;
        event(Severity::Info,
              "OSYRIS: positions given up as unobtainable arrived after all: pass counts recounted");
    }
    for (auto owner : m_gridDirty)
        m_grid->advance(owner, m_store);
    m_gridDirty.clear();
    checkGridBlocks(m_clock.now());
    for (auto owner : m_gridDirty) // given up just now: count on after the gap
        m_grid->advance(owner, m_store);
    m_gridDirty.clear();
    if (auto r = m_grid->takeDirty()) {
        m_passCountsUnpublished = true;
        if (m_listener)
            m_listener->onPassCountChanged(*r);
    }
    publishPassCounts(m_clock.now());
}

void StationCore::publishPassCounts(TimePoint now) {
    // Bounded rate and back-pressure: a GUI that has not taken the previous snapshot gets no new one (the
    // change stays pending), so snapshots never pile up in its queue.
    if (!m_passCountsUnpublished || !m_listener || now < m_nextPassCountPublish ||
        !m_listener->readyForPassCounts())
        return;
    m_passCountsUnpublished = false;
    m_nextPassCountPublish = now + std::chrono::milliseconds(std::max(m_cfg.passCountPublishMs, 0));
    m_listener->onPassCounts(m_grid->snapshot());
}

void StationCore::tick() {
    auto now = m_clock.now();
    if ((m_cfg.active & kActiveAskRequests) && !m_receivedPositions && m_allRetries < 3 &&
        m_allRetryAt != TimePoint{} && now >= m_allRetryAt) {
        enqueueRequest(kIdxAll, {RequestType::All, 0, kSlotLast, 0, 0}); // the first ALL may have been lost
        m_counters.add("tx.all");
        ++m_allRetries;
        m_allRetryAt = now + beats(m_cfg.ttlBeats);
    }
    if (m_cfg.active & kActiveAskRequests)
        processWishes(now);
    if (m_cfg.active & kActiveAnswerRequests)
        processAssets(now);
    if (!m_aliveSent || now - m_lastAlive >= std::chrono::milliseconds(m_cfg.sendPeriodMs)) {
        sendAlive();
        m_lastAlive = now;
        m_aliveSent = true;
    }
    flush(now, false);
    m_store.commit();
    updateGrid();
}

} // namespace ocu::osyris
