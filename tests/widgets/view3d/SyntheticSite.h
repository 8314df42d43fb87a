#pragma once
// A small synthetic site shared by the 3D view tests: hilly Delaunay terrain, a grey east-west road, a
// yellow lane, a green area, a pass-count patch and two machines with distinctive colours.
#include "widgets/view3d/Scene3D.h"

#include <QRgb>

#include <cmath>
#include <cstdlib>

namespace ocu::testsite {

inline constexpr Rgb kTerrain{150, 140, 110};
inline constexpr Rgb kRoad{70, 70, 70};
inline constexpr Rgb kMagenta{255, 0, 255};
inline constexpr Rgb kCyan{0, 230, 230};

inline double groundU(double e, double n) {
    return 4.0 * std::sin(e / 40.0) * std::cos(n / 55.0);
}

inline Machine3D machine(const char* id, double e, double n, double heading, Rgb colour) {
    Machine3D m;
    m.id = QString::fromLatin1(id);
    m.e = e;
    m.n = n;
    m.u = groundU(e, n);
    m.headingDeg = heading;
    m.length = 12.0;
    m.width = 6.0;
    m.height = 5.0;
    m.colour = colour;
    m.label = m.id + QStringLiteral(" hauler");
    return m;
}

inline Scene3D makeSite() {
    Scene3D s;
    s.terrain.colour = kTerrain;
    for (int i = 0; i <= 20; ++i)
        for (int j = 0; j <= 20; ++j) {
            const double e = -100.0 + 10.0 * i, n = -100.0 + 10.0 * j;
            s.terrain.points.push_back({e, n, groundU(e, n)});
        }
    Way3D road;
    road.kind = WayKind::Road;
    road.points = {{-95, 0, 0}, {0, 0, 0}, {95, 0, 0}};
    road.colour = kRoad;
    road.width = 10.0;
    s.ways.push_back(road);
    Way3D lane;
    lane.kind = WayKind::Lane;
    lane.points = {{-60, -60, 0}, {-20, -80, 0}};
    lane.colour = {230, 200, 0};
    lane.width = 3.0;
    s.ways.push_back(lane);
    Way3D area;
    area.kind = WayKind::Area;
    area.points = {{50, 40, 0}, {90, 40, 0}, {90, 90, 0}, {70, 60, 0}, {50, 90, 0}}; // concave on purpose
    area.colour = {60, 170, 60};
    s.ways.push_back(area);
    // Pass counts: 10 x 4 cells of 2 m south of the road, blue / green / red columns, one empty cell.
    PassCountRaster& r = s.passCount;
    r.originE = 10.0;
    r.originN = -40.0;
    r.cellSize = 2.0;
    r.cols = 10;
    r.rows = 4;
    for (int row = 0; row < r.rows; ++row)
        for (int col = 0; col < r.cols; ++col) {
            const Rgb c = col < 3 ? Rgb{30, 144, 255} : col < 7 ? Rgb{154, 205, 50} : Rgb{255, 0, 0};
            const bool empty = row == 0 && col == 0;
            r.rgba.insert(r.rgba.end(), {c.r, c.g, c.b, static_cast<std::uint8_t>(empty ? 0 : 255)});
        }
    s.legend = {{QStringLiteral("< target"), {30, 144, 255}},
                {QStringLiteral("on target"), {154, 205, 50}},
                {QStringLiteral("> target"), {255, 0, 0}}};
    s.machines = {machine("M1", 30.0, 25.0, 45.0, kMagenta), machine("M2", -40.0, -30.0, 270.0, kCyan)};
    return s;
}

// Colour tests tolerate lighting: the dominant channels must match the hue.
inline bool isMagenta(QRgb p) {
    return qRed(p) > 110 && qBlue(p) > 110 && qGreen(p) < 70;
}
inline bool isCyan(QRgb p) {
    return qGreen(p) > 100 && qBlue(p) > 100 && qRed(p) < 60;
}
inline bool isRoadGrey(QRgb p) {
    // Terrain shadows are dark too, but keep r - b >= 15 (brown); the road is neutral.
    return qRed(p) < 140 && std::abs(qRed(p) - qGreen(p)) <= 8 && std::abs(qRed(p) - qBlue(p)) <= 8;
}
// Terrain is brownish (r > g > b); the background is bluish (b > r).
inline bool isTerrain(QRgb p) {
    return qRed(p) > qBlue(p) + 20 && qGreen(p) > qBlue(p) && qRed(p) > 80;
}

} // namespace ocu::testsite
