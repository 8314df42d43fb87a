#include "models/bridges/OsyrisPassCountLayer.h"

#include <algorithm>

namespace ocu {

using namespace osyris;

OsyrisPassCountLayer::OsyrisPassCountLayer(double cellSize, QPointF worksiteOffset)
    : m_cellSize(cellSize), m_offset(worksiteOffset) {}

void OsyrisPassCountLayer::setSnapshot(std::shared_ptr<const PassCountSnapshot> snapshot) {
    if (!snapshot || (m_snap && snapshot->sequence() <= m_snap->sequence()))
        return;
    m_snap = std::move(snapshot);
    m_revision = 1 + m_snap->sequence() + m_offsetRevision;
    updateExtent();
    m_cellSize = m_snap->cellSize();
}

void OsyrisPassCountLayer::setViewLift(int lift) {
    lift = std::max(-1, lift);
    if (lift == m_lift)
        return;
    m_lift = lift;
    ++m_offsetRevision;
    ++m_revision;
    m_liftRevision = m_revision; // everything shown changed
    m_histograms.clear();
    updateExtent();
}

void OsyrisPassCountLayer::updateExtent() {
    std::int32_t cx0 = 0, cy0 = 0;
    int cols = 0, rows = 0;
    // The extent of the top view covers every lift: the frame stays put when the lift shown changes.
    if (m_snap && !m_snap->empty()) {
        const CellBox e = m_snap->extent();
        cx0 = e.cx0;
        cy0 = e.cy0;
        cols = e.cx1 - e.cx0 + 1;
        rows = e.cy1 - e.cy0 + 1;
    }
    if (cx0 != m_cx0 || cy0 != m_cy0 || cols != m_cols || rows != m_rows ||
        (m_snap && m_snap->cellSize() != m_cellSize)) {
        m_cx0 = cx0;
        m_cy0 = cy0;
        m_cols = cols;
        m_rows = rows;
        m_extentRevision = m_revision;
    }
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
    return m_snap->countAtCell(m_cx0 + col, m_cy0 + row, m_lift);
}

QRect OsyrisPassCountLayer::countsIn(QRect cells, std::vector<std::uint16_t>& out) const {
    const QRect clipped = cells.intersected(QRect(0, 0, m_cols, m_rows));
    out.assign(clipped.isEmpty() ? 0 : size_t(clipped.width()) * size_t(clipped.height()), 0);
    if (!clipped.isEmpty() && m_snap)
        m_snap->countsInRect(m_cx0 + clipped.left(), m_cy0 + clipped.top(), clipped.width(), clipped.height(),
                             out.data(), m_lift);
    return clipped;
}

QRect OsyrisPassCountLayer::changedCellsSince(quint64 revision) const {
    if (revision >= m_revision)
        return {};
    const QRect all(0, 0, m_cols, m_rows);
    // Revision r was snapshot r - 1 - offset; before the lift shown or the grid changed wholesale, everything
    // is new. A grown extent alone is not: the tiles' generations are in grid cells, whatever the frame.
    if (!m_snap || revision < m_liftRevision || revision < 1 + m_offsetRevision + m_snap->clearedAt() ||
        revision < 2 + m_offsetRevision)
        return all;
    const auto box = m_snap->changedSince(revision - 1 - m_offsetRevision, m_lift);
    if (!box)
        return {};
    return QRect(QPoint(box->cx0 - m_cx0, box->cy0 - m_cy0), QPoint(box->cx1 - m_cx0, box->cy1 - m_cy0))
        .intersected(all);
}

bool OsyrisPassCountLayer::fastSummary(PassTarget target, ocu::PassCountSummary& s) const {
    s = {};
    s.histogram = QVector<qint64>(10, 0);
    TileHistogram total{};
    std::unordered_map<const PassCountTile*, Cached> next;
    if (m_snap) {
        const auto& entries = m_snap->tiles(m_lift);
        next.reserve(entries.size());
        for (const auto& e : entries) {
            const PassCountTile* key = e.tile.get();
            auto it = m_histograms.find(key);
            Cached c;
            if (it != m_histograms.end()) {
                c = std::move(it->second);
            } else {
                c.tile = e.tile;
                c.histogram.fill(0);
                for (auto v : e.tile->counts)
                    ++c.histogram[std::min<std::size_t>(v, kBins - 1)];
            }
            for (int i = 1; i < kBins; ++i)
                total[static_cast<std::size_t>(i)] += c.histogram[static_cast<std::size_t>(i)];
            next.emplace(key, std::move(c));
        }
    }
    m_histograms = std::move(next); // only the tiles shown now stay referenced
    qint64 below = 0, within = 0, above = 0;
    for (int v = 1; v < kBins; ++v) {
        const qint64 n = total[static_cast<std::size_t>(v)];
        if (!n)
            continue;
        s.histogram[std::min(v, 9)] += n;
        if (v < target.min)
            below += n;
        else if (v > target.max && v < kBins - 1)
            above += n;
        else if (v >= kBins - 1)
            above += target.max < kBins - 1 ? n : 0, within += target.max >= kBins - 1 ? n : 0;
        else
            within += n;
    }
    s.coveredCells = below + within + above;
    s.coveredArea = double(s.coveredCells) * m_cellSize * m_cellSize;
    if (s.coveredCells > 0) {
        s.belowPct = 100.0 * double(below) / double(s.coveredCells);
        s.withinPct = 100.0 * double(within) / double(s.coveredCells);
        s.abovePct = 100.0 * double(above) / double(s.coveredCells);
    }
    return true;
}

} // namespace ocu
