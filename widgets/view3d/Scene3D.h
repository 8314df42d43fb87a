#pragma once
// Protocol-neutral description of the 3D site scene. Plain value types: no VTK, no models.
// Coordinates are local ENU metres (E east, N north, U up) relative to the site origin
// (see protocols/common/GeoFrame.h for the WGS84 <-> ENU conversion).
#include <QString>

#include <cstdint>
#include <vector>

namespace ocu {

struct Rgb {
    std::uint8_t r = 0;
    std::uint8_t g = 0;
    std::uint8_t b = 0;
    friend bool operator==(const Rgb&, const Rgb&) = default;
};

struct Enu {
    double e = 0.0;
    double n = 0.0;
    double u = 0.0;
};

// A regular height grid in the site frame (from a DEM): sample (c, r) is at (originE + c*step,
// originN + r*step), row 0 southernmost; `u` holds cols*rows heights, row-major.
struct TerrainGrid3D {
    double originE = 0.0;
    double originN = 0.0;
    double step = 1.0;
    int cols = 0;
    int rows = 0;
    std::vector<double> u;
    bool valid() const {
        return cols >= 2 && rows >= 2 && step > 0.0 && u.size() == static_cast<std::size_t>(cols) * rows;
    }
};

// Terrain: the `grid` surface when it is valid (a DEM), else a Delaunay surface through `points` when there
// are at least 3 non-collinear ones, otherwise a flat plane at height `planeU` covering [minE, maxE] x
// [minN, maxN].
struct Terrain3D {
    TerrainGrid3D grid;
    std::vector<Enu> points;
    double minE = -100.0;
    double minN = -100.0;
    double maxE = 100.0;
    double maxN = 100.0;
    double planeU = 0.0;
    Rgb colour{150, 140, 110}; // base colour; the Delaunay surface is shaded darker/lighter by height
};

enum class WayKind { Road, Lane, Area };

// A road or lane is a ribbon of `width` metres along the polyline; an area is a filled polygon
// (the outline, closed implicitly). All are draped over the terrain.
struct Way3D {
    WayKind kind = WayKind::Road;
    std::vector<Enu> points; // only e and n are used; the height comes from the terrain
    Rgb colour{90, 90, 90};
    double width = 6.0;
};

// Simple type-specific 3D shapes: told apart at a glance, the front recognisable (heading).
enum class MachineShape { Unknown, HaulTruck, Ugv, Roller, Paver, Loader, LightVehicle };

struct Machine3D {
    QString id;
    MachineShape shape = MachineShape::Unknown;
    double e = 0.0;
    double n = 0.0;
    double u = 0.0;          // height of the box bottom (replaced by the terrain height, see Scene3D)
    double headingDeg = 0.0; // 0 = north, clockwise
    double length = 10.0;    // along the heading
    double width = 4.0;
    double height = 4.0;
    Rgb colour{0, 200, 0};
    QString label; // name shown above the machine (decluttered; the selected one always; id when empty)
    bool selected = false;
};

// Pass-count raster: cell (c, r) covers [originE + c*cellSize, +cellSize] x [originN + r*cellSize,
// +cellSize]; row 0 is the southernmost row. `rgba` holds cols*rows*4 bytes, row-major; alpha 0 = no data
// (not drawn).
struct PassCountRaster {
    double originE = 0.0;
    double originN = 0.0;
    double cellSize = 1.0;
    int cols = 0;
    int rows = 0;
    std::vector<std::uint8_t> rgba;
    bool empty() const {
        return cols <= 0 || rows <= 0 || rgba.size() < static_cast<std::size_t>(cols) * rows * 4;
    }
};

struct LegendEntry {
    QString label;
    Rgb colour;
};

struct Scene3D {
    Terrain3D terrain;
    std::vector<Way3D> ways;
    std::vector<Machine3D> machines;
    PassCountRaster passCount;
    std::vector<LegendEntry> legend; // pass-count legend (same palette as the 2D map)
    Rgb background{200, 215, 235};
    // Machines stand on the terrain: their u is replaced by the terrain height under (e, n). Turn off only
    // when u is a trusted height in the same vertical datum as the terrain points.
    bool clampMachinesToTerrain = true;
};

enum class CameraMode { FreeOrbit, FollowSelected, TopDown };

// Box size for a machine whose footprint is unknown (0), by equipment type text (case-insensitive match on
// common words). Rough public figures: a 100 t rigid haul truck is ~10 x 6 x 6 m, a tandem roller ~5 x 2 x 3
// m.
struct MachineSize {
    double length, width, height;
};
inline MachineSize defaultMachineSize(const QString& type) {
    const QString t = type.toLower();
    if (t.contains(QLatin1String("haul")) || t.contains(QLatin1String("truck")) ||
        t.contains(QLatin1String("dump")))
        return {10.0, 6.0, 6.0};
    if (t.contains(QLatin1String("excavat")) || t.contains(QLatin1String("shovel")))
        return {11.0, 5.0, 5.0};
    if (t.contains(QLatin1String("loader")) || t.contains(QLatin1String("dozer")) ||
        t.contains(QLatin1String("grader")))
        return {8.0, 4.0, 4.0};
    if (t.contains(QLatin1String("roller")) || t.contains(QLatin1String("compact")))
        return {5.0, 2.2, 3.0};
    if (t.contains(QLatin1String("paver")))
        return {6.5, 3.2, 3.5};
    if (t.contains(QLatin1String("ugv")) || t.contains(QLatin1String("robot")))
        return {1.5, 1.0, 1.0};
    if (t.contains(QLatin1String("car")) || t.contains(QLatin1String("light")) ||
        t.contains(QLatin1String("pickup")))
        return {5.0, 2.0, 2.0};
    return {6.0, 3.0, 3.0};
}

// Shape by equipment type text (the same words as defaultMachineSize).
inline MachineShape machineShapeFor(const QString& type) {
    const QString t = type.toLower();
    if (t.contains(QLatin1String("haul")) || t.contains(QLatin1String("truck")) ||
        t.contains(QLatin1String("dump")))
        return MachineShape::HaulTruck;
    if (t.contains(QLatin1String("roller")) || t.contains(QLatin1String("compact")))
        return MachineShape::Roller;
    if (t.contains(QLatin1String("paver")))
        return MachineShape::Paver;
    if (t.contains(QLatin1String("excavat")) || t.contains(QLatin1String("shovel")) ||
        t.contains(QLatin1String("loader")) || t.contains(QLatin1String("dozer")))
        return MachineShape::Loader;
    if (t.contains(QLatin1String("ugv")) || t.contains(QLatin1String("robot")))
        return MachineShape::Ugv;
    if (t.contains(QLatin1String("car")) || t.contains(QLatin1String("light")) ||
        t.contains(QLatin1String("pickup")))
        return MachineShape::LightVehicle;
    return MachineShape::Unknown;
}

} // namespace ocu
