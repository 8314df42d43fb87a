#pragma once
// The synthetic view of a simulated UGV camera: a ground grid in perspective (2 m cells, 10 m
// lines stronger), horizon and sky, the other machines as boxes, rendered from the vehicle's pose and the
// camera's mount and pan/tilt into an I420 frame, with the capture time stamped by ocu::timecode
// (protocols/common/FrameTimeCode.h) into the top rows. Plain C++, no GStreamer: the camera server
// (SimCameraServer) calls it for each frame, tests call it directly.
#include <cstdint>
#include <vector>

namespace ocu::sim {

// Local frame of the UGV simulator: x north, y east (m), yaw clockwise from north (rad).
struct SceneBox {
    double x = 0, y = 0, yaw = 0;
    double length = 1.2, width = 0.8, height = 0.9;
};

struct CameraPose {
    double x = 0, y = 0, yaw = 0; // the vehicle
    double forwardOffset = 0.5;   // camera position along the vehicle's axis
    double height = 1.1;          // above ground
    double yawOffset = 0;         // mount (rear camera: π)
    double pan = 0, tilt = 0;     // pan-tilt (+ right, + up)
    double horizontalFov = 1.2;   // rad
};

struct I420Frame {
    std::uint8_t* y = nullptr;
    std::uint8_t* u = nullptr;
    std::uint8_t* v = nullptr;
    int strideY = 0, strideU = 0, strideV = 0;
    int width = 0, height = 0; // even
};

// Renders the view; stamps captureUnixUs (system_clock µs) as the frame's time code.
void renderCameraView(const I420Frame& frame, const CameraPose& camera, const std::vector<SceneBox>& others,
                      std::uint64_t captureUnixUs);

} // namespace ocu::sim
