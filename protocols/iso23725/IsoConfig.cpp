#include "protocols/iso23725/IsoConfig.h"

#include "protocols/common/ConfigReader.h"

#include <cmath>
#include <set>

namespace ocu::iso23725 {

namespace {
std::chrono::milliseconds ms(ConfigObject& o, const char* key, std::chrono::milliseconds def,
                             std::int64_t min, std::int64_t max) {
    return std::chrono::milliseconds(o.integer(key, def.count(), min, max));
}
} // namespace

IsoConfig parseIsoConfig(ConfigObject& section) {
    IsoConfig c;
    c.enabled = section.boolean("enabled", true);
    c.fmsId = section.string("fmsId", c.fmsId);
    if (!isGuid(c.fmsId))
        section.error("fmsId", "must be a GUID (8-4-4-4-12 hex digits)");
    c.sendPositions = section.boolean("sendPositions", false);
    c.positionRateHz = section.number("positionRateHz", 1.0, 1.0, 10.0);
    c.allStopAckTimeout = ms(section, "allStopAckTimeoutMs", c.allStopAckTimeout, 100, 60000);
    c.allStopStatusTimeout = ms(section, "allStopStatusTimeoutMs", c.allStopStatusTimeout, 100, 120000);
    c.dimensionTolerance = section.number("dimensionTolerance", 0.05, 0.0, 10.0);
    // Plausibility gate for machine positions: outside these a position is not drawn.
    c.plausibility.extentM = section.number("plausibleExtentM", c.plausibility.extentM, 10, 1e6);
    c.plausibility.maxSpeedMps =
        section.number("plausibleSpeedMaxMps", c.plausibility.maxSpeedMps, 0.1, 1000);
    c.plausibility.jumpSlackM = section.number("plausibleJumpSlackM", c.plausibility.jumpSlackM, 0, 1e5);
    c.interfaceDiagnosticPeriod =
        ms(section, "interfaceDiagnosticPeriodMs", c.interfaceDiagnosticPeriod, 1000, 3600000);
    std::set<std::string> names;
    for (auto& l : section.objectList("links")) {
        IsoLinkConfig link;
        link.name = l.string("name", "ahs" + std::to_string(c.links.size() + 1));
        if (!names.insert(link.name).second)
            l.error("name", "duplicate link name '" + link.name + "'");
        link.ws.url = l.string("url", "");
        if (link.ws.url.empty())
            l.error("url", "required (ws://host:port/path or wss://...)");
        else if (auto u = parseWsUrl(link.ws.url); !u)
            l.error("url", u.error());
        link.ws.role =
            l.choice("role", "client", {"client", "service"}) == "service" ? WsRole::Service : WsRole::Client;
        if (auto tls = l.object("tls")) {
            link.ws.tls.caFile = tls->string("ca", "");
            link.ws.tls.certFile = tls->string("cert", "");
            link.ws.tls.keyFile = tls->string("key", "");
            link.ws.tls.verifyHostname = tls->boolean("verifyHostname", true);
            tls->finish();
        }
        link.ws.pingInterval = ms(l, "pingIntervalMs", link.ws.pingInterval, 100, 600000);
        link.ws.deadAfter = ms(l, "deadAfterMs", link.ws.deadAfter, 200, 3600000);
        link.ws.backoffMin = ms(l, "backoffMinMs", link.ws.backoffMin, 10, 600000);
        link.ws.backoffMax = ms(l, "backoffMaxMs", link.ws.backoffMax, 10, 3600000);
        link.ws.maxFrameBytes = static_cast<std::size_t>(
            l.integer("maxFrameBytes", 16 * 1024 * 1024, 1024, 1024LL * 1024 * 1024));
        link.ws.subprotocol = l.string("subprotocol", "");
        if (link.ws.deadAfter <= link.ws.pingInterval)
            l.error("deadAfterMs", "must be longer than pingIntervalMs");
        // Q10 [I]: the map service on its own socket; same TLS files and timing, always the client side.
        if (std::string mapUrl = l.string("mapUrl", ""); !mapUrl.empty()) {
            if (auto u = parseWsUrl(mapUrl); !u)
                l.error("mapUrl", u.error());
            link.mapWs = link.ws;
            link.mapWs.role = WsRole::Client;
            link.mapWs.url = mapUrl;
        }
        l.finish();
        c.links.push_back(std::move(link));
    }
    std::set<std::string> ids;
    for (auto& m : section.objectList("fleet")) {
        Equipment e;
        e.equipmentId = m.string("equipmentId", "");
        if (!isGuid(e.equipmentId))
            m.error("equipmentId", "must be a GUID");
        else if (!ids.insert(e.equipmentId).second)
            m.error("equipmentId", "duplicate machine " + e.equipmentId);
        e.hid = m.string("hid", "");
        if (e.hid.empty())
            m.error("hid", "required");
        std::vector<std::string> types(enums::equipmentType.begin(), enums::equipmentType.end());
        e.type = m.choice("type", "LightVehicle", types);
        e.oem = m.string("oem", "");
        e.model = m.string("model", "");
        e.autonomous = m.boolean("autonomous", false);
        e.length = m.number("length", 5.0, 0.1, 100.0);
        e.width = m.number("width", 2.5, 0.1, 50.0);
        m.finish();
        c.fleet.push_back(std::move(e));
    }
    if (auto r = section.object("inferred")) {
        c.rules.acceptAliases = r->boolean("acceptAliases", true);
        c.rules.repairTimestamps = r->boolean("repairTimestamps", true);
        c.rules.acceptNumericStrings = r->boolean("acceptNumericStrings", true);
        c.rules.acceptMissingVersion = r->boolean("acceptMissingVersion", true);
        c.rules.caseInsensitiveEnums = r->boolean("caseInsensitiveEnums", true);
        c.rules.allStopStatusAlias = r->string("allStopStatusAlias", c.rules.allStopStatusAlias);
        c.rules.mapServiceMember = r->string("mapServiceMember", c.rules.mapServiceMember);
        c.rules.emitNegativeWayIds = r->boolean("emitNegativeWayIds", false);
        c.rules.sendRoutes = r->boolean("sendRoutes", true);
        r->finish();
    }
    section.finish();
    return c;
}

} // namespace ocu::iso23725
