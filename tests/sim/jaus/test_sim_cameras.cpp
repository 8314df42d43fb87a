// Simulated cameras on loopback: the console's JAUS stack discovers a simulated UGV's cameras through the IOP
// services (Digital Resource Discovery → RTSP URL, Visual Sensor → names, geometry → the pan-tilt camera), a
// GStreamer RTSP client (this test's own pipeline) receives H.264 frames and reads the capture time stamped
// in them, a pan-tilt command moves the reported joint position, and stopping the UGV's RTSP server loses the
// stream until it is started again. Plus the synthetic view on its own (time code, the view follows the pan).
#include <QtTest>

#include <gst/app/gstappsink.h>
#include <gst/gst.h>
#include <gst/video/video-info.h>

#include <chrono>
#include <mutex>
#include <optional>
#include <thread>

#include "protocols/common/FrameTimeCode.h"
#include "protocols/jaus/JausStack.h"
#include "sim/jaus/CameraScene.h"
#include "sim/jaus/JausDemo.h"

using namespace ocu;
using namespace ocu::jaus;
using namespace ocu::sim;
using Clk = std::chrono::steady_clock;

namespace {

template <class Pred> bool waitFor(Pred p, double seconds = 30) {
    const auto end =
        Clk::now() + std::chrono::duration_cast<Clk::duration>(std::chrono::duration<double>(seconds));
    while (Clk::now() < end) {
        if (p())
            return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return p();
}

std::uint64_t nowUs() {
    return std::uint64_t(std::chrono::duration_cast<std::chrono::microseconds>(
                             std::chrono::system_clock::now().time_since_epoch())
                             .count());
}

struct Quiet : JausListener {
    void onSubsystemChanged(const SubsystemSnapshot&) override {}
    void onEvent(const JausEvent&) override {}
};

// The test's RTSP client: rtspsrc (RTP over the RTSP TCP connection) → H.264 decode → luma → appsink.
class RtspClient {
public:
    explicit RtspClient(const std::string& url) {
        const std::string desc =
            "rtspsrc location=" + url +
            " latency=0 protocols=tcp ! rtph264depay ! avdec_h264 ! videoconvert ! "
            "video/x-raw,format=GRAY8 ! appsink name=sink sync=false max-buffers=2 drop=true";
        GError* err = nullptr;
        m_pipe = gst_parse_launch(desc.c_str(), &err);
        if (err) {
            qWarning("pipeline: %s", err->message);
            g_error_free(err);
        }
        if (!m_pipe)
            return;
        m_sink = gst_bin_get_by_name(GST_BIN(m_pipe), "sink");
        gst_element_set_state(m_pipe, GST_STATE_PLAYING);
    }
    ~RtspClient() {
        if (m_sink)
            gst_object_unref(m_sink);
        if (m_pipe) {
            gst_element_set_state(m_pipe, GST_STATE_NULL);
            gst_object_unref(m_pipe);
        }
    }
    // The time code of the next decoded frame (nullopt: no frame within the timeout, or none readable).
    std::optional<std::uint64_t> nextTimeCode(double timeoutS, int* width = nullptr) {
        if (!m_sink)
            return std::nullopt;
        GstSample* s =
            gst_app_sink_try_pull_sample(GST_APP_SINK(m_sink), GstClockTime(timeoutS * GST_SECOND));
        if (!s)
            return std::nullopt;
        std::optional<std::uint64_t> out;
        GstVideoInfo info;
        GstMapInfo map;
        GstBuffer* b = gst_sample_get_buffer(s);
        if (gst_video_info_from_caps(&info, gst_sample_get_caps(s)) &&
            gst_buffer_map(b, &map, GST_MAP_READ)) {
            out = timecode::read(map.data, GST_VIDEO_INFO_WIDTH(&info), GST_VIDEO_INFO_HEIGHT(&info),
                                 GST_VIDEO_INFO_PLANE_STRIDE(&info, 0));
            if (width)
                *width = GST_VIDEO_INFO_WIDTH(&info);
            gst_buffer_unmap(b, &map);
        }
        gst_sample_unref(s);
        return out;
    }
    // True once the stream is lost: the pipeline reported an error or end of stream, or no frame arrived for
    // `silentS` seconds (rtspsrc may wait for a reconnect instead of reporting the closed connection).
    bool lost(double timeoutS, double silentS = 3) {
        GstBus* bus = gst_element_get_bus(m_pipe);
        const auto end =
            Clk::now() + std::chrono::duration_cast<Clk::duration>(std::chrono::duration<double>(timeoutS));
        auto lastFrame = Clk::now();
        bool gone = false;
        while (!gone && Clk::now() < end) {
            if (GstMessage* m =
                    gst_bus_pop_filtered(bus, GstMessageType(GST_MESSAGE_ERROR | GST_MESSAGE_EOS))) {
                gst_message_unref(m);
                gone = true;
                m_how = "error or end of stream";
                break;
            }
            if (GstSample* s = gst_app_sink_try_pull_sample(GST_APP_SINK(m_sink), GST_SECOND / 10)) {
                gst_sample_unref(s);
                lastFrame = Clk::now();
            } else if (Clk::now() - lastFrame > std::chrono::duration<double>(silentS)) {
                gone = true;
                m_how = "no frames";
            }
        }
        gst_object_unref(bus);
        return gone;
    }
    const char* how() const { return m_how; }

private:
    GstElement* m_pipe = nullptr;
    GstElement* m_sink = nullptr;
    const char* m_how = "";
};

JausDemoOptions oneUgv() {
    JausDemoOptions o;
    o.count = 2; // the second one is a box in the first one's cameras
    o.video = true;
    return o;
}

JausConfig consoleConfig(const JausDemo& demo) {
    JausConfig c;
    c.subsystemId = 200;
    c.callSign = "OCU-200";
    demo.configure(c);
    return c;
}

} // namespace

class TestSimCameras : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        // GStreamer's plugin registry goes to a temporary directory, never the user's home.
        static QTemporaryDir dir;
        qputenv("GST_REGISTRY", (dir.path() + QStringLiteral("/registry.bin")).toLocal8Bit());
        gst_init(nullptr, nullptr);
    }

    // The synthetic view on its own: the time code reads back; the picture follows the pan.
    void sceneStampsTimeAndFollowsPan() {
        const int w = 640, h = 360;
        std::vector<std::uint8_t> a(std::size_t(w * h * 3 / 2)), b(a.size());
        auto frame = [&](std::vector<std::uint8_t>& buf) {
            I420Frame f{buf.data(), buf.data() + w * h, buf.data() + w * h + w * h / 4, w, w / 2, w / 2, w,
                        h};
            return f;
        };
        CameraPose pose;
        std::vector<SceneBox> boxes{SceneBox{8, 0, 0}}; // 8 m ahead
        renderCameraView(frame(a), pose, boxes, 1'764'000'000'123'456ull);
        QCOMPARE(timecode::read(a.data(), w, h, w).value_or(0), 1'764'000'000'123'456ull);
        pose.pan = 0.8;
        renderCameraView(frame(b), pose, boxes, 1);
        // The box ahead is in the middle of the first view and out of the panned one.
        const int rowY = h / 2 + 20;
        int dark = 0, darkPanned = 0;
        for (int x = 0; x < w; ++x) {
            dark += a[std::size_t(rowY * w + x)] == 30;
            darkPanned += b[std::size_t(rowY * w + x)] == 30;
        }
        QVERIFY(dark >= 2); // the box's outline
        QCOMPARE(darkPanned, 0);
        QVERIFY(a != b);
    }

    void discoverReceivePanTiltLoseReturn() {
        JausDemo demo(oneUgv());
        SimulatedUgv* ugv = demo.find(126);
        QVERIFY(ugv && ugv->camerasRunning());
        Quiet quiet;
        JausStack stack(consoleConfig(demo), quiet);
        stack.start();

        // 1. Discovery through the IOP services: URL from Digital Resource Discovery, names from Visual
        // Sensor, the pan-tilt camera from the sensor geometry.
        auto endpoints = [&] {
            auto s = stack.snapshot(126);
            return s ? s->videoEndpoints : std::vector<VideoEndpoint>{};
        };
        QVERIFY2(waitFor([&] {
                     auto e = endpoints();
                     return e.size() == 2 && !e[0].name.empty() && !e[1].name.empty() && e[0].panTilt;
                 }),
                 "cameras not discovered through the IOP services");
        auto eps = endpoints();
        QCOMPARE(eps[0].sensorId, 1000);
        QCOMPARE(QString::fromStdString(eps[0].name), QStringLiteral("front (pan-tilt)"));
        QCOMPARE(QString::fromStdString(eps[0].url), QString::fromStdString(ugv->cameraUrl(1000)));
        QVERIFY(eps[0].panTilt);
        QCOMPARE(eps[1].sensorId, 1001);
        QCOMPARE(QString::fromStdString(eps[1].name), QStringLiteral("rear"));
        QVERIFY(!eps[1].panTilt);
        QVERIFY(QString::fromStdString(eps[0].url).startsWith(QStringLiteral("rtsp://127.0.0.1:")));
        // Nobody watches yet: nothing rendered.
        QCOMPARE(ugv->cameraFramesRendered(), std::uint64_t(0));

        // 2. Frames over RTSP with the capture time in them.
        {
            RtspClient client(eps[0].url);
            std::optional<std::uint64_t> tc;
            int width = 0;
            QVERIFY2(waitFor([&] { return (tc = client.nextTimeCode(1.0, &width)).has_value(); }),
                     "no frame with a readable time code");
            QCOMPARE(width, 640);
            // A capture time of this run (system clock), not garbage: within a minute of now.
            const std::uint64_t now = nowUs();
            QVERIFY(*tc <= now && now - *tc < 60'000'000ull);
            // Later frames carry later capture times.
            std::optional<std::uint64_t> later;
            QVERIFY(waitFor([&] { return (later = client.nextTimeCode(1.0)) && *later > *tc; }));
            QVERIFY(ugv->cameraFramesRendered() > 0);

            // 3. Pan-tilt: control of the vehicle, then of the pan-tilt unit, then rates; the reported
            // joint position (ReportPanTiltJointPositions) moves.
            stack.requestControl(126, {});
            QVERIFY2(waitFor([&] {
                         auto s = stack.snapshot(126);
                         return s && s->controlledByUs && !s->panTilts.empty() &&
                                s->panTilts[0].controlledByUs;
                     }),
                     "control of the vehicle and its pan-tilt unit not confirmed");
            auto pan = [&] {
                auto s = stack.snapshot(126);
                return s && !s->panTilts.empty() && s->panTilts[0].pan ? *s->panTilts[0].pan : -99.0;
            };
            QVERIFY(std::abs(pan()) < 0.01 || pan() == -99.0);
            // The demand is refreshed like a held key (it goes to zero when not refreshed).
            QVERIFY2(waitFor([&] {
                         stack.panTilt(126, 1000, 0.6, 0.0, [](std::vector<TargetOutcome>) {});
                         std::this_thread::sleep_for(std::chrono::milliseconds(100));
                         return pan() > 0.3;
                     }),
                     "the reported pan did not follow the command");
            QVERIFY(ugv->panTilt().pan > 0.3);
            stack.panTilt(126, 1000, 0, 0, [](std::vector<TargetOutcome>) {});
            // The rear camera is not on the pan-tilt: refused with the reason.
            std::mutex m;
            std::optional<TargetOutcome> refused;
            stack.panTilt(126, 1001, 0.5, 0, [&](std::vector<TargetOutcome> o) {
                std::lock_guard lock(m);
                refused = o.at(0);
            });
            QVERIFY(waitFor([&] {
                std::lock_guard lock(m);
                return refused.has_value();
            }));
            QVERIFY(!refused->sent);
            QVERIFY(QString::fromStdString(refused->reason).contains(QStringLiteral("not on a pan-tilt")));

            // 4. Loss: the UGV's RTSP server stops; the client loses the stream.
            ugv->stopCameras();
            QVERIFY2(client.lost(30), "the client did not notice the server going away");
            qInfo("stream lost: %s", client.how());
            // The server side stopped rendering (its pipelines are gone, not only the socket).
            const std::uint64_t rendered = ugv->cameraFramesRendered();
            std::this_thread::sleep_for(std::chrono::milliseconds(500));
            QVERIFY(ugv->cameraFramesRendered() - rendered <= 2);
        }
        // 5. Return: the server starts again on the same URL; a new client gets frames again.
        QCOMPARE(ugv->startCameras(), std::string());
        QCOMPARE(QString::fromStdString(ugv->cameraUrl(1000)), QString::fromStdString(eps[0].url));
        {
            RtspClient again(eps[0].url);
            QVERIFY2(waitFor([&] { return again.nextTimeCode(1.0).has_value(); }),
                     "no frames after the return");
        }
        stack.stop();
    }
};

QTEST_GUILESS_MAIN(TestSimCameras)
#include "test_sim_cameras.moc"
