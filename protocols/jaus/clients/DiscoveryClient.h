#pragma once
// Discovery (AS5710A Discovery, AEP-4818 §6.2.2 and §9 item 6): finds vehicles (QueryIdentification to
// everyone at start and every discovery_interval_s; a unicast one to a subsystem heard but not identified),
// learns each vehicle's call sign and its component table (QueryServices to the platform manager, answers
// merged, re-checked every interval) and tells other consoles apart (they answer as OCU and are never listed
// as vehicles). As the console's own Discovery service it answers QueryIdentification, QueryServices and
// QueryServiceList.
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
    // Called once per subsystem, when its first ReportServices has filled the component table.
    using ServicesKnown = std::function<void(RemoteSubsystem&)>;
    DiscoveryClient(ClientContext& context, ServicesKnown onServicesKnown)
        : ClientService(context), m_onServicesKnown(std::move(onServicesKnown)) {}

    void registerMessages(MessageTable& table) override;
    // Identification and services of one subsystem until known, then the periodic re-check.
    void tick(RemoteSubsystem& remote, TimePoint now) override;
    void forget(std::uint16_t subsystem) override { m_state.erase(subsystem); }

    // The broadcast QueryIdentification: now, and on the first tick and every discovery interval.
    void discoverNow();
    void tickBroadcast(TimePoint now);

    enum class Sender { Vehicle, Console, NewConsole };
    // Whether a message comes from a vehicle or from another console; NewConsole when this message (a
    // ReportIdentification of type OCU) is the one that tells: its record must go.
    Sender classify(const JausId& source, std::uint16_t id, ByteSpan payload);

private:
    struct State {
        TimePoint lastIdentQuery{}, lastServicesQuery{}, lastRecheck{};
        bool discoveredEvent = false;
    };
    void onIdentification(RemoteSubsystem& remote, const JausId& source, ByteSpan payload);
    void onServices(RemoteSubsystem& remote, const JausId& source, const std::vector<NodeServices>& nodes);
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
