#include "protocols/common/FrameTimeCode.h"

#include <QTest>

#include <vector>

class TestFrameTimeCode : public QObject {
    Q_OBJECT
private slots:
    void roundTripOnLuma() {
        const int w = 1280, h = 720;
        std::vector<std::uint8_t> y(static_cast<size_t>(w) * h, 90);
        const std::uint64_t t = 1795000000123456ull;
        QVERIFY(ocu::timecode::stamp(y.data(), w, h, w, t));
        QCOMPARE(ocu::timecode::cellSize(w), 16);
        QCOMPARE(y[0], ocu::timecode::kLow); // bit 63 of t is 0
        auto back = ocu::timecode::read(y.data(), w, h, w);
        QVERIFY(back);
        QCOMPARE(*back, t);
    }
    void readsOneChannelOfRgbaWithNoise() {
        const int w = 640, h = 480;
        std::vector<std::uint8_t> y(static_cast<size_t>(w) * h, 0);
        const std::uint64_t t = 0x0123456789abcdefull;
        QVERIFY(ocu::timecode::stamp(y.data(), w, h, w, t));
        std::vector<std::uint8_t> rgba(static_cast<size_t>(w) * h * 4);
        for (size_t i = 0; i < y.size(); ++i) // blur-like noise at cell edges does not reach the centre
            for (int c = 0; c < 4; ++c)
                rgba[i * 4 + c] = static_cast<std::uint8_t>(std::clamp(int(y[i]) + int(i % 7) - 3, 0, 255));
        auto back = ocu::timecode::read(rgba.data() + 1, w, h, w * 4, 4);
        QVERIFY(back);
        QCOMPARE(*back, t);
    }
    void refusesAFrameWithoutCode() {
        const int w = 320, h = 240;
        std::vector<std::uint8_t> y(static_cast<size_t>(w) * h, 200);
        QVERIFY(!ocu::timecode::read(y.data(), w, h, w));     // both rows bright: not inverted copies
        QVERIFY(!ocu::timecode::stamp(y.data(), w, 5, w, 1)); // too short for two rows
    }
};

QTEST_APPLESS_MAIN(TestFrameTimeCode)
#include "test_frame_time_code.moc"
