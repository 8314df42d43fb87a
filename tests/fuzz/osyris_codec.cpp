// Fuzz harness: one OSYRIS datagram (seed 004 §3) through decodeDatagram with each checksum mode.
// Invariants: each decoded message lies inside the datagram; each re-encodes to bytes that decode again and
// re-encode identically (encode∘decode idempotent, NaN floats included, since the bytes are compared).
#include "protocols/osyris/OsyrisCodec.h"
#include "tests/fuzz/FuzzSupport.h"

using namespace ocu;
using namespace ocu::osyris;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    ocu::fuzz::quietLogs();
    ByteSpan datagram(data, size);
    for (Checksum cs : {Checksum::None, Checksum::Xor, Checksum::Crc16}) {
        DecodedDatagram d = decodeDatagram(datagram, cs);
        OCU_FUZZ_CHECK(d.reason.empty() == d.error.empty());
        for (const Message& m : d.messages) {
            // A CmPos with its PosProp table inside (the other reading of §6) yields two messages that share
            // the header, so the lengths are bounded one by one, not summed.
            OCU_FUZZ_CHECK(m.header.len >= kHeaderSize && m.header.len <= size);
            Bytes once;
            encodeMessage(once, m, cs);
            auto again = decodeMessage(ByteSpan(once), cs);
            OCU_FUZZ_CHECK(again.ok());
            OCU_FUZZ_CHECK(again->header.who == m.header.who && again->header.whose == m.header.whose);
            Bytes twice;
            encodeMessage(twice, *again, cs);
            OCU_FUZZ_CHECK(once == twice);
        }
    }
    return 0;
}
