#pragma once
// The OSYRIS pass counts as a PassCountLayer for the map, the 3D view and the summary panel, placed in the
// site frame through the worksite origin. GUI thread only: it reads the immutable snapshot the bridge handed
// over (copy-on-write tiles, protocols/osyris/PassCountSnapshot.h) and shares no lock with the io thread,
// which keeps counting into its own grid meanwhile.
//
// It shows one lift: the top-most lift with data per cell (default) or a chosen one. Its
// summary is incremental: a histogram per tile, cached by the tile's identity (an unchanged tile is the same
// immutable object in the next snapshot), so a new snapshot costs only its changed tiles.
#include "models/PassCountLayer.h"

#include "protocols/osyris/PassCountSnapshot.h"

#include <array>
#include <memory>
#include <unordered_map>

namespace ocu {

class OsyrisPassCountLayer final : public PassCountLayer {
public:
    OsyrisPassCountLayer(double cellSize, QPointF worksiteOffset);

    // Takes over a newer snapshot (older ones are ignored); the extent is the covered tiles' bounding box.
    void setSnapshot(std::shared_ptr<const osyris::PassCountSnapshot> snapshot);
    const std::shared_ptr<const osyris::PassCountSnapshot>& snapshot() const { return m_snap; }
    // -1 = the top-most lift with data per cell; a lift beyond the snapshot's shows the top view.
    void setViewLift(int lift);
    int viewLift() const { return m_lift; }

    double cellSize() const override;
    QPointF origin() const override;
    int columns() const override { return m_cols; }
    int rows() const override { return m_rows; }
    int count(int col, int row) const override;
    // Bumped on every snapshot and on a change of the lift shown.
    quint64 revision() const override { return m_revision; }
    QRect countsIn(QRect cells, std::vector<std::uint16_t>& out) const override;
    // The tiles written after `revision` (their generation says so; in the current frame, so a grown extent
    // is not a change of its own), or everything after a clear or a change of the lift shown.
    QRect changedCellsSince(quint64 revision) const override;
    bool fastSummary(PassTarget target, PassCountSummary& out) const override;

private:
    static constexpr int kBins = 128; // exact counts 0..126, 127 = "127 or more"
    using TileHistogram = std::array<std::uint32_t, kBins>;
    void updateExtent();

    std::shared_ptr<const osyris::PassCountSnapshot> m_snap;
    double m_cellSize;
    QPointF m_offset; // site-frame (E, N) of the worksite origin
    int m_lift = -1;
    std::int32_t m_cx0 = 0, m_cy0 = 0;
    int m_cols = 0, m_rows = 0;
    quint64 m_revision = 1;
    quint64 m_offsetRevision = 0; // revision = 1 + sequence + m_offsetRevision
    quint64 m_extentRevision = 1; // revision at which origin/columns/rows/lift last changed
    quint64 m_liftRevision = 1;   // revision at which the lift shown last changed
    // Per-tile histograms of the tiles shown, keyed by the tile object (kept alive by the cache).
    struct Cached {
        std::shared_ptr<const osyris::PassCountTile> tile;
        TileHistogram histogram;
    };
    mutable std::unordered_map<const osyris::PassCountTile*, Cached> m_histograms;
};

} // namespace ocu
