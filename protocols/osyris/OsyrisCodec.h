#pragma once
// OSYRIS message codec (seed 004 §6): CmHeader, CmPos, CmPosProps, CmRequest, CmMsg. Tight 1-byte packing,
// little-endian, several messages per datagram. Decisions on the specification's ambiguities are in
// docs/osyris.md ("Wire decisions").
#include "protocols/common/Bytes.h"
#include "protocols/common/Result.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace ocu::osyris {

constexpr std::uint8_t kIdxNobody = 254; // §6 idNobody
constexpr std::uint8_t kIdxAll = 255;    // §6 idAll
constexpr std::uint32_t kSlotLast = 0xFFFFFFFFu;

constexpr std::size_t kHeaderSize = 8;
constexpr std::size_t kPosBodySize = 65;
constexpr std::size_t kPosSize = kHeaderSize + kPosBodySize; // 73
constexpr std::size_t kPosPropSize = 8;
constexpr std::size_t kRequestBodySize = 9; // bType + 8-byte union (From/To or X/Y)
constexpr std::size_t kRequestSize = kHeaderSize + kRequestBodySize;
constexpr std::size_t kMsgTextSize = 80;
constexpr std::size_t kMsgSize = kHeaderSize + kMsgTextSize;
constexpr std::size_t kMaxDatagram = 65507;

enum class MsgType : std::uint16_t { Pos = 1, Request = 2, Msg = 4, PosProps = 5 };
// WType 3 is accepted as CmMsg on input: the table names 4 twice, so a peer may number CmMsg 3 (docs).
constexpr std::uint16_t kTypeMsgAlt = 3;

// Position flags (§6 "Flags"). POS_INVALID is the absence of POS_VALID.
constexpr std::uint32_t kPosInvalid = 0x00000000u;
constexpr std::uint32_t kPosValid = 0x80000000u;
constexpr std::uint32_t kPosStop = 0x00000001u;
constexpr std::uint32_t kPosForward = 0x00000002u;
constexpr std::uint32_t kPosBackward = 0x00000004u;
constexpr std::uint32_t kPosErrorHeading = 0x00000020u;
constexpr std::uint32_t kPosVibrating = 0x00000080u;
constexpr std::uint32_t kPosAccuracyLow = 0x00000100u;
constexpr std::uint32_t kPosAccuracyMed = 0x00000200u;
constexpr std::uint32_t kPosAccuracyHigh = 0x00000400u;
constexpr std::uint32_t kPosGpsShadow = 0x00000800u;

enum class RequestType : std::uint8_t { Nak = 0, Ncf = 1, All = 2, Ping = 3, Pong = 4, Alive = 5 };
enum class Checksum { None, Xor, Crc16 };

const char* nameFor(RequestType t);
const char* nameFor(Checksum c);

struct CmHeader {
    std::uint16_t crc = 0;
    std::uint16_t len = 0;
    std::uint16_t type = 0;
    std::uint8_t who = kIdxNobody;   // sender
    std::uint8_t whose = kIdxNobody; // owner of the ribbon (Pos/PosProps/NAK/NCF/ALL/ALIVE), target otherwise
    bool operator==(const CmHeader&) const = default;
};

struct CmPos {
    std::uint32_t numPos = 0;
    float x = 0, y = 0, z = 0;          // m, east / north / height
    float yaw = 0, pitch = 0, roll = 0; // rad; yaw north = 0, west = pi/2
    std::uint32_t flags = 0;
    float dx = 0, dy = 0, dz = 0; // extents; dx = drum/machine width (docs)
    double speed = 0;             // m/s
    std::uint64_t time = 0;       // FILETIME, 100 ns since 1601-01-01
    std::uint32_t slot = 0;
    std::uint8_t epoch = 0;
    bool operator==(const CmPos&) const = default;
};

struct PosProp {
    std::uint32_t value = 0; // union of float/int/char[4]; floats in practice
    std::uint32_t id = 0;    // perfect-hash id of the property name
    float asFloat() const;
    static PosProp fromFloat(std::uint32_t id, float v);
    bool operator==(const PosProp&) const = default;
};

struct CmPosProps {
    std::vector<PosProp> props;
    bool operator==(const CmPosProps&) const = default;
};

struct CmRequest {
    RequestType type = RequestType::Nak;
    std::uint32_t from = 0; // NAK, NCF, ALL, ALIVE
    std::uint32_t to = 0;
    float x = 0; // PING, PONG
    float y = 0;
    bool operator==(const CmRequest&) const = default;
};

struct CmMsg {
    std::string text; // at most 80 bytes on the wire
    bool operator==(const CmMsg&) const = default;
};

using Body = std::variant<CmPos, CmPosProps, CmRequest, CmMsg>;

struct Message {
    CmHeader header;
    Body body;
};

// FILETIME <-> Unix milliseconds.
constexpr std::uint64_t kFileTimeUnixEpoch = 116444736000000000ull;
inline std::uint64_t unixMillisToFileTime(std::int64_t ms) {
    return kFileTimeUnixEpoch + static_cast<std::uint64_t>(ms) * 10000ull;
}
// Any 64-bit value a peer sends (fuzz finding, docs/reliability.md): milliseconds first, then the epoch
// shift, so no signed overflow; the epoch is a whole number of milliseconds.
inline std::int64_t fileTimeToUnixMillis(std::uint64_t ft) {
    return static_cast<std::int64_t>(ft / 10000) - static_cast<std::int64_t>(kFileTimeUnixEpoch / 10000);
}

// Checksums over the message bytes after the WCrc field ([2, WLen)).
std::uint16_t crc16(ByteSpan data); // CRC-16/CCITT-FALSE: poly 0x1021, init 0xFFFF
std::uint16_t xor16(ByteSpan data); // XOR of little-endian 16-bit words, odd byte zero-padded
std::uint16_t checksum(Checksum mode, ByteSpan data);

// Encoders append one complete message (header + body, checksum filled in) to out.
void encodePos(Bytes& out, std::uint8_t who, std::uint8_t whose, const CmPos& p,
               Checksum cs = Checksum::None);
void encodePosProps(Bytes& out, std::uint8_t who, std::uint8_t whose, const std::vector<PosProp>& props,
                    Checksum cs = Checksum::None);
void encodeRequest(Bytes& out, std::uint8_t who, std::uint8_t whose, const CmRequest& r,
                   Checksum cs = Checksum::None);
void encodeMsg(Bytes& out, std::uint8_t who, std::uint8_t whose, std::string_view text,
               Checksum cs = Checksum::None);
void encodeMessage(Bytes& out, const Message& m, Checksum cs = Checksum::None);

// Position body alone (65 bytes), used by the ribbon store.
void encodePosBody(ByteWriter& w, const CmPos& p);
CmPos decodePosBody(ByteReader& r);

// One message from exactly its bytes.
Result<Message> decodeMessage(ByteSpan bytes, Checksum cs = Checksum::None);

struct DecodedDatagram {
    std::vector<Message> messages; // every message that decoded before the first error
    std::string reason;            // empty = whole datagram fine; else counter suffix (e.g. "bad_checksum")
    std::string error;             // human-readable
};
// Splits a datagram into messages. A bad message stops decoding (its length can no longer be trusted),
// but every good message before it is kept.
DecodedDatagram decodeDatagram(ByteSpan datagram, Checksum cs = Checksum::None,
                               std::size_t maxLen = kMaxDatagram);

} // namespace ocu::osyris
