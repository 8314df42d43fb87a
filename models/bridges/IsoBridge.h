#pragma once
// The Qt face of the ISO 23725 stack (the FMS side): AHS machines become MachineState rows (coalesced),
// links become link states, the AHS map becomes SiteMapData, and STOP ALL becomes all-stop Apply on
// every AHS link. The stop state shown is only ever what MachineAllStopV1 reported.
#include "models/FleetBridge.h"
#include "models/ProductionReport.h"
#include "models/bridges/IsoBridgeDispatch.h"

#include "protocols/common/GeoFrame.h"
#include "protocols/common/MessageTap.h"
#include "protocols/common/PosePlausibility.h"
#include "protocols/iso23725/IsoConfig.h"
#include "protocols/iso23725/IsoStack.h"
#include "protocols/iso23725/Routing.h"

#include <QHash>

#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <set>

namespace ocu {

// One line for the operator about a haul truck's work (§12/§13 members as last reported): production state
// and way, payload, sensor flags, assignment status, last dump. Empty when the AHS reported none of them.
QString isoWorkText(const iso23725::IsoMachineSnapshot& m);

class IsoBridge : public FleetBridge, private iso23725::IsoListener {
    Q_OBJECT
public:
    IsoBridge(const iso23725::IsoConfig& config, const GeoFrame& frame, QObject* parent = nullptr);
    ~IsoBridge() override;

    QString start();
    // The flight recorder's tap on the stack's inbound messages (before start()).
    void setMessageTap(MessageTap* tap);
    void stop();
    QStringList linkNames() const;
    // Position of one of the FMS's own (manned) machines (MachinePositionV1 to every AHS link, at the links'
    // position rate); GUI thread, posted to the stack.
    void setOwnPosition(const QString& equipmentId, double lat, double lon, double altitude,
                        double headingDeg, double speedKmh);

    void stopAll(OutcomeCallback done) override;
    bool stopAllFromAnyThread() const override { return true; } // link state and running flag are locked
    void stopMachine(const QString& id, OutcomeCallback done) override;
    void clearStop(const QString& id, OutcomeCallback done) override;
    // AllStopApply / AllStopRemove, FetchMap (the link by name, else the machine's, else the only one),
    // ResetAssignment, Assign. Assign and reset name the truck as their target, the others the link; each is
    // sent only when the socket took it. Every other command is not supported.
    void command(const OperatorCommand& command, OutcomeCallback done) override;
    bool reportsStopped(const QString& target) const override;
    // clear_stop / all_stop_remove: confirmed when the AHS reports all-stop inactive (MachineAllStop off).
    bool confirmsCommand(const QString& action) const override;
    bool reportsConfirmed(const QString& action, const QString& target) const override;
    SiteMapData siteMap() const override { return m_map; }
    // Watchdog: the stack's io thread.
    QVector<LinkCounters> linkCounters() const override;
    std::chrono::milliseconds ioStalledFor() const override;
    // Runs f on the stack's io thread without waiting (diagnostics; the watchdog tests block it on purpose).
    void postToIo(std::function<void()> f);

    // GUI thread: the all-stop status per link as the AHS reported it.
    iso23725::AllStopState allStopState(const QString& link) const;

    // ---- dispatch, GUI thread ----
    // Every ISO 23725 machine's dispatch view, in id order; one machine's, or nullopt.
    QVector<IsoDispatchState> dispatchStates() const;
    std::optional<IsoDispatchState> dispatchState(const QString& id) const;
    // Areas of the AHS's MapConnectivityV1 (all links when `link` is empty), by link then way id.
    QVector<IsoDestination> destinations(const QString& link = {}) const;
    // Why an assignment to this truck would be refused now (link down, custodian not FMS, unknown truck), or
    // empty: for enabling the assign control. The stack checks again when the command is sent.
    QString assignRefusal(const QString& id) const;
    // The assign command for these tasks (first = current, then future).
    static Assign assignCommand(const QString& id, const QVector<IsoTask>& tasks);
    // The headless "production" answer: dispatchToJson of every truck that reported a custodian, an
    // assignment or production (HaulTruck), in id order.
    QJsonArray productionJson() const;
    // The link's MapConnectivityV1 as a route graph (for the dispatch panel's routes and ETAs), or null.
    std::shared_ptr<const iso23725::RouteGraph> routeGraph(const QString& link) const {
        return m_routeGraphs.value(link);
    }

signals:
    void mapProgress(const QString& link, int received, int total);
    // Dispatch views changed (coalesced; ids changed or removed since the last signal).
    void dispatchChanged(const QStringList& ids);
    // Every production report as it arrived (not coalesced: a production tally must see each cycle and
    // dump). Emitted on the io thread: connect with a queued (or auto) connection.
    void productionReport(const ocu::ProductionReport& report);
    // A link's MapConnectivityV1 arrived: destinations() and routeGraph() changed.
    void destinationsChanged(const QString& link);

private:
    void onLinkState(const std::string& link, iso23725::LinkState state, const std::string& reason) override;
    void onMachineChanged(const iso23725::IsoMachineSnapshot& machine) override;
    void onMachinePositions(const std::string& link,
                            const std::vector<const iso23725::IsoMachineSnapshot*>& machines) override;
    void onProductionReport(const iso23725::IsoMachineSnapshot& machine, const iso23725::Body& member,
                            std::int64_t headerUnixMs) override;
    void onMachineRemoved(const std::string& link, const iso23725::Guid& equipmentId) override;
    void onAllStopChanged(const std::string& link, const iso23725::AllStopStatus& status) override;
    void onMapProgress(const std::string& link, const iso23725::MapProgress& progress) override;
    void onMapChanged(const std::string& link, const iso23725::MapModel& map) override;
    void onFleetDiscrepancies(const std::string& link,
                              const std::vector<iso23725::FleetDiscrepancy>& items) override;
    void onConnectivity(const std::string& link, const iso23725::MapConnectivityV1& connectivity) override;
    // io thread: queue a machine's dispatch view (nullopt = removed) for the GUI thread, coalesced.
    void publishDispatch(const QString& id, std::optional<IsoDispatchState> state);
    void deliverDispatch();
    void onEvent(iso23725::IsoSeverity severity, const std::string& text) override;

    MachineState toMachine(const iso23725::IsoMachineSnapshot& m, iso23725::AllStopState stop) const;
    void setPosition(MachineState& row, const iso23725::IsoPosition& p) const;
    const std::string& keyOf(const std::string& link, const iso23725::Guid& equipmentId);
    QString linkOf(const QString& machineId) const;
    // Any thread: why `what` cannot go to the AHS on `link` now (its link is not up, as the io thread last
    // reported it), or an empty string.
    QString linkRefusal(const QString& link, const QString& what) const;
    // All-stop Apply/Remove on one link with its outcome (target IsoStack::linkTarget(link)).
    void applyOrRefuse(const QString& link, bool apply, OutcomeCallback done);
    // The link a command names: by name, else the link of machine `id`, else the only link.
    QString commandLink(const QString& link, const QString& id) const;
    // True (and `done` called with the refusal naming `shown`) when `what` cannot go on `link` now: unknown
    // link, link not up, stack not running.
    bool refuseLink(const QString& what, const QString& link, const QString& shown,
                    OutcomeCallback& done) const;
    // A command for one truck (assign, reset): refused unless `id` names an ISO 23725 machine on an up link;
    // else `send(link, equipment id, done)` posts it.
    void
    truckCommand(const QString& what, const QString& id, OutcomeCallback done,
                 const std::function<void(const std::string&, const std::string&, OutcomeCallback)>& send);
    std::atomic<bool> m_running{false};
    mutable std::mutex m_linkNowMutex;
    QHash<QString, LinkStatus> m_linkNow; // every link's latest state (io thread; start() first)

    iso23725::IsoConfig m_config;
    GeoFrame m_frame;
    std::unique_ptr<iso23725::IsoStack> m_stack;
    // io thread only, per machine ("link/equipmentId"): the snapshot of its last full change (to re-derive
    // the row when the all-stop or the link changes) and the row last published. A position patches both (the
    // snapshot's position, the row's position fields): no snapshot copy, and one hand-over per batch.
    struct IoMachine {
        iso23725::IsoMachineSnapshot snapshot; // its position: the last plausible one
        MachineState row;
        QString implausible; // why the newest position was not drawn; empty when it was
    };
    // The row of a machine as published: derived from its snapshot, marked implausible when it is.
    MachineState rowOf(const IoMachine& io, iso23725::AllStopState stop) const;
    // io thread, plausibility gate: true when `p` may be drawn (it becomes the machine's position); otherwise
    // the cause is counted on the link (rx.implausible.<cause>), a warning raised once per machine and cause
    // every 30 s, and io.implausible says why.
    bool admitPosition(const std::string& link, const std::string& key, IoMachine& io,
                       const iso23725::IsoPosition& p);
    PoseGate m_poseGate; // io thread only
    std::map<std::string, IoMachine> m_machinesIo;
    std::string m_key; // reused by keyOf()
    // io thread only: all-stop per link.
    std::map<std::string, iso23725::AllStopState> m_allStopIo;
    std::set<std::string> m_everUp;
    // GUI thread
    SiteMapData m_map;
    QHash<QString, int> m_allStop;
    QHash<QString, IsoDispatchState> m_dispatch;                  // by machine id
    QHash<QString, QHash<qint64, IsoDestination>> m_destinations; // link -> area way id -> destination
    QHash<QString, std::shared_ptr<const iso23725::RouteGraph>> m_routeGraphs; // link -> its connectivity
    std::mutex m_dispatchMutex;
    QHash<QString, std::optional<IsoDispatchState>> m_dispatchPending; // io -> GUI, latest wins
    bool m_dispatchScheduled = false;
    mutable std::mutex m_machineLinksMutex;
    QHash<QString, QString> m_machineLinks; // machine id -> link (written on the io thread)
};

} // namespace ocu
