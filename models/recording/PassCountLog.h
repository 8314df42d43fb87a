#pragma once
// OSYRIS pass counts in a flight recording (docs/recording.md "Schema"): the layer's changed cells,
// at most once a second, as absolute counts. One row of the `passcounts` table is one change, qCompress'ed:
//   f64 origin E, f64 origin N, f64 cell size, i32 columns, i32 rows (the grid then),
//   i32 x, i32 y, i32 w, i32 h (the changed cells), then w*h u16 counts, row-major (little-endian).
// A change whose grid differs from the previous one covers the whole grid. Replaying the rows up to T in
// order gives the counts of T. Decoding checks every size (a hostile row is refused, never read past).
#include "models/PassCountLayer.h"

#include <QByteArray>
#include <QPointF>
#include <QRect>

#include <cstdint>
#include <memory>
#include <vector>

namespace ocu::recording {

struct PassCountChange {
    QPointF origin;
    double cellSize = 0;
    int columns = 0, rows = 0;
    QRect cells;
    std::vector<std::uint16_t> counts; // cells.width() * cells.height()

    bool sameGrid(const PassCountChange& o) const {
        return origin == o.origin && cellSize == o.cellSize && columns == o.columns && rows == o.rows;
    }
};

QByteArray encodePassCounts(const PassCountChange& c); // uncompressed
bool decodePassCounts(const QByteArray& bytes, PassCountChange& out);

// The grid a replay shows: the changes applied in order (a change of grid starts a new one).
class ReplayPassCounts {
public:
    void apply(const PassCountChange& c);
    void clear();
    const PassCountLayer* layer() const { return m_grid.get(); }

private:
    std::unique_ptr<GridPassCountLayer> m_grid;
    PassCountChange m_geometry;
};

} // namespace ocu::recording
