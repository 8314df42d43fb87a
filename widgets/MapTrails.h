#pragma once
// The machines' recent positions on the 2D map: the newest points of each machine's trail, all machines'
// in one flat array of floats (site ENU metres, a millimetre's precision over kilometres). Drawing 1,000
// trails ten times a second then walks memory in order instead of chasing a deque's blocks per machine.
#include <QHash>
#include <QPointF>
#include <QString>

#include <vector>

namespace ocu {

class MapTrails {
public:
    // The newest `points` of each trail are kept (0: none; a change keeps the newest of what is there).
    void setCapacity(int points);
    int capacity() const { return m_capacity; }
    // Appends `p` to the machine's trail unless it is within `minDistance` of the trail's newest point.
    void appendIfMoved(const QString& id, QPointF p, double minDistance);
    void remove(const QString& id);
    void clear();
    int size() const { return int(m_slotOf.size()); }
    bool isEmpty() const { return m_slotOf.isEmpty(); }

    // One trail: `n` points, oldest first, point k at (xy[2k], xy[2k + 1]).
    struct Span {
        const float* xy = nullptr;
        int n = 0;
        QPointF back() const { return QPointF(xy[2 * (n - 1)], xy[2 * (n - 1) + 1]); }
    };
    // Calls f(Span) for every trail with points.
    template <class F> void forEach(F&& f) const {
        for (size_t s = 0; s < m_count.size(); ++s)
            if (m_count[s] > 0)
                f(Span{m_xy.data() + (s * slotPoints() + size_t(m_start[s])) * 2, m_count[s]});
    }

private:
    // Each machine's slot has room for twice the capacity: points are appended at its end and moved back to
    // its front once per `capacity` appends, not shifted on every one.
    size_t slotPoints() const { return size_t(m_capacity) * 2; }
    int slotFor(const QString& id);

    int m_capacity = 0;
    QHash<QString, int> m_slotOf;
    std::vector<int> m_freeSlots;
    std::vector<float> m_xy;
    std::vector<int> m_start, m_count; // per slot: first point, points
};

} // namespace ocu
