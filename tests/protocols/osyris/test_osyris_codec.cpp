// Codec vectors computed by hand from seed 004 §6 tables (1-byte packing, little-endian).
#include "protocols/osyris/OsyrisCodec.h"

#include <QtTest>

#include <random>

using namespace ocu;
using namespace ocu::osyris;

namespace {

Bytes hex(const char* s) {
    Bytes b;
    std::string h;
    for (const char* p = s; *p; ++p)
        if (std::isxdigit(static_cast<unsigned char>(*p)))
            h.push_back(*p);
    for (std::size_t i = 0; i + 1 < h.size(); i += 2)
        b.push_back(static_cast<std::uint8_t>(std::stoi(h.substr(i, 2), nullptr, 16)));
    return b;
}

CmPos samplePos() {
    CmPos p;
    p.numPos = 0x01020304;
    p.x = 1.0f;
    p.y = -2.0f;
    p.z = 0.5f;
    p.yaw = 0;
    p.pitch = 0;
    p.roll = 0;
    p.flags = kPosValid | kPosForward | kPosVibrating | kPosAccuracyMed | kPosAccuracyHigh; // 0x80000682
    p.dx = 2.0f;
    p.speed = 1.5;
    p.time = 0x0102030405060708ull;
    p.slot = 7;
    p.epoch = 1;
    return p;
}

} // namespace

class TestOsyrisCodec : public QObject {
    Q_OBJECT
private slots:
    void cmPosVector() {
        Bytes b;
        encodePos(b, 1, 2, samplePos());
        Bytes want = hex("0000 4900 0100 01 02"       // WCrc 0, WLen 73, WType 1, IdxWho 1, IdxWhose 2
                         "04030201"                   // dwNumPos
                         "0000803F 000000C0 0000003F" // x 1.0, y -2.0, z 0.5
                         "00000000 00000000 00000000" // yaw pitch roll
                         "82060080"                   // flags 0x80000682
                         "00000040 00000000 00000000" // dx 2.0 dy dz
                         "000000000000F83F"           // speed 1.5 (double)
                         "0807060504030201"           // FILETIME
                         "07000000"                   // slot 7
                         "01");                       // epoch
        QCOMPARE(b.size(), kPosSize);
        QCOMPARE(b, want);
        auto m = decodeMessage(b);
        QVERIFY2(m.ok(), m.ok() ? "" : m.error().c_str());
        QCOMPARE(m->header.who, std::uint8_t(1));
        QCOMPARE(m->header.whose, std::uint8_t(2));
        QVERIFY(std::get<CmPos>(m->body) == samplePos());
        Bytes again;
        encodeMessage(again, *m);
        QCOMPARE(again, b);
    }
    void everyFlagRoundTrips() {
        const std::uint32_t flags[] = {kPosInvalid,     kPosValid,        kPosStop,         kPosForward,
                                       kPosBackward,    kPosVibrating,    kPosErrorHeading, kPosAccuracyLow,
                                       kPosAccuracyMed, kPosAccuracyHigh, kPosGpsShadow};
        const char* bytes[] = {"00000000", "00000080", "01000000", "02000000", "04000000", "80000000",
                               "20000000", "00010000", "00020000", "00040000", "00080000"};
        for (std::size_t i = 0; i < std::size(flags); ++i) {
            CmPos p = samplePos();
            p.flags = flags[i];
            Bytes b;
            encodePos(b, 0, 0, p);
            QCOMPARE(Bytes(b.begin() + 36, b.begin() + 40), hex(bytes[i])); // flags at header 8 + 28
            auto m = decodeMessage(b);
            QVERIFY(m.ok());
            QCOMPARE(std::get<CmPos>(m->body).flags, flags[i]);
        }
    }
    void cmRequestVectors() {
        struct V {
            CmRequest r;
            const char* body;
        };
        const V vs[] = {
            {{RequestType::Nak, 10, 20, 0, 0}, "00 0A000000 14000000"},
            {{RequestType::Ncf, 0x100, kSlotLast, 0, 0}, "01 00010000 FFFFFFFF"},
            {{RequestType::All, 0, kSlotLast, 0, 0}, "02 00000000 FFFFFFFF"},
            {{RequestType::Ping, 0, 0, 1.0f, 2.0f}, "03 0000803F 00000040"},
            {{RequestType::Pong, 0, 0, -1.0f, 0.5f}, "04 000080BF 0000003F"},
            {{RequestType::Alive, 0, 99, 0, 0}, "05 00000000 63000000"},
        };
        for (auto& v : vs) {
            Bytes b;
            encodeRequest(b, 3, 1, v.r);
            Bytes want = hex("0000 1100 0200 03 01");
            Bytes body = hex(v.body);
            want.insert(want.end(), body.begin(), body.end());
            QCOMPARE(b, want);
            auto m = decodeMessage(b);
            QVERIFY(m.ok());
            QVERIFY(std::get<CmRequest>(m->body) == v.r);
        }
    }
    void requestOtherReadingsAccepted() {
        // 17-byte body (From, To, X, Y all present) and a bare ALL (bType only).
        Bytes b = hex("0000 1900 0200 03 01  00 0A000000 14000000 0000803F 00000040");
        auto m = decodeMessage(b);
        QVERIFY(m.ok());
        auto q = std::get<CmRequest>(m->body);
        QCOMPARE(q.from, 10u);
        QCOMPARE(q.to, 20u);
        QCOMPARE(q.x, 1.0f);
        Bytes all = hex("0000 0900 0200 03 FF 02");
        m = decodeMessage(all);
        QVERIFY(m.ok());
        QCOMPARE(std::get<CmRequest>(m->body).to, kSlotLast);
        Bytes nak = hex("0000 0900 0200 03 01 00"); // NAK without range makes no sense
        QVERIFY(!decodeMessage(nak).ok());
    }
    void cmMsgAndPropsVectors() {
        Bytes b;
        encodeMsg(b, 5, kIdxAll, "HI");
        Bytes want = hex("0000 5800 0400 05 FF 4849");
        want.resize(kMsgSize, 0);
        QCOMPARE(b, want);
        auto m = decodeMessage(b);
        QVERIFY(m.ok());
        QCOMPARE(QString::fromStdString(std::get<CmMsg>(m->body).text), QString("HI"));
        // WType 3 accepted as CmMsg on input.
        Bytes alt = b;
        alt[4] = 3;
        m = decodeMessage(alt);
        QVERIFY(m.ok());
        QCOMPARE(m->header.type, std::uint16_t(4));
        // Long text truncated to 79 characters + NUL.
        Bytes longMsg;
        encodeMsg(longMsg, 5, kIdxAll, std::string(100, 'a'));
        QCOMPARE(longMsg.size(), kMsgSize);
        QCOMPARE(std::get<CmMsg>(decodeMessage(longMsg)->body).text.size(), std::size_t(79));

        Bytes p;
        encodePosProps(p, 1, 2, {PosProp::fromFloat(0x11, 1.0f), PosProp{0xAABBCCDD, 0x22}});
        QCOMPARE(p, hex("0000 1800 0500 01 02  0000803F 11000000  DDCCBBAA 22000000"));
        m = decodeMessage(p);
        QVERIFY(m.ok());
        auto pp = std::get<CmPosProps>(m->body).props;
        QCOMPARE(pp.size(), std::size_t(2));
        QCOMPARE(pp[0].asFloat(), 1.0f);
        QCOMPARE(pp[1].value, 0xAABBCCDDu);
    }
    void propsInsidePosAccepted() {
        Bytes b;
        encodePos(b, 1, 2, samplePos());
        Bytes prop = hex("0000803F 11000000");
        b.insert(b.end(), prop.begin(), prop.end());
        b[2] = static_cast<std::uint8_t>(b.size());
        auto d = decodeDatagram(b);
        QVERIFY(d.reason.empty());
        QCOMPARE(d.messages.size(), std::size_t(2));
        QVERIFY(std::holds_alternative<CmPosProps>(d.messages[1].body));
    }
    void checksums() {
        const char* s = "123456789";
        ByteSpan check(reinterpret_cast<const std::uint8_t*>(s), 9);
        QCOMPARE(crc16(check), std::uint16_t(0x29B1)); // CRC-16/CCITT-FALSE check value
        QCOMPARE(xor16(hex("01020304")), std::uint16_t(0x0602));
        QCOMPARE(xor16(hex("010203")), std::uint16_t(0x0202));
        for (Checksum cs : {Checksum::Xor, Checksum::Crc16}) {
            Bytes b;
            encodeRequest(b, 3, 1, {RequestType::Nak, 10, 20, 0, 0}, cs);
            std::uint16_t crc = std::uint16_t(b[0] | (b[1] << 8));
            QCOMPARE(crc, checksum(cs, ByteSpan(b).subspan(2)));
            QVERIFY(crc != 0);
            QVERIFY(decodeMessage(b, cs).ok());
            b[12] ^= 0x40;
            auto d = decodeDatagram(b, cs);
            QCOMPARE(QString::fromStdString(d.reason), QString("bad_checksum"));
            QVERIFY(d.messages.empty());
        }
        // XOR of the NAK by hand: LE words after WCrc: 0011 0002 0103 0A00 0000 1400 0000 00(00)
        Bytes b;
        encodeRequest(b, 3, 1, {RequestType::Nak, 10, 20, 0, 0}, Checksum::Xor);
        QCOMPARE(std::uint16_t(b[0] | (b[1] << 8)),
                 std::uint16_t(0x0011 ^ 0x0002 ^ 0x0103 ^ 0x0A00 ^ 0x0000 ^ 0x1400 ^ 0x0000 ^ 0x0000));
    }
    void multipleMessagesPerDatagram() {
        Bytes d;
        encodePos(d, 1, 1, samplePos());
        encodePosProps(d, 1, 1, {PosProp::fromFloat(1, 2.0f)});
        encodeRequest(d, 1, 1, {RequestType::Alive, 0, 7, 0, 0});
        encodeMsg(d, 1, kIdxAll, "x");
        auto r = decodeDatagram(d);
        QVERIFY(r.reason.empty());
        QCOMPARE(r.messages.size(), std::size_t(4));
        Bytes again;
        for (auto& m : r.messages)
            encodeMessage(again, m);
        QCOMPARE(again, d);
    }
    void rejections() {
        Bytes good;
        encodePos(good, 1, 1, samplePos());
        // truncated: cut inside the second message; the first is kept
        Bytes d = good;
        d.insert(d.end(), good.begin(), good.begin() + 50);
        auto r = decodeDatagram(d);
        QCOMPARE(QString::fromStdString(r.reason), QString("truncated"));
        QCOMPARE(r.messages.size(), std::size_t(1));
        // trailing bytes shorter than a header
        d = good;
        d.push_back(1);
        QCOMPARE(QString::fromStdString(decodeDatagram(d).reason), QString("truncated"));
        // oversized datagram
        Bytes big(2000, 0);
        QCOMPARE(QString::fromStdString(decodeDatagram(big, Checksum::None, 1400).reason),
                 QString("oversized"));
        // WLen below header size
        Bytes tiny = hex("0000 0400 0100 01 01");
        QCOMPARE(QString::fromStdString(decodeDatagram(tiny).reason), QString("bad_length"));
        // wrong CmPos length
        Bytes shortPos = good;
        shortPos.resize(70);
        shortPos[2] = 70;
        QCOMPARE(QString::fromStdString(decodeDatagram(shortPos).reason), QString("bad_length"));
        // unknown type, reserved sender, reserved owner, bad request type
        Bytes u = good;
        u[4] = 9;
        QCOMPARE(QString::fromStdString(decodeDatagram(u).reason), QString("unknown_type"));
        u = good;
        u[6] = kIdxAll;
        QCOMPARE(QString::fromStdString(decodeDatagram(u).reason), QString("bad_index"));
        u = good;
        u[7] = kIdxNobody;
        QCOMPARE(QString::fromStdString(decodeDatagram(u).reason), QString("bad_index"));
        Bytes rq;
        encodeRequest(rq, 1, 1, {RequestType::Nak, 1, 2, 0, 0});
        rq[8] = 6;
        QCOMPARE(QString::fromStdString(decodeDatagram(rq).reason), QString("bad_request_type"));
        QCOMPARE(QString::fromStdString(decodeDatagram(Bytes{}).reason), QString("truncated"));
    }
    void randomDatagramsNeverCrash() {
        std::mt19937 rng(42);
        int rejected = 0, accepted = 0;
        for (int i = 0; i < 20000; ++i) {
            Bytes d(rng() % 300);
            for (auto& b : d)
                b = static_cast<std::uint8_t>(rng());
            if (i % 2 && d.size() >= 8) { // plausible WLen makes the decoder go deeper
                d[2] = static_cast<std::uint8_t>(d.size());
                d[3] = static_cast<std::uint8_t>(d.size() >> 8);
                d[4] = static_cast<std::uint8_t>(1 + rng() % 5);
                d[5] = 0;
            }
            auto r = decodeDatagram(d, i % 3 ? Checksum::None : Checksum::Crc16);
            if (r.reason.empty())
                ++accepted;
            else {
                ++rejected;
                QVERIFY(!r.error.empty());
            }
        }
        qInfo("random datagrams: %d rejected, %d accepted", rejected, accepted);
        QVERIFY(rejected > 15000);
    }
    void fileTime() {
        QCOMPARE(unixMillisToFileTime(0), kFileTimeUnixEpoch);
        QCOMPARE(fileTimeToUnixMillis(unixMillisToFileTime(1763712000123)), std::int64_t(1763712000123));
        // Any FILETIME a peer sends converts without signed overflow (fuzz finding, docs/reliability.md):
        // the far future stays in the future, not wrapped into the past.
        QCOMPARE(fileTimeToUnixMillis(~0ull), std::int64_t(1844674407370955) - std::int64_t(11644473600000));
        QCOMPARE(fileTimeToUnixMillis(0x8000000000000000ull),
                 std::int64_t(922337203685477) - std::int64_t(11644473600000));
        QCOMPARE(fileTimeToUnixMillis(kFileTimeUnixEpoch), std::int64_t(0));
    }
};

QTEST_GUILESS_MAIN(TestOsyrisCodec)
#include "test_osyris_codec.moc"
