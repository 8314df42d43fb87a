// The hand-off message codecs (EnhancedAccessControl / HandoffController 1.1) against byte vectors: the
// RequestHandoff vector of shared/research/jaus-autonomy.md §11 and the others written out field by field
// from the layouts of §8 (HandoffClass.xml), both directions, plus bad input.
#include <QtTest>

#include "protocols/jaus/Messages.h"
#include "protocols/jaus/MessagesHandoff.h"

using namespace ocu;
using namespace ocu::jaus;

namespace {

Bytes hex(const std::string& s) {
    Bytes out;
    std::string digits;
    for (char c : s)
        if (c != ' ')
            digits.push_back(c);
    for (std::size_t i = 0; i + 1 < digits.size(); i += 2)
        out.push_back(std::uint8_t(std::stoi(digits.substr(i, 2), nullptr, 16)));
    return out;
}
QString toHex(const Bytes& b) {
    return QString::fromLatin1(
        QByteArray(reinterpret_cast<const char*>(b.data()), qsizetype(b.size())).toHex(' '));
}

} // namespace

class TestJausHandoffCodec : public QObject {
    Q_OBJECT
private slots:
    void requestHandoffVector() {
        // jaus-autonomy.md §11 V6: RequestHandoff(200, "need ctl").
        const Bytes wire = hex("31 ff c8 08 6e 65 65 64 20 63 74 6c");
        QCOMPARE(toHex(encode(RequestHandoff{200, "need ctl"})), toHex(wire));
        auto m = decodeRequestHandoff(wire);
        QVERIFY(m);
        QCOMPARE(m->authority, std::uint8_t(200));
        QCOMPARE(QString::fromStdString(m->explanation), QStringLiteral("need ctl"));
        // An empty explanation is a zero length.
        QCOMPARE(toHex(encode(RequestHandoff{125, ""})), QStringLiteral("31 ff 7d 00"));
    }

    void confirmHandoffRequest() {
        // ID u8, ResponseCode u8: queued as entry 3; the EAC's immediate answers carry ID 255.
        QCOMPARE(toHex(encode(ConfirmHandoffRequest{3, HandoffCode::Queued})), QStringLiteral("35 ff 03 04"));
        QCOMPARE(toHex(encode(ConfirmHandoffRequest{kNoHandoffId, HandoffCode::InsufficientAuthority})),
                 QStringLiteral("35 ff ff 06"));
        auto m = decodeConfirmHandoffRequest(hex("35 ff 07 00"));
        QVERIFY(m);
        QCOMPARE(m->id, std::uint8_t(7));
        QVERIFY(m->code == HandoffCode::Granted);
        for (auto [code, name] : {std::pair{HandoffCode::Timeout, "timeout"},
                                  {HandoffCode::Denied, "denied"},
                                  {HandoffCode::Deferred, "deferred"},
                                  {HandoffCode::Wait, "wait"}}) {
            auto d = decodeConfirmHandoffRequest(encode(ConfirmHandoffRequest{1, code}));
            QVERIFY(d);
            QVERIFY(d->code == code);
            QCOMPARE(nameFor(d->code), name);
        }
        auto fkieWait = decodeConfirmHandoffRequest(hex("35 ff 01 07")); // FKIE's private WAIT
        QVERIFY(fkieWait && fkieWait->code == HandoffCode::Wait);
        QVERIFY(!decodeConfirmHandoffRequest(hex("35 ff 01 08"))); // no such code
        QVERIFY(!decodeConfirmHandoffRequest(hex("35 ff 01")));    // truncated
    }

    void requestReleaseControl() {
        // count u8 × {ID u8; Subsystem u16; Node u8; Component u8; Authority u8; Explanation str8}.
        RequestReleaseControl m;
        m.requests.push_back({1, JausId{201, 1, 1}, 205, "OCU-201: ops"});
        m.requests.push_back({2, JausId{0x1234, 2, 3}, 125, ""});
        const Bytes wire = hex("38 ff 02"
                               " 01 c9 00 01 01 cd 0c 4f 43 55 2d 32 30 31 3a 20 6f 70 73"
                               " 02 34 12 02 03 7d 00");
        QCOMPARE(toHex(encode(m)), toHex(wire));
        auto d = decodeRequestReleaseControl(wire);
        QVERIFY(d);
        QVERIFY(*d == m);
        // The empty queue (every request withdrawn or answered).
        QCOMPARE(toHex(encode(RequestReleaseControl{})), QStringLiteral("38 ff 00"));
        auto e = decodeRequestReleaseControl(hex("38 ff 00"));
        QVERIFY(e && e->requests.empty());
        // A record cut short, and an explanation longer than what is left.
        QVERIFY(!decodeRequestReleaseControl(hex("38 ff 01 01 c9 00 01")));
        QVERIFY(!decodeRequestReleaseControl(hex("38 ff 01 01 c9 00 01 01 cd 05 61 62")));
    }

    void confirmReleaseControl() {
        // count u8 × {ID u8; ResponseCode u8: 0 GRANTED, 1 DENIED, 2 WAIT}.
        ConfirmReleaseControl m{
            {{1, ReleaseCode::Granted}, {2, ReleaseCode::Denied}, {3, ReleaseCode::Wait}}};
        const Bytes wire = hex("39 ff 03 01 00 02 01 03 02");
        QCOMPARE(toHex(encode(m)), toHex(wire));
        auto d = decodeConfirmReleaseControl(wire);
        QVERIFY(d);
        QVERIFY(*d == m);
        QVERIFY(!decodeConfirmReleaseControl(hex("39 ff 01 01 03"))); // no such code
        QVERIFY(!decodeConfirmReleaseControl(hex("39 ff 02 01 00"))); // one record missing
    }

    void timeoutsAndRemoval() {
        // One u8 each: the decision timeout (60 s), the re-assertion timeout (5 s), the entry to remove.
        QCOMPARE(toHex(encodeU8(msg::ReportHandoffTimeout, 60)), QStringLiteral("36 ff 3c"));
        QCOMPARE(toHex(encodeU8(msg::ReportEnhancedTimeout, 5)), QStringLiteral("37 ff 05"));
        QCOMPARE(toHex(encodeU8(msg::RemoveHandoffRequest, 4)), QStringLiteral("34 ff 04"));
        QCOMPARE(toHex(encodeEmpty(msg::QueryHandoffTimeout)), QStringLiteral("32 ff"));
        QCOMPARE(toHex(encodeEmpty(msg::QueryEnhancedTimeout)), QStringLiteral("33 ff"));
        auto t = decodeU8(hex("36 ff 3c"), msg::ReportHandoffTimeout);
        QVERIFY(t && *t == 60);
        QCOMPARE(messageName(msg::RequestReleaseControl), "RequestReleaseControl");
        QCOMPARE(messageName(msg::ConfirmHandoffRequest), "ConfirmHandoffRequest");
        QVERIFY(!decodeRequestHandoff(hex("35 ff 01 00"))); // another message's ID
    }
};

QTEST_APPLESS_MAIN(TestJausHandoffCodec)
#include "test_jaus_handoff_codec.moc"
