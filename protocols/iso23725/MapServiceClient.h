#pragma once
// The FMS side of one AHS's map service (§10.6, research note §8 and Q10), without sockets: the service's
// identification (MapServiceV1, with a deadline for one that never identifies itself), the summary whose
// change sets decide when to fetch, the chunked transfer assembled into a MapModel (a failed or interrupted
// transfer keeps the previous map), and MapConnectivityV1 merged into the map. The service speaks either on
// the link's main socket or on a socket of its own (a separate map URL). Part of FmsCore, which routes the
// frames and sends what this asks for; not thread-safe (the stack's io thread).
#include "protocols/iso23725/IsoListener.h"
#include "protocols/iso23725/MapModel.h"
#include "protocols/iso23725/Messages.h"

#include "protocols/common/Clock.h"
#include "protocols/common/Counters.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace ocu::iso23725 {

class MapServiceClient {
public:
    struct Hooks {
        // Sends one member to the map service (its own socket, or the main one); false when not sent.
        std::function<bool(const Body&)> send;
        // An operator event (logged too).
        std::function<void(IsoSeverity, const std::string&)> event;
        // A map the service sent was rejected, to be reported in an interface diagnostic; frameRejected when
        // a chunk itself was bad (counted among the rejected frames), not the map assembled from good ones.
        std::function<void(const std::string& error, bool frameRejected)> rejected;
    };

    MapServiceClient(std::string link, bool separateChannel, std::string identificationMember,
                     IsoListener& listener, Counters& counters, const Clock& clock, Hooks hooks);

    bool separateChannel() const { return m_separate; }
    // The separate channel's state (Unknown until it first opens).
    LinkState channelState() const { return m_channelState; }
    std::shared_ptr<const MapModel> map() const { return m_map; }

    // ---- the socket the service speaks on ----
    void linkOpened();                           // main socket up
    void linkClosed();                           // main socket down
    void channelOpened(const std::string& peer); // separate socket up
    void channelClosed(const std::string& reason);

    // ---- what the service sent (onMapChannel: received on the separate socket) ----
    void chunk(std::string_view xml, bool onMapChannel);
    void service(const MapServiceV1& s, bool onMapChannel);
    void summary(const MapSummaryV1& s, bool onMapChannel);
    void connectivity(const MapConnectivityV1& c);

    // MapCommandV1 GET "/" now. False (with an event) when the separate channel is not up or the socket did
    // not take the frame; the caller checks the main link when the service shares it.
    bool fetch();
    // The identification deadline, due at clock.now().
    void poll();

private:
    bool requestMap(); // false: the socket did not take MapCommandV1
    void finishMap();
    void interruptTransfer(const std::string& why);
    void askSummaryIfIdle();

    std::string m_link;
    bool m_separate;
    std::string m_identificationMember;
    IsoListener& m_listener;
    Counters& m_counters;
    const Clock& m_clock;
    Hooks m_hooks;

    LinkState m_channelState = LinkState::Unknown;
    MapAssembler m_assembler;
    bool m_fetchPending = false;
    std::optional<MapSummaryV1> m_fetchingSummary;
    std::shared_ptr<MapModel> m_map;
    std::optional<MapConnectivityV1> m_connectivity;
    // A service that never identifies itself is asked for its summary anyway after this deadline.
    std::optional<TimePoint> m_identificationDeadline;
};

} // namespace ocu::iso23725
