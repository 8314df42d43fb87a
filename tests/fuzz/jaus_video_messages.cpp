// Fuzz harness: the JAUS video message decoders (protocols/jaus/MessagesVideo.h). The first input
// byte picks the decoder, the rest is the body behind that decoder's message ID. Invariant as for
// jaus_messages: a message that decodes re-encodes to bytes that decode again and re-encode identically.
#include "protocols/jaus/MessagesVideo.h"
#include "tests/fuzz/FuzzSupport.h"

#include <functional>
#include <vector>

using namespace ocu;
using namespace ocu::jaus;

namespace {

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

struct Entry {
    std::uint16_t id;
    std::function<void(ByteSpan)> run;
};

template <class T> auto plain(Result<T> (*decode)(ByteSpan)) {
    return [decode](ByteSpan p) { roundTrip(p, decode, [](const T& m) { return encode(m); }); };
}

std::vector<Entry> table() {
    std::vector<Entry> t;
    t.push_back({msg::RegisterDigitalResourceEndpoint, plain(&decodeRegisterDigitalResourceEndpoint)});
    t.push_back({msg::RemoveDigitalResourceEndpoint, plain(&decodeRemoveDigitalResourceEndpoint)});
    t.push_back({msg::ConfirmDigitalResourceEndpoint, plain(&decodeConfirmDigitalResourceEndpoint)});
    t.push_back({msg::ReportDigitalResourceEndpoint, plain(&decodeReportDigitalResourceEndpoint)});
    t.push_back({msg::ReportVisualSensorCapabilities, plain(&decodeReportVisualSensorCapabilities)});
    t.push_back({msg::ReportVisualSensorConfiguration, plain(&decodeReportVisualSensorConfiguration)});
    t.push_back({msg::ReportDigitalVideoSensorCapabilities, plain(&decodeReportDigitalVideoCapabilities)});
    t.push_back({msg::ReportDigitalVideoSensorConfiguration, plain(&decodeReportDigitalVideoConfiguration)});
    t.push_back({msg::ControlDigitalVideoSensorStream, plain(&decodeControlDigitalVideoSensorStream)});
    t.push_back({msg::QuerySensorGeometricProperties, plain(&decodeQuerySensorGeometricProperties)});
    t.push_back({msg::ReportSensorGeometricProperties, plain(&decodeReportSensorGeometricProperties)});
    for (std::uint16_t id :
         {msg::QueryVisualSensorCapabilities, msg::QueryVisualSensorConfiguration,
          msg::QueryDigitalVideoSensorCapabilities, msg::QueryDigitalVideoSensorConfiguration})
        t.push_back({id, [id](ByteSpan p) {
                         roundTrip(
                             p, [id](ByteSpan q) { return decodeSensorQuery(q, id); },
                             [id](const QuerySensors& m) { return encodeSensorQuery(id, m); });
                     }});
    for (std::uint16_t id : {msg::SetPanTiltJointPositions, msg::ReportPanTiltJointPositions})
        t.push_back({id, [id](ByteSpan p) {
                         roundTrip(
                             p, [id](ByteSpan q) { return decodePanTiltPositions(q, id); },
                             [id](const PanTiltJoints& m) { return encodePanTiltPositions(id, m); });
                     }});
    for (std::uint16_t id : {msg::SetPanTiltJointVelocity, msg::ReportPanTiltJointVelocity})
        t.push_back({id, [id](ByteSpan p) {
                         roundTrip(
                             p, [id](ByteSpan q) { return decodePanTiltVelocities(q, id); },
                             [id](const PanTiltJoints& m) { return encodePanTiltVelocities(id, m); });
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
    return 0;
}
