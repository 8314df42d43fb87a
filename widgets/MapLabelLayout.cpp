#include "widgets/MapLabelLayout.h"

#include <algorithm>
#include <cmath>

namespace ocu {

void MapLabelLayout::reset(const QRectF& viewport, double cellPx) {
    m_viewport = viewport;
    m_cell = cellPx;
    m_cols = std::max(1, int(std::ceil(viewport.width() / cellPx)));
    m_rows = std::max(1, int(std::ceil(viewport.height() / cellPx)));
    m_buckets.assign(size_t(m_cols) * size_t(m_rows), {});
    m_rects.clear();
    m_placed.clear();
}

template <typename F> void MapLabelLayout::forCells(const QRectF& r, F&& f) const {
    const int c0 = std::clamp(int((r.left() - m_viewport.left()) / m_cell), 0, m_cols - 1);
    const int c1 = std::clamp(int((r.right() - m_viewport.left()) / m_cell), 0, m_cols - 1);
    const int r0 = std::clamp(int((r.top() - m_viewport.top()) / m_cell), 0, m_rows - 1);
    const int r1 = std::clamp(int((r.bottom() - m_viewport.top()) / m_cell), 0, m_rows - 1);
    for (int y = r0; y <= r1; ++y)
        for (int x = c0; x <= c1; ++x)
            if (!f(size_t(y) * size_t(m_cols) + size_t(x)))
                return;
}

bool MapLabelLayout::fits(const QRectF& r) const {
    if (!m_viewport.contains(r))
        return false;
    bool free = true;
    forCells(r, [&](size_t cell) {
        for (int i : m_buckets[cell])
            if (m_rects[i].intersects(r)) {
                free = false;
                return false;
            }
        return true;
    });
    return free;
}

void MapLabelLayout::block(const QRectF& r) {
    const int idx = int(m_rects.size());
    m_rects.push_back(r);
    forCells(r, [&](size_t cell) {
        m_buckets[cell].push_back(idx);
        return true;
    });
}

void MapLabelLayout::place(const QRectF& r, Kind kind, const QString& text, int priority, double angleDeg) {
    block(r);
    m_placed.push_back({r, kind, text, priority, angleDeg});
}

} // namespace ocu
