#pragma once
// The OSYRIS pass counts as a PassCountLayer for the map, the 3D view and the summary panel, placed in the
// site frame through the worksite origin. GUI thread only: it reads the immutable snapshot the bridge handed
// over (copy-on-write tiles, protocols/osyris/PassCountSnapshot.h) and shares no lock with the io thread,
// which keeps counting into its own grid meanwhile.
#include "models/PassCountLayer.h"

#include "protocols/osyris/PassCountSnapshot.h"

#include <memory>

namespace ocu {

class OsyrisPassCountLayer final : public PassCountLayer {
public:
    OsyrisPassCountLayer(double cellSize, QPointF worksiteOffset);

    // Takes over a newer snapshot (older ones are ignored); the extent is the covered tiles' bounding box.
    void setSnapshot(std::shared_ptr<const osyris::PassCountSnapshot> snapshot);
    const std::shared_ptr<const osyris::PassCountSnapshot>& snapshot() const { return m_snap; }

    double cellSize() const override;
    QPointF origin() const override;
    int columns() const override { return m_cols; }
    int rows() const override { return m_rows; }
    int count(int col, int row) const override;
    // 1 before the first snapshot, then 1 + the snapshot's sequence.
    quint64 revision() const override { return m_revision; }
    QRect countsIn(QRect cells, std::vector<std::uint16_t>& out) const override;
    // The tiles written after `revision` (their generation says so), or everything after a clear or when the
    // extent moved.
    QRect changedCellsSince(quint64 revision) const override;

private:
    std::shared_ptr<const osyris::PassCountSnapshot> m_snap;
    double m_cellSize;
    QPointF m_offset; // site-frame (E, N) of the worksite origin
    std::int32_t m_cx0 = 0, m_cy0 = 0;
    int m_cols = 0, m_rows = 0;
    quint64 m_revision = 1;
    quint64 m_extentRevision = 1; // revision at which origin/columns/rows last changed
};

} // namespace ocu
