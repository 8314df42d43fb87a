#pragma once
// Pass-count grid interface shared by the 2D map, the 3D view and the summary panel, with the palettes of
// anchors-features.md §4.3 (TRex: discrete per-count palette; below/within/above summary; target 3-5).
#include <QColor>
#include <QPointF>
#include <QRect>
#include <QVector>
#include <cstdint>
#include <vector>

namespace ocu {

struct PassTarget;
struct PassCountSummary;

// Cell (col, row) covers E in [origin.x + col*cellSize, +cellSize) and N in [origin.y + row*cellSize, ...).
class PassCountLayer {
public:
    virtual ~PassCountLayer() = default;
    virtual double cellSize() const = 0;
    virtual QPointF origin() const = 0; // (E, N) of the south-west corner of cell (0, 0)
    virtual int columns() const = 0;
    virtual int rows() const = 0;
    virtual int count(int col, int row) const = 0; // 0 = not covered
    // Bumped on every change; consumers cache rendered images per revision.
    virtual quint64 revision() const = 0;

    // Bounding rectangle of the cells changed after `revision` (consumers recolour only that part).
    // Default: the whole grid (always correct).
    virtual QRect changedCellsSince(quint64 revision) const;

    // Counts of the cells in `cells` (clipped to the grid), row-major, one entry per cell of the clipped
    // rect.
    // Layers with a faster bulk read (a dense array, tiled snapshots) override it.
    virtual QRect countsIn(QRect cells, std::vector<std::uint16_t>& out) const;

    // Layers that can summarise faster than a read of every cell (tiled, incremental) fill `out` and return
    // true; summarize() then uses it.
    virtual bool fastSummary(PassTarget target, PassCountSummary& out) const;
};

// A dense in-memory grid (tests, benchmarks; 1 km² at 0.34 m is ~8.6 M cells, 17 MB). The OSYRIS bridge's
// layer is OsyrisPassCountLayer (models/bridges), which reads immutable tile snapshots.
class GridPassCountLayer final : public PassCountLayer {
public:
    GridPassCountLayer(QPointF origin, double cellSize, int columns, int rows);
    double cellSize() const override { return m_cell; }
    QPointF origin() const override { return m_origin; }
    int columns() const override { return m_cols; }
    int rows() const override { return m_rows; }
    int count(int col, int row) const override;
    quint64 revision() const override { return m_revision; }

    void setCount(int col, int row, int count); // bumps the revision
    void addPass(double e, double n);           // +1 at the cell containing (e, n), if inside
    void fillRect(QRect cells, int count);
    void clear();
    const std::uint16_t* data() const { return m_cells.data(); }
    QRect countsIn(QRect cells, std::vector<std::uint16_t>& out) const override;
    QRect changedCellsSince(quint64 revision) const override;

private:
    void touched(QRect cells);

    QPointF m_origin;
    double m_cell;
    int m_cols, m_rows;
    std::vector<std::uint16_t> m_cells;
    quint64 m_revision = 1;
    // The last changes (revision after the change, cells), oldest first; older history means "everything".
    struct Change {
        quint64 revision;
        QRect cells;
    };
    std::vector<Change> m_changes;
    static constexpr size_t kMaxChanges = 512;
};

struct PassTarget {
    int min = 3; // TRex default target range 3-5
    int max = 5;
};

enum class PassPalette { Discrete, Summary };

// One colour per count 1..9+ on an ordered scale (viridis steps, dark purple -> blue -> green -> yellow):
// lightness rises with the count.
QColor passCountDiscreteColor(int count);
// Below = DodgerBlue, within = YellowGreen, above = Red.
QColor passCountSummaryColor(int count, PassTarget target);
QColor passCountColor(int count, PassPalette palette, PassTarget target);

struct PassCountSummary {
    qint64 coveredCells = 0;
    double coveredArea = 0;                           // m²
    double belowPct = 0, withinPct = 0, abovePct = 0; // of the covered area
    QVector<qint64> histogram; // index = pass count (1..), last bucket = 9+; [0] unused
};
PassCountSummary summarize(const PassCountLayer& layer, PassTarget target);

} // namespace ocu
