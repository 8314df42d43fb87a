// Writes the binary seed corpora of the fuzz harnesses (tests/fuzz/corpus/<harness>/) from the test vectors:
// the JUDP byte vectors of shared/research/jaus-wire.md §4-§5 (captured and computed), messages made by the
// project's own encoders (fragments, every OSYRIS message type and checksum), and OSYRIS station sessions
// (late join, positions with gaps, NAK/NCF/ALL/ALIVE/PING, absurd values of a hostile station).
// Usage: fuzz_make_seeds <corpus dir>. Text corpora (ISO frames, OSM, site configs, headless commands) are
// copied from the tests' data by scripts/fuzz.sh --seed.
#include "protocols/jaus/JudpCodec.h"
#include "protocols/jaus/Messages.h"
#include "protocols/osyris/OsyrisCodec.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

using namespace ocu;
namespace fs = std::filesystem;

namespace {

fs::path g_root;

Bytes hex(const std::string& s) {
    Bytes b;
    std::string digits;
    for (char c : s)
        if (std::isxdigit(static_cast<unsigned char>(c)))
            digits += c;
    for (std::size_t i = 0; i + 1 < digits.size(); i += 2)
        b.push_back(std::uint8_t(std::stoul(digits.substr(i, 2), nullptr, 16)));
    return b;
}

void write(const std::string& harness, const std::string& name, const Bytes& data) {
    fs::path dir = g_root / harness;
    fs::create_directories(dir);
    std::ofstream out(dir / name, std::ios::binary);
    out.write(reinterpret_cast<const char*>(data.data()), std::streamsize(data.size()));
}

// jaus-wire.md §4 (JTS capture, 22 packets) and §5 (C1-C9 captured, K1-K24 computed).
const std::vector<std::pair<std::string, std::string>> kJudpVectors = {
    {"c1_query_identification", "0200110009ffffffffc8409600002b04ed0d"},
    {"c2_request_control", "02001100190a017e0014017e000d00c80100"},
    {"c3_ack", "02000e003114017e000a017e000100"},
    {"c4_confirm_control", "020011000114017e000a017e000f00000100"},
    {"c5_query_status", "02001000010a017e0014017e0002200200"},
    {"c6_report_status", "020015000114017e000a017e00024002000000000200"},
    {"c7_resume", "02001000010a017e0014017e0004000300"},
    {"c8_set_emergency", "02001200010a017e0014017e00060000000500"},
    {"c8_clear_emergency", "02001200010a017e0014017e00070000000700"},
    {"c9_reject_control", "020011000114017e000a017e001000000600"},
    {"k1_query_heartbeat", "0200100001c7017e000101020002220000"},
    {"k3_heartbeat_broadcast", "0200100009ffffffffc7017e0002420000"},
    {"k4_set_authority", "0200110001c7017e00010102000100640000"},
    {"k5_shutdown", "0200100001c7017e000101020002000000"},
    {"k6_create_event", "02001c0001c7017e0001010200f00101005802040000000224ff010000"},
    {"k7_create_event", "02001a0001c7017e0001010200f001020100000200000002200000"},
    {"k8_confirm_event", "020014000101010200c7017e00f301010558020000"},
    {"k9_reject_event", "020013000101010200c7017e00f4010101050000"},
    {"k10_event", "02001d000101010200c7017e00f141050007000000024001000000000000"},
    {"k11_cancel_event", "0200120001c7017e0001010200f20103050000"},
    {"k12_set_wrench", "0200160001c7017e000101020005042100ffbf00600000"},
    {"k14_query_wrench", "0200120001c7017e00010102000524ff0f0000"},
    {"k15_report_wrench", "020016000101010200c7017e0005442100ffbf00600000"},
    {"k16_set_velocity", "0200180001c7017e00010102001504210096809680c8800000"},
    {"k17_query_global_pose", "0200120001c7017e00010102000224ff010000"},
    {"k18_report_global_pose", "020020000101010200c7017e0002444700f13376c47a5e3b8846dcd83bbea80000"},
    {"k19_report_local_pose", "02001c000101010200c7017e0003444300cd7003805eeffe7f00400000"},
    {"k21_report_velocity_state", "020018000101010200c7017e000444410096809680c8800000"},
    {"k22_query_platform_specs", "0200100001c7017e000101020002250000"},
    {"k23_report_platform_specs",
     "020027000101010200c7017e00024500031f05d70307b005d802c428000007546573745547560000"},
    {"k24_register_services",
     "02002e000101017e00c7017e00000b011a75726e3a6a6175733a6a73733a636f72653a4c6976656e65737301010000"},
};

void jausSeeds() {
    using namespace ocu::jaus;
    Bytes stream{kJudpVersion};
    for (const auto& [name, h] : kJudpVectors) {
        Bytes d = hex(h);
        write("judp_datagram", name, d);
        stream.insert(stream.end(), d.begin() + 1, d.end());
        // jaus_messages: a selector byte, then the payload (ID + body) dispatched by its own ID.
        ByteSpan msgBytes(d);
        std::size_t used = 0;
        auto m = decodeMessage(msgBytes.subspan(1), used);
        if (m) {
            Bytes sel{0};
            sel.insert(sel.end(), m->payload.begin(), m->payload.end());
            write("jaus_messages", name, sel);
        }
    }
    write("jtcp_stream", "all_vectors", stream);
    write("jtcp_stream", "two_messages", Bytes(stream.begin(), stream.begin() + 1 + 18 + 15));

    // Fragments (JTS/FKIE style and the JAUS++ variant), several messages per datagram.
    JudpHeader h;
    h.source = JausId{126, 1, 199};
    h.destination = JausId{2, 1, 1};
    h.sequence = 40;
    Bytes big = encode(ReportIdentification{});
    big.resize(300, 0x41);
    auto frags = fragmentPayload(h, ByteSpan(big), 100);
    write("judp_datagram", "fragments_one_datagram", encodeDatagram(frags));
    Bytes tcp{kJudpVersion};
    for (auto& f : frags)
        appendMessage(tcp, f.header, ByteSpan(f.payload));
    write("jtcp_stream", "fragments", tcp);
    std::vector<JudpMessage> several;
    JudpHeader a = h;
    several.push_back({a, encodeU8(msg::RequestControl, 200)});
    a.sequence++;
    several.push_back({a, encodeEmpty(msg::QueryStatus)});
    a.ackNak = AckNak::Request;
    a.sequence++;
    several.push_back({a, encodeQueryPv16(msg::QueryGlobalPose, 0x1FF)});
    write("judp_datagram", "three_messages", encodeDatagram(several));

    // Every decoder of jaus_messages once by selector (the harness's table order), with an empty body and a
    // body of 0xFF.
    for (int sel = 0; sel < 48; ++sel) {
        write("jaus_messages", "selector_" + std::to_string(sel) + "_short", Bytes{std::uint8_t(sel), 0x01});
        Bytes ff(24, 0xFF);
        ff[0] = std::uint8_t(sel);
        write("jaus_messages", "selector_" + std::to_string(sel) + "_ff", ff);
    }
}

osyris::CmPos pos(std::uint32_t slot, float x, float y, float width = 2.1f) {
    osyris::CmPos p;
    p.numPos = slot;
    p.slot = slot;
    p.x = x;
    p.y = y;
    p.z = 400;
    p.yaw = 0.5f;
    p.flags = osyris::kPosValid | osyris::kPosForward | osyris::kPosVibrating | osyris::kPosAccuracyHigh;
    p.dx = width;
    p.speed = 1.2;
    p.time = osyris::unixMillisToFileTime(1700000000000 + slot * 100);
    return p;
}

// Steps of the osyris_station harness: [op][len u16][bytes].
void step(Bytes& s, std::uint8_t op, const Bytes& body = {}) {
    s.push_back(op);
    s.push_back(std::uint8_t(body.size()));
    s.push_back(std::uint8_t(body.size() >> 8));
    s.insert(s.end(), body.begin(), body.end());
}

void osyrisSeeds() {
    using namespace ocu::osyris;
    const Checksum modes[] = {Checksum::None, Checksum::Xor, Checksum::Crc16};
    for (Checksum cs : modes) {
        std::string suffix = std::string("_") + nameFor(cs);
        Bytes b;
        encodePos(b, 7, 7, pos(3, 10, 20), cs);
        write("osyris_codec", "pos" + suffix, b);
        encodePosProps(b, 7, 7, {PosProp::fromFloat(0x11, 1.0f), PosProp{0xAABBCCDD, 0x22}}, cs);
        write("osyris_codec", "pos_props" + suffix, b);
        for (RequestType t : {RequestType::Nak, RequestType::Ncf, RequestType::All, RequestType::Ping,
                              RequestType::Pong, RequestType::Alive}) {
            Bytes r;
            encodeRequest(r, 3, 7, {t, 10, 20, 1.5f, -2.5f}, cs);
            write("osyris_codec", std::string("request_") + nameFor(t) + suffix, r);
        }
        Bytes m;
        encodeMsg(m, 5, kIdxAll, "STOP", cs);
        write("osyris_codec", "msg" + suffix, m);
    }

    // Station sessions. op % 5: 0 receive, 1 receive + Beat, 2 Beat, 3 pause (op >> 2 Beats), 4 ping.
    Bytes s;
    Bytes d;
    encodeRequest(d, 7, 7, {RequestType::Alive, 0, 4, 0, 0});
    step(s, 1, d);
    for (std::uint32_t slot : {0u, 1u, 2u, 5u, 6u}) { // 3 and 4 lost: the station NAKs them
        d.clear();
        encodePos(d, 7, 7, pos(slot, 1.0f * slot, 2));
        step(s, 1, d);
    }
    step(s, 3 + 4 * 5);
    d.clear();
    encodeRequest(d, 8, 7, {RequestType::Ncf, 3, 4, 0, 0});
    step(s, 0, d);
    d.clear();
    encodePos(d, 8, 7, pos(3, 3, 2));
    encodePos(d, 8, 7, pos(4, 4, 2));
    step(s, 1, d);
    d.clear();
    encodeRequest(d, 9, 7, {RequestType::Nak, 0, 6, 0, 0});
    encodeRequest(d, 9, 200, {RequestType::All, 0, 0, 0, 0});
    encodeRequest(d, 9, 200, {RequestType::Ping, 0, 0, 1, 2});
    step(s, 1, d);
    step(s, 4, Bytes{7});
    d.clear();
    encodeRequest(d, 7, 200, {RequestType::Pong, 0, 0, 1, 2});
    encodeMsg(d, 7, kIdxAll, "hello");
    step(s, 1, d);
    step(s, 2);
    write("osyris_station", "late_join_gap_repair", s);

    // Hostile inputs: a huge drum, NaN, far away, a phantom ALIVE range, a flood of ALL.
    s.clear();
    d.clear();
    encodePos(d, 9, 9, pos(0, 1, 1, 1e6f));
    step(s, 1, d);
    d.clear();
    encodePos(d, 9, 9, pos(1, std::numeric_limits<float>::quiet_NaN(), 1));
    encodePos(d, 9, 9, pos(2, 1e30f, 1));
    step(s, 1, d);
    d.clear();
    encodeRequest(d, 10, 10, {RequestType::Alive, 0, 0xFFFFFFFEu, 0, 0});
    step(s, 1, d);
    d.clear();
    for (int i = 0; i < 16; ++i)
        encodeRequest(d, 11, 9, {RequestType::All, 0, 0, 0, 0});
    step(s, 1, d);
    step(s, 3 + 4 * 40);
    write("osyris_station", "hostile", s);

    // A roller driving over the same lane back and forth (pass counts).
    s.clear();
    for (std::uint32_t slot = 0; slot < 40; ++slot) {
        d.clear();
        float x = float(slot < 20 ? slot : 40 - slot);
        encodePos(d, 12, 12, pos(slot, x, 5));
        step(s, slot % 4 == 0 ? 1 : 0, d);
    }
    step(s, 2);
    write("osyris_station", "passes", s);
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s <corpus dir>\n", argv[0]);
        return 2;
    }
    g_root = argv[1];
    jausSeeds();
    osyrisSeeds();
    return 0;
}
