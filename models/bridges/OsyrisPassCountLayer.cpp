#include "models/bridges/OsyrisPassCountLayer.h"

namespace ocu {

using namespace osyris;

OsyrisPassCountLayer::OsyrisPassCountLayer(double cellSize, QPointF worksiteOffset)
    : m_cellSize(cellSize), m_offset(worksiteOffset) {}

void OsyrisPassCountLayer::setSnapshot(std::shared_ptr<const PassCountSnapshot> snapshot) {
    if (!snapshot || (m_snap && snapshot->sequence() <= m_snap->sequence()))
        return;
    m_snap = std::move(snapshot);
    std::int32_t cx0 = 0, cy0 = 0;
    int cols = 0, rows = 0;
    if (!m_snap->empty()) {
        const CellBox e = m_snap->extent();
        cx0 = e.cx0;
        cy0 = e.cy0;
        cols = e.cx1 - e.cx0 + 1;
        rows = e.cy1 - e.cy0 + 1;
    }
    m_revision = 1 + m_snap->sequence();
    if (cx0 != m_cx0 || cy0 != m_cy0 || cols != m_cols || rows != m_rows ||
        m_snap->cellSize() != m_cellSize) {
        m_cx0 = cx0;
        m_cy0 = cy0;
        m_cols = cols;
        m_rows = rows;
        m_extentRevision = m_revision;
    }
    m_cellSize = m_snap->cellSize();
}

double OsyrisPassCountLayer::cellSize() const {
    return m_cellSize;
}

QPointF OsyrisPassCountLayer::origin() const {
    return {m_offset.x() + m_cx0 * m_cellSize, m_offset.y() + m_cy0 * m_cellSize};
}

int OsyrisPassCountLayer::count(int col, int row) const {
    if (!m_snap || col < 0 || row < 0 || col >= m_cols || row >= m_rows)
        return 0;
    return m_snap->countAtCell(m_cx0 + col, m_cy0 + row);
}

QRect OsyrisPassCountLayer::countsIn(QRect cells, std::vector<std::uint16_t>& out) const {
    const QRect clipped = cells.intersected(QRect(0, 0, m_cols, m_rows));
    out.assign(clipped.isEmpty() ? 0 : size_t(clipped.width()) * size_t(clipped.height()), 0);
    if (!clipped.isEmpty() && m_snap)
        m_snap->countsInRect(m_cx0 + clipped.left(), m_cy0 + clipped.top(), clipped.width(), clipped.height(),
                             out.data());
    return clipped;
}

QRect OsyrisPassCountLayer::changedCellsSince(quint64 revision) const {
    if (revision >= m_revision)
        return {};
    const QRect all(0, 0, m_cols, m_rows);
    // Revision r was snapshot r - 1; before the extent or the grid changed wholesale, everything is new.
    if (!m_snap || revision < m_extentRevision || revision < 1 + m_snap->clearedAt() || revision < 2)
        return all;
    const auto box = m_snap->changedSince(revision - 1);
    if (!box)
        return {};
    return QRect(QPoint(box->cx0 - m_cx0, box->cy0 - m_cy0), QPoint(box->cx1 - m_cx0, box->cy1 - m_cy0))
        .intersected(all);
}

} // namespace ocu
