#pragma once
// Fast path for the hot message, MachinePositionV1 (ISO §7.4; shared/research/iso23725.md §5 row 5: every
// machine, 1-10 Hz). A strict hand-written scanner reads exactly the clean shape of that frame and gives the
// same Envelope as the DOM path (nlohmann parse + decodeJson), or declines and lets the DOM path decode it.
#include "protocols/iso23725/Messages.h"

#include <optional>
#include <string_view>

namespace ocu::iso23725 {

// Accepts one JSON object holding exactly the header members Protocol (= rules.protocol), Version (plain
// integer), Timestamp, EquipmentId and one MachinePositionV1 object with Timestamp and the nine pose members
// (numbers or null), in any order and with any RFC 8259 whitespace. Returns nullopt ("declined") for
// anything else and whenever the DOM path would report an error, a warning, an alias or an out-of-standard
// protocol: unknown/duplicate members, Attachment, escapes, non-ASCII text, numbers sent as strings,
// decimals for integer members, timestamps needing repair, out-of-range values, trailing text.
std::optional<Envelope> tryDecodePositionFast(std::string_view text, const InferredRules& rules);

// The DOM path alone (what decodeMessage does when the fast path declines): the reference the fast path is
// tested and benchmarked against.
Result<Envelope> decodeMessageDom(std::string_view text, const InferredRules& rules = defaultInferredRules());

} // namespace ocu::iso23725
