#pragma once
// Internals of the LandXML import, shared by its files: the namespace-tolerant XML helpers (LandXml.cpp), the
// plan geometry of alignment elements (LandXmlGeometry.cpp) and the parser, whose alignment and plan-feature
// part is in LandXmlAlignments.cpp and whose surface part is in LandXmlSurfaces.cpp. Not part of the API.
#include "protocols/site/LandXml.h"

#include <pugixml.hpp>

#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ocu::landxml::detail {

constexpr double kPi = std::numbers::pi;

// Local name of an element ("lx:Line" -> "Line"): files in the wild use prefixes.
std::string_view localName(const pugi::xml_node& n);
// Element and attribute names compare without case: exporters disagree on it.
bool nameIs(const pugi::xml_node& n, std::string_view want);
pugi::xml_node child(const pugi::xml_node& n, std::string_view want);
pugi::xml_attribute attr(const pugi::xml_node& n, std::string_view want);
std::string attrText(const pugi::xml_node& n, std::string_view want);
// Parses whitespace-separated finite numbers; false on anything else. At most maxCount numbers.
bool parseNumbers(std::string_view s, std::vector<double>& out, std::size_t maxCount);
std::optional<double> attrNumber(const pugi::xml_node& n, std::string_view want);

template <class F> void forChildren(const pugi::xml_node& n, std::string_view want, F&& f) {
    for (pugi::xml_node c = n.first_child(); c; c = c.next_sibling())
        if (c.type() == pugi::node_element && nameIs(c, want))
            f(c);
}

inline bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == ',';
}

double normAngle(double a); // [0, 2pi)
inline double dist(PlanPoint a, PlanPoint b) {
    return std::hypot(a.e - b.e, a.n - b.n);
}
// Position and heading on an element at distance t from its start (0 <= t <= length).
PlanPoint elementPoint(const AlignmentElement& el, double t, double* heading);
// Nearest point of one element to p: distance along the element (clamped to [0, length]).
double elementFoot(const AlignmentElement& el, PlanPoint p);

struct Parser {
    explicit Parser(const LandXmlLimits& l) : lim(l) {}
    const LandXmlLimits& lim;
    LandXmlDesign d;
    double unit = 1; // metres per file unit
    std::size_t elementCount = 0, surfacePoints = 0, faceCount = 0, boundaryVertices = 0, droppedWarnings = 0;
    std::string error;
    std::vector<double> nums;

    void warn(std::string w) {
        if (d.warnings.size() < lim.maxWarnings)
            d.warnings.push_back(std::move(w));
        else
            ++droppedWarnings;
    }
    bool fail(std::string e) {
        if (error.empty())
            error = std::move(e);
        return false;
    }
    bool coordOk(double v) const { return std::isfinite(v) && std::fabs(v) <= lim.maxCoordinate; }

    // "northing easting [z]" of an element's text.
    std::optional<PlanPoint> point(const pugi::xml_node& n, std::string_view what, const std::string& where);
    void units(const pugi::xml_node& root);
    void crs(const pugi::xml_node& root);

    // LandXmlAlignments.cpp
    bool element(const pugi::xml_node& g, Alignment& a, PlanPoint& cursor, bool& haveCursor, int index);
    bool curve(const pugi::xml_node& g, AlignmentElement& el, const std::optional<PlanPoint>& s,
               const std::optional<PlanPoint>& e, std::optional<double> lenAttr, const std::string& where);
    bool spiral(const pugi::xml_node& g, AlignmentElement& el, const std::optional<PlanPoint>& s,
                const std::optional<PlanPoint>& e, std::optional<double> lenAttr, const std::string& where);
    bool alignments(const pugi::xml_node& root);
    // Closed plan features (a chain of Lines/Curves whose end meets its start) as boundaries.
    bool planFeatures(const pugi::xml_node& root);

    // LandXmlSurfaces.cpp
    // A ring of "n e [z]" numbers (stride 2 or 3) into a boundary; false on a limit.
    bool ring(std::string_view text, int stride, DesignBoundary& b, const std::string& where);
    bool surfaceBoundaries(const pugi::xml_node& sn, DesignSurface& s);
    bool surfaceDefinition(const pugi::xml_node& def, DesignSurface& s);
    bool surfaces(const pugi::xml_node& root);
};

} // namespace ocu::landxml::detail
