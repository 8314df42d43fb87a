#pragma once
// A hand-made compaction job for the coverage report tests and benchmark: three lifts of counts on the
// simulated road (worksite frame of the built-in site), given-up cells, the shipped design.
#include "models/coverage/CoverageReport.h"

#include <map>

namespace ocu::testing {

// The built-in site's OSYRIS worksite origin (sim/modules/OsyrisSimModule: site origin + ENU (-260, -180)).
inline GeoPoint worksiteOrigin() {
    return {48.2068811596591, 11.4667019208163, 480.0};
}

// Counts: lift 0 at every cell of x in [x0, x1), y in [y0, y1): 1 + (cx % 4); lift 1 for x < xSplit:
// 1 + (cy & 3); lift 2 for x < xThird: 3. Cells with cx in [incFrom, incTo) are incomplete (top view).
struct HandJob {
    double cell = 0.34;
    double x0 = 40, x1 = 102, y0 = -2.7, y1 = 2.7, xSplit = 85, xThird = 51;
    std::int32_t incFrom = 200, incTo = 205;
};

inline int countIn(const HandJob& h, int lift, std::int32_t cx, std::int32_t cy) {
    const double x = (cx + 0.5) * h.cell, y = (cy + 0.5) * h.cell;
    if (x < h.x0 || x >= h.x1 || y < h.y0 || y >= h.y1)
        return 0;
    if (lift == 0)
        return 1 + (((cx % 4) + 4) % 4);
    if (lift == 1)
        return x < h.xSplit ? 1 + (cy & 3) : 0;
    return x < h.xThird ? 3 : 0;
}

inline std::shared_ptr<const osyris::PassCountSnapshot> makeSnapshot(const HandJob& h) {
    using namespace osyris;
    std::map<std::pair<int, int>, std::shared_ptr<PassCountTile>> lifts[3];
    std::map<std::pair<int, int>, std::shared_ptr<PassCountTopTile>> top;
    const std::int32_t cx0 = std::int32_t(std::floor(h.x0 / h.cell)) - 1,
                       cx1 = std::int32_t(h.x1 / h.cell) + 1;
    const std::int32_t cy0 = std::int32_t(std::floor(h.y0 / h.cell)) - 1,
                       cy1 = std::int32_t(h.y1 / h.cell) + 1;
    for (std::int32_t cy = cy0; cy <= cy1; ++cy)
        for (std::int32_t cx = cx0; cx <= cx1; ++cx) {
            const std::pair<int, int> key{cx >> kTileBits, cy >> kTileBits};
            const std::size_t i = std::size_t(((cy & 31) << 5) | (cx & 31));
            int topLift = -1, topCount = 0;
            for (int l = 0; l < 3; ++l) {
                const int c = countIn(h, l, cx, cy);
                if (!c)
                    continue;
                auto& t = lifts[l][key];
                if (!t)
                    t = std::make_shared<PassCountTile>();
                t->counts[i] = PassCount(c);
                topLift = l;
                topCount = c;
            }
            const bool inc = cx >= h.incFrom && cx < h.incTo;
            if (topLift < 0 && !inc)
                continue;
            auto& t = top[key];
            if (!t)
                t = std::make_shared<PassCountTopTile>();
            t->counts[i] = PassCount(topCount);
            if (topLift >= 0)
                t->lift[i] = std::int16_t(topLift);
            if (inc)
                t->flags[i] = kCellIncomplete;
        }
    auto entries = [](auto& m) {
        std::vector<PassCountSnapshot::Entry> out;
        for (auto& [k, t] : m)
            out.push_back({k.first, k.second, t});
        std::sort(out.begin(), out.end(),
                  [](const auto& a, const auto& b) { return a.ty != b.ty ? a.ty < b.ty : a.tx < b.tx; });
        return out;
    };
    PassCountSettings st;
    st.cellSize = h.cell;
    st.liftThickness = 0.05;
    st.liftBase = 0;
    std::vector<PassCountSnapshot::Lift> ls;
    for (int l = 0; l < 3; ++l)
        ls.push_back({l, 0.05 * l, 0.05 * (l + 1), entries(lifts[l])});
    return std::make_shared<PassCountSnapshot>(
        entries(top), std::move(ls), st, 7, 1,
        std::map<std::uint8_t, std::vector<SlotRange>>{{2, {SlotRange{100, 120}}}});
}

} // namespace ocu::testing
