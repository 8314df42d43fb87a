#pragma once
// Platform specifications (AS6009 PlatformSpecifications): asked for every 2 s until the report arrives;
// the drive client clamps commands to its speed limits (AEP-4818 §7.2), the console shows name and size.
#include <cstdint>
#include <map>

#include "protocols/jaus/clients/ClientService.h"

namespace ocu::jaus {

class PlatformSpecificationsClient : public ClientService {
public:
    explicit PlatformSpecificationsClient(ClientContext& context) : ClientService(context) {}

    void registerMessages(MessageTable& table) override;
    void tick(RemoteSubsystem& remote, TimePoint now) override;
    void forget(std::uint16_t subsystem) override { m_lastQuery.erase(subsystem); }

private:
    std::map<std::uint16_t, TimePoint> m_lastQuery;
};

} // namespace ocu::jaus
