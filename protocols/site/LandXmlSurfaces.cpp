// The surfaces of a LandXML file: TIN points and faces (Definition) and their boundaries (SourceData), within
// the limits of LandXmlLimits.
#include "protocols/site/LandXmlParser.h"

#include <algorithm>
#include <unordered_map>

namespace ocu::landxml::detail {

// A ring of "n e [z]" numbers (stride 2 or 3) into a boundary; false on a limit.
bool Parser::ring(std::string_view text, int stride, DesignBoundary& b, const std::string& where) {
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

// The surface's SourceData boundaries into design boundaries; false on a limit.
bool Parser::surfaceBoundaries(const pugi::xml_node& sn, DesignSurface& s) {
    bool ok = true;
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
    return ok;
}

// The surface's Definition: points (ids renumbered) and triangular faces; false on a limit.
bool Parser::surfaceDefinition(const pugi::xml_node& def, DesignSurface& s) {
    bool ok = true;
    std::unordered_map<std::string, std::uint32_t> ids;
    forChildren(child(def, "Pnts"), "P", [&](const pugi::xml_node& p) {
        if (!ok)
            return;
        if (++surfacePoints > lim.maxSurfacePoints) {
            ok = fail("more than " + std::to_string(lim.maxSurfacePoints) + " surface points");
            return;
        }
        if (!parseNumbers(p.child_value(), nums, 3) || nums.size() != 3 || !coordOk(nums[0] * unit) ||
            !coordOk(nums[1] * unit) || !coordOk(nums[2] * unit)) {
            warn("surface \"" + s.name + "\": a point is not \"n e z\"; skipped");
            return;
        }
        const std::string id = attrText(p, "id");
        ids[id] = static_cast<std::uint32_t>(s.points.size());
        s.points.push_back({nums[1] * unit, nums[0] * unit, nums[2] * unit});
    });
    if (!ok)
        return false;
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
    return ok;
}

bool Parser::surfaces(const pugi::xml_node& root) {
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
            ok = surfaceBoundaries(sn, s);
            if (!ok)
                return;
            if (pugi::xml_node def = child(sn, "Definition"))
                ok = surfaceDefinition(def, s);
            if (!ok)
                return;
            if (!s.points.empty()) {
                auto [lo, hi] = std::minmax_element(s.points.begin(), s.points.end(),
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

} // namespace ocu::landxml::detail
