#pragma once
// A small RTSP server for the console's video tests and bench_video, independent of sim/: each
// mount serves H.264 (x264, zero-latency) from an appsrc that draws a flat background of the camera's own
// grey level, a moving bar and the capture time (protocols/common/FrameTimeCode.h) at the given size and
// rate. Runs its own GLib main loop thread; binds 127.0.0.1 only. stop() drops every client (the stream is
// lost as when a camera dies); start() again serves on the same port.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace ocu::testing {

class TestRtspServer {
public:
    struct Mount {
        std::string path;        // "/front"
        std::uint8_t background; // luma of the picture below the time code (tells cameras apart)
    };
    TestRtspServer(std::vector<Mount> mounts, int width = 640, int height = 360, int fps = 30);
    ~TestRtspServer();

    // Starts serving (port 0 = a free one the first time; afterwards the same port). False on failure.
    bool start();
    void stop();
    bool running() const;
    int port() const;
    std::string url(const std::string& path) const; // rtsp://127.0.0.1:<port><path>
    // Frames pushed into the encoders so far (all mounts).
    std::uint64_t framesPushed() const;

    struct Impl;

private:
    std::unique_ptr<Impl> d;
};

} // namespace ocu::testing
