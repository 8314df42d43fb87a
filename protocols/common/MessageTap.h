#pragma once
// What a stack received, handed to an observer on the io thread (the console's flight recorder
// keeps every decoded inbound message and, with record.raw, every raw frame). Plain C++: the stacks know
// nothing of the recorder; models/recording implements the tap.
//
// Contract for implementations: called on the stack's io thread for every inbound message, so it must only
// copy and hand over (a bounded queue) - never block, never do I/O, never format heavily. Views passed in are
// valid during the call only.
#include <cstdint>
#include <span>
#include <string_view>

namespace ocu {

struct TappedMessage {
    std::string_view protocol; // "JAUS", "ISO 23725", "OSYRIS"
    std::string_view link;     // the stack's link (ISO 23725 link name, JAUS/OSYRIS: the stack's own name)
    std::string_view peer;     // who sent it (JAUS ID, OSYRIS station, the AHS link), as the stack names it
    std::string_view type;     // the message type as the codec names it (JAUS: 4 hex digits of the code)
    std::span<const std::uint8_t> bytes; // decoded: the validated message bytes the codec decodes again;
                                         // raw: the frame/datagram as received
};

class MessageTap {
public:
    virtual ~MessageTap() = default;
    // One message the codec accepted.
    virtual void onDecoded(const TappedMessage& m) = 0;
    // One raw frame/datagram as received, decodable or not (only when wantsRaw()).
    virtual void onRaw(const TappedMessage& m) = 0;
    virtual bool wantsRaw() const = 0;
};

inline std::span<const std::uint8_t> tapBytes(std::string_view text) {
    return {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()};
}

} // namespace ocu
