#include "protocols/jaus/clients/MessageTable.h"

#include <stdexcept>
#include <string>

#include "protocols/jaus/Messages.h"

namespace ocu::jaus {

void MessageTable::onRequest(std::uint16_t id, RequestHandler handler) {
    if (!m_requests.emplace(id, std::move(handler)).second)
        throw std::logic_error(std::string("two JAUS services answer ") + messageName(id));
}

void MessageTable::onVehicleMessage(std::uint16_t id, VehicleHandler handler) {
    if (!m_vehicle.emplace(id, std::move(handler)).second)
        throw std::logic_error(std::string("two JAUS client services handle ") + messageName(id));
}

bool MessageTable::answer(std::uint16_t id, const JausId& source, ByteSpan payload) const {
    auto it = m_requests.find(id);
    return it != m_requests.end() && it->second(source, payload);
}

bool MessageTable::dispatch(RemoteSubsystem& remote, const JausId& source, std::uint16_t id,
                            ByteSpan payload) const {
    auto it = m_vehicle.find(id);
    if (it == m_vehicle.end())
        return false;
    it->second(remote, source, payload);
    return true;
}

} // namespace ocu::jaus
