#include "models/video/VideoPlayer.h"

#include "protocols/common/FrameTimeCode.h"

#include <QCoreApplication>
#include <QMetaObject>
#include <QTimer>

#include <gst/app/gstappsink.h>
#include <gst/gst.h>
#include <gst/video/video.h>

#include <atomic>
#include <chrono>
#include <cstring>
#include <ctime>
#include <deque>
#include <mutex>

namespace ocu {

namespace {

std::int64_t threadCpuNs() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return std::int64_t(ts.tv_sec) * 1000000000 + ts.tv_nsec;
}

// CPU time of this streaming thread when the decoder took its last access unit (decode, colour conversion
// and the copy into the QImage run on the same thread, avdec_h264 with one thread and no frame delay).
thread_local std::int64_t t_decodeStartNs = -1;

bool initGst(QString* why) {
    static std::once_flag once;
    static bool ok = false;
    static QString error;
    std::call_once(once, [] {
        GError* err = nullptr;
        ok = gst_init_check(nullptr, nullptr, &err);
        if (!ok) {
            error = err ? QString::fromUtf8(err->message) : QStringLiteral("gst_init failed");
            if (err)
                g_error_free(err);
            return;
        }
        for (const char* f :
             {"rtspsrc", "rtph264depay", "h264parse", "avdec_h264", "videoconvert", "appsink"}) {
            if (GstElementFactory* fac = gst_element_factory_find(f)) {
                gst_object_unref(fac);
            } else {
                ok = false;
                error = QStringLiteral("GStreamer element %1 is missing (install gstreamer1.0-plugins-good, "
                                       "-bad and gstreamer1.0-libav)")
                            .arg(QLatin1String(f));
                return;
            }
        }
    });
    if (why)
        *why = error;
    return ok;
}

} // namespace

QString videoStateKey(VideoState s) {
    switch (s) {
    case VideoState::Idle:
        return QStringLiteral("idle");
    case VideoState::Connecting:
        return QStringLiteral("connecting");
    case VideoState::Playing:
        return QStringLiteral("playing");
    case VideoState::Lost:
        return QStringLiteral("lost");
    case VideoState::Reconnecting:
        return QStringLiteral("reconnecting");
    }
    return {};
}

QString videoStateText(VideoState s) {
    switch (s) {
    case VideoState::Idle:
        return QCoreApplication::translate("ocu::VideoPlayer", "no video");
    case VideoState::Connecting:
        return QCoreApplication::translate("ocu::VideoPlayer", "connecting");
    case VideoState::Playing:
        return QCoreApplication::translate("ocu::VideoPlayer", "playing");
    case VideoState::Lost:
        return QCoreApplication::translate("ocu::VideoPlayer", "video LOST");
    case VideoState::Reconnecting:
        return QCoreApplication::translate("ocu::VideoPlayer", "reconnecting");
    }
    return {};
}

// What the streaming threads share with the GUI thread. The callbacks hold it by shared_ptr (through the
// pipeline's user data), so it outlives the player if GStreamer finishes a pipeline late.
struct VideoPlayer::Shared {
    std::mutex mutex;
    VideoPlayer* owner = nullptr; // cleared (under the mutex) by the player's destructor
    std::uint64_t generation = 0; // the pipeline frames are accepted from
    VideoFrame latest;
    bool notifyPending = false;
    std::deque<std::int64_t> arrivals; // µs, last 2 s
    std::deque<std::int64_t> decodeNs; // per frame, last 60
    QString lastError;
    std::shared_ptr<const ModelClock> clock = systemModelClock(); // the player's, under the mutex

    // Posts f to the owner's thread while the owner lives.
    template <typename F> void post(F&& f) {
        // Called with mutex held.
        if (owner)
            QMetaObject::invokeMethod(owner, std::forward<F>(f), Qt::QueuedConnection);
    }
    // Streaming threads: a frame of pipeline `gen` decoded (kept as the latest, the rates updated, the owner
    // told unless a notification is pending; arrival now on the clock, the time code's wall-clock capture
    // time taken onto it); an error or end of stream of pipeline `gen`.
    void frameDecoded(std::uint64_t gen, QImage img, std::optional<std::int64_t> captureWallUs,
                      std::int64_t cpuNs);
    void busProblem(std::uint64_t gen, const QString& text);
};

void VideoPlayer::Shared::frameDecoded(std::uint64_t gen, QImage img,
                                       std::optional<std::int64_t> captureWallUs, std::int64_t cpuNs) {
    std::lock_guard lock(mutex);
    if (generation != gen)
        return; // an old pipeline on its way down
    const std::int64_t arrivalUs = clock->nowUs();
    latest.image = std::move(img);
    latest.arrivalUs = arrivalUs;
    latest.captureUs.reset();
    if (captureWallUs)
        latest.captureUs = wallStampToModelUs(*clock, *captureWallUs);
    ++latest.number;
    arrivals.push_back(arrivalUs);
    while (!arrivals.empty() && arrivals.front() < arrivalUs - 2000000)
        arrivals.pop_front();
    if (cpuNs >= 0) {
        decodeNs.push_back(cpuNs);
        while (decodeNs.size() > 60)
            decodeNs.pop_front();
    }
    if (!notifyPending && owner) {
        notifyPending = true;
        VideoPlayer* o = owner;
        post([o, gen] { o->onFrame(gen); });
    }
}

void VideoPlayer::Shared::busProblem(std::uint64_t gen, const QString& text) {
    std::lock_guard lock(mutex);
    if (owner && generation == gen) {
        VideoPlayer* o = owner;
        post([o, gen, text] { o->onBusProblem(gen, text); });
    }
}

namespace {

struct PipelineContext {
    std::shared_ptr<VideoPlayer::Shared> shared;
    std::uint64_t generation;
    GstElement* depay;
};

void destroyContext(gpointer p) {
    delete static_cast<PipelineContext*>(p);
}

// The elements of one pipeline: rtspsrc ! rtph264depay ! h264parse ! avdec_h264 ! videoconvert ! appsink.
struct Elements {
    GstElement *pipe, *src, *depay, *parse, *dec, *conv, *sink;
};

// False when one is missing (the others are released).
bool makeElements(Elements& e) {
    e.pipe = gst_pipeline_new("ocu-video");
    e.src = gst_element_factory_make("rtspsrc", "src");
    e.depay = gst_element_factory_make("rtph264depay", "depay");
    e.parse = gst_element_factory_make("h264parse", "parse");
    e.dec = gst_element_factory_make("avdec_h264", "dec");
    e.conv = gst_element_factory_make("videoconvert", "conv");
    e.sink = gst_element_factory_make("appsink", "sink");
    if (e.pipe && e.src && e.depay && e.parse && e.dec && e.conv && e.sink)
        return true;
    for (GstElement* x : {e.pipe, e.src, e.depay, e.parse, e.dec, e.conv, e.sink})
        if (x)
            gst_object_unref(x);
    return false;
}

void configureElements(const Elements& e, const QByteArray& url, int latencyMs,
                       VideoPlayer::Transport transport) {
    g_object_set(e.src, "location", url.constData(), "latency", guint(std::max(0, latencyMs)),
                 "drop-on-latency", TRUE, "do-retransmission", FALSE, "tcp-timeout", guint64(2000000),
                 "timeout", guint64(2000000), nullptr);
    if (transport == VideoPlayer::Transport::Tcp)
        gst_util_set_object_arg(G_OBJECT(e.src), "protocols", "tcp");
    else if (transport == VideoPlayer::Transport::Udp)
        gst_util_set_object_arg(G_OBJECT(e.src), "protocols", "udp");
    // One decoder thread: no frame-threading delay (each frame comes out as its access unit goes in), and
    // its CPU time is measurable on the streaming thread. Corrupt frames (before the first key frame after
    // a loss) are dropped rather than shown.
    g_object_set(e.dec, "max-threads", 1, "output-corrupt", FALSE, nullptr);
    GstCaps* caps = gst_caps_new_simple("video/x-raw", "format", G_TYPE_STRING, "BGRx", nullptr);
    g_object_set(e.sink, "caps", caps, "drop", TRUE, "max-buffers", guint(1), "sync", FALSE, "emit-signals",
                 FALSE, "enable-last-sample", FALSE, nullptr);
    gst_caps_unref(caps);
}

// rtspsrc's pads appear once the stream is described: link the H.264 video one.
void onPadAdded(GstElement*, GstPad* pad, gpointer p) {
    auto* c = static_cast<PipelineContext*>(p);
    GstCaps* pc = gst_pad_get_current_caps(pad);
    if (!pc)
        pc = gst_pad_query_caps(pad, nullptr);
    bool h264 = false;
    QString encoding;
    if (pc && gst_caps_get_size(pc) > 0) {
        const GstStructure* st = gst_caps_get_structure(pc, 0);
        const gchar* media = gst_structure_get_string(st, "media");
        const gchar* enc = gst_structure_get_string(st, "encoding-name");
        encoding = QString::fromUtf8(enc ? enc : "?");
        h264 = media && g_str_equal(media, "video") && enc && g_ascii_strcasecmp(enc, "H264") == 0;
    }
    if (pc)
        gst_caps_unref(pc);
    if (!h264) {
        std::lock_guard lock(c->shared->mutex);
        c->shared->lastError = QStringLiteral("stream encoding %1 is not H.264").arg(encoding);
        return;
    }
    GstPad* sinkPad = gst_element_get_static_pad(c->depay, "sink");
    if (!gst_pad_is_linked(sinkPad))
        gst_pad_link(pad, sinkPad);
    gst_object_unref(sinkPad);
}

// Decode CPU time: mark the thread's CPU clock as an access unit enters the decoder.
GstPadProbeReturn onDecoderInput(GstPad*, GstPadProbeInfo*, gpointer) {
    t_decodeStartNs = threadCpuNs();
    return GST_PAD_PROBE_OK;
}

// A decoded frame: copied into a QImage, its capture time code read, handed to the shared state.
GstFlowReturn onNewSample(GstAppSink* appsink, gpointer p) {
    auto* c = static_cast<PipelineContext*>(p);
    GstSample* sample = gst_app_sink_pull_sample(appsink);
    if (!sample)
        return GST_FLOW_OK;
    GstBuffer* buf = gst_sample_get_buffer(sample);
    GstVideoInfo info;
    GstMapInfo map;
    if (!buf || !gst_video_info_from_caps(&info, gst_sample_get_caps(sample)) ||
        !gst_buffer_map(buf, &map, GST_MAP_READ)) {
        gst_sample_unref(sample);
        return GST_FLOW_OK;
    }
    const int w = GST_VIDEO_INFO_WIDTH(&info), h = GST_VIDEO_INFO_HEIGHT(&info);
    const int stride = GST_VIDEO_INFO_PLANE_STRIDE(&info, 0);
    QImage img(w, h, QImage::Format_RGB32);
    if (!img.isNull() && std::size_t(stride) * std::size_t(h) <= map.size) {
        for (int y = 0; y < h; ++y)
            std::memcpy(img.scanLine(y), map.data + std::size_t(y) * stride, std::size_t(w) * 4);
    }
    gst_buffer_unmap(buf, &map);
    gst_sample_unref(sample);
    if (img.isNull())
        return GST_FLOW_OK;
    // The time code is drawn in luma; in BGRx every channel carries it (green is the one least
    // disturbed by chroma).
    std::optional<std::int64_t> capture;
    if (auto v = timecode::read(img.constBits() + 1, w, h, img.bytesPerLine(), 4))
        capture = static_cast<std::int64_t>(*v);
    const std::int64_t cpu = t_decodeStartNs >= 0 ? threadCpuNs() - t_decodeStartNs : -1;
    t_decodeStartNs = -1;
    c->shared->frameDecoded(c->generation, std::move(img), capture, cpu);
    return GST_FLOW_OK;
}

// Errors and end of stream come from the streaming threads: handed to the GUI thread, never queued on the
// bus (nobody pops it).
GstBusSyncReply onBusMessage(GstBus*, GstMessage* msg, gpointer p) {
    auto* c = static_cast<PipelineContext*>(p);
    QString text;
    if (GST_MESSAGE_TYPE(msg) == GST_MESSAGE_ERROR) {
        GError* err = nullptr;
        gst_message_parse_error(msg, &err, nullptr);
        text = err ? QString::fromUtf8(err->message) : QStringLiteral("error");
        if (err)
            g_error_free(err);
    } else if (GST_MESSAGE_TYPE(msg) == GST_MESSAGE_EOS) {
        text = QStringLiteral("end of stream");
    } else {
        return GST_BUS_DROP;
    }
    c->shared->busProblem(c->generation, text);
    return GST_BUS_DROP;
}

// The callbacks of pipeline `generation`, each with its own context (freed with the callback).
void connectCallbacks(const Elements& e, const std::shared_ptr<VideoPlayer::Shared>& shared,
                      std::uint64_t generation) {
    g_signal_connect_data(
        e.src, "pad-added", G_CALLBACK(onPadAdded), new PipelineContext{shared, generation, e.depay},
        +[](gpointer p, GClosure*) { destroyContext(p); }, GConnectFlags(0));
    GstPad* decSink = gst_element_get_static_pad(e.dec, "sink");
    gst_pad_add_probe(decSink, GST_PAD_PROBE_TYPE_BUFFER, onDecoderInput, nullptr, nullptr);
    gst_object_unref(decSink);
    GstAppSinkCallbacks cbs{};
    cbs.new_sample = onNewSample;
    gst_app_sink_set_callbacks(GST_APP_SINK(e.sink), &cbs, new PipelineContext{shared, generation, e.depay},
                               destroyContext);
    GstBus* bus = gst_element_get_bus(e.pipe);
    gst_bus_set_sync_handler(bus, onBusMessage, new PipelineContext{shared, generation, e.depay},
                             destroyContext);
    gst_object_unref(bus);
}

} // namespace

VideoPlayer::VideoPlayer(QObject* parent)
    : QObject(parent), m_shared(std::make_shared<Shared>()), m_timer(new QTimer(this)) {
    m_shared->owner = this;
    m_timer->setInterval(100);
    connect(m_timer, &QTimer::timeout, this, &VideoPlayer::tick);
}

VideoPlayer::~VideoPlayer() {
    {
        std::lock_guard lock(m_shared->mutex);
        m_shared->owner = nullptr;
        ++m_shared->generation;
    }
    teardown();
}

bool VideoPlayer::available(QString* why) {
    return initGst(why);
}

void VideoPlayer::setUrl(const QString& url) {
    if (url == m_url)
        return;
    m_url = url;
    if (m_state != VideoState::Idle) {
        teardown();
        m_everPlayed = false;
        m_reconnects = 0;
        m_backoffMs = m_backoffFirstMs;
        startPipeline();
    }
}

void VideoPlayer::setReconnectBackoff(int firstMs, int maxMs) {
    m_backoffFirstMs = std::max(10, firstMs);
    m_backoffMaxMs = std::max(m_backoffFirstMs, maxMs);
    m_backoffMs = m_backoffFirstMs;
}

void VideoPlayer::setClock(std::shared_ptr<const ModelClock> clock) {
    m_clock = clockOrSystem(std::move(clock));
    std::lock_guard lock(m_shared->mutex);
    m_shared->clock = m_clock;
}

std::int64_t VideoPlayer::nowUs() const {
    return m_clock->nowUs();
}

void VideoPlayer::play() {
    if (m_state != VideoState::Idle)
        return;
    m_everPlayed = false;
    m_reconnects = 0;
    m_backoffMs = m_backoffFirstMs;
    {
        std::lock_guard lock(m_shared->mutex);
        m_shared->latest = {};
        m_shared->arrivals.clear();
        m_shared->decodeNs.clear();
    }
    m_timer->start();
    startPipeline();
}

void VideoPlayer::stop() {
    m_timer->stop();
    teardown();
    m_reconnectAtUs = 0;
    setState(VideoState::Idle);
}

void VideoPlayer::setState(VideoState s) {
    if (s == m_state)
        return;
    m_state = s;
    emit stateChanged(s);
}

void VideoPlayer::startPipeline() {
    m_reconnectAtUs = 0;
    m_attemptStartUs = m_clock->nowUs();
    setState(m_everPlayed || m_reconnects > 0 ? VideoState::Reconnecting : VideoState::Connecting);
    QString why;
    if (!initGst(&why)) {
        m_error = why;
        lose(why);
        return;
    }
    const bool rtsp = m_url.startsWith(QLatin1String("rtsp://")) ||
                      m_url.startsWith(QLatin1String("rtspt://")) ||
                      m_url.startsWith(QLatin1String("rtsps://"));
    if (!rtsp) {
        m_error = m_url.isEmpty() ? tr("no video URL") : tr("not an RTSP URL: %1").arg(m_url.left(200));
        lose(m_error);
        return;
    }
    std::uint64_t generation;
    {
        std::lock_guard lock(m_shared->mutex);
        generation = ++m_shared->generation;
        m_shared->lastError.clear();
    }

    Elements e{};
    if (!makeElements(e)) {
        m_error = tr("GStreamer elements missing");
        lose(m_error);
        return;
    }
    configureElements(e, m_url.toUtf8(), m_latencyMs, m_transport);
    gst_bin_add_many(GST_BIN(e.pipe), e.src, e.depay, e.parse, e.dec, e.conv, e.sink, nullptr);
    if (!gst_element_link_many(e.depay, e.parse, e.dec, e.conv, e.sink, nullptr)) {
        gst_object_unref(e.pipe);
        m_error = tr("cannot link the video pipeline");
        lose(m_error);
        return;
    }
    connectCallbacks(e, m_shared, generation);
    m_pipeline = e.pipe;
    // Asynchronous: rtspsrc connects on its own thread; the GUI thread does not wait for the server.
    if (gst_element_set_state(e.pipe, GST_STATE_PLAYING) == GST_STATE_CHANGE_FAILURE) {
        m_error = tr("the video pipeline did not start");
        lose(m_error);
    }
}

void VideoPlayer::teardown() {
    if (!m_pipeline)
        return;
    {
        std::lock_guard lock(m_shared->mutex);
        ++m_shared->generation; // whatever the old pipeline still delivers is ignored
        m_shared->notifyPending = false;
    }
    auto* pipe = static_cast<GstElement*>(m_pipeline);
    m_pipeline = nullptr;
    // Going to NULL closes the RTSP session (a TEARDOWN, bounded by tcp-timeout): on one of GStreamer's
    // threads, never blocking the GUI thread. call_async keeps its own reference until done.
    gst_element_call_async(
        pipe, +[](GstElement* e, gpointer) { gst_element_set_state(e, GST_STATE_NULL); }, nullptr, nullptr);
    gst_object_unref(pipe);
}

void VideoPlayer::onFrame(std::uint64_t generation) {
    {
        std::lock_guard lock(m_shared->mutex);
        m_shared->notifyPending = false;
        if (generation != m_shared->generation)
            return;
    }
    if (m_state == VideoState::Connecting || m_state == VideoState::Reconnecting) {
        m_everPlayed = true;
        m_backoffMs = m_backoffFirstMs;
        m_error.clear();
        setState(VideoState::Playing);
    }
    emit frameReady();
}

void VideoPlayer::onBusProblem(std::uint64_t generation, const QString& text) {
    {
        std::lock_guard lock(m_shared->mutex);
        if (generation != m_shared->generation)
            return;
    }
    m_error = text;
    lose(text);
}

void VideoPlayer::lose(const QString& why) {
    m_error = why;
    teardown();
    setState(VideoState::Lost);
    m_reconnectAtUs = m_clock->nowUs() + std::int64_t(m_backoffMs) * 1000;
    m_backoffMs = std::min(m_backoffMaxMs, m_backoffMs * 2);
}

void VideoPlayer::tick() {
    const std::int64_t now = m_clock->nowUs();
    switch (m_state) {
    case VideoState::Idle:
        return;
    case VideoState::Lost:
        if (m_reconnectAtUs && now >= m_reconnectAtUs) {
            ++m_reconnects;
            startPipeline();
        }
        return;
    case VideoState::Connecting:
    case VideoState::Reconnecting:
        if (now - m_attemptStartUs > std::int64_t(m_connectTimeoutMs) * 1000) {
            QString why;
            {
                std::lock_guard lock(m_shared->mutex);
                why = m_shared->lastError;
            }
            lose(why.isEmpty() ? tr("no video from %1").arg(m_url.left(200)) : why);
        }
        return;
    case VideoState::Playing: {
        std::int64_t last;
        {
            std::lock_guard lock(m_shared->mutex);
            last = m_shared->latest.arrivalUs;
        }
        if (m_clock->nowUs() - last > std::int64_t(m_lossTimeoutMs) * 1000)
            lose(tr("no frame for %1 ms").arg(m_lossTimeoutMs));
        return;
    }
    }
}

VideoFrame VideoPlayer::currentFrame() const {
    std::lock_guard lock(m_shared->mutex);
    return m_shared->latest;
}

std::optional<std::int64_t> VideoPlayer::frameAgeMs() const {
    VideoFrame f;
    {
        std::lock_guard lock(m_shared->mutex);
        if (m_shared->latest.number == 0)
            return std::nullopt;
        f.arrivalUs = m_shared->latest.arrivalUs;
        f.captureUs = m_shared->latest.captureUs;
    }
    const std::int64_t now = m_clock->nowUs();
    return std::max<std::int64_t>(0, (now - f.captureUs.value_or(f.arrivalUs)) / 1000);
}

VideoStatus VideoPlayer::status() const {
    VideoStatus s;
    s.url = m_url;
    s.state = m_state;
    s.reconnects = m_reconnects;
    s.error = m_error;
    const std::int64_t now = m_clock->nowUs();
    {
        std::lock_guard lock(m_shared->mutex);
        const VideoFrame& f = m_shared->latest;
        s.frames = f.number;
        if (f.number) {
            s.resolution = f.image.size();
            s.ageFromTimeCode = f.captureUs.has_value();
        }
        // Frames decoded within the last 2 s (the rate falls to 0 when frames stop).
        int n = 0;
        std::int64_t first = 0;
        for (std::int64_t t : m_shared->arrivals)
            if (t >= now - 2000000) {
                if (!n)
                    first = t;
                ++n;
            }
        if (n >= 2)
            s.fps = (n - 1) * 1e6 / double(std::max<std::int64_t>(1, now - first));
        if (!m_shared->decodeNs.empty()) {
            double sum = 0;
            for (std::int64_t ns : m_shared->decodeNs)
                sum += double(ns);
            s.decodeMsPerFrame = sum / double(m_shared->decodeNs.size()) / 1e6;
        }
    }
    s.decodeCpuPercent = s.decodeMsPerFrame * s.fps / 10.0;
    if (m_state == VideoState::Idle)
        s.fps = 0;
    s.frameAgeMs = frameAgeMs();
    return s;
}

} // namespace ocu
