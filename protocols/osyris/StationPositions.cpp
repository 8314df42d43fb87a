// How StationCore takes in positions (OSYRIS §4-§6): admission and the store's bounds, the ribbon's known
// range, the effect on pending answers and relays (§5), plausibility, and the snapshot for the listener.
#include "protocols/osyris/StationCore.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ocu::osyris {

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
                bad.implausible = std::string("implausible position ignored (") + nameFor(fault) + ")";
                m_listener->onMachinePosition(bad);
            }
        }
    } else if (isNew) {
        if (const PositionFault fault = checkPosition(p, m_cfg.passCount.plausibility);
            fault != PositionFault::None)
            implausible(owner, p, fault, now);
    }
}

void StationCore::implausible(std::uint8_t owner, const CmPos& p, PositionFault fault, TimePoint now) {
    m_counters.add(std::string("rx.implausible.") + nameFor(fault));
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
                                 " (counted in rx.implausible." + nameFor(fault) +
                                 "; one warning per machine and cause every 30 s)");
}

} // namespace ocu::osyris
