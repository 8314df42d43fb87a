#include "protocols/jaus/JudpCodec.h"

#include <algorithm>
#include <cstdio>

namespace ocu::jaus {

std::string JausId::toString() const {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%u.%u.%u", unsigned(subsystem), unsigned(node), unsigned(component));
    return buf;
}

std::string rejectReason(const std::string& error) {
    auto pos = error.find(':');
    return pos == std::string::npos ? error : error.substr(0, pos);
}

void appendMessage(Bytes& out, const JudpHeader& h, ByteSpan payload) {
    ByteWriter w(out);
    w.u8(0); // message type normal, no header compression (we never send HC, jaus-wire.md §6.1)
    w.u16(std::uint16_t(kMessageOverhead + payload.size()));
    w.u8(h.props());
    w.u32(h.destination.value());
    w.u32(h.source.value());
    w.bytes(payload);
    w.u16(h.sequence);
}

Bytes encodeDatagram(const std::vector<JudpMessage>& messages) {
    Bytes out;
    out.push_back(kJudpVersion);
    for (auto& m : messages)
        appendMessage(out, m.header, m.payload);
    return out;
}

Bytes encodeDatagram(const JudpHeader& header, ByteSpan payload) {
    Bytes out;
    out.reserve(1 + kMessageOverhead + payload.size());
    out.push_back(kJudpVersion);
    appendMessage(out, header, payload);
    return out;
}

Result<JudpMessage> decodeMessage(ByteSpan data, std::size_t& consumed) {
    consumed = 0;
    if (data.size() < kMessageOverhead)
        return makeError("short: message needs 14 bytes, " + std::to_string(data.size()) + " left");
    const std::uint8_t typeHc = data[0];
    if (typeHc != 0) {
        // JTS tests HC in bits 0-1, JAUS++/Wireshark in bits 6-7 (jaus-wire.md §2.1): refuse both rather than
        // guess.
        if (typeHc & 0xC3)
            return makeError("header_compression: type/HC byte 0x" + std::to_string(typeHc) +
                             " requests header compression, which is not supported");
        return makeError("message_type: reserved message type " + std::to_string(typeHc & 0x3F));
    }
    ByteReader r(data);
    r.u8();
    const std::size_t size = r.u16();
    if (size < kMessageOverhead || size > data.size())
        return makeError("size: DataSize " + std::to_string(size) + " but " + std::to_string(data.size()) +
                         " bytes available");
    JudpMessage m;
    const std::uint8_t props = r.u8();
    m.header.priority = Priority(props & 0x03);
    m.header.broadcast = BroadcastFlag((props >> 2) & 0x03);
    m.header.ackNak = AckNak((props >> 4) & 0x03);
    m.header.dataFlags = DataFlags((props >> 6) & 0x03);
    m.header.destination = JausId::fromValue(r.u32());
    m.header.source = JausId::fromValue(r.u32());
    auto payload = r.bytes(size - kMessageOverhead);
    m.payload.assign(payload.begin(), payload.end());
    m.header.sequence = r.u16();
    if (m.header.broadcast == BroadcastFlag(3))
        return makeError("props: broadcast value 3 is reserved");
    consumed = size;
    return m;
}

Result<DecodedDatagram> decodeDatagram(ByteSpan d) {
    if (d.empty())
        return makeError("short: empty datagram");
    if (d[0] == 'J' && d.size() >= 8 && std::string(d.begin(), d.begin() + 8) == "JAUS01.0")
        return makeError("legacy_opc: JAUS01.0 (OPC 2.75 / RA 3.x) header is not AS5669A");
    if (d[0] == 0x01)
        return makeError("legacy_v1: AS5669 version 1 datagram is not supported");
    if (d[0] != kJudpVersion)
        return makeError("version: unknown JUDP version byte " + std::to_string(d[0]));
    if (d.size() < 1 + kMessageOverhead)
        return makeError("short: datagram of " + std::to_string(d.size()) + " bytes has no complete message");
    DecodedDatagram out;
    out.messages.reserve(1);
    std::size_t pos = 1;
    while (pos < d.size()) {
        std::size_t used = 0;
        auto m = decodeMessage(d.subspan(pos), used);
        if (!m) {
            if (out.messages.empty())
                return makeError(m.error());
            out.error = m.error();
            break;
        }
        out.messages.push_back(std::move(*m));
        pos += used;
    }
    return out;
}

JudpHeader makeAckHeader(const JudpHeader& req) {
    JudpHeader h;
    h.priority = req.priority;
    h.ackNak = AckNak::Ack;
    h.destination = req.source;
    h.source = req.destination;
    h.sequence = req.sequence;
    return h;
}

std::vector<JudpMessage> fragmentPayload(const JudpHeader& header, ByteSpan payload, std::size_t maxChunk) {
    std::vector<JudpMessage> out;
    if (maxChunk == 0)
        maxChunk = kMaxFragmentPayload;
    if (payload.size() <= maxChunk) {
        JudpMessage m{header, Bytes(payload.begin(), payload.end())};
        m.header.dataFlags = DataFlags::Single;
        out.push_back(std::move(m));
        return out;
    }
    std::uint16_t seq = header.sequence;
    for (std::size_t pos = 0; pos < payload.size(); pos += maxChunk) {
        const std::size_t n = std::min(maxChunk, payload.size() - pos);
        JudpMessage m{header, Bytes(payload.begin() + long(pos), payload.begin() + long(pos + n))};
        m.header.sequence = seq++;
        m.header.dataFlags = pos == 0                    ? DataFlags::First
                             : pos + n >= payload.size() ? DataFlags::Last
                                                         : DataFlags::Middle;
        out.push_back(std::move(m));
    }
    return out;
}

Result<std::optional<JudpMessage>> Reassembler::feed(JudpMessage msg, TimePoint now) {
    const std::uint32_t src = msg.header.source.value();
    switch (msg.header.dataFlags) {
    case DataFlags::Single:
        return std::optional<JudpMessage>(std::move(msg));
    case DataFlags::First: {
        if (msg.payload.size() < 2)
            return makeError("fragment_sequence: first fragment without a message ID");
        std::uint16_t next = std::uint16_t(msg.header.sequence + 1);
        if (auto old = m_sets.find({src, next}); old != m_sets.end())
            erase(old); // the same chain started again: the new first fragment replaces it
        makeRoomFor(src);
        m_sets[{src, next}] = Set{std::move(msg), next, now};
        ++m_perSource[src];
        return std::optional<JudpMessage>{};
    }
    case DataFlags::Middle:
    case DataFlags::Last:
        break;
    }
    auto it = m_sets.find({src, msg.header.sequence});
    if (it == m_sets.end())
        return makeError(
            "fragment_sequence: " + std::string(msg.header.dataFlags == DataFlags::Last ? "last" : "middle") +
            " fragment seq " + std::to_string(msg.header.sequence) + " from " + msg.header.source.toString() +
            " has no preceding fragment");
    Set set = std::move(it->second);
    erase(it);
    ByteSpan part(msg.payload);
    // JAUS++ repeats the message ID in every fragment (jaus-wire.md §2.4): strip it when it matches.
    if (part.size() >= 2 && part[0] == set.first.payload[0] && part[1] == set.first.payload[1])
        part = part.subspan(2);
    if (set.first.payload.size() + part.size() > m_opt.maxBytes)
        return makeError("fragment_size: reassembled message exceeds " + std::to_string(m_opt.maxBytes) +
                         " bytes");
    set.first.payload.insert(set.first.payload.end(), part.begin(), part.end());
    if (msg.header.dataFlags == DataFlags::Last) {
        set.first.header.dataFlags = DataFlags::Single;
        return std::optional<JudpMessage>(std::move(set.first));
    }
    std::uint16_t next = std::uint16_t(msg.header.sequence + 1);
    set.nextSeq = next;
    if (auto old = m_sets.find({src, next}); old != m_sets.end())
        erase(old); // another chain of this source already expects that number: the older loses
    m_sets[{src, next}] = std::move(set);
    ++m_perSource[src];
    return std::optional<JudpMessage>{};
}

std::size_t Reassembler::pending(std::uint32_t source) const {
    auto it = m_perSource.find(source);
    return it == m_perSource.end() ? 0 : it->second;
}

void Reassembler::erase(std::map<Key, Set>::iterator it) {
    auto n = m_perSource.find(it->first.first);
    if (n != m_perSource.end() && --n->second == 0)
        m_perSource.erase(n);
    m_sets.erase(it);
}

void Reassembler::evictOldestOf(std::uint32_t source) {
    // A source's sets are contiguous in the map (keyed by source first); at most maxSetsPerSource of them.
    auto oldest = m_sets.end();
    for (auto it = m_sets.lower_bound({source, 0}); it != m_sets.end() && it->first.first == source; ++it)
        if (oldest == m_sets.end() || it->second.started < oldest->second.started)
            oldest = it;
    if (oldest == m_sets.end())
        return;
    erase(oldest);
    ++m_evicted;
}

void Reassembler::makeRoomFor(std::uint32_t source) {
    const std::size_t perSource = std::max<std::size_t>(1, m_opt.maxSetsPerSource);
    while (pending(source) >= perSource)
        evictOldestOf(source); // a source at its own bound loses its own oldest set
    while (!m_sets.empty() && m_sets.size() >= std::max<std::size_t>(1, m_opt.maxSets)) {
        // Fair eviction: the source holding the most sets loses its oldest; on a tie the newcomer's own
        // sets go first, so nobody can push out another source's only set by holding as many.
        std::uint32_t victim = source;
        std::size_t most = pending(source);
        for (const auto& [s, n] : m_perSource)
            if (n > most) {
                victim = s;
                most = n;
            }
        if (most == 0) { // the newcomer holds nothing: the oldest set of the sources holding the most
            for (const auto& [s, n] : m_perSource)
                most = std::max(most, n);
            auto oldest = m_sets.end();
            for (auto it = m_sets.begin(); it != m_sets.end(); ++it)
                if (pending(it->first.first) == most &&
                    (oldest == m_sets.end() || it->second.started < oldest->second.started))
                    oldest = it;
            victim = oldest->first.first;
        }
        evictOldestOf(victim);
    }
}

std::size_t Reassembler::expire(TimePoint now) {
    std::size_t n = 0;
    for (auto it = m_sets.begin(); it != m_sets.end();) {
        if (now - it->second.started > m_opt.staleAfter) {
            auto stale = it++;
            erase(stale);
            ++n;
        } else {
            ++it;
        }
    }
    return n;
}

Result<std::vector<JudpMessage>> JtcpStreamDecoder::fail(std::vector<JudpMessage>& good, std::string error) {
    m_failed = true;
    m_error = std::move(error);
    m_buffer.clear();
    if (good.empty())
        return makeError(m_error);
    return std::move(good);
}

Result<std::vector<JudpMessage>> JtcpStreamDecoder::feed(ByteSpan data) {
    if (m_failed)
        return makeError("stream: stream already failed");
    m_buffer.insert(m_buffer.end(), data.begin(), data.end());
    std::size_t pos = 0;
    std::vector<JudpMessage> out;
    if (!m_versionSeen && !m_buffer.empty()) {
        if (m_buffer[0] != kJudpVersion)
            return fail(out,
                        "version: JTCP stream starts with 0x" + std::to_string(m_buffer[0]) + ", not 0x02");
        m_versionSeen = true;
        pos = 1;
    }
    while (m_buffer.size() - pos >= 3) {
        const std::size_t size = m_buffer[pos + 1] | (m_buffer[pos + 2] << 8);
        if (size < kMessageOverhead)
            return fail(out, "size: JTCP message DataSize " + std::to_string(size) + " below 14");
        if (m_buffer.size() - pos < size)
            break;
        std::size_t used = 0;
        auto m = decodeMessage(ByteSpan(m_buffer).subspan(pos, size), used);
        if (!m)
            return fail(out, m.error());
        out.push_back(std::move(*m));
        pos += size;
    }
    m_buffer.erase(m_buffer.begin(), m_buffer.begin() + long(pos));
    return out;
}

Bytes encodeJtcp(const JudpHeader& header, ByteSpan payload, bool firstOnStream) {
    Bytes out;
    if (firstOnStream)
        out.push_back(kJudpVersion);
    appendMessage(out, header, payload);
    return out;
}

} // namespace ocu::jaus
