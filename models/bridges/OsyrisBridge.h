#pragma once
// The Qt face of the OCU's OSYRIS station: machine positions become MachineState rows (coalesced), text
// messages become events, and the station's pass counts are offered to the map as a PassCountLayer placed in
// the site frame through the worksite origin: immutable snapshots published by the io thread and handed to
// the GUI thread by a queued call (OsyrisPassCountLayer).
#include "models/CrewMessaging.h"
#include "models/FleetBridge.h"
#include "models/PassCountControls.h"
#include "models/bridges/OsyrisPassCountLayer.h"

#include "protocols/common/GeoFrame.h"
#include "protocols/common/MessageTap.h"
#include "protocols/osyris/OsyrisConfig.h"
#include "protocols/osyris/OsyrisStack.h"

#include <QTimer>

#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <set>

namespace ocu {

class OsyrisBridge : public FleetBridge,
                     public PassCountControls,
                     public CrewMessaging,
                     private osyris::OsyrisListener {
    Q_OBJECT
public:
    OsyrisBridge(const osyris::OsyrisConfig& config, const GeoFrame& siteFrame, QObject* parent = nullptr);
    ~OsyrisBridge() override;

    QString start();
    // The flight recorder's tap on the stack's inbound messages (before start()).
    void setMessageTap(MessageTap* tap);
    void stop();

    void stopAll(OutcomeCallback done) override;
    bool stopsFromCallersThread() const override { return true; } // the stack's fast path
    void stopMachine(const QString& id, OutcomeCallback done) override;
    void clearStop(const QString& id, OutcomeCallback done) override;
    // send_text {"text"} to every station, or {"id": "osyris:<idx>", "text"} to one (CmMsg IdxWhose; the
    // result's target is then that machine); ping {"idx"}.
    void command(const OperatorCommand& command, OutcomeCallback done) override;
    // OSYRIS carries no stop state: a stop can never be confirmed by the machines.
    bool reportsStopState() const override { return false; }
    const PassCountLayer* passCountLayer() const override { return m_layer.get(); }
    const OsyrisPassCountLayer* osyrisPassCountLayer() const { return m_layer.get(); } // with its snapshots
    osyris::PassCountSummary passCountSummary() const;
    // Watchdog: the stack's io thread.
    QVector<LinkCounters> linkCounters() const override;
    std::chrono::milliseconds ioStalledFor() const override;
    // Runs f on the stack's io thread without waiting (diagnostics; the watchdog tests block it on purpose).
    void postToIo(std::function<void()> f);
    // Lifts and filters (GUI thread): a new filter makes the station recount from the ribbons.
    PassCountFilter passCountFilter() const override;
    void setPassCountFilter(const PassCountFilter& filter) override;
    QVector<PassCountLiftInfo> passCountLifts() const override;
    int viewLift() const override;
    void setViewLift(int lift) override;
    QStringList passCountGaps() const override;
    const osyris::PassCountSettings& passCountSettings() const { return m_config.passCount; }

    // Crew messages: the configured machines (relays excepted) and every station that wrote.
    QVector<CrewRecipient> crewRecipients() const override;
    int crewMessageMaxBytes() const override { return 79; }

    // The display name of station idx (configured, else "station <idx>").
    QString stationName(int idx) const;

signals:
    // A crew message (CmMsg) for this console or for all arrived (GUI thread): sender id ("osyris:3"), its
    // name, the text.
    void textReceived(const QString& fromId, const QString& fromName, const QString& text);

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
    std::atomic<bool> m_heard{false};           // a station (position or alive) was heard
    std::atomic<std::int64_t> m_lastHeardMs{0}; // steady clock, io thread writes
    QTimer m_silenceCheck;                      // GUI thread: asks the io thread to look every second
    // io thread: a station was heard (link up again); no station for 2.5 SendPeriods (link degraded).
    void noteHeard();
    void checkSilence();
    std::map<std::uint8_t, MachineState> m_lastGoodIo; // io thread only: the last plausible state per machine
    std::atomic<bool> m_running{false};
    std::set<int> m_textSenders; // GUI thread
    // Why a message cannot go out now (no station heard, station not running), or an empty string.
    QString linkRefusal(const QString& what) const;
    // The kind of linkRefusal's refusal: the station not running, or no station heard yet.
    OutcomeReason linkCause() const;
    void sendText(const SendText& command, OutcomeCallback done);
};

} // namespace ocu
