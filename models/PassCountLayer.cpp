#include "models/PassCountLayer.h"

#include <algorithm>
#include <cmath>

namespace ocu {

QRect PassCountLayer::countsIn(QRect cells, std::vector<std::uint16_t>& out) const {
    const QRect clipped = cells.intersected(QRect(0, 0, columns(), rows()));
    out.clear();
    if (clipped.isEmpty())
        return clipped;
    out.reserve(size_t(clipped.width()) * size_t(clipped.height()));
    for (int r = clipped.top(); r <= clipped.bottom(); ++r)
        for (int c = clipped.left(); c <= clipped.right(); ++c)
            out.push_back(std::uint16_t(std::clamp(count(c, r), 0, 65535)));
    return clipped;
}

QRect GridPassCountLayer::countsIn(QRect cells, std::vector<std::uint16_t>& out) const {
    const QRect clipped = cells.intersected(QRect(0, 0, m_cols, m_rows));
    out.clear();
    if (clipped.isEmpty())
        return clipped;
    out.reserve(size_t(clipped.width()) * size_t(clipped.height()));
    for (int r = clipped.top(); r <= clipped.bottom(); ++r) {
        const std::uint16_t* row = m_cells.data() + size_t(r) * size_t(m_cols);
        out.insert(out.end(), row + clipped.left(), row + clipped.right() + 1);
    }
    return clipped;
}

QRect PassCountLayer::changedCellsSince(quint64) const {
    return QRect(0, 0, columns(), rows());
}

void GridPassCountLayer::touched(QRect cells) {
    ++m_revision;
    if (m_changes.size() >= kMaxChanges)
        m_changes.erase(m_changes.begin(), m_changes.begin() + kMaxChanges / 2);
    m_changes.push_back({m_revision, cells});
}

QRect GridPassCountLayer::changedCellsSince(quint64 revision) const {
    if (revision >= m_revision)
        return {};
    // History must reach back to the first change after `revision`, otherwise everything may have changed.
    if (m_changes.empty() || m_changes.front().revision > revision + 1)
        return QRect(0, 0, m_cols, m_rows);
    QRect r;
    for (auto it = m_changes.rbegin(); it != m_changes.rend() && it->revision > revision; ++it)
        r = r.united(it->cells);
    return r;
}

GridPassCountLayer::GridPassCountLayer(QPointF origin, double cellSize, int columns, int rows)
    : m_origin(origin), m_cell(cellSize > 0 ? cellSize : 1.0), m_cols(std::max(0, columns)),
      m_rows(std::max(0, rows)), m_cells(size_t(m_cols) * size_t(m_rows), 0) {}

int GridPassCountLayer::count(int col, int row) const {
    if (col < 0 || row < 0 || col >= m_cols || row >= m_rows)
        return 0;
    return m_cells[size_t(row) * size_t(m_cols) + size_t(col)];
}

void GridPassCountLayer::setCount(int col, int row, int count) {
    if (col < 0 || row < 0 || col >= m_cols || row >= m_rows)
        return;
    m_cells[size_t(row) * size_t(m_cols) + size_t(col)] = std::uint16_t(std::clamp(count, 0, 65535));
    touched(QRect(col, row, 1, 1));
}

void GridPassCountLayer::addPass(double e, double n) {
    const int col = int(std::floor((e - m_origin.x()) / m_cell));
    const int row = int(std::floor((n - m_origin.y()) / m_cell));
    if (col < 0 || row < 0 || col >= m_cols || row >= m_rows)
        return;
    auto& c = m_cells[size_t(row) * size_t(m_cols) + size_t(col)];
    if (c < 65535)
        ++c;
    touched(QRect(col, row, 1, 1));
}

void GridPassCountLayer::fillRect(QRect cells, int count) {
    const QRect r = cells.intersected(QRect(0, 0, m_cols, m_rows));
    const auto v = std::uint16_t(std::clamp(count, 0, 65535));
    for (int y = r.top(); y <= r.bottom(); ++y)
        std::fill_n(m_cells.begin() + ptrdiff_t(size_t(y) * size_t(m_cols) + size_t(r.left())), r.width(), v);
    touched(r);
}

void GridPassCountLayer::clear() {
    std::fill(m_cells.begin(), m_cells.end(), std::uint16_t(0));
    touched(QRect(0, 0, m_cols, m_rows));
}

QColor passCountDiscreteColor(int count) {
    // An ordered scale (viridis in 9 steps): lightness rises with every pass, so more passes always read as
    // "further along" and neighbouring counts stay apart; readable for colour-blind viewers and on the light
    // map and the grey hillshade alike. (TRex's per-count colours put 2 = red between teal and cyan: no
    // order.)
    static const QRgb steps[9] = {0x440154, 0x472d7b, 0x3b528b, 0x2c728e, 0x21918c,
                                  0x28ae80, 0x5ec962, 0xaddc30, 0xfde725};
    if (count <= 0)
        return QColor(0, 0, 0, 0);
    return QColor(steps[std::min(count, 9) - 1]);
}

QColor passCountSummaryColor(int count, PassTarget target) {
    if (count <= 0)
        return QColor(0, 0, 0, 0);
    if (count < target.min)
        return QColor(0x1E, 0x90, 0xFF); // DodgerBlue
    if (count > target.max)
        return QColor(0xFF, 0x00, 0x00); // Red
    return QColor(0x9A, 0xCD, 0x32);     // YellowGreen
}

QColor passCountColor(int count, PassPalette palette, PassTarget target) {
    return palette == PassPalette::Discrete ? passCountDiscreteColor(count)
                                            : passCountSummaryColor(count, target);
}

bool PassCountLayer::fastSummary(PassTarget, PassCountSummary&) const {
    return false;
}

PassCountSummary summarize(const PassCountLayer& layer, PassTarget target) {
    PassCountSummary s;
    if (layer.fastSummary(target, s))
        return s;
    s.histogram = QVector<qint64>(10, 0);
    qint64 below = 0, within = 0, above = 0;
    auto add = [&](int v) {
        if (v <= 0)
            return;
        ++s.histogram[std::min(v, 9)];
        if (v < target.min)
            ++below;
        else if (v > target.max)
            ++above;
        else
            ++within;
    };
    const int cols = layer.columns(), rows = layer.rows();
    if (const auto* grid = dynamic_cast<const GridPassCountLayer*>(&layer)) {
        const std::uint16_t* d = grid->data();
        for (size_t i = 0, n = size_t(cols) * size_t(rows); i < n; ++i)
            add(d[i]);
    } else {
        // Bulk reads of bands of rows (one countsIn per band rather than a lookup per cell), bounded memory.
        const int band = std::max(1, (1 << 20) / std::max(cols, 1));
        std::vector<std::uint16_t> counts;
        for (int r = 0; r < rows; r += band) {
            layer.countsIn(QRect(0, r, cols, std::min(band, rows - r)), counts);
            for (auto v : counts)
                add(v);
        }
    }
    s.coveredCells = below + within + above;
    s.coveredArea = double(s.coveredCells) * layer.cellSize() * layer.cellSize();
    if (s.coveredCells > 0) {
        s.belowPct = 100.0 * double(below) / double(s.coveredCells);
        s.withinPct = 100.0 * double(within) / double(s.coveredCells);
        s.abovePct = 100.0 * double(above) / double(s.coveredCells);
    }
    return s;
}

} // namespace ocu
