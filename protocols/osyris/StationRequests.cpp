// How StationCore answers the requests of other stations (OSYRIS §4, §5): NAK (with the soft relay of a
// non-owner), NCF, ALL (late join), PING/PONG and ALIVE, each bounded by the received datagram's answer
// budget.
#include "protocols/osyris/StationCore.h"

#include <algorithm>
#include <chrono>

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

void StationCore::handleRequest(const CmHeader& h, const CmRequest& r, TimePoint now) {
    switch (r.type) {
    case RequestType::Nak:
        handleNak(h, r, now);
        break;
    case RequestType::Ncf:
        handleNcf(h, r, now);
        break;
    case RequestType::All:
        handleAll(h, r, now);
        break;
    case RequestType::Ping:
        handlePing(h, r, now);
        break;
    case RequestType::Pong:
        handlePong(h, r, now);
        break;
    case RequestType::Alive:
        handleAlive(h, r, now);
        break;
    }
}

void StationCore::handleNak(const CmHeader& h, const CmRequest& r, TimePoint now) {
    const std::uint8_t who = h.who;
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
}

void StationCore::handleNcf(const CmHeader& h, const CmRequest& r, TimePoint now) {
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
}

void StationCore::handleAll(const CmHeader& h, const CmRequest&, TimePoint now) {
    const std::uint8_t who = h.who;
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
}

void StationCore::handlePing(const CmHeader& h, const CmRequest&, TimePoint now) {
    const std::uint8_t who = h.who;
    m_counters.add("rx.ping");
    if (h.whose != idx() && h.whose != kIdxAll)
        return;
    if (!answerAllowed(who, h.whose, RequestType::Ping, now) || !charge(kRequestSize))
        return;
    auto own = ownPosition();
    enqueueRequest(who, {RequestType::Pong, 0, 0, own ? own->x : 0.f, own ? own->y : 0.f});
    m_counters.add("tx.pong");
    m_pongQueued = true; // answered at once, not at the next Beat: the round-trip time means something
}

void StationCore::handlePong(const CmHeader& h, const CmRequest& r, TimePoint now) {
    const std::uint8_t who = h.who;
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
}

void StationCore::handleAlive(const CmHeader& h, const CmRequest& r, TimePoint) {
    const std::uint8_t who = h.who;
    m_counters.add("rx.alive");
    std::uint8_t owner = h.whose;
    bool hasRange = r.from <= r.to && r.to != kSlotLast;
    if (owner < kIdxNobody && hasRange && !admitted(owner)) {
        reject("station_cap", "ALIVE from " + std::to_string(who) + " about station " +
                                  std::to_string(owner) + ": already " + std::to_string(kMaxUnknownStations) +
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
                   "ALIVE from " + std::to_string(who) + " announces slots " + std::to_string(r.from) + "-" +
                       std::to_string(r.to) + " of station " + std::to_string(owner));
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
}

} // namespace ocu::osyris
