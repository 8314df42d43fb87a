// Fuzz harness: ISO 23725 text frames through decodeMessage (the DOM path: nlohmann parse, header and member
// validation, timestamp repair, aliases, unknown members). Invariant: a frame that decodes re-encodes
// (encodeMessage) to a frame that decodes again, with the same header and the same members.
#include "protocols/iso23725/PositionFastPath.h"
#include "tests/fuzz/FuzzSupport.h"

using namespace ocu;
using namespace ocu::iso23725;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    ocu::fuzz::quietLogs();
    std::string_view text(reinterpret_cast<const char*>(data), data ? size : 0);
    auto env = decodeMessageDom(text);
    auto full = decodeMessage(text);
    OCU_FUZZ_CHECK(env.ok() == full.ok());
    if (!env)
        return 0;
    std::string again = encodeMessage(*env);
    auto back = decodeMessage(again);
    OCU_FUZZ_CHECK(back.ok());
    OCU_FUZZ_CHECK(back->members.size() == env->members.size());
    for (std::size_t i = 0; i < env->members.size(); ++i)
        OCU_FUZZ_CHECK(back->members[i].body.index() == env->members[i].body.index());
    return 0;
}
