#include "sim/jaus/SimCameraServer.h"

#include <gst/app/gstappsrc.h>
#include <gst/gst.h>
#include <gst/rtsp-server/rtsp-server.h>
#include <gst/video/video-info.h>

#include <atomic>
#include <chrono>
#include <future>
#include <mutex>
#include <thread>

#include "protocols/common/Log.h"

namespace ocu::sim {

namespace {

constexpr const char* kCameraLog = "ocu.sim.camera";
using SteadyTime = std::chrono::steady_clock::time_point;

void initGstreamerOnce() {
    static std::once_flag once;
    std::call_once(once, [] { gst_init(nullptr, nullptr); });
}

// One camera, shared by the server and every media (pipeline) built for it.
struct StreamCtx {
    CameraStream cfg;
    std::atomic<std::uint64_t>* frames = nullptr;
    GstVideoInfo info{};
    // False once the server stops: a pipeline still winding down renders nothing and calls no scene
    // function (whose owner may be going away); busy counts callbacks in flight, stop() waits for them.
    std::atomic<bool> serving{false};
    std::atomic<int> busy{0};
};

// One running pipeline of a camera (created when the first client asks for it).
struct MediaCtx {
    std::shared_ptr<StreamCtx> stream;
    SteadyTime next{};
    std::vector<SceneBox> boxes;
};

// appsrc asks for a frame: wait for the frame's time (the camera's rate), render it, stamp the capture time,
// push it. Runs on the appsrc's streaming thread.
void needData(GstAppSrc* src, guint, gpointer user) {
    auto* m = static_cast<MediaCtx*>(user);
    StreamCtx& s = *m->stream;
    s.busy.fetch_add(1);
    struct Done {
        StreamCtx& s;
        ~Done() { s.busy.fetch_sub(1); }
    } done{s};
    if (!s.serving.load())
        return;
    const auto period = std::chrono::microseconds(1'000'000 / std::max(1, s.cfg.fps));
    const SteadyTime now = std::chrono::steady_clock::now();
    if (m->next == SteadyTime{} || now - m->next > 2 * period)
        m->next = now; // first frame, or fell behind (loaded machine): no burst to catch up
    else
        std::this_thread::sleep_until(m->next);
    m->next += period;

    if (!s.serving.load())
        return;
    CameraPose pose;
    m->boxes.clear();
    if (s.cfg.scene)
        s.cfg.scene(pose, m->boxes);
    GstBuffer* buf = gst_buffer_new_allocate(nullptr, GST_VIDEO_INFO_SIZE(&s.info), nullptr);
    GstMapInfo map;
    if (!buf || !gst_buffer_map(buf, &map, GST_MAP_WRITE)) {
        if (buf)
            gst_buffer_unref(buf);
        return;
    }
    I420Frame f;
    f.y = map.data + GST_VIDEO_INFO_PLANE_OFFSET(&s.info, 0);
    f.u = map.data + GST_VIDEO_INFO_PLANE_OFFSET(&s.info, 1);
    f.v = map.data + GST_VIDEO_INFO_PLANE_OFFSET(&s.info, 2);
    f.strideY = GST_VIDEO_INFO_PLANE_STRIDE(&s.info, 0);
    f.strideU = GST_VIDEO_INFO_PLANE_STRIDE(&s.info, 1);
    f.strideV = GST_VIDEO_INFO_PLANE_STRIDE(&s.info, 2);
    f.width = s.cfg.width;
    f.height = s.cfg.height;
    // The capture time: system_clock µs when the frame is taken (FrameTimeCode.h).
    const auto capture = std::chrono::duration_cast<std::chrono::microseconds>(
                             std::chrono::system_clock::now().time_since_epoch())
                             .count();
    renderCameraView(f, pose, m->boxes, std::uint64_t(capture));
    gst_buffer_unmap(buf, &map);
    GST_BUFFER_DURATION(buf) = gst_util_uint64_scale_int(GST_SECOND, 1, std::max(1, s.cfg.fps));
    gst_app_src_push_buffer(src, buf); // takes the buffer; timestamped by do-timestamp (live source)
    s.frames->fetch_add(1, std::memory_order_relaxed);
}

void destroyMediaCtx(gpointer p) {
    delete static_cast<MediaCtx*>(p);
}
void destroyStreamRef(gpointer p, GClosure*) {
    delete static_cast<std::shared_ptr<StreamCtx>*>(p);
}

void mediaConfigure(GstRTSPMediaFactory*, GstRTSPMedia* media, gpointer user) {
    const auto& stream = *static_cast<std::shared_ptr<StreamCtx>*>(user);
    GstElement* element = gst_rtsp_media_get_element(media);
    GstElement* appsrc = gst_bin_get_by_name_recurse_up(GST_BIN(element), "src");
    if (appsrc) {
        GstCaps* caps = gst_video_info_to_caps(&stream->info);
        g_object_set(appsrc, "caps", caps, "format", GST_FORMAT_TIME, "is-live", TRUE, "do-timestamp", TRUE,
                     "max-buffers", guint64(2), nullptr);
        gst_caps_unref(caps);
        GstAppSrcCallbacks cb{};
        cb.need_data = needData;
        auto* ctx = new MediaCtx{stream, {}, {}};
        gst_app_src_set_callbacks(GST_APP_SRC(appsrc), &cb, ctx, destroyMediaCtx);
        gst_object_unref(appsrc);
    }
    gst_object_unref(element);
}

GstRTSPFilterResult closeClient(GstRTSPServer*, GstRTSPClient* client, gpointer) {
    gst_rtsp_client_close(client);
    return GST_RTSP_FILTER_REMOVE;
}
GstRTSPFilterResult removeSession(GstRTSPSessionPool*, GstRTSPSession*, gpointer) {
    return GST_RTSP_FILTER_REMOVE;
}

} // namespace

struct SimCameraServer::Impl {
    std::vector<std::shared_ptr<StreamCtx>> streams;
    std::atomic<std::uint64_t> frames{0};
    mutable std::mutex mutex; // below
    GMainContext* context = nullptr;
    GMainLoop* loop = nullptr;
    std::thread thread;
    GstRTSPServer* server = nullptr;
    GSource* source = nullptr;
    std::uint16_t port = 0;
    bool running = false;

    // Runs f on the server's main-loop thread and waits for it.
    template <class F> void onLoop(F f) {
        std::promise<void> done;
        struct Call {
            F* f;
            std::promise<void>* done;
        } call{&f, &done};
        g_main_context_invoke(
            context,
            [](gpointer p) -> gboolean {
                auto* c = static_cast<Call*>(p);
                (*c->f)();
                c->done->set_value();
                return G_SOURCE_REMOVE;
            },
            &call);
        done.get_future().wait();
    }
};

SimCameraServer::SimCameraServer(std::vector<CameraStream> streams) : m_impl(std::make_unique<Impl>()) {
    for (CameraStream& s : streams) {
        auto ctx = std::make_shared<StreamCtx>();
        ctx->cfg = std::move(s);
        ctx->cfg.width = std::max(64, ctx->cfg.width & ~1);
        ctx->cfg.height = std::max(32, ctx->cfg.height & ~1);
        ctx->frames = &m_impl->frames;
        m_impl->streams.push_back(std::move(ctx));
    }
}

SimCameraServer::~SimCameraServer() {
    stop();
}

std::string SimCameraServer::start(std::uint16_t port) {
    std::lock_guard lock(m_impl->mutex);
    Impl& d = *m_impl;
    if (d.running)
        return {};
    initGstreamerOnce();
    if (port == 0)
        port = d.port; // same URL after a stop
    d.context = g_main_context_new();
    d.loop = g_main_loop_new(d.context, FALSE);
    d.server = gst_rtsp_server_new();
    gst_rtsp_server_set_address(d.server, "127.0.0.1");
    gst_rtsp_server_set_service(d.server, std::to_string(port).c_str());
    GstRTSPMountPoints* mounts = gst_rtsp_server_get_mount_points(d.server);
    for (auto& s : d.streams) {
        gst_video_info_set_format(&s->info, GST_VIDEO_FORMAT_I420, guint(s->cfg.width), guint(s->cfg.height));
        s->info.fps_n = std::max(1, s->cfg.fps);
        s->info.fps_d = 1;
        const int kbps = s->cfg.width * s->cfg.height >= 1280 * 720 ? 4000 : 1200;
        // A key frame every second: a client that joins (or returns) sees a picture within a second.
        const std::string launch =
            "( appsrc name=src ! x264enc tune=zerolatency speed-preset=ultrafast key-int-max=" +
            std::to_string(std::max(1, s->cfg.fps)) + " bitrate=" + std::to_string(kbps) +
            " threads=" + (kbps > 2000 ? "2" : "1") + " ! rtph264pay name=pay0 pt=96 config-interval=-1 )";
        GstRTSPMediaFactory* factory = gst_rtsp_media_factory_new();
        gst_rtsp_media_factory_set_launch(factory, launch.c_str());
        gst_rtsp_media_factory_set_shared(factory, TRUE);
        g_signal_connect_data(factory, "media-configure", G_CALLBACK(mediaConfigure),
                              new std::shared_ptr<StreamCtx>(s), destroyStreamRef, GConnectFlags(0));
        gst_rtsp_mount_points_add_factory(mounts, ("/" + s->cfg.path).c_str(), factory); // takes the factory
    }
    g_object_unref(mounts);
    GError* error = nullptr;
    d.source = gst_rtsp_server_create_source(d.server, nullptr, &error);
    if (!d.source) {
        std::string why = error ? error->message : "unknown error";
        if (error)
            g_error_free(error);
        g_object_unref(d.server);
        d.server = nullptr;
        g_main_loop_unref(d.loop);
        g_main_context_unref(d.context);
        d.loop = nullptr;
        d.context = nullptr;
        return "RTSP server on 127.0.0.1:" + std::to_string(port) + ": " + why;
    }
    g_source_attach(d.source, d.context);
    d.port = std::uint16_t(gst_rtsp_server_get_bound_port(d.server));
    d.thread = std::thread([ctx = d.context, loop = d.loop] {
        g_main_context_push_thread_default(ctx);
        g_main_loop_run(loop);
        g_main_context_pop_thread_default(ctx);
    });
    for (auto& s : d.streams)
        s->serving = true;
    d.running = true;
    logInfo(kCameraLog, "camera RTSP server on rtsp://127.0.0.1:" + std::to_string(d.port));
    return {};
}

void SimCameraServer::stop() {
    std::lock_guard lock(m_impl->mutex);
    Impl& d = *m_impl;
    if (!d.running)
        return;
    for (auto& s : d.streams)
        s->serving = false;
    d.onLoop([&d] {
        // Clients and their sessions go first (their pipelines stop), then the listening socket.
        gst_rtsp_server_client_filter(d.server, closeClient, nullptr);
        GstRTSPSessionPool* pool = gst_rtsp_server_get_session_pool(d.server);
        if (pool) {
            GList* left = gst_rtsp_session_pool_filter(pool, removeSession, nullptr);
            g_list_free_full(left, g_object_unref);
            g_object_unref(pool);
        }
        g_source_destroy(d.source);
        g_main_loop_quit(d.loop);
    });
    d.thread.join();
    // A frame callback still running (it may wait up to one frame period) finishes before we return.
    for (auto& s : d.streams)
        while (s->busy.load() > 0)
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
    g_source_unref(d.source);
    d.source = nullptr;
    g_object_unref(d.server);
    d.server = nullptr;
    g_main_loop_unref(d.loop);
    g_main_context_unref(d.context);
    d.loop = nullptr;
    d.context = nullptr;
    d.running = false;
    logInfo(kCameraLog, "camera RTSP server on port " + std::to_string(d.port) + " stopped");
}

bool SimCameraServer::running() const {
    std::lock_guard lock(m_impl->mutex);
    return m_impl->running;
}
std::uint16_t SimCameraServer::port() const {
    std::lock_guard lock(m_impl->mutex);
    return m_impl->port;
}
std::string SimCameraServer::url(const std::string& path) const {
    std::lock_guard lock(m_impl->mutex);
    if (!m_impl->running)
        return {};
    return "rtsp://127.0.0.1:" + std::to_string(m_impl->port) + "/" + path;
}
std::uint64_t SimCameraServer::framesRendered() const {
    return m_impl->frames.load();
}

} // namespace ocu::sim
