#include "protocols/osyris/StationCore.h"

#include "protocols/common/Log.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ocu::osyris {

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

// ---- the Beat ----

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
