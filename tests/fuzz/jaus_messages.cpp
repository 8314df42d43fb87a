// Fuzz harness: every JAUS message decoder (protocols/jaus/Messages.h). The first input byte picks the
// decoder, the rest is the body behind that decoder's message ID, so every decoder is reached whatever the ID
// table. Invariant: a message that decodes re-encodes to bytes that decode again and re-encode identically
// (encode∘decode is idempotent on the wire: no value drifts through scaling or presence vectors).
#include "protocols/jaus/Messages.h"
#include "tests/fuzz/FuzzSupport.h"

#include <functional>
#include <vector>

using namespace ocu;
using namespace ocu::jaus;

namespace {

// Decodes, and when the message has an encoder, checks the round trip.
template <class Decode, class Encode> void roundTrip(ByteSpan payload, Decode decode, Encode encode) {
    auto first = decode(payload);
    if (!first)
        return;
    Bytes once = encode(*first);
    auto second = decode(ByteSpan(once));
    OCU_FUZZ_CHECK(second.ok());
    Bytes twice = encode(*second);
    OCU_FUZZ_CHECK(once == twice);
}

template <class Decode> void decodeOnly(ByteSpan payload, Decode decode) {
    (void)decode(payload);
}

struct Entry {
    std::uint16_t id;
    std::function<void(ByteSpan)> run;
};

template <class T> auto plain(Result<T> (*decode)(ByteSpan)) {
    return [decode](ByteSpan p) { roundTrip(p, decode, [](const T& m) { return encode(m); }); };
}

std::vector<Entry> table() {
    std::vector<Entry> t;
    for (std::uint16_t id : {msg::SetAuthority, msg::SetEmergency, msg::ClearEmergency, msg::RequestControl,
                             msg::ConfirmControl, msg::RejectControl, msg::ReportAuthority,
                             msg::QueryIdentification, msg::ReportTimeout, msg::QueryConfiguration})
        t.push_back({id, [id](ByteSpan p) {
                         roundTrip(
                             p, [id](ByteSpan q) { return decodeU8(q, id); },
                             [id](std::uint8_t v) { return encodeU8(id, v); });
                     }});
    for (std::uint16_t id : {msg::ReportHeartbeatPulse, msg::QueryServices})
        t.push_back({id, [id](ByteSpan p) {
                         roundTrip(
                             p, [id](ByteSpan q) { return decodeU16(q, id); },
                             [id](std::uint16_t v) { return encodeU16(id, v); });
                     }});
    t.push_back({msg::ReportStatus, plain(&decodeReportStatus)});
    t.push_back({msg::ReportControl, plain(&decodeReportControl)});
    t.push_back({msg::QueryIdentification, plain(&decodeQueryIdentification)});
    t.push_back({msg::ReportIdentification, plain(&decodeReportIdentification)});
    t.push_back({msg::RegisterServices, plain(&decodeRegisterServices)});
    t.push_back({msg::QueryServices, plain(&decodeQueryServices)});
    t.push_back({msg::ReportServices, plain(&decodeReportServices)});
    t.push_back({msg::QueryServiceList, plain(&decodeQueryServiceList)});
    t.push_back({msg::ReportServiceList, plain(&decodeReportServiceList)});
    t.push_back({msg::ReportSubsystemList, plain(&decodeReportSubsystemList)});
    t.push_back({msg::CreateEvent, plain(&decodeCreateEvent)});
    t.push_back({msg::UpdateEvent, plain(&decodeUpdateEvent)});
    t.push_back({msg::CancelEvent, plain(&decodeCancelEvent)});
    t.push_back({msg::ConfirmEventRequest, plain(&decodeConfirmEventRequest)});
    t.push_back({msg::RejectEventRequest, plain(&decodeRejectEventRequest)});
    t.push_back({msg::Event, plain(&decodeEvent)});
    t.push_back({msg::QueryEvents, plain(&decodeQueryEvents)});
    t.push_back({msg::ReportEvents, plain(&decodeReportEvents)});
    t.push_back({msg::ReportVelocityState, plain(&decodeVelocityState)});
    t.push_back({msg::ReportPlatformSpecifications, plain(&decodePlatformSpecifications)});
    t.push_back({msg::ReportHealthSummary, plain(&decodeHealthSummary)});
    for (std::uint16_t id : {msg::SetWrenchEffort, msg::ReportWrenchEffort})
        t.push_back({id, [id](ByteSpan p) {
                         roundTrip(
                             p, [id](ByteSpan q) { return decodeWrench(q, id); },
                             [id](const WrenchEffort& m) { return encodeWrench(id, m); });
                     }});
    for (std::uint16_t id : {msg::SetVelocityCommand, msg::ReportVelocityCommand})
        t.push_back({id, [id](ByteSpan p) {
                         roundTrip(
                             p, [id](ByteSpan q) { return decodeVelocityCommand(q, id); },
                             [id](const VelocityCommand& m) { return encodeVelocityCommand(id, m); });
                     }});
    for (std::uint16_t id : {msg::QueryGlobalPose, msg::QueryLocalPose, msg::QueryVelocityState,
                             msg::QueryWrenchEffort, msg::QueryHealthSummary})
        t.push_back({id, [id](ByteSpan p) {
                         roundTrip(
                             p, [id](ByteSpan q) { return decodeQueryPv16(q, id); },
                             [id](std::uint16_t v) { return encodeQueryPv16(id, v); });
                     }});
    for (std::uint16_t id : {msg::ReportGlobalPose, msg::ReportLocalPose})
        t.push_back({id, [id](ByteSpan p) {
                         if (id == msg::ReportGlobalPose)
                             roundTrip(
                                 p, [id](ByteSpan q) { return decodeGlobalPose(q, id); },
                                 [id](const GlobalPose& m) { return encode(m, id); });
                         else
                             roundTrip(
                                 p, [id](ByteSpan q) { return decodeLocalPose(q, id); },
                                 [id](const LocalPose& m) { return encode(m, id); });
                     }});
    return t;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    ocu::fuzz::quietLogs();
    static const std::vector<Entry> decoders = table();
    if (size == 0)
        return 0;
    const Entry& e = decoders[data[0] % decoders.size()];
    Bytes payload{std::uint8_t(e.id), std::uint8_t(e.id >> 8)};
    payload.insert(payload.end(), data + 1, data + size);
    e.run(ByteSpan(payload));
    // The receive path dispatches on the ID the peer sent: the same bytes, unmodified, by their own ID.
    ByteSpan raw(data + 1, size - 1);
    for (const Entry& other : decoders)
        if (other.id == peekMessageId(raw))
            other.run(raw);
    return 0;
}
