// Fuzz harness: the LandXML 1.2 design import (protocols/site/LandXml: alignments, surfaces, boundaries).
// Invariants: deterministic; a failure says why; an accepted design is bounded by the limits, its alignments
// have finite stationing, pointAt/stationOf stay finite and agree on the centre line, and its boundaries have
// at least three finite vertices.
#include "protocols/site/LandXml.h"
#include "tests/fuzz/FuzzSupport.h"

#include <cmath>
#include <string>

using namespace ocu::landxml;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    ocu::fuzz::quietLogs();
    const std::string text(reinterpret_cast<const char*>(data), data ? size : 0);
    LandXmlLimits lim;
    lim.maxElements = 2000;
    lim.maxSurfacePoints = 20000;
    lim.maxFaces = 40000;
    lim.maxBoundaryVertices = 20000;
    auto a = parseLandXml(text, lim);
    auto b = parseLandXml(text, lim);
    OCU_FUZZ_CHECK(a.ok() == b.ok());
    if (!a) {
        OCU_FUZZ_CHECK(!a.error().empty());
        OCU_FUZZ_CHECK(a.error() == b.error());
        return 0;
    }
    const LandXmlDesign& d = *a;
    OCU_FUZZ_CHECK(d.warnings == b->warnings);
    OCU_FUZZ_CHECK(d.warnings.size() <= lim.maxWarnings + 1);
    OCU_FUZZ_CHECK(!d.alignments.empty() || !d.surfaces.empty() || !d.boundaries.empty());
    OCU_FUZZ_CHECK(d.alignments.size() <= lim.maxAlignments);
    std::size_t elements = 0;
    for (const Alignment& al : d.alignments) {
        OCU_FUZZ_CHECK(!al.elements.empty());
        elements += al.elements.size();
        OCU_FUZZ_CHECK(std::isfinite(al.staStart) && std::isfinite(al.length()) && al.length() > 0);
        for (const AlignmentElement& el : al.elements)
            OCU_FUZZ_CHECK(el.length > 0 && el.length <= lim.maxElementLength);
        // A few stations along it: the point is finite and stationOf finds it again (centre line).
        for (int k = 0; k <= 4; ++k) {
            const double s = al.staStart + al.length() * k / 4;
            const auto p = al.pointAt(s);
            OCU_FUZZ_CHECK(p && std::isfinite(p->e) && std::isfinite(p->n));
            const auto so = al.stationOf(*p);
            OCU_FUZZ_CHECK(so && std::isfinite(so->station) && std::isfinite(so->offset));
            OCU_FUZZ_CHECK(so->distance <= 1e-3 * std::max(1.0, al.length()) + 0.01);
        }
        OCU_FUZZ_CHECK(!al.pointAt(al.staStart - 1).has_value());
    }
    OCU_FUZZ_CHECK(elements <= lim.maxElements);
    std::size_t vertices = 0, points = 0, faces = 0;
    for (const DesignBoundary& bd : d.boundaries) {
        OCU_FUZZ_CHECK(bd.points.size() >= 3);
        vertices += bd.points.size();
        for (const PlanPoint& p : bd.points)
            OCU_FUZZ_CHECK(std::isfinite(p.e) && std::isfinite(p.n) && std::fabs(p.e) <= lim.maxCoordinate);
        OCU_FUZZ_CHECK(std::isfinite(bd.area()));
    }
    for (const DesignSurface& s : d.surfaces) {
        points += s.points.size();
        faces += s.faces.size();
        for (const auto& f : s.faces)
            for (auto i : f)
                OCU_FUZZ_CHECK(i < s.points.size());
        for (auto bi : s.boundaryIndices)
            OCU_FUZZ_CHECK(bi < d.boundaries.size());
    }
    OCU_FUZZ_CHECK(vertices <= lim.maxBoundaryVertices + 2000 * 64);
    OCU_FUZZ_CHECK(points <= lim.maxSurfacePoints && faces <= lim.maxFaces);
    return 0;
}
