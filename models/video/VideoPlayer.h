#pragma once
// One H.264 video stream (RTSP) played for the operator: GStreamer decodes on its own streaming
// threads (rtspsrc ! rtph264depay ! h264parse ! avdec_h264 ! videoconvert ! appsink, latency-minded: no
// jitter buffer beyond what is needed, appsink keeps only the newest frame and never waits for a clock); the
// GUI thread gets the latest frame as a QImage (latest wins: no queue grows when the GUI is slow). The player
// tracks the stream's state, reconnects on loss with a backoff, and measures resolution, frame rate, the
// decoder's CPU time and the age of the current frame (from the capture time stamped in the picture,
// protocols/common/FrameTimeCode.h, when there is one; else the time since it arrived).
//
// The GStreamer C API stays in VideoPlayer.cpp; this header is plain Qt.
#include "models/ModelClock.h"

#include <QImage>
#include <QObject>
#include <QSize>
#include <QString>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>

class QTimer;

namespace ocu {

enum class VideoState { Idle, Connecting, Playing, Lost, Reconnecting };
// Stable English keys ("idle", "connecting", "playing", "lost", "reconnecting") for headless output.
QString videoStateKey(VideoState s);
// The operator's words (translated).
QString videoStateText(VideoState s);

struct VideoFrame {
    QImage image;                          // RGB32; null before the first frame
    std::int64_t arrivalUs = 0;            // the player's clock, when the decoded frame reached the appsink
    std::optional<std::int64_t> captureUs; // the frame's time code, on the player's clock
    std::uint64_t number = 0;              // frames decoded since play()
};

struct VideoStatus {
    QString url;
    VideoState state = VideoState::Idle;
    QSize resolution;            // of the decoded frames; empty before the first
    double fps = 0;              // decoded frames per second over the last 2 s
    double decodeMsPerFrame = 0; // CPU time of decode + colour conversion per frame (mean, last 2 s)
    double decodeCpuPercent = 0; // of one core: decodeMsPerFrame * fps / 10
    std::optional<std::int64_t> frameAgeMs; // of the current frame; nullopt before the first
    bool ageFromTimeCode = false;           // frameAgeMs is capture-to-now (else arrival-to-now)
    std::uint64_t frames = 0;               // decoded since play()
    int reconnects = 0;                     // since play()
    QString error;                          // the last problem (GStreamer's message), empty when none
};

class VideoPlayer : public QObject {
    Q_OBJECT
public:
    enum class Transport { Auto, Tcp, Udp };

    explicit VideoPlayer(QObject* parent = nullptr);
    ~VideoPlayer() override;

    // False (with the reason) when GStreamer or one of the elements is missing on this machine.
    static bool available(QString* why = nullptr);

    QString url() const { return m_url; }
    // Changing the URL of a playing player switches to it (reconnect); only rtsp://, rtspt:// and rtsps://.
    void setUrl(const QString& url);
    void setTransport(Transport t) { m_transport = t; }
    void setLatencyMs(int ms) { m_latencyMs = ms; } // rtspsrc jitter buffer; default 0
    // No new frame for this long while playing: the stream is lost (then reconnect). Default 1500 ms.
    void setLossTimeoutMs(int ms) { m_lossTimeoutMs = ms; }
    // No first frame for this long after connecting: the attempt failed. Default 6000 ms.
    void setConnectTimeoutMs(int ms) { m_connectTimeoutMs = ms; }
    // First reconnect delay; it doubles up to maxMs while attempts fail. Defaults 500 / 8000 ms.
    void setReconnectBackoff(int firstMs, int maxMs);
    // The clock of frame arrivals and ages, the loss and connect timeouts and the reconnect back-off (null:
    // the system clock); a frame's time code (the camera's wall clock) is taken onto it as the frame arrives.
    void setClock(std::shared_ptr<const ModelClock> clock);
    std::shared_ptr<const ModelClock> clock() const { return m_clock; }
    std::int64_t nowUs() const;

    void play();
    void stop();
    bool isActive() const { return m_state != VideoState::Idle; }

    VideoState state() const { return m_state; }
    // The newest decoded frame (GUI thread).
    VideoFrame currentFrame() const;
    VideoStatus status() const;
    std::optional<std::int64_t> frameAgeMs() const;

signals:
    // A new frame is available (coalesced: at most one pending notification).
    void frameReady();
    void stateChanged(ocu::VideoState state);

public:
    // The state GStreamer's threads share with this player (VideoPlayer.cpp).
    struct Shared;

private:
    void startPipeline();
    void teardown();
    void setState(VideoState s);
    void onFrame(std::uint64_t generation);
    void onBusProblem(std::uint64_t generation, const QString& text);
    void lose(const QString& why);
    void tick();

    std::shared_ptr<Shared> m_shared;
    void* m_pipeline = nullptr; // GstElement*
    QString m_url;
    Transport m_transport = Transport::Auto;
    int m_latencyMs = 0;
    int m_lossTimeoutMs = 1500;
    int m_connectTimeoutMs = 6000;
    int m_backoffFirstMs = 500, m_backoffMaxMs = 8000, m_backoffMs = 500;
    VideoState m_state = VideoState::Idle;
    std::int64_t m_attemptStartUs = 0;
    std::int64_t m_reconnectAtUs = 0; // 0 = none scheduled
    int m_reconnects = 0;
    bool m_everPlayed = false;
    QString m_error;
    std::shared_ptr<const ModelClock> m_clock = systemModelClock();
    QTimer* m_timer;
};

} // namespace ocu
