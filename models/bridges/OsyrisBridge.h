#pragma once
// The Qt face of the OCU's OSYRIS station: machine positions become MachineState rows (coalesced), text
// messages become events, and the station's pass-count grid is offered to the map as a PassCountLayer
// placed in the site frame through the worksite origin.
#include "models/FleetBridge.h"
#include "models/PassCountLayer.h"

#include "protocols/common/GeoFrame.h"
#include "protocols/osyris/OsyrisConfig.h"
#include "protocols/osyris/OsyrisStack.h"

#include <atomic>
#include <memory>

namespace ocu {

// Reads the station's sparse grid (thread-safe readers) as a dense layer over its covered extent.
class OsyrisPassCountLayer final : public PassCountLayer {
public:
    OsyrisPassCountLayer(const osyris::PassCountGrid& grid, QPointF worksiteOffset);
    double cellSize() const override;
    QPointF origin() const override;
    int columns() const override { return m_cols; }
    int rows() const override { return m_rows; }
    int count(int col, int row) const override;
    quint64 revision() const override { return m_revision; }
    QRect countsIn(QRect cells, std::vector<std::uint16_t>& out) const override;
    // GUI thread: re-reads the covered extent after the grid changed.
    void refreshExtent();

private:
    const osyris::PassCountGrid& m_grid;
    QPointF m_offset; // site-frame (E, N) of the worksite origin
    std::int32_t m_cx0 = 0, m_cy0 = 0;
    int m_cols = 0, m_rows = 0;
    quint64 m_revision = 1;
};

class OsyrisBridge : public FleetBridge, private osyris::OsyrisListener {
    Q_OBJECT
public:
    OsyrisBridge(const osyris::OsyrisConfig& config, const GeoFrame& siteFrame, QObject* parent = nullptr);
    ~OsyrisBridge() override;

    QString start();
    void stop();

    CommandResult stopAll() override;
    CommandResult stopMachine(const QString& id) override;
    CommandResult clearStop(const QString& id) override;
    // send_text {"text"}, ping {"idx"}.
    CommandResult command(const QString& name, const QJsonObject& args) override;
    const PassCountLayer* passCountLayer() const override { return m_layer.get(); }
    osyris::PassCountSummary passCountSummary() const;

private:
    void onMachinePosition(const osyris::MachineSnapshot& s) override;
    void onStationAlive(std::uint8_t idx, std::optional<osyris::SlotRange> range) override;
    void onText(std::uint8_t idx, const std::string& text) override;
    void onPassCountChanged(const osyris::GridRect& dirty) override;
    void onEvent(osyris::Severity severity, const std::string& text) override;

    osyris::OsyrisConfig m_config;
    GeoFrame m_frame;
    std::unique_ptr<osyris::OsyrisStack> m_station;
    std::unique_ptr<OsyrisPassCountLayer> m_layer;
    std::atomic<bool> m_passCountQueued{false};
    std::atomic<bool> m_linkUp{false};
    std::atomic<bool> m_heard{false}; // a station (position or alive) was heard
    std::atomic<bool> m_running{false};
    // Why a message cannot go out now (no station heard, station not running), or an empty string.
    QString linkRefusal(const QString& what) const;
};

} // namespace ocu
