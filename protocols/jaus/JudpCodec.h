#pragma once
// AS5669A JUDP/JTCP framing (jaus-wire.md §2): version byte 0x02, then general-transport-header messages
// [TypeHC u8][DataSize u16][Props u8][Dst u32][Src u32][Payload][Seq u16], all little-endian.
// Pure functions; no sockets here.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "protocols/common/Bytes.h"
#include "protocols/common/Clock.h"
#include "protocols/common/Result.h"

namespace ocu::jaus {

// JAUS ID subsystem.node.component; on the wire a u32 = ss<<16 | node<<8 | comp (little-endian).
struct JausId {
    std::uint16_t subsystem = 0;
    std::uint8_t node = 0;
    std::uint8_t component = 0;

    constexpr std::uint32_t value() const {
        return (std::uint32_t(subsystem) << 16) | (std::uint32_t(node) << 8) | component;
    }
    static constexpr JausId fromValue(std::uint32_t v) {
        return JausId{std::uint16_t(v >> 16), std::uint8_t(v >> 8), std::uint8_t(v)};
    }
    // 65535 / 255 are wildcards (AS5669A); 0 subsystem means "this subsystem" (AEP-4818 §4.6.1).
    constexpr bool isBroadcast() const { return subsystem == 0xFFFF || node == 0xFF || component == 0xFF; }
    // True when a message addressed to this (possibly wildcard) destination reaches id.
    constexpr bool matches(const JausId& id) const {
        return (subsystem == 0xFFFF || subsystem == 0 || subsystem == id.subsystem) &&
               (node == 0xFF || node == id.node) && (component == 0xFF || component == id.component);
    }
    std::string toString() const;
    friend constexpr bool operator==(const JausId&, const JausId&) = default;
    friend constexpr bool operator<(const JausId& a, const JausId& b) { return a.value() < b.value(); }
};
inline constexpr JausId kBroadcastAll{0xFFFF, 0xFF, 0xFF};

inline constexpr std::uint8_t kJudpVersion = 0x02;
inline constexpr std::size_t kMessageOverhead = 14;      // DataSize of a payload-less message
inline constexpr std::size_t kMaxFragmentPayload = 4079; // JTS MTU_Size default and maximum

enum class Priority : std::uint8_t { Low = 0, Standard = 1, High = 2, Safety = 3 };
enum class BroadcastFlag : std::uint8_t { None = 0, Local = 1, Global = 2 };
enum class AckNak : std::uint8_t { None = 0, Request = 1, Nak = 2, Ack = 3 };
enum class DataFlags : std::uint8_t { Single = 0, First = 1, Middle = 2, Last = 3 };

struct JudpHeader {
    Priority priority = Priority::Standard;
    BroadcastFlag broadcast = BroadcastFlag::None;
    AckNak ackNak = AckNak::None;
    DataFlags dataFlags = DataFlags::Single;
    JausId destination;
    JausId source;
    std::uint16_t sequence = 0;

    std::uint8_t props() const {
        return std::uint8_t(std::uint8_t(priority) | (std::uint8_t(broadcast) << 2) |
                            (std::uint8_t(ackNak) << 4) | (std::uint8_t(dataFlags) << 6));
    }
};

// One transport message. payload = message ID (u16) + body for single/first fragments.
struct JudpMessage {
    JudpHeader header;
    Bytes payload;
    // Message ID of a single/first message; 0 when the payload is too short.
    std::uint16_t messageId() const {
        return payload.size() >= 2 ? std::uint16_t(payload[0] | (payload[1] << 8)) : 0;
    }
};

// Error strings are "<reason>: <detail>"; reason is a short token used for the counter rx.rejected.<reason>.
std::string rejectReason(const std::string& error);

// Appends one message (no version byte) to out.
void appendMessage(Bytes& out, const JudpHeader& header, ByteSpan payload);
// Version byte + messages.
Bytes encodeDatagram(const std::vector<JudpMessage>& messages);
Bytes encodeDatagram(const JudpHeader& header, ByteSpan payload);

// A decoded datagram keeps every message that parsed before a bad one ("never lose what was good");
// error names the problem with the rest (empty when the whole datagram was fine).
struct DecodedDatagram {
    std::vector<JudpMessage> messages;
    std::string error;
};
// Fails (no messages at all) for short, legacy (AS5669 v1, JAUS01.0) and unknown-version datagrams.
Result<DecodedDatagram> decodeDatagram(ByteSpan datagram);
// Decodes exactly one message starting at data[0] (no version byte); consumed = its length.
Result<JudpMessage> decodeMessage(ByteSpan data, std::size_t& consumed);

// An ACK for a message that asked for one (jaus-wire.md §2.2): 14 bytes, swapped IDs, same sequence number.
JudpHeader makeAckHeader(const JudpHeader& request);

// Splits a payload the JTS/FKIE way: message ID only in the first fragment, ≤ maxChunk bytes each,
// consecutive sequence numbers starting at header.sequence. Single message when it fits.
std::vector<JudpMessage> fragmentPayload(const JudpHeader& header, ByteSpan payload,
                                         std::size_t maxChunk = kMaxFragmentPayload);

// Reassembles First/Middle/Last sets by (source, sequence chain). Accepts the JAUS++ variant that repeats
// the message ID in every fragment. Stale sets are dropped after a timeout (JTS OldMsgTimeout = 3 s).
// Bounded per peer and in total (docs/reliability.md "Bounds"): a source holds at most
// maxSetsPerSource partial sets (a new one evicts that source's own oldest), and when all sources together
// hold maxSets, a new set evicts the oldest set of the source holding the most (ties: the newcomer's own
// first, then the oldest set), so a flooding peer loses its own sets before anybody else's.
class Reassembler {
public:
    struct Options {
        Duration staleAfter = std::chrono::seconds(3);
        std::size_t maxSets = 50;         // partial sets of all sources together
        std::size_t maxSetsPerSource = 8; // partial sets of one source (JAUS ID)
        std::size_t maxBytes = 1 << 20;   // one reassembled message
    };
    Reassembler() : Reassembler(Options{}) {}
    explicit Reassembler(Options o) : m_opt(o) {}

    // Single messages pass through. Returns the complete message when one finished; an empty optional while a
    // set is in progress; an error for a bad fragment sequence.
    Result<std::optional<JudpMessage>> feed(JudpMessage msg, TimePoint now);
    // Drops sets older than staleAfter; returns how many were dropped.
    std::size_t expire(TimePoint now);
    std::size_t pending() const { return m_sets.size(); }
    std::size_t pending(std::uint32_t source) const;
    // Partial sets dropped to make room for a new one (the per-source or the total bound).
    std::uint64_t evicted() const { return m_evicted; }

private:
    struct Set {
        JudpMessage first;
        std::uint16_t nextSeq = 0;
        TimePoint started;
    };
    using Key = std::pair<std::uint32_t, std::uint16_t>; // (source, next expected sequence)
    void makeRoomFor(std::uint32_t source);
    void evictOldestOf(std::uint32_t source);
    void erase(std::map<Key, Set>::iterator it);
    Options m_opt;
    std::map<Key, Set> m_sets;
    std::map<std::uint32_t, std::size_t> m_perSource; // sets per source (no entry for none)
    std::uint64_t m_evicted = 0;
};

// JTCP: the 0x02 version byte once per stream, then messages back to back (jaus-wire.md §2.1).
class JtcpStreamDecoder {
public:
    // Appends bytes; returns the messages completed so far, those before a bad one in the same read included
    // (never lose what was good; a fuzz finding, docs/reliability.md). After a bad message failed() is true
    // and error() says why: the stream is unusable (the caller closes the connection), since message
    // boundaries are lost. feed() fails when it completed no message before the error, and on every call
    // after it.
    Result<std::vector<JudpMessage>> feed(ByteSpan data);
    bool failed() const { return m_failed; }
    const std::string& error() const { return m_error; }

private:
    Result<std::vector<JudpMessage>> fail(std::vector<JudpMessage>& good, std::string error);
    Bytes m_buffer;
    std::string m_error;
    bool m_versionSeen = false;
    bool m_failed = false;
};
// The first write on a JTCP stream carries the version byte; later ones must not.
Bytes encodeJtcp(const JudpHeader& header, ByteSpan payload, bool firstOnStream);

} // namespace ocu::jaus
