// Fuzz harness: a JTCP byte stream (AS5669A: version byte once, then messages back to back) through
// JtcpStreamDecoder. The stream is fed twice, whole and in chunks whose sizes come from the stream's own
// bytes; invariant: the messages (and whether the stream failed) do not depend on how TCP cut the stream:
// the good messages before a bad one are delivered whatever read they arrived in.
#include "protocols/jaus/JudpCodec.h"

#include "tests/fuzz/FuzzSupport.h"
#include <algorithm>

using namespace ocu;
using namespace ocu::jaus;

namespace {

struct Outcome {
    std::vector<JudpMessage> messages;
    bool failed = false;
};

template <class Cut> Outcome run(ByteSpan stream, Cut cut) {
    Outcome o;
    JtcpStreamDecoder decoder;
    std::size_t pos = 0;
    while (pos < stream.size() && !o.failed) {
        std::size_t n = std::min(cut(pos), stream.size() - pos);
        auto r = decoder.feed(stream.subspan(pos, n));
        pos += n;
        OCU_FUZZ_CHECK(r.ok() || decoder.failed());
        if (r)
            for (auto& m : *r)
                o.messages.push_back(std::move(m));
        if (decoder.failed()) {
            o.failed = true;
            OCU_FUZZ_CHECK(!decoder.error().empty());
            OCU_FUZZ_CHECK(!decoder.feed(stream.subspan(0, 0)).ok()); // stays failed
            break;
        }
    }
    return o;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    ocu::fuzz::quietLogs();
    ByteSpan stream(data, size);
    Outcome whole = run(stream, [&](std::size_t) { return size; });
    Outcome pieces = run(stream, [&](std::size_t pos) { return std::size_t(data[pos] % 23) + 1; });
    OCU_FUZZ_CHECK(whole.failed == pieces.failed);
    OCU_FUZZ_CHECK(whole.messages.size() == pieces.messages.size());
    for (std::size_t i = 0; i < whole.messages.size(); ++i) {
        OCU_FUZZ_CHECK(whole.messages[i].payload == pieces.messages[i].payload);
        OCU_FUZZ_CHECK(whole.messages[i].header.props() == pieces.messages[i].header.props());
        OCU_FUZZ_CHECK(whole.messages[i].header.sequence == pieces.messages[i].header.sequence);
    }
    return 0;
}
