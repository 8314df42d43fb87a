#include "widgets/MapTrails.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace ocu {

void MapTrails::setCapacity(int points) {
    points = std::max(0, points);
    if (points == m_capacity)
        return;
    const MapTrails old = *this;
    const QHash<QString, int> oldSlots = m_slotOf;
    clear();
    m_capacity = points;
    if (m_capacity == 0)
        return;
    for (auto it = oldSlots.cbegin(); it != oldSlots.cend(); ++it) {
        const int s = it.value();
        const float* xy = old.m_xy.data() + (size_t(s) * old.slotPoints() + size_t(old.m_start[s])) * 2;
        const int n = old.m_count[s];
        const int slot = slotFor(it.key());
        const int keep = std::min(n, m_capacity);
        std::memcpy(m_xy.data() + size_t(slot) * slotPoints() * 2, xy + size_t(n - keep) * 2,
                    size_t(keep) * 2 * sizeof(float));
        m_count[size_t(slot)] = keep;
    }
}

int MapTrails::slotFor(const QString& id) {
    if (auto it = m_slotOf.constFind(id); it != m_slotOf.constEnd())
        return it.value();
    int slot;
    if (!m_freeSlots.empty()) {
        slot = m_freeSlots.back();
        m_freeSlots.pop_back();
    } else {
        slot = int(m_count.size());
        m_count.push_back(0);
        m_start.push_back(0);
        m_xy.resize(m_xy.size() + slotPoints() * 2);
    }
    m_start[size_t(slot)] = 0;
    m_count[size_t(slot)] = 0;
    m_slotOf.insert(id, slot);
    return slot;
}

void MapTrails::appendIfMoved(const QString& id, QPointF p, double minDistance) {
    if (m_capacity <= 0)
        return;
    const int slot = slotFor(id);
    float* xy = m_xy.data() + size_t(slot) * slotPoints() * 2;
    int& start = m_start[size_t(slot)];
    int& n = m_count[size_t(slot)];
    if (n > 0) {
        const float* last = xy + size_t(start + n - 1) * 2;
        if (std::hypot(last[0] - p.x(), last[1] - p.y()) < minDistance)
            return;
    }
    if (start + n == int(slotPoints())) {
        // The slot's end: the newest points (all but one of the capacity) to its front.
        const int keep = std::min(n, m_capacity - 1);
        std::memmove(xy, xy + size_t(start + n - keep) * 2, size_t(keep) * 2 * sizeof(float));
        start = 0;
        n = keep;
    }
    xy[size_t(start + n) * 2] = float(p.x());
    xy[size_t(start + n) * 2 + 1] = float(p.y());
    if (++n > m_capacity) {
        ++start;
        --n;
    }
}

void MapTrails::remove(const QString& id) {
    const auto it = m_slotOf.constFind(id);
    if (it == m_slotOf.constEnd())
        return;
    m_count[size_t(it.value())] = 0;
    m_freeSlots.push_back(it.value());
    m_slotOf.erase(it);
}

void MapTrails::clear() {
    m_slotOf.clear();
    m_freeSlots.clear();
    m_xy.clear();
    m_start.clear();
    m_count.clear();
}

} // namespace ocu
