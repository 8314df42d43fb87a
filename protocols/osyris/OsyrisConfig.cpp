#include "protocols/osyris/OsyrisConfig.h"

#include "protocols/common/ConfigReader.h"

#include <pugixml.hpp>

#include <algorithm>
#include <boost/asio/ip/address_v4.hpp>
#include <cctype>
#include <cstdlib>

namespace ocu::osyris {

namespace {

bool validIpv4(const std::string& s) {
    boost::system::error_code ec;
    boost::asio::ip::make_address_v4(s, ec);
    return !ec;
}

} // namespace

OsyrisConfig parseOsyrisConfig(ConfigObject& c) {
    OsyrisConfig o;
    std::string mode = c.choice("addressing", "multicast", {"multicast", "broadcast", "unicast"});
    o.addressing = mode == "broadcast" ? Addressing::Broadcast
                   : mode == "unicast" ? Addressing::Unicast
                                       : Addressing::Multicast;
    o.group = c.string("group", o.group);
    if (!validIpv4(o.group))
        c.error("group", "is not an IPv4 address");
    else if (o.addressing == Addressing::Multicast &&
             !boost::asio::ip::make_address_v4(o.group).is_multicast())
        c.error("group",
                "must be a class-D multicast address (224.0.0.0-239.255.255.255) with addressing multicast");
    o.port = static_cast<std::uint16_t>(c.integer("port", o.port, 49152, 65535));
    o.interfaceAddress = c.string("interface", o.interfaceAddress);
    if (!validIpv4(o.interfaceAddress))
        c.error("interface", "is not an IPv4 address");
    o.unicastPeers = c.stringList("unicastPeers");
    o.multicastTtl = static_cast<int>(c.integer("multicastTtl", o.multicastTtl, 0, 255));
    o.beatMs = static_cast<int>(c.integer("beatMs", o.beatMs, 5, 10000));
    o.minLen = static_cast<int>(c.integer("minLen", o.minLen, 0, 65507));
    o.maxLen = static_cast<int>(c.integer("maxLen", o.maxLen, static_cast<std::int64_t>(kMsgSize), 65507));
    if (o.minLen > o.maxLen)
        c.error("minLen", "must not exceed maxLen");
    o.sendPeriodMs = static_cast<int>(c.integer("sendPeriodMs", o.sendPeriodMs, 10, 600000));
    o.tailPos = static_cast<std::uint32_t>(c.integer("tailPos", 0, 0, 0xFFFFFFFFll));
    o.ttlBeats = static_cast<int>(c.integer("ttlBeats", o.ttlBeats, 1, 10000));
    o.active = static_cast<int>(c.integer("active", o.active, 0, 15));
    o.maxRange = c.number("maxRange", 0, 0, 1e6);
    std::string cs = c.choice("checksum", "none", {"none", "xor", "crc16"});
    o.checksum = cs == "xor" ? Checksum::Xor : cs == "crc16" ? Checksum::Crc16 : Checksum::None;
    o.stationIndex = static_cast<std::uint8_t>(c.integer("stationIndex", o.stationIndex, 0, 253));
    o.sqlitePath = c.string("sqliteFile", "");
    o.originLat = c.number("originLat", 0, -90, 90);
    o.originLon = c.number("originLon", 0, -180, 180);
    o.originAlt = c.number("originAlt", 0, -1000, 10000);
    o.passCount.cellSize = c.number("cellSize", 0.34, 0.05, 10);
    o.passCount.targetMin = static_cast<int>(c.integer("targetMin", 3, 1, 100));
    o.passCount.targetMax = static_cast<int>(c.integer("targetMax", 5, 1, 100));
    if (o.passCount.targetMin > o.passCount.targetMax)
        c.error("targetMin", "must not exceed targetMax");
    const bool vibrationOnly = c.boolean("vibrationOnly", true);
    const std::string vib = c.choice("vibration", vibrationOnly ? "on" : "any", {"on", "off", "any"});
    o.passCount.vibration = vib == "on"    ? VibrationFilter::On
                            : vib == "off" ? VibrationFilter::Off
                                           : VibrationFilter::Any;
    // Lifts and filters.
    o.passCount.liftThickness = c.number("liftThicknessM", 0, 0, 100);
    o.passCount.liftBase = c.number("liftBaseM", 0, -20000, 20000);
    if (c.has("speedMinMps"))
        o.passCount.speedMin = c.number("speedMinMps", 0, 0, 1000);
    if (c.has("speedMaxMps"))
        o.passCount.speedMax = c.number("speedMaxMps", 0, 0, 1000);
    // Late join and gaps.
    o.gapGiveUpNaks = static_cast<int>(c.integer("gapGiveUpNaks", o.gapGiveUpNaks, 0, 1000));
    o.gapGiveUpMs = static_cast<int>(c.number("gapGiveUpSeconds", o.gapGiveUpMs / 1000.0, 0, 86400) * 1000);
    std::string dir = c.choice("direction", "any", {"any", "forward", "backward"});
    o.passCount.direction = dir == "forward"    ? DirectionFilter::Forward
                            : dir == "backward" ? DirectionFilter::Backward
                                                : DirectionFilter::Any;
    o.passCount.minMove = c.number("minMove", 0.25, 0, 10);
    // Plausibility gate: positions outside these never reach the grid or the models.
    auto& pl = o.passCount.plausibility;
    pl.extentM = c.number("plausibleExtentM", pl.extentM, 10, 1e6);
    pl.minWidthM = c.number("plausibleWidthMinM", pl.minWidthM, 0.05, 50);
    pl.maxWidthM = c.number("plausibleWidthMaxM", pl.maxWidthM, 0.05, 50);
    if (pl.minWidthM > pl.maxWidthM)
        c.error("plausibleWidthMinM", "must not exceed plausibleWidthMaxM");
    pl.maxSpeedMps = c.number("plausibleSpeedMaxMps", pl.maxSpeedMps, 0.1, 1000);
    for (auto& m : c.objectList("machines")) {
        auto i = m.integer("idx", -1, 0, 253);
        auto name = m.string("name", "");
        auto type = m.string("type", "");
        if (i < 0) {
            m.error("idx", "is required");
        } else {
            o.machineNames[static_cast<std::uint8_t>(i)] = name;
            if (!type.empty())
                o.machineTypes[static_cast<std::uint8_t>(i)] = type;
        }
        m.finish();
    }
    o.lossWaitBeats = static_cast<int>(c.integer("lossWaitBeats", o.lossWaitBeats, 0, 1000));
    o.maxNakSlots = static_cast<int>(c.integer("maxNakSlots", o.maxNakSlots, 1, 100000));
    o.nakRoundBeats = static_cast<int>(c.integer("nakRoundBeats", o.nakRoundBeats, 1, 10000));
    o.nakBackoffBeats = static_cast<int>(c.integer("nakBackoffBeats", o.nakBackoffBeats, 0, 10000));
    o.passCountPublishMs = static_cast<int>(c.integer("passCountPublishMs", o.passCountPublishMs, 0, 60000));
    c.finish();
    return o;
}

namespace {

// Finds a §7 item as a child element or attribute, case-insensitively, anywhere under the root (depth first,
// an element's attributes before its children). Iterative: a file nested a million levels deep must not
// exhaust the stack.
std::optional<std::string> findItem(const pugi::xml_node& root, const char* name) {
    auto eq = [&](const char* a) {
        std::string x(a), y(name);
        return x.size() == y.size() && std::equal(x.begin(), x.end(), y.begin(), [](char p, char q) {
                   return std::tolower(static_cast<unsigned char>(p)) ==
                          std::tolower(static_cast<unsigned char>(q));
               });
    };
    auto attribute = [&](const pugi::xml_node& n) -> std::optional<std::string> {
        for (auto a : n.attributes())
            if (eq(a.name()))
                return std::string(a.value());
        return std::nullopt;
    };
    if (auto a = attribute(root))
        return a;
    pugi::xml_node n = root.first_child();
    while (n && n != root) {
        if (n.type() == pugi::node_element) {
            if (eq(n.name())) {
                if (auto v = n.attribute("value"))
                    return std::string(v.value());
                return std::string(n.text().get());
            }
            if (auto a = attribute(n))
                return a;
            if (n.first_child()) {
                n = n.first_child();
                continue;
            }
        }
        while (n != root && !n.next_sibling())
            n = n.parent();
        if (n == root)
            break;
        n = n.next_sibling();
    }
    return std::nullopt;
}

} // namespace

Result<OsyrisConfig> importOsyrisXml(const std::string& text, OsyrisConfig o) {
    pugi::xml_document doc;
    auto pr = doc.load_string(text.c_str());
    if (!pr)
        return makeError(std::string("OSYRIS XML: ") + pr.description() + " at offset " +
                         std::to_string(pr.offset));
    std::vector<std::string> errors;
    auto num = [&](const char* name, double min, double max) -> std::optional<double> {
        auto v = findItem(doc, name);
        if (!v)
            return std::nullopt;
        char* end = nullptr;
        double d = std::strtod(v->c_str(), &end);
        // !(in range) rather than (below || above): "nan" parses and compares false both ways, and a NaN
        // cast to int is undefined behaviour (fuzz finding, osyris_xml).
        if (end == v->c_str() || *end != '\0' || !(d >= min && d <= max)) {
            errors.push_back(std::string(name) + ": '" + *v + "' is not a number in [" + std::to_string(min) +
                             ", " + std::to_string(max) + "]");
            return std::nullopt;
        }
        return d;
    };
    // MultiAddr is named twice in §7 (IP and port): accept "ip", "ip:port", and MultiPort/Port elements.
    if (auto a = findItem(doc, "MultiAddr")) {
        std::string ip = *a;
        auto colon = ip.find(':');
        if (colon != std::string::npos) {
            std::string port = ip.substr(colon + 1);
            ip = ip.substr(0, colon);
            int p = std::atoi(port.c_str());
            if (p < 49152 || p > 65535)
                errors.push_back("MultiAddr: port '" + port + "' outside 49152-65535");
            else
                o.port = static_cast<std::uint16_t>(p);
        }
        if (!validIpv4(ip))
            errors.push_back("MultiAddr: '" + ip + "' is not an IPv4 address");
        else {
            o.group = ip;
            auto addr = boost::asio::ip::make_address_v4(ip);
            o.addressing = addr.is_multicast()               ? Addressing::Multicast
                           : (addr.to_uint() & 0xFF) == 0xFF ? Addressing::Broadcast
                                                             : Addressing::Unicast;
        }
    }
    for (const char* pn : {"MultiPort", "Port"})
        if (auto p = num(pn, 49152, 65535))
            o.port = static_cast<std::uint16_t>(*p);
    if (auto v = num("Beat", 5, 10000))
        o.beatMs = static_cast<int>(*v);
    if (auto v = num("MinLen", 0, 65507))
        o.minLen = static_cast<int>(*v);
    if (auto v = num("MaxLen", double(kMsgSize), 65507))
        o.maxLen = static_cast<int>(*v);
    if (auto v = num("SendPeriod", 10, 600000))
        o.sendPeriodMs = static_cast<int>(*v);
    if (auto v = num("TailPos", 0, 4294967295.0))
        o.tailPos = static_cast<std::uint32_t>(*v);
    if (auto v = num("TTL", 1, 10000))
        o.ttlBeats = static_cast<int>(*v);
    if (auto v = num("Active", 0, 15))
        o.active = static_cast<int>(*v);
    if (auto v = num("MaxRange", 0, 1e6))
        o.maxRange = *v;
    if (o.minLen > o.maxLen)
        errors.push_back("MinLen exceeds MaxLen");
    if (!errors.empty()) {
        std::string all = "OSYRIS XML:";
        for (auto& e : errors)
            all += " " + e + ";";
        return makeError(all);
    }
    return o;
}

Result<OsyrisConfig> importOsyrisXmlFile(const std::string& path, OsyrisConfig base) {
    pugi::xml_document doc;
    FILE* f = std::fopen(path.c_str(), "rb");
    if (!f)
        return makeError("OSYRIS XML: cannot open " + path);
    std::string text;
    char buf[4096];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, f)) > 0)
        text.append(buf, n);
    std::fclose(f);
    auto r = importOsyrisXml(text, std::move(base));
    if (!r)
        return makeError(path + ": " + r.error());
    return r;
}

} // namespace ocu::osyris
