// bench_video: glass-to-glass latency of the console's video on loopback. A loopback RTSP server
// (tests/video/TestRtspServer: x264 zerolatency/ultrafast, 1280x720, 30 fps) stamps the capture time into
// each frame (protocols/common/FrameTimeCode.h) just before encoding; the console's VideoPlayer receives,
// decodes (GStreamer threads) and hands the newest frame to the GUI thread, where the VideoView paints it;
// the time code is then read back from the rendered widget image (QWidget::grab) and compared with the clock.
// Prints p50/p99/max latency, frames shown vs sent, and the CPU cost of decode + conversion per frame and as
// a share of one core. Server and console share this process (and the machine): the encoder's CPU is
// included in the process figure.
// Usage: bench_video [seconds=20] [width=1280] [height=720] [fps=30] [scene=flat|sim]
//   flat: the test server's flat picture with a moving bar (cheap to encode and decode);
//   sim:  the simulated UGV camera's scene (sim/jaus SimCameraServer: perspective grid, horizon, boxes) seen
//         from a vehicle driving a circle, a realistic load for the encoder and the decoder.
#include "models/video/VideoPlayer.h"
#include "protocols/common/FrameTimeCode.h"
#include "sim/jaus/SimCameraServer.h"
#include "tests/video/TestRtspServer.h"
#include "widgets/video/VideoView.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QImage>
#include <QTimer>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>
#include <memory>
#include <string>
#include <vector>

using namespace ocu;

namespace {
std::int64_t nowUs() {
    return std::chrono::duration_cast<std::chrono::microseconds>(
               std::chrono::system_clock::now().time_since_epoch())
        .count();
}
double processCpuS() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + ts.tv_nsec / 1e9;
}
double percentile(std::vector<double> v, double p) {
    if (v.empty())
        return 0;
    std::sort(v.begin(), v.end());
    const std::size_t i = std::min(v.size() - 1, std::size_t(p / 100.0 * double(v.size() - 1) + 0.5));
    return v[i];
}
} // namespace

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    const int seconds = argc > 1 ? std::atoi(argv[1]) : 20;
    const int width = argc > 2 ? std::atoi(argv[2]) : 1280;
    const int height = argc > 3 ? std::atoi(argv[3]) : 720;
    const int fps = argc > 4 ? std::atoi(argv[4]) : 30;
    QString why;
    if (!VideoPlayer::available(&why)) {
        std::fprintf(stderr, "bench_video: %s\n", qPrintable(why));
        return 2;
    }
    const bool simScene = argc > 5 && std::string(argv[5]) == "sim";
    std::unique_ptr<ocu::testing::TestRtspServer> flat;
    std::unique_ptr<sim::SimCameraServer> simServer;
    std::string url;
    std::function<std::uint64_t()> framesSent;
    if (simScene) {
        sim::CameraStream cs;
        cs.path = "cam";
        cs.width = width;
        cs.height = height;
        cs.fps = fps;
        const auto t0 = std::chrono::steady_clock::now();
        cs.scene = [t0](sim::CameraPose& pose, std::vector<sim::SceneBox>& boxes) {
            const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            pose.yaw = 0.2 * t; // a circle of 10 m radius at 2 m/s
            pose.x = 10 * std::sin(pose.yaw);
            pose.y = 10 * (1 - std::cos(pose.yaw));
            for (int i = 0; i < 4; ++i)
                boxes.push_back({12.0 * std::cos(i * 1.57), 12.0 * std::sin(i * 1.57), 0, 1.2, 0.8, 0.9});
        };
        simServer = std::make_unique<sim::SimCameraServer>(std::vector<sim::CameraStream>{cs});
        if (const std::string e = simServer->start(); !e.empty()) {
            std::fprintf(stderr, "bench_video: %s\n", e.c_str());
            return 2;
        }
        url = simServer->url("cam");
        framesSent = [&] { return simServer->framesRendered(); };
    } else {
        flat = std::make_unique<ocu::testing::TestRtspServer>(
            std::vector<ocu::testing::TestRtspServer::Mount>{{"/cam", 90}}, width, height, fps);
        if (!flat->start()) {
            std::fprintf(stderr, "bench_video: the RTSP server did not start\n");
            return 2;
        }
        url = flat->url("/cam");
        framesSent = [&] { return flat->framesPushed(); };
    }
    VideoPlayer player;
    player.setTransport(VideoPlayer::Transport::Udp);
    player.setUrl(QString::fromStdString(url));
    VideoView view;
    view.setPlayer(&player);
    view.resize(width, height); // 1:1, as a full-screen video window would show it
    view.show();

    std::vector<double> latencies;
    std::uint64_t shown = 0, unreadable = 0, lastNumber = 0;
    bool measuring = false;
    double cpu0 = 0;
    std::uint64_t pushed0 = 0, decoded0 = 0;
    QObject::connect(&player, &VideoPlayer::frameReady, &view, [&] {
        // Render the widget as the screen would get it, then read the capture time back from those pixels.
        const QImage img = view.grab().toImage().convertToFormat(QImage::Format_RGB32);
        const std::int64_t t = nowUs();
        if (!measuring || view.paintedFrame() == lastNumber)
            return;
        lastNumber = view.paintedFrame();
        ++shown;
        const QRect r = view.frameRect();
        if (r.isEmpty()) {
            ++unreadable;
            return;
        }
        const uchar* origin = img.constBits() + r.y() * img.bytesPerLine() + r.x() * 4 + 1;
        const auto capture = timecode::read(origin, r.width(), r.height(), img.bytesPerLine(), 4);
        if (!capture) {
            ++unreadable;
            return;
        }
        latencies.push_back(double(t - std::int64_t(*capture)) / 1000.0);
    });
    player.play();
    // 3 s warm-up (connection, first key frame), then measure.
    QTimer::singleShot(3000, [&] {
        measuring = true;
        cpu0 = processCpuS();
        pushed0 = framesSent();
        decoded0 = player.status().frames;
    });
    double cpuS = 0, decodeMs = 0, decodeCpu = 0, fpsSeen = 0;
    std::uint64_t pushed = 0, decoded = 0;
    QTimer::singleShot(3000 + seconds * 1000, [&] {
        cpuS = processCpuS() - cpu0;
        pushed = framesSent() - pushed0;
        const VideoStatus st = player.status();
        decoded = st.frames - decoded0;
        decodeMs = st.decodeMsPerFrame;
        decodeCpu = st.decodeCpuPercent;
        fpsSeen = st.fps;
        app.quit();
    });
    app.exec();
    player.stop();
    if (flat)
        flat->stop();
    if (simServer)
        simServer->stop();

    std::printf("bench_video: %dx%d @ %d fps, %d s, %s scene, RTSP over UDP on 127.0.0.1, x264 zerolatency "
                "ultrafast\n",
                width, height, fps, seconds, simScene ? "simulated camera" : "flat test");
    std::printf("  frames: sent %llu, decoded %llu, shown %llu (time code unreadable in %llu), %.1f fps\n",
                (unsigned long long)pushed, (unsigned long long)decoded, (unsigned long long)shown,
                (unsigned long long)unreadable, fpsSeen);
    std::printf(
        "  glass-to-glass (capture stamp -> rendered widget read back): p50 %.1f ms  p99 %.1f ms  max %.1f ms"
        "  (n=%zu)\n",
        percentile(latencies, 50), percentile(latencies, 99),
        latencies.empty() ? 0.0 : *std::max_element(latencies.begin(), latencies.end()), latencies.size());
    std::printf("  decode + colour conversion: %.2f ms CPU per frame, %.1f %% of one core\n", decodeMs,
                decodeCpu);
    std::printf("  whole process (encoder, decoder, paint, read-back): %.1f ms CPU per shown frame, %.0f %% "
                "of one core\n",
                shown ? cpuS * 1000.0 / double(shown) : 0.0, cpuS * 100.0 / seconds);
    return latencies.empty() ? 1 : 0;
}
