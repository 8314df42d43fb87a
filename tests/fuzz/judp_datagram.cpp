// Fuzz harness: one JUDP datagram (AS5669A) through decodeDatagram, and its messages through the fragment
// Reassembler. Invariants: every decoded message re-encodes to bytes that decode to the same header and
// payload; a datagram never yields more messages than its size allows; reassembled payloads stay bounded.
#include "protocols/jaus/JudpCodec.h"
#include "tests/fuzz/FuzzSupport.h"

using namespace ocu;
using namespace ocu::jaus;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    ocu::fuzz::quietLogs();
    ByteSpan datagram(data, size);
    auto decoded = decodeDatagram(datagram);
    if (!decoded)
        return 0;
    OCU_FUZZ_CHECK(decoded->messages.size() * kMessageOverhead <= size);
    Reassembler::Options opt;
    opt.maxSets = 4;
    opt.maxBytes = 4096;
    Reassembler reassembler(opt);
    TimePoint now{};
    for (const JudpMessage& m : decoded->messages) {
        Bytes again;
        appendMessage(again, m.header, ByteSpan(m.payload));
        std::size_t consumed = 0;
        auto back = decodeMessage(ByteSpan(again), consumed);
        OCU_FUZZ_CHECK(back.ok());
        OCU_FUZZ_CHECK(consumed == again.size());
        OCU_FUZZ_CHECK(back->header.props() == m.header.props());
        OCU_FUZZ_CHECK(back->header.destination == m.header.destination);
        OCU_FUZZ_CHECK(back->header.source == m.header.source);
        OCU_FUZZ_CHECK(back->header.sequence == m.header.sequence);
        OCU_FUZZ_CHECK(back->payload == m.payload);

        now += std::chrono::milliseconds(700);
        auto r = reassembler.feed(m, now);
        if (r && r->has_value())
            OCU_FUZZ_CHECK((*r)->payload.size() <= opt.maxBytes);
        OCU_FUZZ_CHECK(reassembler.pending() <= opt.maxSets);
        reassembler.expire(now);
    }
    return 0;
}
