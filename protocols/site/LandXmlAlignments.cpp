// The alignments of a LandXML file (CoordGeom chains of Line, Curve and Spiral with their stationing) and the
// closed plan features, read with the same element parser.
#include "protocols/site/LandXmlParser.h"

#include <algorithm>
#include <cmath>

namespace ocu::landxml::detail {

bool Parser::element(const pugi::xml_node& g, Alignment& a, PlanPoint& cursor, bool& haveCursor, int index) {
    const std::string where = "alignment \"" + a.name + "\" element " + std::to_string(index + 1);
    AlignmentElement el;
    auto s = point(g, "Start", where);
    auto e = point(g, "End", where);
    if (!s || !e)
        return fail(where + " (" + std::string(localName(g)) + "): Start and End are required");
    el.start = *s;
    el.end = *e;
    const std::optional<double> lenAttr = attrNumber(g, "length");
    if (nameIs(g, "Line")) {
        el.kind = ElementKind::Line;
        el.length = dist(*s, *e);
        el.startHeading = std::atan2(e->n - s->n, e->e - s->e);
        if (el.length <= 0)
            return fail(where + ": a line of zero length");
    } else if (nameIs(g, "Curve")) {
        if (!curve(g, el, s, e, lenAttr, where))
            return false;
    } else if (nameIs(g, "Spiral")) {
        if (!spiral(g, el, s, e, lenAttr, where))
            return false;
    } else {
        return fail(where + ": <" + std::string(localName(g)).substr(0, 40) +
                    "> is not supported (Line, Curve, Spiral)");
    }
    if (!(el.length <= lim.maxElementLength))
        return fail(where + ": longer than " + std::to_string(lim.maxElementLength) + " m");
    if (lenAttr && el.kind != ElementKind::Spiral &&
        std::fabs(*lenAttr * unit - el.length) > std::max(0.01, 1e-5 * el.length))
        warn(where + ": length attribute " + std::to_string(*lenAttr) + " differs from the geometry (" +
             std::to_string(el.length) + "); the geometry is used");
    if (haveCursor && dist(cursor, el.start) > 0.01)
        warn(where + ": starts " + std::to_string(dist(cursor, el.start)).substr(0, 8) +
             " m from the previous element's end");
    el.staStart = a.staStart + a.length();
    if (auto st = attrNumber(g, "staStart"); st && std::fabs(*st * unit - el.staStart) > 0.01)
        warn(where + ": staStart " + std::to_string(*st) + " differs from the chained station " +
             std::to_string(el.staStart));
    cursor = el.end;
    haveCursor = true;
    a.elements.push_back(el);
    return true;
}

// A circular arc: centre given, or from the start tangent (Start -> PI) and the radius.
bool Parser::curve(const pugi::xml_node& g, AlignmentElement& el, const std::optional<PlanPoint>& s,
                   const std::optional<PlanPoint>& e, std::optional<double> lenAttr,
                   const std::string& where) {
    el.kind = ElementKind::Arc;
    const std::string crvType = attrText(g, "crvType");
    if (!crvType.empty() && crvType != "arc")
        warn(where + ": crvType \"" + crvType.substr(0, 20) + "\" read as a circular arc");
    const std::string rot = attrText(g, "rot");
    auto c = point(g, "Center", where);
    auto pi = point(g, "PI", where);
    int turn = rot == "ccw" ? 1 : rot == "cw" ? -1 : 0;
    if (turn == 0 && pi) {
        const double cr = (pi->e - s->e) * (e->n - pi->n) - (pi->n - s->n) * (e->e - pi->e);
        turn = cr > 0 ? 1 : -1;
    }
    if (!c && pi) {
        // Centre from the tangent at the start (Start -> PI) and the radius.
        const auto r = attrNumber(g, "radius");
        if (!r || *r <= 0)
            return fail(where + ": a curve needs Center, or PI and radius");
        const double h = std::atan2(pi->n - s->n, pi->e - s->e);
        if (turn == 0)
            turn = 1;
        c = PlanPoint{s->e - turn * *r * unit * std::sin(h), s->n + turn * *r * unit * std::cos(h)};
    }
    if (!c)
        return fail(where + ": a curve needs Center (or PI and radius)");
    el.center = *c;
    el.radius = dist(*s, *c);
    const double r2 = dist(*e, *c);
    if (!(el.radius > 0) || std::fabs(r2 - el.radius) > std::max(0.01, 1e-4 * el.radius))
        return fail(where + ": Start and End are not on one circle about Center");
    if (auto r = attrNumber(g, "radius");
        r && std::fabs(*r * unit - el.radius) > std::max(0.01, 1e-4 * el.radius))
        warn(where + ": radius attribute differs from the geometry; the geometry is used");
    const double a0 = std::atan2(s->n - c->n, s->e - c->e), a1 = std::atan2(e->n - c->n, e->e - c->e);
    if (turn == 0) {
        // No rot and no PI: the shorter way round.
        turn = normAngle(a1 - a0) <= kPi ? 1 : -1;
        warn(where + ": curve without rot; the shorter sweep is used");
    }
    el.turn = turn;
    double sweep = normAngle(turn > 0 ? a1 - a0 : a0 - a1);
    if (sweep < 1e-12) {
        if (lenAttr && *lenAttr * unit > kPi * el.radius)
            sweep = 2 * kPi; // a full circle
        else
            return fail(where + ": a curve of zero length");
    }
    el.length = sweep * el.radius;
    el.startHeading = a0 + turn * kPi / 2;
    return true;
}

// A clothoid from its start tangent (Start -> PI), length and end radii; End is checked, not used.
bool Parser::spiral(const pugi::xml_node& g, AlignmentElement& el, const std::optional<PlanPoint>& s,
                    const std::optional<PlanPoint>& e, std::optional<double> lenAttr,
                    const std::string& where) {
    el.kind = ElementKind::Spiral;
    auto pi = point(g, "PI", where);
    if (!pi)
        return fail(where + ": a spiral needs PI (its start tangent)");
    if (!lenAttr || !(*lenAttr > 0))
        return fail(where + ": a spiral needs a positive length");
    el.length = *lenAttr * unit;
    const std::string spiType = attrText(g, "spiType");
    if (!spiType.empty() && spiType != "clothoid")
        warn(where + ": spiType \"" + spiType.substr(0, 20) + "\" computed as a clothoid");
    auto curvature = [&](std::string_view name) -> std::optional<double> {
        const std::string t = attrText(g, name);
        if (t.empty() || t == "INF" || t == "inf" || t == "Infinity")
            return 0.0;
        auto r = attrNumber(g, name);
        if (!r || *r == 0)
            return std::nullopt;
        return 1.0 / (*r * unit);
    };
    auto k0 = curvature("radiusStart"), k1 = curvature("radiusEnd");
    if (!k0 || !k1)
        return fail(where + ": spiral radii are not numbers or INF");
    const std::string rot = attrText(g, "rot");
    int turn = rot == "ccw" ? 1 : rot == "cw" ? -1 : 0;
    if (turn == 0) {
        const double cr = (pi->e - s->e) * (e->n - pi->n) - (pi->n - s->n) * (e->e - pi->e);
        turn = cr > 0 ? 1 : -1;
    }
    el.curvatureStart = turn * std::fabs(*k0);
    el.curvatureEnd = turn * std::fabs(*k1);
    el.startHeading = std::atan2(pi->n - s->n, pi->e - s->e);
    const PlanPoint computed = elementPoint(el, el.length, nullptr);
    const double miss = dist(computed, *e);
    if (miss > std::max(0.05, 1e-4 * el.length))
        warn(where + ": spiral End is " + std::to_string(miss).substr(0, 8) +
             " m from the computed clothoid end; the computed geometry is used");
    el.end = computed;
    return true;
}

bool Parser::alignments(const pugi::xml_node& root) {
    bool ok = true;
    forChildren(root, "Alignments", [&](const pugi::xml_node& as) {
        forChildren(as, "Alignment", [&](const pugi::xml_node& an) {
            if (!ok)
                return;
            if (d.alignments.size() >= lim.maxAlignments) {
                ok = fail("more than " + std::to_string(lim.maxAlignments) + " alignments");
                return;
            }
            Alignment a;
            a.name = attrText(an, "name").substr(0, 200);
            if (a.name.empty())
                a.name = "Alignment " + std::to_string(d.alignments.size() + 1);
            a.description = attrText(an, "desc").substr(0, 500);
            if (auto s = attrNumber(an, "staStart")) {
                if (std::fabs(*s * unit) > lim.maxCoordinate) {
                    ok = fail("alignment \"" + a.name + "\": staStart out of range");
                    return;
                }
                a.staStart = *s * unit;
            }
            pugi::xml_node cg = child(an, "CoordGeom");
            if (!cg) {
                warn("alignment \"" + a.name + "\" has no CoordGeom; skipped");
                return;
            }
            PlanPoint cursor;
            bool haveCursor = false;
            int index = 0;
            std::string before = error;
            for (pugi::xml_node g = cg.first_child(); g; g = g.next_sibling()) {
                if (g.type() != pugi::node_element)
                    continue;
                if (++elementCount > lim.maxElements) {
                    ok = fail("more than " + std::to_string(lim.maxElements) + " alignment elements");
                    return;
                }
                if (!element(g, a, cursor, haveCursor, index++)) {
                    // One bad element makes the alignment's stationing meaningless: the alignment is left
                    // out (reported), the rest of the file is kept.
                    warn(error + "; alignment \"" + a.name + "\" skipped");
                    error = before;
                    return;
                }
            }
            if (a.elements.empty()) {
                warn("alignment \"" + a.name + "\" has no elements; skipped");
                return;
            }
            if (child(an, "StaEquation"))
                warn("alignment \"" + a.name + "\": station equations (StaEquation) are not applied");
            if (auto len = attrNumber(an, "length"); len && std::fabs(*len * unit - a.length()) > 0.01)
                warn("alignment \"" + a.name + "\": length attribute " + std::to_string(*len) +
                     " differs from its elements' sum " + std::to_string(a.length()));
            d.alignments.push_back(std::move(a));
        });
    });
    return ok;
}

// Closed plan features (a chain of Lines/Curves whose end meets its start) as boundaries.
bool Parser::planFeatures(const pugi::xml_node& root) {
    bool ok = true;
    forChildren(root, "PlanFeatures", [&](const pugi::xml_node& pfs) {
        forChildren(pfs, "PlanFeature", [&](const pugi::xml_node& pf) {
            if (!ok)
                return;
            pugi::xml_node cg = child(pf, "CoordGeom");
            if (!cg)
                return;
            Alignment chain;
            chain.name = attrText(pf, "name").substr(0, 200);
            if (chain.name.empty())
                chain.name = "Plan feature " + std::to_string(d.boundaries.size() + 1);
            PlanPoint cursor;
            bool have = false;
            int index = 0;
            const std::string before = error;
            for (pugi::xml_node g = cg.first_child(); g; g = g.next_sibling()) {
                if (g.type() != pugi::node_element)
                    continue;
                if (++elementCount > lim.maxElements) {
                    ok = fail("more than " + std::to_string(lim.maxElements) + " geometry elements");
                    return;
                }
                if (!element(g, chain, cursor, have, index++)) {
                    warn(error + "; plan feature skipped");
                    error = before;
                    return;
                }
            }
            if (chain.elements.empty())
                return;
            if (dist(chain.elements.front().start, chain.elements.back().end) > 0.01) {
                warn("plan feature \"" + chain.name + "\" is not closed; not used as a boundary");
                return;
            }
            DesignBoundary b;
            b.name = chain.name;
            b.points = chain.polyline(5);
            if (b.points.size() > 1)
                b.points.pop_back();
            if (boundaryVertices + b.points.size() > lim.maxBoundaryVertices) {
                ok = fail("more than " + std::to_string(lim.maxBoundaryVertices) + " boundary vertices");
                return;
            }
            boundaryVertices += b.points.size();
            if (b.points.size() >= 3)
                d.boundaries.push_back(std::move(b));
        });
    });
    return ok;
}

} // namespace ocu::landxml::detail
