// The platform services' codecs (Platform Mode/State, Illumination, Odometry) against the byte vectors of
// shared/research/jaus-autonomy.md §11 (V6), in both directions, and bad input.
#include <QtTest>

#include "protocols/jaus/Messages.h"
#include "protocols/jaus/MessagesPlatformServices.h"

using namespace ocu;
using namespace ocu::jaus;

namespace {

Bytes hex(const std::string& s) {
    Bytes out;
    for (std::size_t i = 0; i + 1 < s.size();) {
        if (s[i] == ' ') {
            ++i;
            continue;
        }
        out.push_back(std::uint8_t(std::stoi(s.substr(i, 2), nullptr, 16)));
        i += 2;
    }
    return out;
}

} // namespace

class TestJausPlatformCodec : public QObject {
    Q_OBJECT
private slots:
    // V6: SetIlluminationState(headlights, running lights, VariableLight1 = 15).
    void illuminationVector() {
        const std::uint32_t bits = light::Headlights | light::RunningLights | (15u << 8);
        QCOMPARE(encodeIllumination(msg::SetIlluminationState, bits), hex("13 05 09 0f 00 00"));
        auto back = decodeIllumination(hex("13 05 09 0f 00 00"), msg::SetIlluminationState);
        QVERIFY(back);
        QCOMPARE(*back, bits);
        QCOMPARE(encodeIllumination(msg::ReportIlluminationState, light::IrLightSource),
                 hex("13 45 80 00 00 00"));
        QVERIFY(!decodeIllumination(hex("13 45 80 00"), msg::ReportIlluminationState));       // truncated
        QVERIFY(!decodeIllumination(hex("13 05 80 00 00 00"), msg::ReportIlluminationState)); // other ID
    }
    // The configuration's mask has its own positions above bit 7.
    void illuminationConfigurationMask() {
        QCOMPARE(illuminationStateMaskOf(0x9F), 0x9Fu);                // b0-7 as in the state
        QCOMPARE(illuminationStateMaskOf(1u << 8), 0xFu << 8);         // variable light 1: its level
        QCOMPARE(illuminationStateMaskOf(1u << 11), 0xFu << 20);       // variable light 4
        QCOMPARE(illuminationStateMaskOf(1u << 12), light::HighBeams); // b12 high beams -> b24
        QCOMPARE(illuminationStateMaskOf(1u << 15), light::HazardLights);
        QVERIFY(!(light::kOperatorSwitchable & light::VisibleLightSource)); // never the whole vehicle's
    }
    // V6: ResetOdometry(TRIP_A); QueryOdometry(PLATFORM) -> ReportOdometry(PLATFORM, 1234 m).
    void odometryVectors() {
        QCOMPARE(encodeU8(msg::ResetOdometry, std::uint8_t(OdometryType::TripA)), hex("15 05 02"));
        QCOMPARE(encodeU8(msg::QueryOdometry, std::uint8_t(OdometryType::Platform)), hex("15 25 01"));
        const ReportOdometry r{1, 1234};
        QCOMPARE(encode(r), hex("15 45 01 d2 04 00 00"));
        auto back = decodeReportOdometry(hex("15 45 01 d2 04 00 00"));
        QVERIFY(back);
        QCOMPARE(*back, r);
        QVERIFY(!decodeReportOdometry(hex("15 45 01 d2 04")));
    }
    // V6: SetPlatformState(Emergency) -> ConfirmPlatformStateRequest(Emergency, Transitioning).
    void platformStateVectors() {
        QCOMPARE(encodeU8(msg::SetPlatformState, std::uint8_t(PlatformState::Emergency)), hex("25 ff 04"));
        const ConfirmPlatformStateRequest c{4, 0};
        QCOMPARE(encode(c), hex("27 ff 04 00"));
        auto back = decodeConfirmPlatformStateRequest(hex("27 ff 04 01"));
        QVERIFY(back);
        QCOMPARE(back->code, std::uint8_t(PlatformStateAnswer::InvalidState));
        QVERIFY(!decodeConfirmPlatformStateRequest(hex("27 ff 04")));
        QCOMPARE(encodeU8(msg::ReportPlatformState, 1), hex("28 ff 01"));
        QCOMPARE(encodeEmpty(msg::QueryPlatformState), hex("26 ff"));
        QCOMPARE(platformStateName(3), std::string("system abort"));
        QCOMPARE(platformStateName(9), std::string("state 9"));
    }
    // Platform Mode (JSIDL layouts, jaus-autonomy.md §6.2).
    void platformModeMessages() {
        QCOMPARE(encodeU8(msg::SetPlatformMode, std::uint8_t(PlatformMode::Training)), hex("20 ff 01"));
        const ReportPlatformMode m{2, 1};
        QCOMPARE(encode(m), hex("23 ff 02 01"));
        auto back = decodeReportPlatformMode(hex("23 ff 02 01"));
        QVERIFY(back);
        QCOMPARE(*back, m);
        QVERIFY(!decodeReportPlatformMode(hex("23 ff 02")));
        const ReportSupportedPlatformModes s{{0, 1, 2}};
        QCOMPARE(encode(s), hex("24 ff 03 00 01 02"));
        auto modes = decodeReportSupportedPlatformModes(hex("24 ff 03 00 01 02"));
        QVERIFY(modes);
        QCOMPARE(*modes, s);
        QVERIFY(!decodeReportSupportedPlatformModes(hex("24 ff 03 00 01")));
        QCOMPARE(platformModeName(2), std::string("maintenance"));
        QCOMPARE(platformModeName(200), std::string("program mode 200"));
    }
    // The names reach messageName() (logs, counters).
    void messageNames() {
        QCOMPARE(std::string(messageName(msg::ReportPlatformState)), std::string("ReportPlatformState"));
        QCOMPARE(std::string(messageName(msg::SetIlluminationState)), std::string("SetIlluminationState"));
        QCOMPARE(std::string(messageName(msg::ReportOdometry)), std::string("ReportOdometry"));
    }
};

QTEST_APPLESS_MAIN(TestJausPlatformCodec)
#include "test_jaus_platform_codec.moc"
