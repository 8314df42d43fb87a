#pragma once
// The RTSP server of a simulated UGV's cameras: gst-rtsp-server bound to 127.0.0.1 (port 0 =
// free port), one mount point per camera, H.264 (x264enc tune=zerolatency speed-preset=ultrafast, a key
// frame every second) over RTP, from an appsrc that renders CameraScene frames at the camera's rate. One
// media per camera is shared by every client; frames are rendered only while a client plays (nothing is
// rendered when nobody watches). Stop/start for loss-and-return tests keeps the port (same URL).
// GStreamer stays inside SimCameraServer.cpp; no GLib or GStreamer type in this header.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "sim/jaus/CameraScene.h"

namespace ocu::sim {

struct CameraStream {
    std::string path; // mount point without the leading '/'
    int width = 640, height = 360, fps = 15;
    // Called on the stream's thread for each frame: the camera's pose and the boxes to draw.
    std::function<void(CameraPose&, std::vector<SceneBox>&)> scene;
};

class SimCameraServer {
public:
    explicit SimCameraServer(std::vector<CameraStream> streams);
    ~SimCameraServer();
    SimCameraServer(const SimCameraServer&) = delete;
    SimCameraServer& operator=(const SimCameraServer&) = delete;

    // Starts serving on 127.0.0.1:port (0: a free port the first time, the same port after a stop).
    // Returns an empty string, or why it could not start.
    std::string start(std::uint16_t port = 0);
    // Closes every client connection and the listening socket; frames stop.
    void stop();
    bool running() const;
    std::uint16_t port() const;
    // rtsp://127.0.0.1:<port>/<path>; empty while not running.
    std::string url(const std::string& path) const;
    // Frames rendered so far (all streams; tests and the "nothing rendered when idle" rule).
    std::uint64_t framesRendered() const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace ocu::sim
