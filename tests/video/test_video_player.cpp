// The video player against a loopback RTSP server: frames arrive off the GUI thread and are
// handed over as the latest QImage with the capture time read back; switching cameras; the server stopped ->
// lost, then reconnecting with backoff; the server back -> playing again. Bad URLs never crash.
#include "models/video/VideoPlayer.h"
#include "tests/video/TestRtspServer.h"

#include <QSignalSpy>
#include <QTest>

using namespace ocu;
using ocu::testing::TestRtspServer;

namespace {
// Grey level of the picture below the time code and left of the moving bar's usual path.
int backgroundGrey(const QImage& img) {
    return qGreen(img.pixel(4, img.height() / 4));
}
} // namespace

class TestVideoPlayer : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QString why;
        if (!VideoPlayer::available(&why))
            QFAIL(qPrintable(why));
    }

    void receiveSwitchLoseAndReconnect() {
        TestRtspServer server({{"/front", 60}, {"/rear", 200}}, 640, 360, 30);
        QVERIFY(server.start());
        VideoPlayer player;
        player.setTransport(VideoPlayer::Transport::Tcp);
        player.setLossTimeoutMs(1000);
        player.setReconnectBackoff(200, 1000);
        QSignalSpy states(&player, &VideoPlayer::stateChanged);
        player.setUrl(QString::fromStdString(server.url("/front")));
        player.play();
        QCOMPARE(player.state(), VideoState::Connecting);
        QTRY_COMPARE_WITH_TIMEOUT(player.state(), VideoState::Playing, 30000);
        QTRY_VERIFY_WITH_TIMEOUT(player.status().frames >= 10, 30000);
        VideoStatus st = player.status();
        QCOMPARE(st.resolution, QSize(640, 360));
        QVERIFY(st.fps > 0);
        QVERIFY(st.decodeMsPerFrame > 0);
        QVERIFY2(st.ageFromTimeCode, "the capture time stamped in the frame is read back");
        QVERIFY(st.frameAgeMs.has_value());
        VideoFrame f = player.currentFrame();
        QVERIFY(f.captureUs.has_value());
        QVERIFY(*f.captureUs <= f.arrivalUs);
        QVERIFY2(backgroundGrey(f.image) < 100, qPrintable(QString::number(backgroundGrey(f.image))));

        // Switch cameras: the rear camera's picture (bright) replaces the front's.
        player.setUrl(QString::fromStdString(server.url("/rear")));
        QTRY_VERIFY_WITH_TIMEOUT(player.state() == VideoState::Playing &&
                                     backgroundGrey(player.currentFrame().image) > 150,
                                 30000);

        // The camera dies: lost, then reconnect attempts with backoff.
        states.clear();
        server.stop();
        QTRY_VERIFY_WITH_TIMEOUT(states.contains(QVariantList{QVariant::fromValue(VideoState::Lost)}), 30000);
        QTRY_VERIFY_WITH_TIMEOUT(player.status().reconnects >= 1, 30000);
        QVERIFY(player.state() != VideoState::Playing);
        QVERIFY(!player.status().error.isEmpty());
        const auto framesBefore = player.status().frames;

        // Back: frames again, by itself.
        QVERIFY(server.start());
        QTRY_VERIFY_WITH_TIMEOUT(
            player.state() == VideoState::Playing && player.status().frames > framesBefore + 5, 60000);
        QVERIFY(backgroundGrey(player.currentFrame().image) > 150);

        player.stop();
        QCOMPARE(player.state(), VideoState::Idle);
        QCOMPARE(player.status().fps, 0.0);
    }

    void badUrlsNeverCrash() {
        VideoPlayer player;
        player.setReconnectBackoff(50, 100);
        player.setConnectTimeoutMs(500);
        player.setUrl(QStringLiteral("http://127.0.0.1/not-rtsp"));
        player.play();
        QCOMPARE(player.state(), VideoState::Lost);
        QVERIFY(player.status().error.contains(QLatin1String("RTSP")));
        // Nobody listens on this port: the attempt fails, the player keeps retrying.
        player.setUrl(QStringLiteral("rtsp://127.0.0.1:1/nothing"));
        QTRY_VERIFY_WITH_TIMEOUT(player.status().reconnects >= 2, 30000);
        QVERIFY(player.state() != VideoState::Playing);
        player.stop();
    }
};

QTEST_GUILESS_MAIN(TestVideoPlayer)
#include "test_video_player.moc"
