#pragma once
// The simulated AHS's WebSocket side (ISO 23725 §2-§5, research note §10): the main socket (service, or
// client of an FMS) and, when configured, the map service on its own socket (Q10). Per FMS session: the
// At-Connection snapshot (FleetDefinitionV2 first), frame validation answered with InterfaceDiagnosticV1 on
// error and periodically with the session's counts, and the FMS's requests: all-stop (with its id rules) and
// assignments handed to the haul fleet, map commands answered from the pit map. Lives on the simulator's io
// thread; every method must be called there.
#include "sim/iso23725/HaulFleet.h"
#include "sim/iso23725/PitMapGenerator.h"
#include "sim/iso23725/SimulatedAhs.h"

#include "protocols/iso23725/Messages.h"
#include "protocols/iso23725/WsEndpoint.h"

#include "protocols/common/Counters.h"

#include <boost/asio/steady_timer.hpp>

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ocu::sim {

class AhsSessions : public iso23725::WsHandler {
public:
    // The map and the fleet must outlive the sessions.
    AhsSessions(boost::asio::io_context& io, const SimulatedAhsConfig& config, PitMap& map, HaulFleet& fleet,
                Counters& counters);
    ~AhsSessions() override;

    // Listens (or connects) on the main socket and, when configured, the map service's.
    Result<bool> start();
    // Closes every session and socket; no callback after this.
    void stop();
    // Drops the sockets (after stop(), once the io thread has ended).
    void release();
    std::uint16_t port() const;    // the main service's (the configured port before start)
    std::uint16_t mapPort() const; // the separate map service's
    std::string mapUrl() const;

    // ---- to the FMSs ----
    // One member to every FMS session on the main socket.
    void broadcast(const iso23725::Body& member, std::optional<iso23725::Guid> equipmentId = std::nullopt);
    // A raw frame to every FMS session on the main socket (fault injection).
    void broadcastRaw(const std::string& data, bool binary);
    // MachinePositionV1 of every truck (§7.4), when an FMS is connected.
    void sendPositions();
    // The map was edited: its new summary to the map service's sessions (§10.6.3).
    void announceMapChange();

    // ---- inspection ----
    std::uint64_t positionsSent() const { return m_positionsSent; }
    std::uint64_t framesReceived() const { return m_framesReceived; }
    std::size_t queuedBytes() const;
    std::size_t sessionCount() const { return m_sessions.size(); }
    std::size_t mapSessionCount() const { return m_mapSessions.size(); }
    bool allStopOn() const { return m_fleet.allStopOn(); }
    const std::vector<std::string>& fmsFirstMessages() const { return m_fmsFirst; }

    // WsHandler (main socket).
    void onOpen(iso23725::SessionId id, const std::string& peer) override;
    void onText(iso23725::SessionId id, std::string text) override;
    void onClose(iso23725::SessionId id, const std::string& reason) override;

private:
    enum class Sock { Main, Map };
    // Per-session bookkeeping; one table per socket because session ids are per endpoint.
    struct SessionState {
        bool gotFirst = false;
        // Frame counts since the session opened, reported in InterfaceDiagnosticV1 (§5 row 15 [I]).
        std::uint64_t received = 0, sent = 0, rejected = 0;
        std::unique_ptr<boost::asio::steady_timer> diagTimer;
    };
    // Forwards the map service's callbacks (its own session ids).
    struct MapSide : iso23725::WsHandler {
        explicit MapSide(AhsSessions& s) : sessions(s) {}
        AhsSessions& sessions;
        void onOpen(iso23725::SessionId id, const std::string& peer) override {
            sessions.onMapOpen(id, peer);
        }
        void onText(iso23725::SessionId id, std::string text) override {
            sessions.onFrame(Sock::Map, id, text);
        }
        void onClose(iso23725::SessionId id, const std::string& reason) override {
            sessions.onMapClose(id, reason);
        }
    };

    std::map<iso23725::SessionId, SessionState>& table(Sock k) {
        return k == Sock::Main ? m_sessions : m_mapSessions;
    }
    void sendText(Sock k, iso23725::SessionId s, std::string text, bool binary = false);
    void sendTo(iso23725::SessionId s, const iso23725::Body& b,
                std::optional<iso23725::Guid> eq = std::nullopt);
    void sendOn(Sock k, iso23725::SessionId s, const iso23725::Body& b);
    void snapshotTo(iso23725::SessionId s);
    void scheduleDiagnostic(iso23725::SessionId id);
    void onMapOpen(iso23725::SessionId id, const std::string& peer);
    void onMapClose(iso23725::SessionId id, const std::string& reason);
    void onFrame(Sock k, iso23725::SessionId id, const std::string& text);
    void onMember(iso23725::SessionId id, const iso23725::Envelope& env, const iso23725::Body& b,
                  const iso23725::Timestamp& ts);
    void onMapServiceMember(iso23725::SessionId id, const iso23725::Body& b, const iso23725::Timestamp& ts);
    void onAllStop(const iso23725::MachineAllStopRequestV1& r);
    void onMapCommand(Sock k, iso23725::SessionId s, const iso23725::MapCommandV1& c,
                      const iso23725::Timestamp& ts);

    boost::asio::io_context& m_io;
    const SimulatedAhsConfig& m_cfg;
    PitMap& m_map;
    HaulFleet& m_fleet;
    Counters& m_counters;
    MapSide m_mapSide{*this};
    std::unique_ptr<iso23725::WsEndpoint> m_main;
    std::unique_ptr<iso23725::WsEndpoint> m_mapService; // null when the map shares the main socket
    std::map<iso23725::SessionId, SessionState> m_sessions, m_mapSessions;
    std::vector<std::string> m_fmsFirst;
    std::optional<iso23725::Guid> m_allStopId;
    std::uint64_t m_positionsSent = 0;
    std::uint64_t m_framesReceived = 0;
};

} // namespace ocu::sim
