#pragma once
// Terrain of the simulated open pit: a DEM consistent with the generated map
// (PitMapGenerator) — the pit floor at the loading areas' level, benches of 10 m stepping up to the surface
// around it, the haul ramp cut through the benches along its lanes — and its hillshade, written as
// georeferenced GeoTIFFs `pit_dem.tif` (Float32, metres above the ellipsoid) and `pit_hillshade.tif` (Byte).
// Both are in the site frame's own projection (orthographic on WGS84 centred at the site origin: x/y are site
// east/north in metres), so a reader that knows the origin needs no reprojection; GDAL/PROJ readers can
// reproject them to anything. No Qt.
#include "sim/iso23725/PitMapGenerator.h"

#include <string>
#include <vector>

namespace ocu::sim {

// The pit's surface as a function: local up (m, relative to the site origin) at (east, north).
class PitTerrainModel {
public:
    explicit PitTerrainModel(const PitMap& pit);
    double up(double e, double n) const;
    // Bounds (site m) that hold the map's roads and areas and the pit with a margin.
    double west() const { return m_west; }
    double east() const { return m_east; }
    double south() const { return m_south; }
    double north() const { return m_north; }
    static constexpr double kBenchHeight = 10.0;

private:
    double benches(double e, double n) const;
    double m_x0 = 0, m_x1 = 0, m_y0 = 0, m_y1 = 0; // pit floor rectangle
    double m_floorU = -60;
    int m_benchCount = 6;
    double m_sideWidth = 25, m_northWidth = 25; // horizontal run per bench (m)
    double m_rampMinE = 0, m_rampMaxE = 0;      // the ramp's east-west extent
    struct Corridor {
        std::vector<EnuPoint> points; // centre line
        double minE, maxE, minN, maxN;
    };
    std::vector<Corridor> m_roads; // roads and lanes
    double m_west = 0, m_east = 0, m_south = 0, m_north = 0;
};

struct PitTerrainFiles {
    std::string dem;       // path of pit_dem.tif
    std::string hillshade; // path of pit_hillshade.tif
    std::string error;     // empty on success
};

// Writes both files into `dir` (created when missing) at `cellM` metres per pixel; files already there from
// an earlier run are reused (the folder name should identify the layout: defaultPitTerrainDir). Written to a
// temporary name and renamed, so concurrent runs never see half a file.
PitTerrainFiles writePitTerrain(const PitMap& pit, const GeoPoint& origin, const std::string& dir,
                                double cellM = 2.0);
// A folder under the system's temporary folder named after the layout and origin.
std::string defaultPitTerrainDir(const PitLayout& layout);

} // namespace ocu::sim
