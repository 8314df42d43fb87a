// LandXML import: the XML helpers, the file's units and CRS, and the entry points (parseLandXml,
// loadLandXml).
#include "protocols/site/LandXml.h"
#include "protocols/site/LandXmlParser.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>

namespace ocu::landxml {

namespace detail {

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

// "northing easting [z]" of an element's text.
std::optional<PlanPoint> Parser::point(const pugi::xml_node& n, std::string_view what,
                                       const std::string& where) {
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

void Parser::units(const pugi::xml_node& root) {
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

void Parser::crs(const pugi::xml_node& root) {
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

} // namespace detail

using namespace detail;

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
