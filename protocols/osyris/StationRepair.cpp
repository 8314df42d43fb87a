// The §5 repair engine of StationCore (seed 004 §5, docs/osyris.md "List of wishes", "List of assets"):
// which gaps this station asks for (NAK) and when, and which requests it answers, in which order.
#include "protocols/osyris/StationCore.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace ocu::osyris {

void StationCore::setHold(RibbonState& rs, std::uint32_t a, std::uint32_t b, TimePoint until) {
    std::vector<Hold> out;
    out.reserve(rs.holds.size() + 2);
    for (auto& h : rs.holds) {
        if (h.to < a || h.from > b) {
            out.push_back(h);
            continue;
        }
        if (h.from < a)
            out.push_back({h.from, a - 1, h.until});
        if (h.to > b)
            out.push_back({b + 1, h.to, h.until});
    }
    out.push_back({a, b, until});
    std::sort(out.begin(), out.end(), [](const Hold& x, const Hold& y) { return x.from < y.from; });
    rs.holds = std::move(out);
}

int StationCore::rankFor(std::uint8_t owner) const {
    // Deterministic stagger of non-owner answers: stations closer after the owner (mod 256) answer first.
    auto dist = [owner](std::uint8_t s) { return static_cast<std::uint8_t>(s - owner); };
    int rank = 0;
    auto now = m_clock.now();
    for (auto& [s, t] : m_lastHeard)
        if (s != owner && s != idx() && now - t < std::chrono::milliseconds(3 * m_cfg.sendPeriodMs) &&
            dist(s) < dist(idx()))
            ++rank;
    return rank;
}

void StationCore::addAsset(std::uint8_t owner, IntervalSet slots, int priority, TimePoint notBefore) {
    for (auto& a : m_assets)
        if (a.owner == owner && !a.ncfSent) { // merge requests for the same ribbon
            for (auto& r : slots.ranges())
                a.pending.insert(r.from, r.to);
            a.priority = std::max(a.priority, priority);
            a.notBefore = std::min(a.notBefore, notBefore);
            return;
        }
    m_assets.push_back({owner, std::move(slots), priority, notBefore, false, false});
}

void StationCore::processWishes(TimePoint now) {
    struct Cand {
        std::uint8_t owner;
        std::uint32_t from, to;
    };
    std::vector<Cand> cands;
    for (auto& [owner, rs] : m_ribbons) {
        if (owner == idx() || !rs.knownMax)
            continue;
        if (storeFull(owner)) { // its positions would be refused: asking would loop forever
            rs.holds.clear();
            continue;
        }
        auto held = m_store.held(owner);
        auto gaps = held.gaps(rs.knownMin.value_or(0), *rs.knownMax);
        // Rebuild the holds over the current gaps; a new gap waits lossWaitBeats before it may be asked for.
        std::vector<Hold> holds;
        for (auto& g : gaps) {
            std::uint64_t cur = g.from;
            for (auto& h : rs.holds) {
                if (h.to < g.from || h.from > g.to)
                    continue;
                std::uint64_t f = std::max<std::uint64_t>(cur, h.from);
                if (f > cur)
                    holds.push_back({static_cast<std::uint32_t>(cur), static_cast<std::uint32_t>(f - 1),
                                     now + beats(m_cfg.lossWaitBeats)});
                std::uint32_t t = std::min(g.to, h.to);
                if (f <= t)
                    holds.push_back({static_cast<std::uint32_t>(f), t, h.until});
                cur = std::uint64_t(t) + 1;
            }
            if (cur <= g.to)
                holds.push_back({static_cast<std::uint32_t>(cur), g.to, now + beats(m_cfg.lossWaitBeats)});
        }
        rs.holds = std::move(holds);
        if (now < rs.lastRepair + beats(2))
            continue; // retransmissions for this ribbon are arriving: let them finish
        for (auto& h : rs.holds)
            if (h.until <= now)
                cands.push_back({owner, h.from, h.to});
    }
    // NAK rounds: the first requestable wish plans a round after the rest of the round
    // interval and a random back-off; until then overheard NAKs, NCFs and repairs take wishes off (they are
    // held), and what is still due when the round comes goes out together, aggregated in one datagram.
    if (cands.empty())
        return;
    std::uint64_t dueSlots = 0;
    for (const auto& c : cands)
        dueSlots += std::uint64_t(c.to) - c.from + 1;
    if (dueSlots >= m_cfg.nakRoundSlots) // enough to fill a round: the aggregation has happened
        m_nakRoundAt = std::min(m_nakRoundAt.value_or(now), now);
    if (!m_nakRoundAt) {
        const TimePoint earliest =
            m_lastNakRound == TimePoint{} ? now : m_lastNakRound + beats(m_cfg.nakRoundBeats);
        m_nakRoundAt = std::max(now, earliest) + nakBackoff();
    }
    if (now < *m_nakRoundAt)
        return;
    m_nakRoundAt.reset();
    m_lastNakRound = now;
    m_counters.add("tx.nak.rounds");
    // Newest and longest misses first within a ribbon (§4).
    std::sort(cands.begin(), cands.end(), [](const Cand& a, const Cand& b) {
        if (a.to != b.to)
            return a.to > b.to;
        return (a.to - a.from) > (b.to - b.from);
    });
    // Fair between ribbons: one candidate of each ribbon per round, the ribbons in turn from a
    // start that moves on every Beat. Sorting all ribbons newest first let one station announcing slots up to
    // 0xFFFFFFFE take every NAK of every Beat, and the real rollers' gaps were never asked for again.
    std::map<std::uint8_t, std::vector<Cand>> perOwner;
    for (const auto& c : cands)
        perOwner[c.owner].push_back(c);
    std::vector<Cand> order;
    order.reserve(cands.size());
    if (!perOwner.empty()) {
        auto start = perOwner.upper_bound(m_nakTurn);
        if (start == perOwner.end())
            start = perOwner.begin();
        m_nakTurn = start->first;
        for (std::size_t round = 0; order.size() < cands.size(); ++round) {
            auto it = start;
            do {
                if (round < it->second.size())
                    order.push_back(it->second[round]);
                if (++it == perOwner.end())
                    it = perOwner.begin();
            } while (it != start);
        }
    }
    int issued = 0;
    for (auto& c : order) {
        if (issued >= m_cfg.maxNaksPerBeat)
            break;
        std::uint32_t n = static_cast<std::uint32_t>(m_cfg.maxNakSlots);
        std::uint32_t from = (c.to - c.from + 1 > n) ? c.to - n + 1 : c.from;
        enqueueRequest(c.owner, {RequestType::Nak, from, c.to, 0, 0});
        if (auto b = m_gridBlocks.find(c.owner);
            b != m_gridBlocks.end() && b->second.slot >= c.from && b->second.slot <= c.to) {
            ++b->second.naks; // a request for the gap the pass counts wait at
            b->second.lastNak = now;
        }
        setHold(m_ribbons[c.owner], from, c.to, now + beats(m_cfg.ttlBeats));
        m_counters.add("tx.nak");
        m_counters.add("tx.nak.slots", std::uint64_t(c.to) - from + 1);
        ++issued;
    }
}

Duration StationCore::nakBackoff() {
    // RFC 5740 §5.5.1 (NORM's NACK back-off): a truncated exponential over [0, T] with lambda = ln(N) + 1 for
    // a group of N receivers, so that few of them NAK before the others can overhear and hold back.
    const double maxBeats = std::max(0, m_cfg.nakBackoffBeats);
    if (maxBeats <= 0)
        return Duration::zero();
    const auto now = m_clock.now();
    std::size_t group = 1;
    for (const auto& [s, t] : m_lastHeard)
        group += now - t < std::chrono::milliseconds(3 * m_cfg.sendPeriodMs);
    const double lambda = std::log(double(group)) + 1.0;
    const double el = std::exp(lambda);
    std::uniform_real_distribution<double> u(lambda / maxBeats / (el - 1.0),
                                             lambda / maxBeats * el / (el - 1.0));
    const double t = maxBeats / lambda * std::log(u(m_rng) * (el - 1.0) * maxBeats / lambda);
    return beats(std::clamp(t, 0.0, maxBeats));
}

void StationCore::processAssets(TimePoint now) {
    // Suppressed answers nobody delivered come back with a boosted priority (§5).
    for (auto it = m_suppressed.begin(); it != m_suppressed.end();) {
        if (it->deadline > now) {
            ++it;
            continue;
        }
        if (!it->heard && !it->pending.empty()) {
            m_counters.add("asset.boosted");
            addAsset(it->owner, std::move(it->pending), kPrioBoost, now);
        }
        it = m_suppressed.erase(it);
    }
    // Drop answers somebody else is already giving, and empty ones.
    std::erase_if(m_assets, [&](const Asset& a) {
        if (a.pending.empty())
            return true;
        if (a.othersAnswering && !a.ncfSent && a.owner != idx()) {
            m_counters.add("asset.dropped.answered");
            return true;
        }
        return false;
    });
    std::stable_sort(m_assets.begin(), m_assets.end(), [](const Asset& a, const Asset& b) {
        if (a.priority != b.priority)
            return a.priority > b.priority;
        return a.pending.max() > b.pending.max();
    });
    int budget = m_cfg.maxRetxPerBeat;
    for (auto& a : m_assets) {
        if (budget <= 0)
            break;
        if (a.notBefore > now || a.pending.empty())
            continue;
        if (!a.ncfSent) {
            // NCF before the retransmission, so other holders stand back (§6).
            enqueueRequest(a.owner, {RequestType::Ncf, a.pending.min(), a.pending.max(), 0, 0});
            m_counters.add("tx.ncf");
            a.ncfSent = true;
        }
        while (budget > 0 && !a.pending.empty()) {
            std::uint32_t s = a.pending.max(); // newest first
            a.pending.erase(s);
            if (auto rec = m_store.get(a.owner, s)) {
                m_recentlySent[a.owner][s] = now;
                enqueuePosition(a.owner, *rec, true);
                m_counters.add("tx.retx");
                if (a.owner != idx())
                    m_counters.add("tx.retx.relay");
                if (a.priority == kPrioBoost)
                    m_counters.add("tx.retx.boosted");
                --budget;
            }
        }
    }
    std::erase_if(m_assets, [](const Asset& a) { return a.pending.empty(); });
    for (auto& [owner, sent] : m_recentlySent)
        std::erase_if(sent, [&](const auto& kv) { return now - kv.second >= beats(m_cfg.answerHoldBeats); });
    for (auto& [owner, seen] : m_nakSeen)
        std::erase_if(seen,
                      [&](const auto& kv) { return now - kv.second.at >= beats(3.0 * m_cfg.ttlBeats); });
}

} // namespace ocu::osyris
