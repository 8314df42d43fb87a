#pragma once
// A simulated autonomous haulage system (AHS) speaking ISO 23725 as a WebSocket service (or client): a
// generated open-pit map served in chunks, N haul trucks on load-haul-dump cycles over the road graph,
// all-stop and assignments honoured, production-state sensors on change, interface diagnostics (periodic and
// on rejected input), the map service on the main socket or its own. No Qt. Runs on its own io thread.
#include "protocols/iso23725/Messages.h"
#include "protocols/iso23725/WsEndpoint.h"

#include "protocols/common/Counters.h"
#include "protocols/common/GeoFrame.h"

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace ocu::sim {

struct SimulatedAhsConfig {
    std::uint16_t port = 0; // 0 = any free port (see SimulatedAhs::port())
    std::string bindAddress = "127.0.0.1";
    std::string path = "/iso23725";
    bool tls = false; // wss:// with certFile/keyFile
    std::string certFile;
    std::string keyFile;
    std::string clientCaFile; // require client certificates signed by this CA (mutual TLS)
    // Client mode (optional): connect to an FMS listening at this URL instead of serving.
    std::string connectUrl;
    std::string caFile; // client mode: CA of the FMS
    int truckCount = 6;
    int shovelCount = 2;
    int dumpCount = 2;
    double positionRateHz = 2.0; // 1-10 Hz
    GeoPoint origin{-23.36, 119.73, 500.0};
    std::uint32_t seed = 1;
    double timeScale = 1.0;           // >1 runs the haul cycle faster (tests)
    std::size_t mapChunkElements = 0; // 0 = choose so the map has at least 3 chunks
    bool healthEvents = true;         // periodic health, occasional diagnostics and autonomy changes
    std::string ahsId = "7d1f3c2a-5b8e-4c61-9a0d-2e4f6b8c1a37";
    std::chrono::milliseconds pingInterval{5000};
    std::chrono::milliseconds deadAfter{15000};
    // InterfaceDiagnosticV1 with the session's message counts, to every FMS session on the main socket at
    // this period (§5 row 15 [I]: periodic 60 s + on error; tests set it short). 0 = no periodic report.
    std::chrono::milliseconds interfaceDiagnosticPeriod{60000};
    // Q10: the map service on its own WebSocket service (mapUrl()) instead of the main socket. It speaks
    // first (MapServiceV1, then MapSummaryV1) and serves MapCommandV1; the main socket then answers
    // MapCommandV1 with a "MapServiceElsewhere" warning. Same TLS settings as the main service; it listens
    // on bindAddress even in client mode (connectUrl), as the map owner hosts it.
    bool separateMapService = false;
    std::uint16_t mapPort = 0; // 0 = any free port (see SimulatedAhs::mapPort())
    std::string mapPath = "/map";
};

struct SimulatedAhsStats {
    std::uint64_t positionsSent = 0;
    std::uint64_t framesReceived = 0;
    std::size_t queuedBytes = 0;
    std::size_t sessions = 0;
    std::size_t mapSessions = 0; // sessions on the separate map service
    bool allStopOn = false;
    int movingTrucks = 0;
    std::vector<std::string> fmsFirstMessages; // first member of each FMS connection's first frame
};

class SimulatedAhs {
public:
    explicit SimulatedAhs(SimulatedAhsConfig config);
    ~SimulatedAhs();
    SimulatedAhs(const SimulatedAhs&) = delete;
    SimulatedAhs& operator=(const SimulatedAhs&) = delete;

    // Starts the io thread and listens (or connects); false with a message in lastError() on failure.
    bool start();
    void stop();
    bool running() const;
    std::uint16_t port() const;
    std::string url() const; // ws://127.0.0.1:port/iso23725 (or wss://)
    // Separate map service (config separateMapService): its port and URL (ws://127.0.0.1:port/map or wss://).
    std::uint16_t mapPort() const;
    std::string mapUrl() const;
    const std::string& lastError() const { return m_error; }

    // The generated fleet (truck GUIDs are stable for a given seed).
    std::vector<iso23725::Equipment> fleet() const;
    SimulatedAhsStats stats();
    Counters& counters() { return m_counters; }

    // Test and demo hooks (thread-safe).
    void bumpMapChangeSet(); // edits the map: pushes a new MapSummaryV1 (to the map service's sessions)
    void sendRaw(const std::string& text);       // text frame to every connected FMS (fault injection)
    void sendRawBinary(const std::string& data); // binary frame to every connected FMS (fault injection)
    // Blocks the simulator's io thread for d (a network stall: no frames, no pongs) to exercise dead-link
    // detection.
    void freezeFor(std::chrono::milliseconds d);
    void setTruckManual(int index, bool manual); // autonomy mode change
    std::vector<double> truckSpeedsKmh();        // current speeds
    // Dispatch: who dispatches a truck ("AHS" or "FMS"; AHS -> FMS asks the FMS for work), and
    // a way closed by the AHS (connectivity re-sent, impossible accepted tasks given up with a Rejected).
    void setTruckCustodian(int index, const std::string& actor);
    void setWayClosed(std::int64_t wayId, bool closed);
    struct DispatchView {
        struct Truck {
            iso23725::Guid id;
            std::string custodian;
            bool idle = false;
            std::string productionState;
            std::size_t queued = 0; // accepted assignments not completed
            std::int64_t wayId = 0;
        };
        std::vector<std::int64_t> loadAreas, dumpAreas;
        std::int64_t parkArea = 0, parkRoad = 0, rampDown = 0, rampUp = 0;
        std::vector<Truck> trucks;
    };
    DispatchView dispatchView(); // blocking round trip to the simulator's io thread

    struct Impl;

private:
    std::unique_ptr<Impl> m_impl;
    Counters m_counters;
    std::string m_error;
};

} // namespace ocu::sim
