#pragma once
// LandXML 1.2 design import: alignments (CoordGeom Line / Curve / Spiral, stationing) and
// surfaces (Definition Pnts/Faces, SourceData Boundaries) plus closed PlanFeatures, with the projected CRS
// from CoordinateSystem/@epsgCode. Plain C++ (pugixml), no Qt.
//
// Coordinates are kept as the file gives them, in its projected CRS (easting, northing; LandXML writes
// "northing easting [elevation]"), converted to metres when Units say feet. Hostile input is bounded
// (LandXmlLimits): a file over a limit is refused with the reason; odd but usable content is kept with a
// warning (design.warnings), never silently.
//
// Stationing: station = Alignment/@staStart + distance along the chain of elements (the elements' own
// staStart attributes are checked against it). Offsets are positive to the RIGHT of the direction of
// increasing station, negative to the left.
#include "protocols/common/Result.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ocu::landxml {

struct PlanPoint {
    double e = 0; // easting, m
    double n = 0; // northing, m
};

enum class ElementKind { Line, Arc, Spiral };

struct AlignmentElement {
    ElementKind kind = ElementKind::Line;
    double staStart = 0; // station at start (cumulative, see above)
    double length = 0;   // m along the element
    PlanPoint start, end;
    double startHeading = 0; // radians, mathematical (counter-clockwise from grid east)
    // Arc: centre, radius, turn (+1 = counter-clockwise/left, -1 = clockwise/right).
    PlanPoint center;
    double radius = 0;
    int turn = 0;
    // Spiral (clothoid): signed curvature at start and end (1/m, positive = turning left).
    double curvatureStart = 0, curvatureEnd = 0;
};

struct StationOffset {
    double station = 0;  // of the foot point on the alignment
    double offset = 0;   // signed distance, + right of the direction of stationing
    double distance = 0; // |offset| when the foot is inside the alignment, else distance to the nearer end
    bool inside = true;  // the foot lies between the alignment's first and last station (not beyond an end)
    int element = -1;
};

class Alignment {
public:
    std::string name;
    std::string description;
    double staStart = 0;
    std::vector<AlignmentElement> elements;

    double length() const;
    double staEnd() const { return staStart + length(); }
    // The point at a station (and signed offset, + right); nullopt outside [staStart, staEnd].
    std::optional<PlanPoint> pointAt(double station, double offset = 0) const;
    // Direction of stationing at a station (radians, counter-clockwise from grid east).
    std::optional<double> headingAt(double station) const;
    // The nearest point of the alignment: station and signed offset of p. Empty alignment: nullopt.
    std::optional<StationOffset> stationOf(PlanPoint p) const;
    // The centre line as a polyline with chords no longer than maxChord (m) and a sagitta under ~1 mm on
    // arcs and spirals; stations of the vertices in `stations` when given.
    std::vector<PlanPoint> polyline(double maxChord = 10, std::vector<double>* stations = nullptr) const;
};

struct SurfacePoint {
    double e = 0, n = 0, z = 0;
};

// A closed polygon (first vertex not repeated at the end), from a surface boundary or a closed plan feature.
struct DesignBoundary {
    std::string name;
    std::string surface;        // owning surface name, empty for a plan feature
    std::string kind = "outer"; // LandXML bndType: outer, void, island, ...
    std::vector<PlanPoint> points;
    double area() const; // m^2, unsigned
    bool contains(PlanPoint p) const;
};

struct DesignSurface {
    std::string name;
    std::string description;
    std::vector<SurfacePoint> points;                // Definition/Pnts (ids renumbered 0..n-1)
    std::vector<std::array<std::uint32_t, 3>> faces; // indices into points
    std::vector<std::size_t> boundaryIndices;        // into LandXmlDesign::boundaries
    double elevMin = 0, elevMax = 0;                 // from the points (0/0 when none)
};

struct LandXmlDesign {
    int epsg = 0;        // CoordinateSystem/@epsgCode; 0 when the file names none
    std::string crsName; // CoordinateSystem/@name or horizontalCoordinateSystemName
    std::string linearUnit = "meter";
    std::vector<Alignment> alignments;
    std::vector<DesignSurface> surfaces;
    std::vector<DesignBoundary> boundaries;
    std::vector<std::string> warnings;
};

struct LandXmlLimits {
    std::size_t maxBytes = 64u << 20;
    std::size_t maxAlignments = 1000;
    std::size_t maxElements = 100000;       // alignment elements, all alignments
    std::size_t maxSurfacePoints = 2000000; // all surfaces
    std::size_t maxFaces = 4000000;         // all surfaces
    std::size_t maxBoundaryVertices = 1000000;
    std::size_t maxWarnings = 50; // further warnings are counted in one line
    double maxCoordinate = 1e8;   // |easting|, |northing| in metres
    double maxElementLength = 1e6;
};

Result<LandXmlDesign> parseLandXml(std::string_view text, const LandXmlLimits& limits = {});
Result<LandXmlDesign> loadLandXml(const std::string& path, const LandXmlLimits& limits = {});

// "1+234.56" style station text (km + metres), as reports and labels print it.
std::string formatStation(double station, int decimals = 2);

} // namespace ocu::landxml
