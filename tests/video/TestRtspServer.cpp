#include "tests/video/TestRtspServer.h"

#include "protocols/common/FrameTimeCode.h"

#include <gst/app/gstappsrc.h>
#include <gst/gst.h>
#include <gst/rtsp-server/rtsp-server.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstring>
#include <mutex>
#include <thread>

namespace ocu::testing {

struct TestRtspServer::Impl {
    std::vector<Mount> mounts;
    int width, height, fps;
    int port = 0;
    GMainContext* context = nullptr;
    GMainLoop* loop = nullptr;
    GstRTSPServer* server = nullptr;
    guint sourceId = 0;
    std::thread thread;
    std::shared_ptr<std::atomic<std::uint64_t>> frames = std::make_shared<std::atomic<std::uint64_t>>(0);
    std::vector<GstRTSPMedia*> medias; // prepared on the loop thread, unprepared by stop() there
};

namespace {

// Copied per media: the media's threads may run a little longer than the server object.
struct MediaData {
    TestRtspServer::Impl* impl; // only in media-configure (on the loop thread)
    std::uint8_t background;
    int width = 0, height = 0, fps = 30;
    std::shared_ptr<std::atomic<std::uint64_t>> frames;
    std::uint64_t count = 0;
    std::chrono::steady_clock::time_point next{};
};

std::int64_t systemNowUs() {
    return std::chrono::duration_cast<std::chrono::microseconds>(
               std::chrono::system_clock::now().time_since_epoch())
        .count();
}

// appsrc asks for data on its own streaming thread: pace to the frame rate there, stamp the capture time
// just before the frame goes into the encoder.
void needData(GstElement* appsrc, guint, gpointer p) {
    auto* m = static_cast<MediaData*>(p);
    const auto period = std::chrono::microseconds(1000000 / m->fps);
    const auto now = std::chrono::steady_clock::now();
    if (m->next.time_since_epoch().count() == 0 || m->next < now - period * 3)
        m->next = now;
    std::this_thread::sleep_until(m->next);
    m->next += period;
    const int w = m->width, h = m->height;
    const gsize ySize = gsize(w) * h, cSize = gsize(w / 2) * (h / 2);
    GstBuffer* buf = gst_buffer_new_allocate(nullptr, ySize + 2 * cSize, nullptr);
    GstMapInfo map;
    gst_buffer_map(buf, &map, GST_MAP_WRITE);
    std::memset(map.data, m->background, ySize);
    const int bar = int((m->count * 8) % std::uint64_t(w));
    for (int y = h / 3; y < h; ++y)
        std::memset(map.data + gsize(y) * w + bar, 235, std::min(16, w - bar));
    std::memset(map.data + ySize, 128, 2 * cSize);
    timecode::stamp(map.data, w, h, w, std::uint64_t(systemNowUs()));
    gst_buffer_unmap(buf, &map);
    ++m->count;
    ++*m->frames;
    gst_app_src_push_buffer(GST_APP_SRC(appsrc), buf);
}

void mediaConfigure(GstRTSPMediaFactory*, GstRTSPMedia* media, gpointer p) {
    auto* proto = static_cast<MediaData*>(p);
    GstElement* bin = gst_rtsp_media_get_element(media);
    GstElement* src = gst_bin_get_by_name_recurse_up(GST_BIN(bin), "src");
    TestRtspServer::Impl& d = *proto->impl;
    auto* m = new MediaData{nullptr, proto->background, d.width, d.height, d.fps, d.frames};
    d.medias.push_back(GST_RTSP_MEDIA(g_object_ref(media)));
    GstCaps* caps = gst_caps_new_simple("video/x-raw", "format", G_TYPE_STRING, "I420", "width", G_TYPE_INT,
                                        proto->impl->width, "height", G_TYPE_INT, proto->impl->height,
                                        "framerate", GST_TYPE_FRACTION, proto->impl->fps, 1, nullptr);
    g_object_set(src, "caps", caps, "format", GST_FORMAT_TIME, "is-live", TRUE, "do-timestamp", TRUE,
                 nullptr);
    gst_caps_unref(caps);
    g_signal_connect_data(
        src, "need-data", G_CALLBACK(needData), m,
        +[](gpointer q, GClosure*) { delete static_cast<MediaData*>(q); }, GConnectFlags(0));
    gst_object_unref(src);
    gst_object_unref(bin);
}

} // namespace

TestRtspServer::TestRtspServer(std::vector<Mount> mounts, int width, int height, int fps)
    : d(std::make_unique<Impl>()) {
    d->mounts = std::move(mounts);
    d->width = width;
    d->height = height;
    d->fps = fps;
    gst_init(nullptr, nullptr);
}

TestRtspServer::~TestRtspServer() {
    stop();
}

bool TestRtspServer::running() const {
    return d->server != nullptr;
}

int TestRtspServer::port() const {
    return d->port;
}

std::string TestRtspServer::url(const std::string& path) const {
    return "rtsp://127.0.0.1:" + std::to_string(d->port) + path;
}

std::uint64_t TestRtspServer::framesPushed() const {
    return *d->frames;
}

bool TestRtspServer::start() {
    if (d->server)
        return true;
    d->context = g_main_context_new();
    d->loop = g_main_loop_new(d->context, FALSE);
    d->server = gst_rtsp_server_new();
    gst_rtsp_server_set_address(d->server, "127.0.0.1");
    gst_rtsp_server_set_service(d->server, std::to_string(d->port).c_str());
    GstRTSPMountPoints* mounts = gst_rtsp_server_get_mount_points(d->server);
    for (const Mount& m : d->mounts) {
        GstRTSPMediaFactory* f = gst_rtsp_media_factory_new();
        gst_rtsp_media_factory_set_launch(
            f,
            "( appsrc name=src ! x264enc tune=zerolatency speed-preset=ultrafast key-int-max=15 bitrate=3000 "
            "threads=1 ! video/x-h264,profile=baseline ! rtph264pay name=pay0 pt=96 config-interval=-1 )");
        gst_rtsp_media_factory_set_shared(f, TRUE);
        auto* proto = new MediaData{d.get(), m.background, 0, 0, 0, nullptr};
        g_signal_connect_data(
            f, "media-configure", G_CALLBACK(mediaConfigure), proto,
            +[](gpointer q, GClosure*) { delete static_cast<MediaData*>(q); }, GConnectFlags(0));
        gst_rtsp_mount_points_add_factory(mounts, m.path.c_str(), f);
    }
    g_object_unref(mounts);
    d->sourceId = gst_rtsp_server_attach(d->server, d->context);
    if (!d->sourceId) {
        g_object_unref(d->server);
        d->server = nullptr;
        g_main_loop_unref(d->loop);
        g_main_context_unref(d->context);
        return false;
    }
    d->port = gst_rtsp_server_get_bound_port(d->server);
    d->thread = std::thread([loop = d->loop] { g_main_loop_run(loop); });
    return true;
}

void TestRtspServer::stop() {
    if (!d->server)
        return;
    // On the server's own loop: stop listening, close every session and connection.
    struct Ctx {
        Impl* d = nullptr;
        std::mutex m;
        std::condition_variable cv;
        bool done = false;
    } ctx;
    ctx.d = d.get();
    GSource* idle = g_idle_source_new();
    g_source_set_callback(
        idle,
        +[](gpointer p) -> gboolean {
            auto* c = static_cast<Ctx*>(p);
            if (GSource* s = g_main_context_find_source_by_id(c->d->context, c->d->sourceId))
                g_source_destroy(s);
            gst_rtsp_server_client_filter(
                c->d->server,
                +[](GstRTSPServer*, GstRTSPClient*, gpointer) { return GST_RTSP_FILTER_REMOVE; }, nullptr);
            if (GstRTSPSessionPool* pool = gst_rtsp_server_get_session_pool(c->d->server)) {
                gst_rtsp_session_pool_filter(
                    pool,
                    +[](GstRTSPSessionPool*, GstRTSPSession*, gpointer) { return GST_RTSP_FILTER_REMOVE; },
                    nullptr);
                g_object_unref(pool);
            }
            for (GstRTSPMedia* media : c->d->medias) {
                gst_rtsp_media_unprepare(media);
                g_object_unref(media);
            }
            c->d->medias.clear();
            g_main_loop_quit(c->d->loop);
            std::lock_guard l(c->m);
            c->done = true;
            c->cv.notify_all();
            return G_SOURCE_REMOVE;
        },
        &ctx, nullptr);
    g_source_attach(idle, d->context);
    g_source_unref(idle);
    {
        std::unique_lock l(ctx.m);
        ctx.cv.wait(l, [&] { return ctx.done; });
    }
    d->thread.join();
    g_object_unref(d->server);
    d->server = nullptr;
    g_main_loop_unref(d->loop);
    d->loop = nullptr;
    g_main_context_unref(d->context);
    d->context = nullptr;
}

} // namespace ocu::testing
