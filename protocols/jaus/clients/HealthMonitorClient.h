#pragma once
// Health (IOP custom HealthMonitor, AEP-4818; FKIE HealthClass ED10/FD10): the summary polled every 5 s,
// an operator event when the severity rises to ERR (3) or FAIL (4).
#include <cstdint>
#include <map>

#include "protocols/jaus/clients/ClientService.h"

namespace ocu::jaus {

class HealthMonitorClient : public ClientService {
public:
    explicit HealthMonitorClient(ClientContext& context) : ClientService(context) {}

    void registerMessages(MessageTable& table) override;
    void tick(RemoteSubsystem& remote, TimePoint now) override;
    void forget(std::uint16_t subsystem) override { m_lastPoll.erase(subsystem); }

private:
    std::map<std::uint16_t, TimePoint> m_lastPoll;
};

} // namespace ocu::jaus
