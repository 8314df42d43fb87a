#pragma once
// The OSYRIS station state machine (seed 004 §4-§6), free of sockets and threads: datagrams enter through
// receive(), time advances through tick() (once per Beat), datagrams leave through the send function.
// OsyrisStack runs it on an io thread with an OsyrisTransport; tests drive it with a FakeClock and an
// in-memory network. StationCore.cpp holds the station's life (start, receive, send, Beat);
// StationPositions.cpp the intake of positions; StationRequests.cpp the answers to other stations' requests
// (NAK, NCF, ALL, PING/PONG, ALIVE); StationPassCounts.cpp the pass-count grid's upkeep and publication;
// StationRepair.cpp the §5 repair engine (list of wishes, list of assets).
//
// Reliability (§5): a "list of wishes" (gaps of every ribbon, requested with NAK) and a "list of assets"
// (requests this station can answer), both priority queues with dynamic priorities. See docs/osyris.md.
#include "protocols/osyris/IntervalSet.h"
#include "protocols/osyris/OsyrisCodec.h"
#include "protocols/osyris/OsyrisConfig.h"
#include "protocols/osyris/PassCountGrid.h"
#include "protocols/osyris/RibbonStore.h"

#include "protocols/common/Clock.h"
#include "protocols/common/Counters.h"
#include "protocols/common/GeoFrame.h"

#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace ocu::osyris {

enum class Severity { Info, Warning, Error };

struct MachineSnapshot {
    std::uint8_t idx = 0;
    std::string name; // from OsyrisConfig::machineNames, empty when unknown
    std::string type; // from OsyrisConfig::machineTypes ("roller", "paver", ...), empty when unknown
    double x = 0, y = 0, z = 0; // local ENU [m]
    double lat = 0, lon = 0;    // geo-referenced through the worksite origin
    double yaw = 0;             // rad, north = 0, west = pi/2 (§6)
    double headingDeg = 0;      // compass, clockwise from north
    double speed = 0;           // m/s
    double width = 0;           // m, from the position extent dx
    std::uint32_t flags = 0;
    bool valid = false, vibrating = false, forward = false, backward = false, stopped = false,
         gpsShadow = false;
    int accuracy = 0;             // 0 none, 1 low, 2 medium, 3 high
    std::int64_t timestampMs = 0; // Unix ms from the FILETIME
    std::uint32_t slot = 0;
    // Set when the position broke a plausibility rule: the reason for the operator; position,
    // speed and width are then not filled in (the machine keeps its last good position in the models).
    std::string implausible;
};

// Callbacks run on the station's io thread (or the test's thread); they must not block.
struct OsyrisListener {
    virtual ~OsyrisListener() = default;
    virtual void onMachinePosition(const MachineSnapshot&) {}
    // A station was heard (ALIVE from its owner); range = its own ribbon's slots, nullopt when it has none.
    virtual void onStationAlive(std::uint8_t /*idx*/, std::optional<SlotRange> /*range*/) {}
    virtual void onText(std::uint8_t /*idx*/, const std::string& /*text*/) {}
    virtual void onPassCountChanged(const GridRect& /*dirty*/) {}
    // Pass counts for other threads: after the grid changed, at most every passCountPublishMs, the core
    // offers an immutable snapshot (copy-on-write tiles), but only while the listener is ready for one, i.e.
    // has taken over the previous one; otherwise it asks again on the next Beat. Not ready by default, so
    // stations nobody reads from build no snapshots.
    virtual bool readyForPassCounts() { return false; }
    virtual void onPassCounts(std::shared_ptr<const PassCountSnapshot> /*snapshot*/) {}
    virtual void onEvent(Severity /*severity*/, const std::string& /*text*/) {}
    virtual void onPong(std::uint8_t /*idx*/, double /*rttMs*/, float /*x*/, float /*y*/) {}
};

MachineSnapshot makeSnapshot(std::uint8_t idx, const CmPos& p, const GeoFrame* frame = nullptr,
                             const std::string& name = {}, const std::string& type = {});

class StationCore {
public:
    // Stations not named in the configuration (machineNames/machineTypes) nor held in the store at start
    // that get per-station state, first come first served. OSYRIS §4 expects at most 10 stations in
    // one network; beyond this cap a datagram from (or a message about) yet another station is counted in
    // rx.rejected.station_cap and ignored before anything is allocated for it.
    static constexpr int kMaxUnknownStations = 16;
    // Amplification bound: everything one received datagram makes this station send on its
    // behalf (PONG, the ALL answer, retransmissions and NCFs for its NAKs) is charged to a budget of
    // kAnswerBudgetDatagrams x MaxLen bytes; what is over it is not answered (rx.limited.budget), the
    // requester asks again after TTL. Packed greedily into datagrams of MaxLen, that is at most
    // kMaxDatagramsPerReceived datagrams sent per datagram received.
    static constexpr int kAnswerBudgetDatagrams = 8;
    static constexpr int kMaxDatagramsPerReceived = 2 * kAnswerBudgetDatagrams;
    // Slots whose first overheard NAK is remembered per ribbon (soft relay answers only a repeated one).
    static constexpr std::size_t kMaxNakSeenPerRibbon = 4096;

    using SendFn = std::function<void(const Bytes&)>;
    // store and clock must outlive the core; grid and listener may be null.
    StationCore(OsyrisConfig cfg, const Clock& clock, RibbonStore& store, PassCountGrid* grid,
                OsyrisListener* listener, SendFn send, std::uint32_t seed = 1);

    // Late join (§4): ask everybody for everything, newest state first.
    void start();
    void receive(ByteSpan datagram);
    void tick();

    // This station's own machine writes a position into its ribbon (slot assigned here). Returns the slot.
    std::uint32_t publishOwnPosition(CmPos p, std::vector<PosProp> props = {});
    // An operator text (the console's STOP among them) as its own datagram at once, not with the next Beat.
    void sendText(const std::string& text, std::uint8_t to = kIdxAll);
    // The same datagram, encoded without sending (any thread: reads only the configuration), and the
    // counting sendText does once a caller sent it itself (OsyrisStack's STOP fast path; counters are
    // thread-safe). A text carries no slot, so sending it from another thread leaves the ribbon state alone.
    Bytes textDatagram(const std::string& text, std::uint8_t to = kIdxAll) const;
    void textSent(std::size_t bytes);
    void ping(std::uint8_t idx);
    // The same request as its own datagram at once (an operator's ping, whose send result is then this
    // request's alone; §7 binds only Alive to the Beat).
    void pingNow(std::uint8_t idx);

    std::uint8_t idx() const { return m_cfg.stationIndex; }
    const OsyrisConfig& config() const { return m_cfg; }
    Counters& counters() { return m_counters; }
    const Counters& counters() const { return m_counters; }
    std::optional<std::uint32_t> knownMax(std::uint8_t owner) const;
    std::uint64_t missingCount() const; // slots known to exist but not held
    std::set<std::uint8_t> heardStations() const;
    // Advances the grid over every ribbon now (normally done in tick()) and publishes the pass counts when
    // due.
    void updateGrid();
    // New pass-count settings (filters, lifts, cell size): the grid is cleared and every ribbon recounted,
    // keeping the slots given up as unobtainable.
    void setPassCountSettings(const PassCountSettings& s);

private:
    static constexpr int kPrioOwner = 3;   // our own ribbon
    static constexpr int kPrioAll = 2;     // we hold every requested slot
    static constexpr int kPrioPartial = 1; // we hold some
    static constexpr int kPrioBoost = 4;   // nobody answered an overheard NCF

    struct Hold {
        std::uint32_t from, to;
        TimePoint until;
    };
    struct RibbonState {
        std::optional<std::uint32_t> knownMax;
        std::optional<std::uint32_t> knownMin;
        std::vector<Hold> holds; // sorted, disjoint; when each gap may be requested
        TimePoint lastRepair{};
        std::uint32_t lastReported = 0;
        bool reported = false;
    };
    struct Asset {
        std::uint8_t owner;
        IntervalSet pending; // slots still to send (Asset) or overheard (Suppressed)
        int priority;        // higher first
        TimePoint notBefore;
        bool ncfSent = false;
        bool othersAnswering = false;
    };
    struct Suppressed {
        std::uint8_t owner;
        IntervalSet pending; // slots still to send (Asset) or overheard (Suppressed)
        TimePoint deadline;
        bool heard = false;
    };
    struct Unit {
        Bytes bytes;
        TimePoint queuedAt;
        bool urgent;
    };

    Duration beats(double n) const;
    void enqueue(Bytes unit, bool urgent);
    void enqueuePosition(std::uint8_t owner, const PositionRecord& rec, bool urgent);
    void enqueueRequest(std::uint8_t whose, const CmRequest& r, bool urgent = true);
    void flush(TimePoint now, bool force);
    void handlePosition(const CmHeader& h, const CmPos& p, const std::vector<PosProp>* props, TimePoint now);
    void handleRequest(const CmHeader& h, const CmRequest& r, TimePoint now);
    void handleNak(const CmHeader& h, const CmRequest& r, TimePoint now);
    void handleNcf(const CmHeader& h, const CmRequest& r, TimePoint now);
    void handleAll(const CmHeader& h, const CmRequest& r, TimePoint now);
    void handlePing(const CmHeader& h, const CmRequest& r, TimePoint now);
    void handlePong(const CmHeader& h, const CmRequest& r, TimePoint now);
    void handleAlive(const CmHeader& h, const CmRequest& r, TimePoint now);
    void noteKnown(std::uint8_t owner, std::uint32_t from, std::uint32_t to);
    void setHold(RibbonState& rs, std::uint32_t a, std::uint32_t b, TimePoint until);
    void addAsset(std::uint8_t owner, IntervalSet slots, int priority, TimePoint notBefore);
    void processWishes(TimePoint now);
    void processAssets(TimePoint now);
    void sendAlive();
    int rankFor(std::uint8_t owner) const;
    std::optional<CmPos> ownPosition() const;
    std::string nameOf(std::uint8_t owner) const;
    std::string typeOf(std::uint8_t owner) const;
    void publishPassCounts(TimePoint now);
    void event(Severity s, const std::string& text);
    // Counts an implausible position and raises at most one event per machine and cause per
    // kImplausibleEventGap.
    void implausible(std::uint8_t owner, const CmPos& p, PositionFault fault, TimePoint now);
    void reject(const std::string& reason, const std::string& text);
    // Per-station state exists only for admitted stations (kMaxUnknownStations).
    bool admitted(std::uint8_t station);
    // The ribbon of `owner` or the whole store is at its bound (OsyrisConfig::maxRibbonSlots/maxStoreSlots).
    bool storeFull(std::uint8_t owner) const;
    // Takes bytes from the current received datagram's answer budget; false (and counted) when over it.
    bool charge(std::size_t bytes);
    std::size_t unitSize(const PositionRecord& rec) const;
    // The newest slots of `slots` whose answer fits the budget.
    IntervalSet chargeSlots(std::uint8_t owner, const IntervalSet& slots);

    OsyrisConfig m_cfg;
    const Clock& m_clock;
    RibbonStore& m_store;
    PassCountGrid* m_grid;
    OsyrisListener* m_listener;
    SendFn m_send;
    std::mt19937 m_rng;
    Counters m_counters;
    GeoFrame m_frame;
    bool m_geo = false;

    std::map<std::uint8_t, RibbonState> m_ribbons;
    std::set<std::uint8_t> m_configured; // named in the configuration or held at start: always admitted
    std::set<std::uint8_t> m_unknown;    // admitted without being configured, at most kMaxUnknownStations
    bool m_pongQueued = false;           // a PING of the datagram being received was answered
    std::size_t m_answerBudget = 0;      // bytes left for answers to the datagram being received
    static constexpr Duration kImplausibleEventGap = std::chrono::seconds(30);
    std::map<std::pair<std::uint8_t, PositionFault>, TimePoint> m_implausibleEventAt;
    bool answerAllowed(std::uint8_t requester, std::uint8_t whose, RequestType type, TimePoint now);
    std::map<std::tuple<std::uint8_t, std::uint8_t, RequestType>, TimePoint> m_answeredAt;
    // NAK rounds: when the next round may go out (nullopt: none planned) and when the last did.
    std::optional<TimePoint> m_nakRoundAt;
    TimePoint m_lastNakRound{};
    Duration nakBackoff();
    std::uint8_t m_nakTurn = 0xFF; // the ribbon whose gaps were asked for first on the last Beat (fairness)
    // ALIVE ranges wider than this are not believed: 2^22 slots are 116 h of a machine at 10
    // Hz.
    static constexpr std::uint32_t kMaxAnnouncedSpan = 1u << 22;
    // A third station may announce another's ribbon at most this far beyond what that owner itself showed.
    static constexpr std::uint32_t kMaxAnnouncedAhead = 1u << 16;
    std::map<std::uint8_t, std::uint32_t> m_ownerShown; // highest slot each owner sent or announced itself
    std::vector<Asset> m_assets;
    std::vector<Suppressed> m_suppressed;
    std::map<std::uint8_t, TimePoint> m_lastHeard;
    std::map<std::uint8_t, CmPos> m_senderPos; // newest own position of each sender (MaxRange)
    std::map<std::uint8_t, TimePoint> m_pings;
    std::deque<Unit> m_queue;
    std::size_t m_queuedBytes = 0;
    TimePoint m_lastAlive{};
    bool m_aliveSent = false;
    int m_allRetries = 0;
    TimePoint m_allRetryAt{};
    bool m_receivedPositions = false;
    std::uint32_t m_nextOwnSlot = 0;
    std::set<std::uint8_t> m_gridDirty;
    // Late join and gaps: where the grid waits for each ribbon, since when, and how many NAKs
    // asked for that gap without an answer for the ribbon since; a late given-up slot asks for a recount.
    struct GridBlock {
        std::uint32_t slot = 0;
        TimePoint since{};
        int naks = 0;
        TimePoint lastNak{};
    };
    std::map<std::uint8_t, GridBlock> m_gridBlocks;
    bool m_gridRecount = false;
    TimePoint m_nextRecount{}; // a recount (the whole job) at most every kRecountGap
    static constexpr Duration kRecountGap = std::chrono::seconds(5);
    void checkGridBlocks(TimePoint now);
    bool m_passCountsUnpublished = false;
    TimePoint m_nextPassCountPublish{};
    std::map<std::string, std::uint64_t> m_rejectLogged;
    std::map<std::string, TimePoint> m_rejectEventAt; // bounded: one entry per reject reason (a fixed set)
    // Slots this station re-sent recently, per ribbon: a NAK that crossed our answer on the air is not
    // answered twice (the requester asks again after TTL if the answer was lost).
    std::map<std::uint8_t, std::map<std::uint32_t, TimePoint>> m_recentlySent;
    // First time a NAK for (ribbon, slot) was overheard: a non-owner answers only a repeated NAK, i.e. when
    // the owner evidently did not (out of range, or its answer was lost).
    // A relay that hears the owner itself answers only the second repetition (the owner hears the requester
    // most likely, and only this relay missed its answer); one that does not, the first.
    struct NakSeen {
        TimePoint at;
        int repeats = 0;
        std::uint8_t requester = kIdxNobody; // repetitions count per requester
    };
    std::map<std::uint8_t, std::map<std::uint32_t, NakSeen>> m_nakSeen;
};

} // namespace ocu::osyris
