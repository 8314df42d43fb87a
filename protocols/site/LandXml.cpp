#include "protocols/site/LandXml.h"

#include <pugixml.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <numbers>
#include <sstream>
#include <unordered_map>

namespace ocu::landxml {

namespace {

constexpr double kPi = std::numbers::pi;

// Local name of an element ("lx:Line" -> "Line"): files in the wild use prefixes.
std::string_view localName(const pugi::xml_node& n) {
    std::string_view s = n.name();
    const auto colon = s.rfind(':');
    return colon == std::string_view::npos ? s : s.substr(colon + 1);
}

bool nameIs(const pugi::xml_node& n, std::string_view want) {
    const std::string_view s = localName(n);
    if (s.size() != want.size())
        return false;
    for (std::size_t i = 0; i < s.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(s[i])) !=
            std::tolower(static_cast<unsigned char>(want[i])))
            return false;
    return true;
}

pugi::xml_node child(const pugi::xml_node& n, std::string_view want) {
    for (pugi::xml_node c = n.first_child(); c; c = c.next_sibling())
        if (c.type() == pugi::node_element && nameIs(c, want))
            return c;
    return {};
}

template <class F> void forChildren(const pugi::xml_node& n, std::string_view want, F&& f) {
    for (pugi::xml_node c = n.first_child(); c; c = c.next_sibling())
        if (c.type() == pugi::node_element && nameIs(c, want))
            f(c);
}

pugi::xml_attribute attr(const pugi::xml_node& n, std::string_view want) {
    for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute()) {
        std::string_view s = a.name();
        if (s.size() == want.size() && std::equal(s.begin(), s.end(), want.begin(), [](char x, char y) {
                return std::tolower(static_cast<unsigned char>(x)) ==
                       std::tolower(static_cast<unsigned char>(y));
            }))
            return a;
    }
    return {};
}

std::string attrText(const pugi::xml_node& n, std::string_view want) {
    auto a = attr(n, want);
    return a ? std::string(a.value()) : std::string();
}

bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == ',';
}

// Parses whitespace-separated finite numbers; false on anything else. At most maxCount numbers.
bool parseNumbers(std::string_view s, std::vector<double>& out, std::size_t maxCount) {
    out.clear();
    std::size_t i = 0;
    while (true) {
        while (i < s.size() && isSpace(s[i]))
            ++i;
        if (i >= s.size())
            return true;
        if (out.size() >= maxCount)
            return false;
        std::size_t j = i;
        while (j < s.size() && !isSpace(s[j]))
            ++j;
        double v = 0;
        const char* b = s.data() + i;
        const char* e = s.data() + j;
        if (*b == '+')
            ++b;
        auto [p, ec] = std::from_chars(b, e, v);
        if (ec != std::errc() || p != e || !std::isfinite(v))
            return false;
        out.push_back(v);
        i = j;
    }
}

std::optional<double> attrNumber(const pugi::xml_node& n, std::string_view want) {
    auto a = attr(n, want);
    if (!a)
        return std::nullopt;
    std::vector<double> v;
    if (!parseNumbers(a.value(), v, 1) || v.size() != 1)
        return std::nullopt;
    return v[0];
}

double normAngle(double a) { // [0, 2pi)
    a = std::fmod(a, 2 * kPi);
    if (a < 0)
        a += 2 * kPi;
    return a;
}

double dist(PlanPoint a, PlanPoint b) {
    return std::hypot(a.e - b.e, a.n - b.n);
}

// Position and heading on an element at distance t from its start (0 <= t <= length).
PlanPoint elementPoint(const AlignmentElement& el, double t, double* heading) {
    switch (el.kind) {
    case ElementKind::Line: {
        const double c = std::cos(el.startHeading), s = std::sin(el.startHeading);
        if (heading)
            *heading = el.startHeading;
        return {el.start.e + t * c, el.start.n + t * s};
    }
    case ElementKind::Arc: {
        const double a0 = std::atan2(el.start.n - el.center.n, el.start.e - el.center.e);
        const double a = a0 + el.turn * t / el.radius;
        if (heading)
            *heading = a + el.turn * kPi / 2;
        return {el.center.e + el.radius * std::cos(a), el.center.n + el.radius * std::sin(a)};
    }
    case ElementKind::Spiral: {
        const double L = el.length, k0 = el.curvatureStart, dk = el.curvatureEnd - el.curvatureStart;
        auto theta = [&](double s) { return el.startHeading + k0 * s + (L > 0 ? dk * s * s / (2 * L) : 0); };
        int n = std::max(8, static_cast<int>(std::ceil(t / 0.5)));
        n += n & 1;
        const double h = t / n;
        double se = 0, sn = 0;
        for (int i = 0; i <= n; ++i) {
            const double w = (i == 0 || i == n) ? 1 : (i & 1) ? 4 : 2;
            const double th = theta(i * h);
            se += w * std::cos(th);
            sn += w * std::sin(th);
        }
        if (heading)
            *heading = theta(t);
        return {el.start.e + se * h / 3, el.start.n + sn * h / 3};
    }
    }
    return el.start;
}

// Nearest point of one element to p: distance along the element (clamped to [0, length]).
double elementFoot(const AlignmentElement& el, PlanPoint p) {
    switch (el.kind) {
    case ElementKind::Line: {
        const double t =
            (p.e - el.start.e) * std::cos(el.startHeading) + (p.n - el.start.n) * std::sin(el.startHeading);
        return std::clamp(t, 0.0, el.length);
    }
    case ElementKind::Arc: {
        const double sweep = el.length / el.radius;
        const double a0 = std::atan2(el.start.n - el.center.n, el.start.e - el.center.e);
        const double ap = std::atan2(p.n - el.center.n, p.e - el.center.e);
        const double d = normAngle(el.turn > 0 ? ap - a0 : a0 - ap);
        if (d <= sweep)
            return d * el.radius;
        // Outside the sweep: the nearer end (by angle past the end vs. before the start).
        return (d - sweep) < (2 * kPi - d) ? el.length : 0.0;
    }
    case ElementKind::Spiral: {
        const int n = std::max(4, static_cast<int>(std::ceil(el.length / 2.0)));
        double best = 0, bestD = 1e300;
        // March along the spiral once (positions by small chords), then refine around the best sample.
        for (int i = 0; i <= n; ++i) {
            const double t = el.length * i / n;
            const double d = dist(elementPoint(el, t, nullptr), p);
            if (d < bestD) {
                bestD = d;
                best = t;
            }
        }
        double lo = std::max(0.0, best - el.length / n), hi = std::min(el.length, best + el.length / n);
        for (int it = 0; it < 40 && hi - lo > 1e-5; ++it) {
            const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
            if (dist(elementPoint(el, m1, nullptr), p) < dist(elementPoint(el, m2, nullptr), p))
                hi = m2;
            else
                lo = m1;
        }
        return (lo + hi) / 2;
    }
    }
    return 0;
}

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
    std::optional<PlanPoint> point(const pugi::xml_node& n, std::string_view what, const std::string& where) {
        pugi::xml_node c = child(n, what);
        if (!c)
            return std::nullopt;
        if (!parseNumbers(c.child_value(), nums, 3) || nums.size() < 2) {
            warn(where + ": <" + std::string(what) + "> is not \"northing easting\"");
            return std::nullopt;
        }
        PlanPoint p{nums[1] * unit, nums[0] * unit};
        if (!coordOk(p.e) || !coordOk(p.n)) {
            warn(where + ": <" + std::string(what) + "> is out of range");
            return std::nullopt;
        }
        return p;
    }

    void units(const pugi::xml_node& root) {
        pugi::xml_node u = child(root, "Units");
        if (!u)
            return;
        pugi::xml_node m = child(u, "Metric");
        pugi::xml_node i = child(u, "Imperial");
        const std::string lu = m ? attrText(m, "linearUnit") : i ? attrText(i, "linearUnit") : std::string();
        if (lu.empty())
            return;
        static const std::pair<const char*, double> known[] = {
            {"meter", 1},        {"millimeter", 0.001}, {"centimeter", 0.01},
            {"kilometer", 1000}, {"foot", 0.3048},      {"USSurveyFoot", 1200.0 / 3937.0},
            {"inch", 0.0254},    {"mile", 1609.344}};
        for (const auto& [name, f] : known)
            if (lu == name) {
                unit = f;
                d.linearUnit = lu;
                return;
            }
        warn("Units: linear unit \"" + lu + "\" is unknown; metres assumed");
    }

    void crs(const pugi::xml_node& root) {
        pugi::xml_node c = child(root, "CoordinateSystem");
        if (!c)
            return;
        d.crsName = attrText(c, "name");
        if (d.crsName.empty())
            d.crsName = attrText(c, "horizontalCoordinateSystemName");
        const std::string epsg = attrText(c, "epsgCode");
        if (epsg.empty())
            return;
        int code = 0;
        auto [p, ec] = std::from_chars(epsg.data(), epsg.data() + epsg.size(), code);
        if (ec != std::errc() || p != epsg.data() + epsg.size() || code <= 0 || code > 999999) {
            warn("CoordinateSystem: epsgCode \"" + epsg.substr(0, 40) + "\" is not a number");
            return;
        }
        d.epsg = code;
    }

    bool element(const pugi::xml_node& g, Alignment& a, PlanPoint& cursor, bool& haveCursor, int index) {
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
        } else if (nameIs(g, "Spiral")) {
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

    bool alignments(const pugi::xml_node& root) {
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

    // A ring of "n e [z]" numbers (stride 2 or 3) into a boundary; false on a limit.
    bool ring(std::string_view text, int stride, DesignBoundary& b, const std::string& where) {
        const std::size_t budget = (lim.maxBoundaryVertices - boundaryVertices) * stride + stride;
        if (!parseNumbers(text, nums, budget + 1)) {
            if (nums.size() > budget)
                return fail("more than " + std::to_string(lim.maxBoundaryVertices) + " boundary vertices");
            warn(where + ": point list is not numbers; skipped");
            return true;
        }
        if (nums.size() % stride != 0)
            warn(where + ": point list length is not a multiple of " + std::to_string(stride));
        for (std::size_t i = 0; i + stride <= nums.size(); i += stride) {
            PlanPoint p{nums[i + 1] * unit, nums[i] * unit};
            if (!coordOk(p.e) || !coordOk(p.n)) {
                warn(where + ": a vertex is out of range; boundary skipped");
                b.points.clear();
                return true;
            }
            b.points.push_back(p);
        }
        if (b.points.size() > 1 && dist(b.points.front(), b.points.back()) < 1e-6)
            b.points.pop_back();
        boundaryVertices += b.points.size();
        return true;
    }

    bool surfaces(const pugi::xml_node& root) {
        bool ok = true;
        forChildren(root, "Surfaces", [&](const pugi::xml_node& ss) {
            forChildren(ss, "Surface", [&](const pugi::xml_node& sn) {
                if (!ok)
                    return;
                DesignSurface s;
                s.name = attrText(sn, "name").substr(0, 200);
                if (s.name.empty())
                    s.name = "Surface " + std::to_string(d.surfaces.size() + 1);
                s.description = attrText(sn, "desc").substr(0, 500);
                if (pugi::xml_node bs = child(child(sn, "SourceData"), "Boundaries")) {
                    forChildren(bs, "Boundary", [&](const pugi::xml_node& bn) {
                        if (!ok)
                            return;
                        DesignBoundary b;
                        b.surface = s.name;
                        b.name = attrText(bn, "name").substr(0, 200);
                        if (b.name.empty())
                            b.name = s.name;
                        const std::string kind = attrText(bn, "bndType");
                        if (!kind.empty())
                            b.kind = kind.substr(0, 20);
                        const std::string where = "surface \"" + s.name + "\" boundary \"" + b.name + "\"";
                        if (pugi::xml_node l3 = child(bn, "PntList3D"))
                            ok = ring(l3.child_value(), 3, b, where);
                        else if (pugi::xml_node l2 = child(bn, "PntList2D"))
                            ok = ring(l2.child_value(), 2, b, where);
                        if (!ok)
                            return;
                        if (b.points.size() < 3) {
                            warn(where + ": fewer than 3 vertices; skipped");
                            return;
                        }
                        s.boundaryIndices.push_back(d.boundaries.size());
                        d.boundaries.push_back(std::move(b));
                    });
                }
                if (!ok)
                    return;
                pugi::xml_node def = child(sn, "Definition");
                if (def) {
                    std::unordered_map<std::string, std::uint32_t> ids;
                    forChildren(child(def, "Pnts"), "P", [&](const pugi::xml_node& p) {
                        if (!ok)
                            return;
                        if (++surfacePoints > lim.maxSurfacePoints) {
                            ok =
                                fail("more than " + std::to_string(lim.maxSurfacePoints) + " surface points");
                            return;
                        }
                        if (!parseNumbers(p.child_value(), nums, 3) || nums.size() != 3 ||
                            !coordOk(nums[0] * unit) || !coordOk(nums[1] * unit) ||
                            !coordOk(nums[2] * unit)) {
                            warn("surface \"" + s.name + "\": a point is not \"n e z\"; skipped");
                            return;
                        }
                        const std::string id = attrText(p, "id");
                        ids[id] = static_cast<std::uint32_t>(s.points.size());
                        s.points.push_back({nums[1] * unit, nums[0] * unit, nums[2] * unit});
                    });
                    if (!ok)
                        return;
                    std::size_t badFaces = 0;
                    forChildren(child(def, "Faces"), "F", [&](const pugi::xml_node& f) {
                        if (!ok)
                            return;
                        if (++faceCount > lim.maxFaces) {
                            ok = fail("more than " + std::to_string(lim.maxFaces) + " surface faces");
                            return;
                        }
                        if (attrText(f, "i") == "1")
                            return; // invisible face (outside the surface)
                        std::array<std::uint32_t, 3> face{};
                        std::string_view t = f.child_value();
                        int k = 0;
                        std::size_t i = 0;
                        while (k < 4) {
                            while (i < t.size() && isSpace(t[i]))
                                ++i;
                            if (i >= t.size())
                                break;
                            std::size_t j = i;
                            while (j < t.size() && !isSpace(t[j]))
                                ++j;
                            auto it = ids.find(std::string(t.substr(i, j - i)));
                            if (it == ids.end() || k >= 3) {
                                k = 4;
                                break;
                            }
                            face[k++] = it->second;
                            i = j;
                        }
                        if (k != 3) {
                            ++badFaces;
                            return;
                        }
                        s.faces.push_back(face);
                    });
                    if (badFaces)
                        warn("surface \"" + s.name + "\": " + std::to_string(badFaces) +
                             " faces name unknown points or are not triangles; skipped");
                }
                if (!ok)
                    return;
                if (!s.points.empty()) {
                    auto [lo, hi] =
                        std::minmax_element(s.points.begin(), s.points.end(),
                                            [](const auto& a, const auto& b) { return a.z < b.z; });
                    s.elevMin = lo->z;
                    s.elevMax = hi->z;
                }
                if (s.points.empty() && s.boundaryIndices.empty()) {
                    warn("surface \"" + s.name + "\" has neither points nor boundaries; skipped");
                    return;
                }
                d.surfaces.push_back(std::move(s));
            });
        });
        return ok;
    }

    // Closed plan features (a chain of Lines/Curves whose end meets its start) as boundaries.
    bool planFeatures(const pugi::xml_node& root) {
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
};

} // namespace

double Alignment::length() const {
    double l = 0;
    for (const auto& e : elements)
        l += e.length;
    return l;
}

std::optional<PlanPoint> Alignment::pointAt(double station, double offset) const {
    if (elements.empty() || !std::isfinite(station) || !std::isfinite(offset))
        return std::nullopt;
    const double tol = 1e-9;
    if (station < staStart - tol || station > staEnd() + tol)
        return std::nullopt;
    // Elements are few; a binary search would matter only for very long chains.
    auto it = std::upper_bound(elements.begin(), elements.end(), station,
                               [](double s, const AlignmentElement& e) { return s < e.staStart; });
    const AlignmentElement& el = it == elements.begin() ? elements.front() : *(it - 1);
    const double t = std::clamp(station - el.staStart, 0.0, el.length);
    double h = 0;
    PlanPoint p = elementPoint(el, t, &h);
    p.e += offset * std::sin(h);
    p.n -= offset * std::cos(h);
    return p;
}

std::optional<double> Alignment::headingAt(double station) const {
    if (elements.empty() || !std::isfinite(station) || station < staStart - 1e-9 || station > staEnd() + 1e-9)
        return std::nullopt;
    auto it = std::upper_bound(elements.begin(), elements.end(), station,
                               [](double s, const AlignmentElement& e) { return s < e.staStart; });
    const AlignmentElement& el = it == elements.begin() ? elements.front() : *(it - 1);
    double h = 0;
    elementPoint(el, std::clamp(station - el.staStart, 0.0, el.length), &h);
    return h;
}

std::optional<StationOffset> Alignment::stationOf(PlanPoint p) const {
    if (elements.empty() || !std::isfinite(p.e) || !std::isfinite(p.n))
        return std::nullopt;
    StationOffset best;
    best.distance = 1e300;
    for (std::size_t i = 0; i < elements.size(); ++i) {
        const AlignmentElement& el = elements[i];
        const double t = elementFoot(el, p);
        double h = 0;
        const PlanPoint f = elementPoint(el, t, &h);
        const double d = dist(f, p);
        if (d < best.distance - 1e-12) {
            // + right: the component of (p - foot) along the right normal (sin h, -cos h).
            const double side = (p.e - f.e) * std::sin(h) - (p.n - f.n) * std::cos(h);
            const double along = (p.e - f.e) * std::cos(h) + (p.n - f.n) * std::sin(h);
            best.station = el.staStart + t;
            best.distance = d;
            best.offset = side >= 0 ? d : -d;
            best.element = static_cast<int>(i);
            best.inside = !((i == 0 && t <= 0 && along < -1e-9) ||
                            (i + 1 == elements.size() && t >= el.length && along > 1e-9));
            if (best.inside && std::fabs(along) > 1e-6 * std::max(1.0, d))
                best.offset = side; // at a kink: the lateral part
        }
    }
    return best;
}

std::vector<PlanPoint> Alignment::polyline(double maxChord, std::vector<double>* stations) const {
    std::vector<PlanPoint> out;
    if (stations)
        stations->clear();
    if (!(maxChord > 0))
        maxChord = 10;
    for (std::size_t i = 0; i < elements.size(); ++i) {
        const AlignmentElement& el = elements[i];
        double chord = maxChord;
        if (el.kind == ElementKind::Arc)
            chord = std::min(maxChord, std::sqrt(8 * el.radius * 0.001));
        else if (el.kind == ElementKind::Spiral) {
            const double k = std::max(std::fabs(el.curvatureStart), std::fabs(el.curvatureEnd));
            if (k > 0)
                chord = std::min(maxChord, std::sqrt(8 * 0.001 / k));
        }
        const int n =
            el.kind == ElementKind::Line ? 1 : std::max(1, static_cast<int>(std::ceil(el.length / chord)));
        for (int k = (i == 0 ? 0 : 1); k <= n; ++k) {
            const double t = el.length * k / n;
            out.push_back(k == n && el.kind == ElementKind::Line ? el.end : elementPoint(el, t, nullptr));
            if (stations)
                stations->push_back(el.staStart + t);
        }
    }
    return out;
}

double DesignBoundary::area() const {
    double a = 0;
    for (std::size_t i = 0, j = points.size() - 1; i < points.size(); j = i++)
        a += (points[j].e - points[0].e) * (points[i].n - points[0].n) -
             (points[i].e - points[0].e) * (points[j].n - points[0].n);
    return std::fabs(a) / 2;
}

bool DesignBoundary::contains(PlanPoint p) const {
    bool in = false;
    for (std::size_t i = 0, j = points.size() - 1; i < points.size(); j = i++) {
        const PlanPoint& a = points[i];
        const PlanPoint& b = points[j];
        if ((a.n > p.n) != (b.n > p.n) && p.e < (b.e - a.e) * (p.n - a.n) / (b.n - a.n) + a.e)
            in = !in;
    }
    return in;
}

Result<LandXmlDesign> parseLandXml(std::string_view text, const LandXmlLimits& limits) {
    if (text.size() > limits.maxBytes)
        return makeError("LandXML file is larger than " + std::to_string(limits.maxBytes >> 20) + " MiB");
    pugi::xml_document doc;
    const pugi::xml_parse_result r =
        doc.load_buffer(text.data(), text.size(), pugi::parse_default, pugi::encoding_auto);
    if (!r)
        return makeError(std::string("not well-formed XML: ") + r.description() + " at byte " +
                         std::to_string(r.offset));
    pugi::xml_node root = doc.document_element();
    if (!root || !nameIs(root, "LandXML"))
        return makeError("not a LandXML document (root element <" +
                         std::string(root ? localName(root) : "").substr(0, 40) + ">)");
    Parser p(limits);
    const std::string version = attrText(root, "version");
    if (!version.empty() && version.rfind("1.", 0) != 0)
        p.warn("LandXML version " + version.substr(0, 20) + " read as 1.2");
    p.units(root);
    p.crs(root);
    if (!p.alignments(root) || !p.surfaces(root) || !p.planFeatures(root))
        return makeError(p.error);
    if (p.droppedWarnings)
        p.d.warnings.push_back(std::to_string(p.droppedWarnings) + " further warnings");
    if (p.d.alignments.empty() && p.d.boundaries.empty() && p.d.surfaces.empty())
        return makeError(p.d.warnings.empty() ? "the file holds no alignment, surface or boundary"
                                              : "nothing usable in the file: " + p.d.warnings.front());
    return std::move(p.d);
}

Result<LandXmlDesign> loadLandXml(const std::string& path, const LandXmlLimits& limits) {
    std::ifstream f(path, std::ios::binary);
    if (!f)
        return makeError("cannot open " + path);
    f.seekg(0, std::ios::end);
    const auto size = f.tellg();
    if (size < 0)
        return makeError("cannot read " + path);
    if (static_cast<std::uint64_t>(size) > limits.maxBytes)
        return makeError(path + " is larger than " + std::to_string(limits.maxBytes >> 20) + " MiB");
    f.seekg(0);
    std::string text(static_cast<std::size_t>(size), '\0');
    if (!f.read(text.data(), size))
        return makeError("cannot read " + path);
    auto r = parseLandXml(text, limits);
    if (!r)
        return makeError(path + ": " + r.error());
    return r;
}

std::string formatStation(double station, int decimals) {
    if (!std::isfinite(station))
        return "?";
    decimals = std::clamp(decimals, 0, 4);
    const bool neg = station < 0;
    const double scale = std::pow(10.0, decimals);
    const double a = std::round(std::fabs(station) * scale) / scale;
    const long long km = static_cast<long long>(std::floor(a / 1000));
    const double m = a - km * 1000.0;
    char buf[64];
    std::snprintf(buf, sizeof buf, "%s%lld+%0*.*f", neg ? "-" : "", km, decimals > 0 ? 4 + decimals : 3,
                  decimals, m);
    return buf;
}

} // namespace ocu::landxml
