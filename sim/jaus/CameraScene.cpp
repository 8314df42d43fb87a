#include "sim/jaus/CameraScene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include "protocols/common/FrameTimeCode.h"

namespace ocu::sim {

namespace {

struct V3 {
    double x, y, z; // north, east, up
};
V3 operator+(V3 a, V3 b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
V3 operator-(V3 a, V3 b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
V3 operator*(double s, V3 a) {
    return {s * a.x, s * a.y, s * a.z};
}
double dot(V3 a, V3 b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

// Distance of v to the nearest multiple of cell, in the same units.
double toLine(double v, double cell) {
    const double f = v / cell - std::floor(v / cell + 0.5);
    return std::abs(f) * cell;
}

// The camera's basis and projection for one frame.
struct View {
    int w = 0, h = 0;
    V3 fwd0, right, up, fwd, eye; // fwd0: the heading without tilt
    double fpx = 0;               // focal length in pixels
    double cx = 0, cy = 0;        // image centre
};

View viewOf(const I420Frame& f, const CameraPose& c) {
    View v;
    v.w = f.width;
    v.h = f.height;
    // Camera basis: forward (heading + tilt), right, up.
    const double psi = c.yaw + c.yawOffset + c.pan;
    v.fwd0 = V3{std::cos(psi), std::sin(psi), 0};
    v.right = V3{-std::sin(psi), std::cos(psi), 0};
    const V3 up0{0, 0, 1};
    v.fwd = std::cos(c.tilt) * v.fwd0 + std::sin(c.tilt) * up0;
    v.up = -std::sin(c.tilt) * v.fwd0 + std::cos(c.tilt) * up0;
    v.eye = V3{c.x + c.forwardOffset * std::cos(c.yaw), c.y + c.forwardOffset * std::sin(c.yaw), c.height};
    v.fpx = (v.w / 2.0) / std::tan(std::clamp(c.horizontalFov, 0.1, 3.0) / 2);
    v.cx = v.w / 2.0;
    v.cy = v.h / 2.0;
    return v;
}

// Sky and the ground grid, luma and chroma.
void drawGround(const I420Frame& f, const CameraPose& c, const View& v) {
    const int w = v.w, h = v.h;
    const V3 fwd = v.fwd, right = v.right, up = v.up, eye = v.eye, fwd0 = v.fwd0;
    const double fpx = v.fpx, cx = v.cx, cy = v.cy;
    // Per row the ray's vertical component is constant (no roll): sky or ground, and the ground hit point
    // moves linearly along the row.
    std::vector<std::uint8_t> rowChroma(std::size_t(h / 2 + 1), 0); // 0 sky, 1 ground
    for (int py = 0; py < h; ++py) {
        std::uint8_t* row = f.y + std::ptrdiff_t(py) * f.strideY;
        const double b = -(py + 0.5 - cy) / fpx;
        const V3 base = fwd + b * up;
        const V3 step = (1.0 / fpx) * right;
        const V3 d0 = base + (-(cx - 0.5) / fpx) * right; // ray of pixel 0
        if (d0.z >= -1e-6) {
            // Sky: brighter towards the horizon.
            const double elev = std::atan2(d0.z, std::hypot(d0.x, d0.y));
            const auto yv = std::uint8_t(std::clamp(190.0 - 120.0 * elev, 90.0, 190.0));
            std::memset(row, yv, std::size_t(w));
            rowChroma[std::size_t(py / 2)] = 0;
            continue;
        }
        rowChroma[std::size_t(py / 2)] = 1;
        const double t = -c.height / d0.z; // same for every pixel of the row (d.z constant)
        V3 p = eye + t * d0;
        const V3 dp = t * step;
        const V3 dc = base; // the row's centre ray
        const double dist = t * std::sqrt(dot(dc, dc));
        const double fog = 1.0 - std::exp(-dist / 120.0);
        // Line half-width grows with distance so lines stay about a pixel wide; far lines fade out instead
        // of aliasing into noise (which would also cost the encoder bits).
        // A line must be about a pixel wide across the view, and as wide as a row's ground footprint in depth
        // (about dist² / (fpx · height)) where it runs across the view, or it breaks into dashes. Lines of
        // constant x (north) run across a view facing north; lines of constant y across a view facing east.
        const double lwPx = std::max(0.04, 1.2 * dist / fpx);
        const double lwRow = std::max(lwPx, 0.6 * dist * dist / (fpx * c.height));
        const double cx0 = std::abs(fwd0.x), cy0 = std::abs(fwd0.y);
        const double lwX = lwPx * cy0 + lwRow * cx0, lwY = lwPx * cx0 + lwRow * cy0;
        const double fine = std::clamp(1.0 - dist / 30.0, 0.0, 1.0);
        const double coarse = std::clamp(1.0 - dist / 90.0, 0.0, 1.0);
        for (int px = 0; px < w; ++px, p = p + dp) {
            double yv = ((int(std::floor(p.x / 10)) + int(std::floor(p.y / 10))) & 1) ? 92 : 80;
            if (coarse > 0 && (toLine(p.x, 10) < 1.5 * lwX || toLine(p.y, 10) < 1.5 * lwY))
                yv += (210 - yv) * coarse;
            else if (fine > 0 && (toLine(p.x, 2) < lwX || toLine(p.y, 2) < lwY))
                yv += (150 - yv) * fine;
            yv = yv * (1 - fog) + 160 * fog;
            row[px] = std::uint8_t(yv);
        }
    }
    // Chroma: sky blue-ish, ground olive.
    for (int py = 0; py < h / 2; ++py) {
        const bool ground = rowChroma[std::size_t(py)] != 0;
        std::memset(f.u + std::ptrdiff_t(py) * f.strideU, ground ? 112 : 150, std::size_t(w / 2));
        std::memset(f.v + std::ptrdiff_t(py) * f.strideV, ground ? 130 : 112, std::size_t(w / 2));
    }
}

// Other machines: boxes, far ones first, drawn as their projected bounding rectangles with an outline.
void drawBoxes(const I420Frame& f, const View& v, const std::vector<SceneBox>& others) {
    const int w = v.w, h = v.h;
    const V3 fwd = v.fwd, right = v.right, up = v.up, eye = v.eye;
    const double fpx = v.fpx, cx = v.cx, cy = v.cy;
    struct Proj {
        double depth;
        int x0, y0, x1, y1;
    };
    std::vector<Proj> boxes;
    for (const SceneBox& o : others) {
        const double cs = std::cos(o.yaw), sn = std::sin(o.yaw);
        double minX = 1e9, minY = 1e9, maxX = -1e9, maxY = -1e9, depth = 1e9;
        bool visible = true;
        for (int i = 0; i < 8 && visible; ++i) {
            const double lx = (i & 1 ? 0.5 : -0.5) * o.length, ly = (i & 2 ? 0.5 : -0.5) * o.width;
            const V3 corner{o.x + lx * cs - ly * sn, o.y + lx * sn + ly * cs, i & 4 ? o.height : 0.0};
            const V3 rel = corner - eye;
            const double z = dot(rel, fwd);
            if (z < 0.3) {
                visible = false;
                break;
            }
            const double sx = cx + fpx * dot(rel, right) / z, sy = cy - fpx * dot(rel, up) / z;
            minX = std::min(minX, sx);
            maxX = std::max(maxX, sx);
            minY = std::min(minY, sy);
            maxY = std::max(maxY, sy);
            depth = std::min(depth, z);
        }
        if (!visible || maxX < 0 || minX >= w || maxY < 0 || minY >= h)
            continue;
        boxes.push_back({depth, std::max(0, int(minX)), std::max(0, int(minY)), std::min(w - 1, int(maxX)),
                         std::min(h - 1, int(maxY))});
    }
    std::sort(boxes.begin(), boxes.end(), [](const Proj& a, const Proj& b) { return a.depth > b.depth; });
    for (const Proj& b : boxes) {
        const auto fill = std::uint8_t(std::clamp(150.0 - b.depth, 90.0, 150.0));
        for (int py = b.y0; py <= b.y1; ++py) {
            std::uint8_t* row = f.y + std::ptrdiff_t(py) * f.strideY;
            const bool edge = py == b.y0 || py == b.y1;
            for (int px = b.x0; px <= b.x1; ++px)
                row[px] = (edge || px == b.x0 || px == b.x1) ? 30 : fill;
        }
        for (int py = b.y0 / 2; py <= b.y1 / 2; ++py) {
            std::memset(f.u + std::ptrdiff_t(py) * f.strideU + b.x0 / 2, 80,
                        std::size_t(b.x1 / 2 - b.x0 / 2 + 1));
            std::memset(f.v + std::ptrdiff_t(py) * f.strideV + b.x0 / 2, 190,
                        std::size_t(b.x1 / 2 - b.x0 / 2 + 1));
        }
    }
}

// Centre mark (where the camera points).
void drawCentreMark(const I420Frame& f, const View& v) {
    const int w = v.w, h = v.h;
    const double cx = v.cx, cy = v.cy;
    for (int i = -8; i <= 8; ++i) {
        const int x = int(cx) + i, y = int(cy) + i;
        if (x >= 0 && x < w)
            f.y[std::ptrdiff_t(int(cy)) * f.strideY + x] = 235;
        if (y >= 0 && y < h)
            f.y[std::ptrdiff_t(y) * f.strideY + int(cx)] = 235;
    }
}

// The capture time, on neutral chroma so colour conversion leaves the cells' luma intact.
void stampCaptureTime(const I420Frame& f, std::uint64_t captureUnixUs) {
    const int w = f.width, h = f.height;
    if (timecode::stamp(f.y, w, h, f.strideY, captureUnixUs)) {
        const int rows = 2 * timecode::cellSize(w);
        for (int py = 0; py < (rows + 1) / 2 && py < h / 2; ++py) {
            std::memset(f.u + std::ptrdiff_t(py) * f.strideU, 128, std::size_t(w / 2));
            std::memset(f.v + std::ptrdiff_t(py) * f.strideV, 128, std::size_t(w / 2));
        }
    }
}

} // namespace

void renderCameraView(const I420Frame& f, const CameraPose& c, const std::vector<SceneBox>& others,
                      std::uint64_t captureUnixUs) {
    if (f.width < 2 || f.height < 2 || !f.y || !f.u || !f.v)
        return;
    const View view = viewOf(f, c);
    drawGround(f, c, view);
    drawBoxes(f, view, others);
    drawCentreMark(f, view);
    stampCaptureTime(f, captureUnixUs);
}

} // namespace ocu::sim
