#include "protocols/osyris/OsyrisCodec.h"

#include <cstring>

namespace ocu::osyris {

const char* nameFor(RequestType t) {
    switch (t) {
    case RequestType::Nak:
        return "NAK";
    case RequestType::Ncf:
        return "NCF";
    case RequestType::All:
        return "ALL";
    case RequestType::Ping:
        return "PING";
    case RequestType::Pong:
        return "PONG";
    case RequestType::Alive:
        return "ALIVE";
    }
    return "?";
}

const char* nameFor(Checksum c) {
    switch (c) {
    case Checksum::None:
        return "none";
    case Checksum::Xor:
        return "xor";
    case Checksum::Crc16:
        return "crc16";
    }
    return "?";
}

float PosProp::asFloat() const {
    float f;
    std::memcpy(&f, &value, 4);
    return f;
}

PosProp PosProp::fromFloat(std::uint32_t id, float v) {
    PosProp p;
    std::memcpy(&p.value, &v, 4);
    p.id = id;
    return p;
}

namespace {
struct Crc16Table {
    std::uint16_t t[256];
    constexpr Crc16Table() : t{} {
        for (int i = 0; i < 256; ++i) {
            std::uint16_t c = static_cast<std::uint16_t>(i << 8);
            for (int k = 0; k < 8; ++k)
                c = (c & 0x8000) ? static_cast<std::uint16_t>((c << 1) ^ 0x1021)
                                 : static_cast<std::uint16_t>(c << 1);
            t[i] = c;
        }
    }
};
constexpr Crc16Table kCrc16;
} // namespace

std::uint16_t crc16(ByteSpan data) {
    std::uint16_t crc = 0xFFFF;
    for (std::uint8_t b : data)
        crc = static_cast<std::uint16_t>((crc << 8) ^ kCrc16.t[((crc >> 8) ^ b) & 0xFF]);
    return crc;
}

std::uint16_t xor16(ByteSpan data) {
    std::uint16_t x = 0;
    for (std::size_t i = 0; i < data.size(); i += 2) {
        std::uint16_t w = data[i];
        if (i + 1 < data.size())
            w |= static_cast<std::uint16_t>(data[i + 1]) << 8;
        x ^= w;
    }
    return x;
}

std::uint16_t checksum(Checksum mode, ByteSpan data) {
    switch (mode) {
    case Checksum::None:
        return 0;
    case Checksum::Xor:
        return xor16(data);
    case Checksum::Crc16:
        return crc16(data);
    }
    return 0;
}

namespace {

std::size_t beginMessage(Bytes& out, std::uint8_t who, std::uint8_t whose, std::uint16_t type) {
    std::size_t start = out.size();
    ByteWriter w(out);
    w.u16(0); // WCrc, patched in finish
    w.u16(0); // WLen, patched in finish
    w.u16(type);
    w.u8(who);
    w.u8(whose);
    return start;
}

void finishMessage(Bytes& out, std::size_t start, Checksum cs) {
    std::size_t len = out.size() - start;
    ByteWriter w(out);
    w.patchU16(start + 2, static_cast<std::uint16_t>(len));
    ByteSpan covered(out.data() + start + 2, len - 2);
    w.patchU16(start, checksum(cs, covered));
}

} // namespace

void encodePosBody(ByteWriter& w, const CmPos& p) {
    w.u32(p.numPos);
    w.f32(p.x);
    w.f32(p.y);
    w.f32(p.z);
    w.f32(p.yaw);
    w.f32(p.pitch);
    w.f32(p.roll);
    w.u32(p.flags);
    w.f32(p.dx);
    w.f32(p.dy);
    w.f32(p.dz);
    w.f64(p.speed);
    w.u64(p.time);
    w.u32(p.slot);
    w.u8(p.epoch);
}

CmPos decodePosBody(ByteReader& r) {
    CmPos p;
    p.numPos = r.u32();
    p.x = r.f32();
    p.y = r.f32();
    p.z = r.f32();
    p.yaw = r.f32();
    p.pitch = r.f32();
    p.roll = r.f32();
    p.flags = r.u32();
    p.dx = r.f32();
    p.dy = r.f32();
    p.dz = r.f32();
    p.speed = r.f64();
    p.time = r.u64();
    p.slot = r.u32();
    p.epoch = r.u8();
    return p;
}

void encodePos(Bytes& out, std::uint8_t who, std::uint8_t whose, const CmPos& p, Checksum cs) {
    std::size_t s = beginMessage(out, who, whose, static_cast<std::uint16_t>(MsgType::Pos));
    ByteWriter w(out);
    encodePosBody(w, p);
    finishMessage(out, s, cs);
}

void encodePosProps(Bytes& out, std::uint8_t who, std::uint8_t whose, const std::vector<PosProp>& props,
                    Checksum cs) {
    std::size_t s = beginMessage(out, who, whose, static_cast<std::uint16_t>(MsgType::PosProps));
    ByteWriter w(out);
    for (const auto& p : props) {
        w.u32(p.value);
        w.u32(p.id);
    }
    finishMessage(out, s, cs);
}

void encodeRequest(Bytes& out, std::uint8_t who, std::uint8_t whose, const CmRequest& r, Checksum cs) {
    std::size_t s = beginMessage(out, who, whose, static_cast<std::uint16_t>(MsgType::Request));
    ByteWriter w(out);
    w.u8(static_cast<std::uint8_t>(r.type));
    if (r.type == RequestType::Ping || r.type == RequestType::Pong) {
        w.f32(r.x);
        w.f32(r.y);
    } else {
        w.u32(r.from);
        w.u32(r.to);
    }
    finishMessage(out, s, cs);
}

void encodeMsg(Bytes& out, std::uint8_t who, std::uint8_t whose, std::string_view text, Checksum cs) {
    std::size_t s = beginMessage(out, who, whose, static_cast<std::uint16_t>(MsgType::Msg));
    ByteWriter w(out);
    // Keep a terminating NUL when possible so C peers reading szMsg as a string stay in bounds.
    w.fixedString(text.substr(0, kMsgTextSize - 1), kMsgTextSize);
    finishMessage(out, s, cs);
}

void encodeMessage(Bytes& out, const Message& m, Checksum cs) {
    const auto& h = m.header;
    std::visit(
        [&](const auto& b) {
            using T = std::decay_t<decltype(b)>;
            if constexpr (std::is_same_v<T, CmPos>)
                encodePos(out, h.who, h.whose, b, cs);
            else if constexpr (std::is_same_v<T, CmPosProps>)
                encodePosProps(out, h.who, h.whose, b.props, cs);
            else if constexpr (std::is_same_v<T, CmRequest>)
                encodeRequest(out, h.who, h.whose, b, cs);
            else
                encodeMsg(out, h.who, h.whose, b.text, cs);
        },
        m.body);
}

namespace {

struct Failure {
    const char* reason;
    std::string text;
};

// The PosProp table filling the rest of a message (§6).
CmPosProps readPropTable(ByteReader& r) {
    CmPosProps pp;
    while (r.remaining() >= kPosPropSize) {
        PosProp p;
        p.value = r.u32();
        p.id = r.u32();
        pp.props.push_back(p);
    }
    return pp;
}

// A CmRequest body of `body` bytes after its length was checked, in each of its readings on the wire (§6).
bool decodeRequest(ByteReader& r, std::size_t body, CmRequest& q, Failure& f) {
    std::uint8_t t = r.u8();
    if (t > static_cast<std::uint8_t>(RequestType::Alive)) {
        f = {"bad_request_type", "CmRequest bType " + std::to_string(t)};
        return false;
    }
    q.type = static_cast<RequestType>(t);
    bool xy = q.type == RequestType::Ping || q.type == RequestType::Pong;
    if (body == 1) {
        // Only ALL, PING and PONG make sense without fields (other reading: no fields when unused).
        if (q.type != RequestType::All && !xy) {
            f = {"bad_length", std::string("CmRequest ") + nameFor(q.type) + " without From/To"};
            return false;
        }
        if (q.type == RequestType::All)
            q.to = kSlotLast;
    } else if (body == kRequestBodySize) {
        if (xy) {
            q.x = r.f32();
            q.y = r.f32();
        } else {
            q.from = r.u32();
            q.to = r.u32();
        }
    } else {
        // Other reading: every field on the wire (From, To, X, Y).
        q.from = r.u32();
        q.to = r.u32();
        q.x = r.f32();
        q.y = r.f32();
    }
    return true;
}

// Decodes one message occupying exactly bytes; appends one or two messages (a CmPos with an appended
// PosProp table yields CmPos + CmPosProps). Returns false with reason/text on error.
bool decodeOne(ByteSpan bytes, Checksum cs, std::vector<Message>& out, Failure& f) {
    ByteReader r(bytes);
    CmHeader h;
    h.crc = r.u16();
    h.len = r.u16();
    h.type = r.u16();
    h.who = r.u8();
    h.whose = r.u8();
    if (!r.ok()) {
        f = {"truncated", "shorter than the 8-byte CmHeader"};
        return false;
    }
    if (h.len != bytes.size()) {
        f = {"bad_length",
             "WLen " + std::to_string(h.len) + " != message size " + std::to_string(bytes.size())};
        return false;
    }
    if (cs != Checksum::None) {
        std::uint16_t want = checksum(cs, bytes.subspan(2));
        if (want != h.crc) {
            f = {"bad_checksum", std::string(nameFor(cs)) + " checksum mismatch"};
            return false;
        }
    }
    if (h.who >= kIdxNobody) {
        f = {"bad_index", "IdxWho " + std::to_string(h.who) + " is reserved"};
        return false;
    }
    std::size_t body = bytes.size() - kHeaderSize;
    Message m;
    m.header = h;
    switch (h.type) {
    case static_cast<std::uint16_t>(MsgType::Pos): {
        if (body < kPosBodySize || (body - kPosBodySize) % kPosPropSize != 0) {
            f = {"bad_length", "CmPos body of " + std::to_string(body) + " bytes"};
            return false;
        }
        if (h.whose >= kIdxNobody) {
            f = {"bad_index", "CmPos for reserved IdxWhose " + std::to_string(h.whose)};
            return false;
        }
        m.body = decodePosBody(r);
        out.push_back(std::move(m));
        if (body > kPosBodySize) {
            // Other reading of §6: the PosProp table appended inside the CmPos message.
            Message pm;
            pm.header = h;
            pm.header.type = static_cast<std::uint16_t>(MsgType::PosProps);
            pm.body = readPropTable(r);
            out.push_back(std::move(pm));
        }
        return true;
    }
    case static_cast<std::uint16_t>(MsgType::PosProps): {
        if (body % kPosPropSize != 0) {
            f = {"bad_length",
                 "CmPosProps body of " + std::to_string(body) + " bytes is not a multiple of 8"};
            return false;
        }
        if (h.whose >= kIdxNobody) {
            f = {"bad_index", "CmPosProps for reserved IdxWhose " + std::to_string(h.whose)};
            return false;
        }
        m.body = readPropTable(r);
        out.push_back(std::move(m));
        return true;
    }
    case static_cast<std::uint16_t>(MsgType::Request): {
        if (body != kRequestBodySize && body != 17 && body != 1) {
            f = {"bad_length", "CmRequest body of " + std::to_string(body) + " bytes"};
            return false;
        }
        CmRequest q;
        if (!decodeRequest(r, body, q, f))
            return false;
        m.body = q;
        out.push_back(std::move(m));
        return true;
    }
    case static_cast<std::uint16_t>(MsgType::Msg):
    case kTypeMsgAlt: {
        if (body == 0 || body > kMsgTextSize) {
            f = {"bad_length", "CmMsg body of " + std::to_string(body) + " bytes"};
            return false;
        }
        m.header.type = static_cast<std::uint16_t>(MsgType::Msg);
        m.body = CmMsg{r.fixedString(body)};
        out.push_back(std::move(m));
        return true;
    }
    default:
        f = {"unknown_type", "WType " + std::to_string(h.type)};
        return false;
    }
}

} // namespace

Result<Message> decodeMessage(ByteSpan bytes, Checksum cs) {
    std::vector<Message> out;
    Failure f;
    if (!decodeOne(bytes, cs, out, f))
        return makeError(std::string(f.reason) + ": " + f.text);
    return std::move(out.front());
}

DecodedDatagram decodeDatagram(ByteSpan d, Checksum cs, std::size_t maxLen) {
    DecodedDatagram res;
    if (d.size() > maxLen) {
        res.reason = "oversized";
        res.error =
            "datagram of " + std::to_string(d.size()) + " bytes exceeds MaxLen " + std::to_string(maxLen);
        return res;
    }
    if (d.empty()) {
        res.reason = "truncated";
        res.error = "empty datagram";
        return res;
    }
    std::size_t pos = 0;
    while (pos < d.size()) {
        std::size_t left = d.size() - pos;
        if (left < kHeaderSize) {
            res.reason = "truncated";
            res.error = std::to_string(left) + " trailing bytes at offset " + std::to_string(pos);
            return res;
        }
        std::size_t len = static_cast<std::size_t>(d[pos + 2]) | (static_cast<std::size_t>(d[pos + 3]) << 8);
        if (len < kHeaderSize) {
            res.reason = "bad_length";
            res.error = "WLen " + std::to_string(len) + " at offset " + std::to_string(pos);
            return res;
        }
        if (len > left) {
            res.reason = "truncated";
            res.error =
                "WLen " + std::to_string(len) + " exceeds the " + std::to_string(left) + " bytes left";
            return res;
        }
        Failure f;
        if (!decodeOne(d.subspan(pos, len), cs, res.messages, f)) {
            res.reason = f.reason;
            res.error = f.text + " (offset " + std::to_string(pos) + ")";
            return res;
        }
        pos += len;
    }
    return res;
}

} // namespace ocu::osyris
