#pragma once
// Which client service handles which JAUS message: a dispatch table keyed by message ID, filled by the
// clients themselves (ClientService::registerMessages), instead of one switch over every message.
// Two kinds of entries: requests the console answers as a JAUS subsystem of its own (from anyone), and
// messages from a vehicle (reports, confirmations, events), handled with that vehicle's record.
#include <cstdint>
#include <functional>
#include <unordered_map>

#include "protocols/common/Bytes.h"
#include "protocols/jaus/JudpCodec.h"

namespace ocu::jaus {

struct RemoteSubsystem;

class MessageTable {
public:
    // Returns true when the message is only a question to the console (the sender's record is not touched).
    using RequestHandler = std::function<bool(const JausId& source, ByteSpan payload)>;
    using VehicleHandler =
        std::function<void(RemoteSubsystem& remote, const JausId& source, ByteSpan payload)>;

    // Each ID has at most one handler of each kind: a second registration throws std::logic_error.
    void onRequest(std::uint16_t id, RequestHandler handler);
    void onVehicleMessage(std::uint16_t id, VehicleHandler handler);

    // A request addressed to the console; returns the handler's answer, false when nobody handles it.
    bool answer(std::uint16_t id, const JausId& source, ByteSpan payload) const;
    // A message from a vehicle; returns false when no client handles the ID.
    bool dispatch(RemoteSubsystem& remote, const JausId& source, std::uint16_t id, ByteSpan payload) const;

private:
    std::unordered_map<std::uint16_t, RequestHandler> m_requests;
    std::unordered_map<std::uint16_t, VehicleHandler> m_vehicle;
};

} // namespace ocu::jaus
