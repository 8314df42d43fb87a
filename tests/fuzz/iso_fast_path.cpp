// Fuzz harness: ISO 23725 text frames through decodeMessage's fast path (PositionFastPath, the hot
// MachinePositionV1). Differential: whenever the fast path accepts a frame, the DOM path (the reference) must
// decode it to the same Envelope, doubles bit for bit; decodeMessage itself must never fail on such a frame.
#include "protocols/iso23725/PositionFastPath.h"
#include "tests/fuzz/FuzzSupport.h"

#include <cstring>

using namespace ocu;
using namespace ocu::iso23725;

namespace {

bool sameBits(const std::optional<double>& a, const std::optional<double>& b) {
    return a.has_value() == b.has_value() && (!a || std::memcmp(&*a, &*b, sizeof(double)) == 0);
}

bool samePose(const PoseFields& a, const PoseFields& b) {
    return a == b && sameBits(a.latitude, b.latitude) && sameBits(a.longitude, b.longitude) &&
           sameBits(a.elevation, b.elevation) && sameBits(a.latitudeAccuracy, b.latitudeAccuracy) &&
           sameBits(a.longitudeAccuracy, b.longitudeAccuracy) &&
           sameBits(a.elevationAccuracy, b.elevationAccuracy) &&
           sameBits(a.headingAccuracy, b.headingAccuracy);
}

void checkSame(const Envelope& x, const Envelope& y) {
    OCU_FUZZ_CHECK(x.header == y.header);
    OCU_FUZZ_CHECK(x.errors == y.errors);
    OCU_FUZZ_CHECK(x.warnings == y.warnings);
    OCU_FUZZ_CHECK(x.outOfStandard == y.outOfStandard);
    OCU_FUZZ_CHECK(x.members.size() == y.members.size());
    for (std::size_t i = 0; i < x.members.size(); ++i) {
        OCU_FUZZ_CHECK(x.members[i].body == y.members[i].body);
        OCU_FUZZ_CHECK(x.members[i].extra == y.members[i].extra);
        auto* p = std::get_if<MachinePositionV1>(&x.members[i].body);
        auto* q = std::get_if<MachinePositionV1>(&y.members[i].body);
        if (p && q)
            OCU_FUZZ_CHECK(samePose(p->pose, q->pose));
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    ocu::fuzz::quietLogs();
    std::string_view text(reinterpret_cast<const char*>(data), data ? size : 0);
    const InferredRules& rules = defaultInferredRules();
    auto fast = tryDecodePositionFast(text, rules);
    if (!fast)
        return 0;
    auto dom = decodeMessageDom(text, rules);
    OCU_FUZZ_CHECK(dom.ok());
    checkSame(*fast, *dom);
    auto full = decodeMessage(text, rules);
    OCU_FUZZ_CHECK(full.ok());
    checkSame(*full, *dom);
    return 0;
}
