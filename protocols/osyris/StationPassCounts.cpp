// How StationCore keeps the pass-count grid current: advancing it over new slots, giving up gaps that stay
// unobtainable, recounting when they arrive after all, and publishing snapshots at a bounded rate.
#include "protocols/osyris/StationCore.h"

#include <algorithm>
#include <chrono>

namespace ocu::osyris {

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

} // namespace ocu::osyris
