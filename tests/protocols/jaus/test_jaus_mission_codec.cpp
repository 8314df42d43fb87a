// The mission message codecs (ListManager, waypoint (list) drivers, PathReporter) against the byte vectors
// of shared/research/jaus-autonomy.md §11 and jaus-services-extra.md §3.2, in both directions, plus the
// dialects public stacks send (truncated scaling, ReportElement without its format byte) and bad input.
#include <QtTest>

#include "protocols/jaus/JudpCodec.h"
#include "protocols/jaus/Messages.h"
#include "protocols/jaus/MessagesMission.h"

using namespace ocu;
using namespace ocu::jaus;

namespace {

Bytes hex(const std::string& s) {
    Bytes out;
    for (std::size_t i = 0; i + 1 < s.size(); i += 2)
        if (s[i] != ' ')
            out.push_back(std::uint8_t(std::stoi(s.substr(i, 2), nullptr, 16)));
        else
            --i;
    return out;
}
QString toHex(const Bytes& b) {
    return QString::fromLatin1(
        QByteArray(reinterpret_cast<const char*>(b.data()), qsizetype(b.size())).toHex());
}
// A one-message JUDP frame: its payload, after checking the frame re-encodes byte for byte.
Bytes framePayload(const std::string& frame, JausId src, JausId dst, std::uint16_t seq) {
    auto d = decodeDatagram(hex(frame));
    if (!d || d->messages.size() != 1)
        qFatal("frame does not decode to one message");
    const JudpMessage& m = d->messages.front();
    if (!(m.header.source == src) || !(m.header.destination == dst) || m.header.sequence != seq)
        qFatal("frame header differs");
    if (encodeDatagram(m.header, m.payload) != hex(frame))
        qFatal("frame does not re-encode");
    return m.payload;
}

const JausId kOcu{2, 1, 1}, kUgv{126, 1, 199};

// V1's embedded SetLocalWaypoint: X 10.0 m, Y -5.0 m, WaypointTolerance 1.0 m.
LocalWaypoint v1Waypoint() {
    LocalWaypoint w;
    w.x = 10.0;
    w.y = -5.0;
    w.waypointTolerance = 1.0;
    return w;
}

} // namespace

class TestJausMissionCodec : public QObject {
    Q_OBJECT
private slots:
    // V1: SetElement(Req 1; UID 1, Prev 0, Next 0; SetLocalWaypoint) and its frame.
    void setElementVector() {
        const Bytes wp = encode(v1Waypoint());
        QCOMPARE(toHex(wp), QStringLiteral("0d0410dc460380915cfe7f8f02"));
        SetElement m;
        m.requestId = 1;
        m.elements = {ListElement{1, 0, 0, 0, wp}};
        const QString want = QStringLiteral("1a040101010000000000000d000d0410dc460380915cfe7f8f02");
        QCOMPARE(toHex(encode(m)), want);
        const Bytes frame =
            framePayload("0200280001c7017e00010102001a040101010000000000000d000d0410dc460380915cfe7f"
                         "8f020000",
                         kOcu, kUgv, 0);
        QCOMPARE(toHex(frame), want);
        auto d = decodeSetElement(frame);
        QVERIFY(d);
        QCOMPARE(d->requestId, 1);
        QCOMPARE(d->elements.size(), std::size_t(1));
        QVERIFY(d->elements[0] == m.elements[0]);
        auto w = decodeLocalWaypoint(d->elements[0].data);
        QVERIFY(w);
        QVERIFY(std::abs(w->x - 10.0) < 1e-4 && std::abs(w->y + 5.0) < 1e-4);
        QVERIFY(!w->z && !w->yaw && !w->pathTolerance);
        QVERIFY(std::abs(*w->waypointTolerance - 1.0) < 0.002);
        // JAUS++ truncates: X 0x800346DB decodes within one LSB.
        auto t = decodeLocalWaypoint(hex("0d0410db460380915cfe7f8f02"));
        QVERIFY(t && std::abs(t->x - 10.0) < 1e-4);
    }
    // V2: ConfirmElementRequest and RejectElementRequest(1, invalid next).
    void confirmAndRejectVectors() {
        QCOMPARE(toHex(encodeU8(msg::ConfirmElementRequest, 1)), QStringLiteral("1c0401"));
        QCOMPARE(*decodeU8(hex("1c0400"), msg::ConfirmElementRequest), 0); // the JTS example's RequestID 0
        QCOMPARE(toHex(encode(RejectElementRequest{1, 3})), QStringLiteral("1d040103"));
        auto r = decodeRejectElementRequest(hex("1d040103"));
        QVERIFY(r);
        QCOMPARE(r->requestId, 1);
        QCOMPARE(r->code, 3);
        QCOMPARE(QString(nameFor(ElementRejection(r->code))), QStringLiteral("invalid next element"));
        QVERIFY(!decodeRejectElementRequest(hex("1d0401")));
    }
    // V3: ExecuteList(UID 1, 1.0 m/s), its frame, speed only, FKIE's speed change.
    void executeListVectors() {
        QCOMPARE(toHex(encode(ExecuteList{1.0, std::uint16_t(1)})), QStringLiteral("1e0401c8000100"));
        QCOMPARE(toHex(framePayload("0200150001c7017e00010102001e0401c80001000100", kOcu, kUgv, 1)),
                 QStringLiteral("1e0401c8000100"));
        QCOMPARE(toHex(encode(ExecuteList{1.0, std::nullopt})), QStringLiteral("1e0400c800"));
        QCOMPARE(toHex(encode(ExecuteList{1.0, kAllUids})), QStringLiteral("1e0401c800ffff"));
        auto d = decodeExecuteList(hex("1e0401c8000100"));
        QVERIFY(d);
        QVERIFY(std::abs(d->speed - 1.0) < 0.005);
        QCOMPARE(*d->startUid, 1);
        auto s = decodeExecuteList(hex("1e0400c800"));
        QVERIFY(s && !s->startUid);
        QVERIFY(!decodeExecuteList(hex("1e0401c800"))); // PV says a UID follows
    }
    // V4: QueryActiveElement, ReportActiveElement(2) and its frame, idle.
    void activeElementVectors() {
        QCOMPARE(toHex(encodeEmpty(msg::QueryActiveElement)), QStringLiteral("1e24"));
        QCOMPARE(toHex(encodeU16(msg::ReportActiveElement, 2)), QStringLiteral("1e440200"));
        const Bytes p = framePayload("020012000101010200c7017e001e4402000500", kUgv, kOcu, 5);
        QCOMPARE(*decodeU16(p, msg::ReportActiveElement), 2);
        QCOMPARE(*decodeU16(hex("1e440000"), msg::ReportActiveElement), 0);
    }
    // V5: SetGlobalWaypoint(48.137154, 11.576124, 520 m, tolerance 2.0 m), round and truncated, its frame,
    // and as a list element.
    void globalWaypointVectors() {
        GlobalWaypoint g;
        g.lat = 48.137154;
        g.lon = 11.576124;
        g.alt = 520;
        g.waypointTolerance = 2.0;
        const QString round = QStringLiteral("0c0411f13376c47a5e3b8846dcd83b1f05");
        QCOMPARE(toHex(encode(g)), round);
        QCOMPARE(toHex(framePayload("02001f0001c7017e00010102000c0411f13376c47a5e3b8846dcd83b1f050200", kOcu,
                                    kUgv, 2)),
                 round);
        for (const char* v : {"0c0411f13376c47a5e3b8846dcd83b1f05", "0c0411f13376c47a5e3b8845dcd83b1e05"}) {
            auto d = decodeGlobalWaypoint(hex(v));
            QVERIFY(d);
            QVERIFY(std::abs(d->lat - 48.137154) < 1e-6 && std::abs(d->lon - 11.576124) < 1e-6);
            QVERIFY(std::abs(*d->alt - 520) < 0.01);
            QVERIFY(std::abs(*d->waypointTolerance - 2.0) < 0.003);
            QVERIFY(!d->roll && !d->pathTolerance);
        }
        SetElement m;
        m.requestId = 1;
        m.elements = {ListElement{1, 0, 0, 0, encode(g)}};
        QCOMPARE(toHex(encode(m)), QStringLiteral("1a040101010000000000001100") + round);
        // Report/Query pair of the single waypoint driver.
        QCOMPARE(toHex(encodeU8(msg::QueryGlobalWaypoint, 0x3f)), QStringLiteral("0c243f"));
        QVERIFY(decodeGlobalWaypoint(encode(g, msg::ReportGlobalWaypoint), msg::ReportGlobalWaypoint));
    }
    // Every optional field of a local waypoint survives the round trip (27 bytes with the ID).
    void localWaypointAllFields() {
        LocalWaypoint w = v1Waypoint();
        w.z = 1.5;
        w.roll = 0.1;
        w.pitch = -0.2;
        w.yaw = 3.0;
        w.pathTolerance = 2.5;
        const Bytes b = encode(w, msg::ReportLocalWaypoint);
        QCOMPARE(b.size(), std::size_t(27));
        QCOMPARE(int(b[2]), 0x3f);
        auto d = decodeLocalWaypoint(b, msg::ReportLocalWaypoint);
        QVERIFY(d);
        QVERIFY(std::abs(*d->z - 1.5) < 1e-4 && std::abs(*d->yaw - 3.0) < 1e-4);
        QVERIFY(std::abs(*d->pathTolerance - 2.5) < 1e-4);
        QVERIFY(!decodeLocalWaypoint(hex("0d0410dc460380915cfe7f"))); // tolerance announced, missing
    }
    // V6: DeleteElement, counts, lists, QueryElement / ReportElement (JSIDL and JAUS++), travel speed.
    void otherListVectors() {
        QCOMPARE(toHex(encode(DeleteElement{2, {kAllUids}})), QStringLiteral("1b040201ffff"));
        auto del = decodeDeleteElement(hex("1b040201ffff"));
        QVERIFY(del && del->requestId == 2 && del->uids == std::vector<std::uint16_t>{0xFFFF});
        QCOMPARE(toHex(encodeEmpty(msg::QueryElementCount)), QStringLiteral("1c24"));
        QCOMPARE(toHex(encodeU16(msg::ReportElementCount, 2)), QStringLiteral("1c440200"));
        QCOMPARE(toHex(encodeEmpty(msg::QueryElementList)), QStringLiteral("1b24"));
        QCOMPARE(toHex(encode(ReportElementList{{1, 2}})), QStringLiteral("1b44020001000200"));
        auto list = decodeReportElementList(hex("1b44020001000200"));
        QVERIFY(list && list->uids == (std::vector<std::uint16_t>{1, 2}));
        QVERIFY(!decodeReportElementList(hex("1b4403000100")));
        QCOMPARE(toHex(encodeU16(msg::QueryElement, 1)), QStringLiteral("1a240100"));
        const Bytes wp = encode(v1Waypoint());
        const ListElement e{1, 0, 0, 0, wp};
        const QString jsidl = QStringLiteral("1a4401000000000000") + QStringLiteral("0d00") + toHex(wp);
        QCOMPARE(toHex(encode(e)), jsidl);
        auto d = decodeListElement(hex(jsidl.toStdString()));
        QVERIFY(d && *d == e);
        // JAUS++ leaves the format byte out.
        Bytes noFormat = hex("1a440100000000000d00");
        noFormat.insert(noFormat.end(), wp.begin(), wp.end());
        auto jpp = decodeListElement(noFormat);
        QVERIFY(jpp);
        QCOMPARE(jpp->uid, 1);
        QCOMPARE(toHex(jpp->data), toHex(wp));
        QVERIFY(!decodeListElement(hex("1a4401000000000000ff00")));
        QCOMPARE(toHex(encodeTravelSpeed(msg::SetTravelSpeed, 1.5)), QStringLiteral("0a042c01"));
        QCOMPARE(toHex(encodeTravelSpeed(msg::ReportTravelSpeed, 1.5)), QStringLiteral("0a442c01"));
        QVERIFY(std::abs(*decodeTravelSpeed(hex("0a442c01"), msg::ReportTravelSpeed) - 1.5) < 0.005);
        QCOMPARE(toHex(encodeEmpty(msg::QueryTravelSpeed)), QStringLiteral("0a24"));
    }
    void setElementManyRoundTrip() {
        SetElement m;
        m.requestId = 9;
        for (std::uint16_t i = 1; i <= 5; ++i) {
            LocalWaypoint w;
            w.x = i;
            w.y = -double(i);
            m.elements.push_back(
                ListElement{i, std::uint16_t(i - 1), std::uint16_t(i == 5 ? 0 : i + 1), 0, encode(w)});
        }
        auto d = decodeSetElement(encode(m));
        QVERIFY(d);
        QCOMPARE(d->elements.size(), std::size_t(5));
        for (std::size_t i = 0; i < 5; ++i)
            QVERIFY(d->elements[i] == m.elements[i]);
        Bytes cut = encode(m);
        cut.resize(cut.size() - 1);
        QVERIFY(!decodeSetElement(cut));
    }
    // jaus-services-extra.md §3.2: QueryPath(historical global, at most 100 points), capabilities, paths.
    void pathReporterVectors() {
        QueryPath q;
        q.pathType = 0;
        q.maximumPoints = 100;
        QCOMPARE(toHex(encode(q)), QStringLiteral("f1de02006400"));
        auto dq = decodeQueryPath(hex("f1de02006400"));
        QVERIFY(dq && dq->pathType == 0 && *dq->maximumPoints == 100 && !dq->targetResolution);
        QCOMPARE(toHex(encodeEmpty(msg::QueryPathReporterCapabilities)), QStringLiteral("f0de"));
        ReportPathReporterCapabilities caps;
        PathCapability c;
        c.pathType = 1;
        c.minResolution = 0;
        c.maxResolution = 0;
        c.maximumPoints = 15;
        caps.paths = {c};
        QCOMPARE(toHex(encode(caps)), QStringLiteral("f2de0107010000"
                                                     "0000"
                                                     "0f00"));
        auto dc = decodeReportPathReporterCapabilities(encode(caps));
        QVERIFY(dc && dc->paths.size() == 1 && *dc->paths[0].maximumPoints == 15 &&
                !dc->paths[0].maximumTime);

        ReportPath local;
        local.pathType = 1;
        PathPoint a;
        a.x = 10.0;
        a.y = -5.0;
        PathPoint b;
        b.x = 11.0;
        b.y = -4.0;
        b.yaw = 0.5;
        b.timestamp = 0x12345678;
        local.points = {a, b};
        const Bytes lb = encode(local);
        // vtag 1, count 2; point a: PV 0x0003, X and Y as in V1.
        QVERIFY(toHex(lb).startsWith(QStringLiteral("f3de01020003 00dc460380915cfe7f").remove(' ')));
        auto dl = decodeReportPath(lb);
        QVERIFY(dl && dl->points.size() == 2);
        QVERIFY(std::abs(*dl->points[1].x - 11.0) < 1e-4 && std::abs(*dl->points[1].yaw - 0.5) < 1e-4);
        QCOMPARE(*dl->points[1].timestamp, 0x12345678u);
        QVERIFY(!dl->points[0].lat && !dl->points[0].z);
        ReportPath global;
        global.pathType = 0;
        PathPoint g;
        g.lat = 48.137154;
        g.lon = 11.576124;
        g.alt = 520;
        global.points = {g};
        // The same scaling as ReportGlobalPose (jaus-wire.md K18).
        QCOMPARE(toHex(encode(global)), QStringLiteral("f3de0001000700f13376c47a5e3b8846dcd83b"));
        auto dg = decodeReportPath(encode(global));
        QVERIFY(dg && std::abs(*dg->points[0].lat - 48.137154) < 1e-6 && !dg->points[0].x);
        QVERIFY(!decodeReportPath(hex("f3de05000000")));
        QVERIFY(!decodeReportPath(hex("f3de0101000700")));
    }
    void namesAndWrongIds() {
        QCOMPARE(QString(messageName(msg::SetElement)), QStringLiteral("SetElement"));
        QCOMPARE(QString(messageName(msg::ReportPath)), QStringLiteral("ReportPath"));
        QCOMPARE(QString(messageName(0xF702)), QStringLiteral("ReportDigitalResourceEndpoint"));
        QVERIFY(!decodeSetElement(hex("1b040201ffff")));
        QVERIFY(!decodeExecuteList(hex("1e")));
    }
};

QTEST_APPLESS_MAIN(TestJausMissionCodec)
#include "test_jaus_mission_codec.moc"
