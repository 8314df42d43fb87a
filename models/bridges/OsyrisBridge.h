#pragma once
// The Qt face of the OCU's OSYRIS station: machine positions become MachineState rows (coalesced), text
// messages become events, and the station's pass counts are offered to the map as a PassCountLayer placed in
// the site frame through the worksite origin: immutable snapshots published by the io thread and handed to
// the GUI thread by a queued call (OsyrisPassCountLayer).
#include "models/FleetBridge.h"
#include "models/bridges/OsyrisPassCountLayer.h"

#include "protocols/common/GeoFrame.h"
#include "protocols/common/MessageTap.h"
#include "protocols/osyris/OsyrisConfig.h"
#include "protocols/osyris/OsyrisStack.h"

#include <atomic>
#include <map>
#include <memory>

namespace ocu {

class OsyrisBridge : public FleetBridge, private osyris::OsyrisListener {
    Q_OBJECT
public:
    OsyrisBridge(const osyris::OsyrisConfig& config, const GeoFrame& siteFrame, QObject* parent = nullptr);
    ~OsyrisBridge() override;

    QString start();
    // Issue 16: the flight recorder's tap on the stack's inbound messages (before start()).
    void setMessageTap(MessageTap* tap);
    void stop();

    void stopAll(OutcomeCallback done) override;
    bool stopsFromCallersThread() const override { return true; } // the stack's fast path (issue 13 §10)
    void stopMachine(const QString& id, OutcomeCallback done) override;
    void clearStop(const QString& id, OutcomeCallback done) override;
    // send_text {"text"}, ping {"idx"}.
    void command(const QString& name, const QJsonObject& args, OutcomeCallback done) override;
    // OSYRIS carries no stop state: a stop can never be confirmed by the machines.
    bool reportsStopState() const override { return false; }
    const PassCountLayer* passCountLayer() const override { return m_layer.get(); }
    osyris::PassCountSummary passCountSummary() const;
    // Watchdog (issue 14 §3): the stack's io thread.
    QVector<LinkCounters> linkCounters() const override;
    std::chrono::milliseconds ioStalledFor() const override;
    // Runs f on the stack's io thread without waiting (diagnostics; the watchdog tests block it on purpose).
    void postToIo(std::function<void()> f);

private:
    void onMachinePosition(const osyris::MachineSnapshot& s) override;
    void onStationAlive(std::uint8_t idx, std::optional<osyris::SlotRange> range) override;
    void onText(std::uint8_t idx, const std::string& text) override;
    bool readyForPassCounts() override;
    void onPassCounts(std::shared_ptr<const osyris::PassCountSnapshot> snapshot) override;
    void onEvent(osyris::Severity severity, const std::string& text) override;

    osyris::OsyrisConfig m_config;
    GeoFrame m_frame;
    std::unique_ptr<osyris::OsyrisStack> m_station;
    std::unique_ptr<OsyrisPassCountLayer> m_layer;
    std::atomic<bool> m_passCountQueued{false};
    std::atomic<bool> m_linkUp{false};
    std::atomic<bool> m_heard{false};                  // a station (position or alive) was heard
    std::map<std::uint8_t, MachineState> m_lastGoodIo; // io thread only: the last plausible state per machine
    std::atomic<bool> m_running{false};
    // Why a message cannot go out now (no station heard, station not running), or an empty string.
    QString linkRefusal(const QString& what) const;
};

} // namespace ocu
