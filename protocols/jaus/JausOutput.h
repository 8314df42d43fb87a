#pragma once
// The seam between the JAUS state machines (JausCore, the simulated UGV) and the transport.
#include <string>

#include "protocols/common/Bytes.h"
#include "protocols/jaus/JudpCodec.h"

namespace ocu::jaus {

struct SendOptions {
    Priority priority = Priority::Standard;
    bool ackRequest = false;
};

class JausOutput {
public:
    virtual ~JausOutput() = default;
    virtual void send(const JausId& destination, const Bytes& payload, SendOptions options) = 0;
    // For hosts of several components (the simulated UGV): send with an explicit source ID.
    virtual void sendFrom(const JausId& source, const JausId& destination, const Bytes& payload,
                          SendOptions options) {
        (void)source;
        send(destination, payload, options);
    }
    // The same, saying whether the message was handed to a socket: empty when it was, else why not (a
    // command counts as sent only then). No default: only the output knows what its socket did, and a
    // default that reported success would make every command "sent".
    virtual std::string sendOrWhy(const JausId& destination, const Bytes& payload, SendOptions options) = 0;
    // "ip:port" last learned for a JAUS ID (for the console), empty when unknown.
    virtual std::string endpointOf(const JausId&) const { return {}; }
};

} // namespace ocu::jaus
