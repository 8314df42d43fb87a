#pragma once
// Discovery (AS5710A Discovery, AEP-4818 §6.2.2 and §9 item 6): finds vehicles (QueryIdentification to
// everyone at start and every discovery_interval_s; a unicast one to a subsystem heard but not identified),
// learns each vehicle's call sign and its component table (QueryServices to the platform manager, answers
// merged, re-checked every interval) and tells other consoles apart (they answer as OCU and are never listed
// as vehicles). As the console's own Discovery service it answers QueryIdentification, QueryServices and
// QueryServiceList.
//
// Vehicles describe themselves in more than one way. Some answer the wildcard QueryServices (node 255,
// component 255) with no components at all and push RegisterServices (AS5710A: a component registering with
// a Discovery service) instead; some list only part of their components. So the table is the merge of every
// ReportServices, ReportServiceList and RegisterServices heard, and a component the vehicle has shown (it
// sent us anything, or ReportConfiguration named it) that no answer lists yet is asked for by name.
#include <cstdint>
#include <functional>
#include <map>
#include <set>
#include <vector>

#include "protocols/jaus/Messages.h"
#include "protocols/jaus/clients/ClientService.h"

namespace ocu::jaus {

class DiscoveryClient : public ClientService {
public:
    // Called when a services answer first lists a component with services, and again whenever a later
    // answer adds services (the clients' subscriptions are idempotent).
    using ServicesKnown = std::function<void(RemoteSubsystem&)>;
    DiscoveryClient(ClientContext& context, ServicesKnown onServicesKnown)
        : ClientService(context), m_onServicesKnown(std::move(onServicesKnown)) {}

    void registerMessages(MessageTable& table) override;
    // Identification and services of one subsystem until known, then the periodic re-check.
    void tick(RemoteSubsystem& remote, TimePoint now) override;
    void forget(std::uint16_t subsystem) override { m_state.erase(subsystem); }
    // Any message from a vehicle: its source is a component that exists, whatever the services say.
    void heardFrom(RemoteSubsystem& remote, const JausId& source);

    // The broadcast QueryIdentification: now, and on the first tick and every discovery interval.
    void discoverNow();
    void tickBroadcast(TimePoint now);

    enum class Sender { Vehicle, Console, NewConsole };
    // Whether a message comes from a vehicle or from another console; NewConsole when this message (a
    // ReportIdentification of type OCU) is the one that tells: its record must go.
    Sender classify(const JausId& source, std::uint16_t id, ByteSpan payload);

private:
    struct NamedQuery {
        TimePoint last{};
        int sent = 0;
    };
    struct State {
        TimePoint lastIdentQuery{}, lastServicesQuery{}, lastRecheck{}, lastConfigurationQuery{};
        bool discoveredEvent = false;
        bool emptyAnswerWarned = false;
        bool managerIdentified = false; // a subsystem-level ReportIdentification chose the platform manager
        int wildcardQueries = 0;        // wildcard QueryServices sent while the services are unknown
        // Components shown to exist (node << 8 | component) and the named queries sent for each.
        std::map<std::uint16_t, NamedQuery> shown;
    };
    void onIdentification(RemoteSubsystem& remote, const JausId& source, ByteSpan payload);
    void onServices(RemoteSubsystem& remote, const JausId& source, const std::vector<NodeServices>& nodes);
    void onConfiguration(RemoteSubsystem& remote, const ReportConfiguration& configuration);
    // Named QueryServices for every shown component that no answer lists yet.
    void askUnlisted(RemoteSubsystem& remote, State& state, TimePoint now);
    static bool listed(const RemoteSubsystem& remote, std::uint8_t node, std::uint8_t component);
    void identify(const JausId& target, State& state, TimePoint now);
    void assignRoles(RemoteSubsystem& remote);
    bool answerIdentification(const JausId& source, ByteSpan payload);
    bool answerServices(const JausId& source, std::uint16_t id);

    ServicesKnown m_onServicesKnown;
    std::map<std::uint16_t, State> m_state;
    std::set<std::uint16_t> m_otherOcus; // subsystems that identified as OCU
    TimePoint m_lastBroadcast{};
    bool m_started = false;
};

} // namespace ocu::jaus
