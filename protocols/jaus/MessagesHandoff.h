#pragma once
// JAUS hand-off messages (IOP EnhancedAccessControl and HandoffController, AEP-4818 §6.3). The profile names
// version 2.0 of both services, of which no layout is public; these are the public 1.1 layouts (FKIE's
// iop/MessageSet/HandoffClass.xml, shared/research/jaus-autonomy.md §8 and jaus-wire.md §3.4), which share
// their IDs with 2.0 as far as the profile lists them. Same rules as Messages.h: little-endian; decoders
// ignore trailing bytes and fail only when a field that must be present is missing. Codecs in
// MessagesHandoff.cpp.
#include <cstdint>
#include <string>
#include <vector>

#include "protocols/common/Bytes.h"
#include "protocols/common/Result.h"
#include "protocols/jaus/JudpCodec.h"

namespace ocu::jaus {

namespace msg {
// Requester → EnhancedAccessControl: RequestHandoff, the two timeout queries, RemoveHandoffRequest; the EAC
// answers ConfirmHandoffRequest and the two reports. EAC → the controller's HandoffController:
// RequestReleaseControl, answered by ConfirmReleaseControl.
inline constexpr std::uint16_t RequestHandoff = 0xFF31, QueryHandoffTimeout = 0xFF32,
                               QueryEnhancedTimeout = 0xFF33, RemoveHandoffRequest = 0xFF34,
                               ConfirmHandoffRequest = 0xFF35, ReportHandoffTimeout = 0xFF36,
                               ReportEnhancedTimeout = 0xFF37, RequestReleaseControl = 0xFF38,
                               ConfirmReleaseControl = 0xFF39;
} // namespace msg

// Names of the IDs above (nullptr for others); messageName() falls back to it.
const char* handoffMessageName(std::uint16_t id);

// The ID the EAC uses in answers that need no queue entry (FKIE's EAC, jaus-autonomy.md §8).
inline constexpr std::uint8_t kNoHandoffId = 255;

struct RequestHandoff {
    std::uint8_t authority = 0;
    std::string explanation; // str8: at most 255 bytes on the wire
    bool operator==(const RequestHandoff&) const = default;
};

enum class HandoffCode : std::uint8_t {
    Granted = 0,
    NotAvailable = 1,
    Timeout = 2,
    Denied = 3,
    Queued = 4,
    Deferred = 5,
    InsufficientAuthority = 6,
    // FKIE's HandoffController reads a private 7 as the holder's WAIT (jaus-autonomy.md §8); the public
    // layout's answer to a WAIT is DEFERRED (or QUEUED again, as FKIE's EAC sends).
    Wait = 7,
};
const char* nameFor(HandoffCode c);

struct ConfirmHandoffRequest {
    std::uint8_t id = 0;
    HandoffCode code = HandoffCode::Queued;
    bool operator==(const ConfirmHandoffRequest&) const = default;
};

// One queued request as the EAC forwards it to the controller.
struct ReleaseRequest {
    std::uint8_t id = 0;
    JausId requester;
    std::uint8_t authority = 0;
    std::string explanation;
    bool operator==(const ReleaseRequest&) const = default;
};
struct RequestReleaseControl {
    std::vector<ReleaseRequest> requests; // count u8: at most 255
    bool operator==(const RequestReleaseControl&) const = default;
};

enum class ReleaseCode : std::uint8_t { Granted = 0, Denied = 1, Wait = 2 };
struct ReleaseAnswer {
    std::uint8_t id = 0;
    ReleaseCode code = ReleaseCode::Denied;
    bool operator==(const ReleaseAnswer&) const = default;
};
struct ConfirmReleaseControl {
    std::vector<ReleaseAnswer> answers; // count u8; at most one Granted
    bool operator==(const ConfirmReleaseControl&) const = default;
};

// RemoveHandoffRequest (ID), ReportHandoffTimeout and ReportEnhancedTimeout (seconds, 0 = off) are one u8:
// encodeU8 / decodeU8 of Messages.h.
Bytes encode(const RequestHandoff& m);
Bytes encode(const ConfirmHandoffRequest& m);
Bytes encode(const RequestReleaseControl& m);
Bytes encode(const ConfirmReleaseControl& m);
Result<RequestHandoff> decodeRequestHandoff(ByteSpan payload);
Result<ConfirmHandoffRequest> decodeConfirmHandoffRequest(ByteSpan payload);
Result<RequestReleaseControl> decodeRequestReleaseControl(ByteSpan payload);
Result<ConfirmReleaseControl> decodeConfirmReleaseControl(ByteSpan payload);

} // namespace ocu::jaus
