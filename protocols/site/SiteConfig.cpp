#include "protocols/site/SiteConfig.h"

#include <boost/asio/ip/address_v4.hpp>
#include <nlohmann/json.hpp>

#include <cmath>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace ocu {

// A relative path in the configuration names a file next to the configuration file (not the working folder).
static std::string resolveSitePath(const std::string& path, const std::string& configFile) {
    if (path.empty() || configFile.empty() || configFile.rfind(":/", 0) == 0)
        return path;
    const std::filesystem::path p(path);
    if (p.is_absolute())
        return path;
    return (std::filesystem::path(configFile).parent_path() / p).lexically_normal().string();
}

// The site's name and its origin (the local frame of every map).
static void readSiteSection(ConfigObject& root, SiteConfig& cfg) {
    if (auto site = root.object("site")) {
        cfg.name = site->string("name", cfg.name);
        if (auto o = site->object("origin")) {
            cfg.origin.lat = o->requiredNumber("latitude", -90, 90).value_or(0);
            cfg.origin.lon = o->requiredNumber("longitude", -180, 180).value_or(0);
            cfg.origin.alt = o->number("altitude", 0, -1000, 9000);
            o->finish();
        } else {
            site->error("origin", "required object is missing (latitude, longitude, altitude)");
        }
        site->finish();
    } else {
        root.error("site", "required object is missing");
    }
}

// The built-in simulators: how many machines of each protocol, and their options.
static void readSimulation(ConfigObject& root, SiteConfig& cfg, const std::string& fileName) {
    if (auto s = root.object("simulation")) {
        cfg.simulation.enabled = s->boolean("enabled", cfg.simulation.enabled);
        cfg.simulation.jausUgvs = static_cast<int>(s->integer("jaus_ugvs", cfg.simulation.jausUgvs, 0, 50));
        cfg.simulation.ahsTrucks =
            static_cast<int>(s->integer("ahs_trucks", cfg.simulation.ahsTrucks, 0, 1000));
        cfg.simulation.ahsSeparateMapService =
            s->boolean("ahs_separate_map_service", cfg.simulation.ahsSeparateMapService);
        cfg.simulation.osyrisRollers =
            static_cast<int>(s->integer("osyris_rollers", cfg.simulation.osyrisRollers, 0, 3));
        cfg.simulation.osyrisSpeedUp = s->number("osyris_speed_up", cfg.simulation.osyrisSpeedUp, 1, 1000);
        cfg.simulation.osyrisPavingJob = s->string("osyris_paving_job", cfg.simulation.osyrisPavingJob);
        if (cfg.simulation.osyrisPavingJob != "built-in" && !cfg.simulation.osyrisPavingJob.empty())
            cfg.simulation.osyrisPavingJob = resolveSitePath(cfg.simulation.osyrisPavingJob, fileName);
        cfg.simulation.osyrisLifts =
            static_cast<int>(s->integer("osyris_lifts", cfg.simulation.osyrisLifts, 1, 20));
        cfg.simulation.osyrisLiftThickness =
            s->number("osyris_lift_thickness", cfg.simulation.osyrisLiftThickness, 0.01, 2);
        cfg.simulation.interfaceAddress = s->string("interface", cfg.simulation.interfaceAddress);
        boost::system::error_code ec;
        boost::asio::ip::make_address_v4(cfg.simulation.interfaceAddress, ec);
        if (ec)
            s->error("interface", "\"" + cfg.simulation.interfaceAddress + "\" is not an IPv4 address");
        s->finish();
    }
}

// When machines go stale and are removed, the monitor rate, the audit log, the stop confirmation.
static void readFleet(ConfigObject& root, SiteConfig& cfg) {
    if (auto f = root.object("fleet")) {
        cfg.fleet.staleAfterSeconds = f->number("stale_after_s", cfg.fleet.staleAfterSeconds, 0.5, 3600);
        cfg.fleet.removeAfterSeconds =
            f->number("remove_after_s", cfg.fleet.removeAfterSeconds, 1, 86400 * 7);
        cfg.fleet.monitorRateHz = f->number("monitor_rate_hz", cfg.fleet.monitorRateHz, 0.01, 100);
        cfg.fleet.auditLog = f->string("audit_log", cfg.fleet.auditLog);
        cfg.fleet.stopConfirmTimeoutSeconds =
            f->number("stop_confirm_timeout_s", cfg.fleet.stopConfirmTimeoutSeconds, 0.1, 600);
        if (cfg.fleet.removeAfterSeconds < cfg.fleet.staleAfterSeconds)
            f->error("remove_after_s", "must not be shorter than stale_after_s");
        f->finish();
    }
}

// Where the console's own position comes from.
static void readOwnPosition(ConfigObject& root, SiteConfig& cfg) {
    if (auto p = root.object("own_position")) {
        cfg.ownPosition.source =
            p->choice("source", cfg.ownPosition.source, {"none", "system", "nmea-file", "nmea-serial"});
        cfg.ownPosition.path = p->string("path", cfg.ownPosition.path);
        cfg.ownPosition.fmsMachineId = p->string("fms_machine_id", cfg.ownPosition.fmsMachineId);
        if ((cfg.ownPosition.source == "nmea-file" || cfg.ownPosition.source == "nmea-serial") &&
            cfg.ownPosition.path.empty())
            p->error("path", "required when source is \"" + cfg.ownPosition.source + "\"");
        p->finish();
    }
}

// The joystick mapping and the video watchdog.
static void readTeleop(ConfigObject& root, SiteConfig& cfg) {
    if (auto t = root.object("teleop")) {
        if (auto j = t->object("joystick")) {
            auto& c = cfg.teleop;
            c.forwardAxis = static_cast<int>(j->integer("forward_axis", c.forwardAxis, 0, 31));
            c.turnAxis = static_cast<int>(j->integer("turn_axis", c.turnAxis, 0, 31));
            c.invertForward = j->boolean("invert_forward", c.invertForward);
            c.invertTurn = j->boolean("invert_turn", c.invertTurn);
            c.deadZone = j->number("dead_zone", c.deadZone, 0, 0.9);
            if (c.forwardAxis == c.turnAxis)
                j->error("turn_axis", "must differ from forward_axis");
            j->finish();
        }
        // The video watchdog's frame age limit (seconds).
        cfg.teleop.videoWatchdogS = t->number("video_watchdog_s", cfg.teleop.videoWatchdogS, 0.1, 10);
        t->finish();
    }
}

// The hardware STOP ALL button.
static void readStopButton(ConfigObject& root, SiteConfig& cfg) {
    if (auto b = root.object("stop_button")) {
        StopButtonConfig c;
        c.device = b->string("device", c.device);
        c.button = static_cast<int>(b->integer("button", c.button, 0, 31));
        b->finish();
        cfg.stopButton = c;
    }
}

// The flight recorder and its retention.
static void readRecord(ConfigObject& root, SiteConfig& cfg) {
    if (auto r = root.object("record")) {
        auto& c = cfg.record;
        c.enabled = r->boolean("enabled", c.enabled);
        c.dir = r->string("dir", c.dir);
        c.maxTotalMb = r->number("max_total_mb", c.maxTotalMb, 0, 1e7);
        c.maxAgeDays = r->number("max_age_days", c.maxAgeDays, 0, 36500);
        c.maxFileMb = r->number("max_file_mb", c.maxFileMb, 0, 1e7);
        c.raw = r->boolean("raw", c.raw);
        c.messages = r->boolean("messages", c.messages);
        r->finish();
    }
}

// The compaction job: design file, stationing, bands, CRS and the areas to compact.
static void readCompaction(ConfigObject& root, SiteConfig& cfg, const std::string& fileName) {
    if (auto c = root.object("compaction")) {
        auto& k = cfg.compaction;
        k.design = resolveSitePath(c->string("design", k.design), fileName);
        k.stationStep = c->number("station_step", k.stationStep, 0.5, 10000);
        k.bandLeft = c->number("band_left", k.bandLeft, 0, 1000);
        k.bandRight = c->number("band_right", k.bandRight, 0, 1000);
        k.epsg = static_cast<int>(c->integer("epsg", k.epsg, 0, 999999));
        for (auto& a : c->objectList("areas")) {
            CompactionAreaConfig area;
            area.name = a.string("name", "");
            area.source = a.choice("source", area.source, {"drawn", "design"});
            const nlohmann::json* pts = a.raw("points");
            if (area.name.empty())
                a.error("name", "required: the area's name");
            if (!pts || !pts->is_array() || pts->size() < 3 || pts->size() > 100000) {
                a.error("points", "required: 3 to 100000 [latitude, longitude] pairs");
            } else {
                for (const auto& p : *pts) {
                    if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number() ||
                        std::fabs(p[0].get<double>()) > 90 || std::fabs(p[1].get<double>()) > 180) {
                        a.error("points", "each point is [latitude, longitude] in degrees");
                        area.ring.clear();
                        break;
                    }
                    area.ring.push_back({p[0].get<double>(), p[1].get<double>(), 0});
                }
            }
            a.finish();
            if (!area.name.empty() && area.ring.size() >= 3)
                k.areas.push_back(std::move(area));
        }
        c->finish();
    }
}

// The control-room history database.
static void readHistory(ConfigObject& root, SiteConfig& cfg) {
    if (auto h = root.object("history")) {
        if (auto pg = h->object("postgres")) {
            PostgresHistoryConfig c;
            c.conninfo = pg->string("conninfo", c.conninfo);
            c.console = pg->string("console", c.console);
            c.outbox = pg->string("outbox", c.outbox);
            if (c.conninfo.empty())
                pg->error("conninfo", "required: the libpq connection string of the control-room database");
            pg->finish();
            cfg.historyPostgres = std::move(c);
        }
        h->finish();
    }
}

static SiteConfig readSite(const ConfigDocument& doc, ConfigErrors& errors, const std::string& fileName) {
    SiteConfig cfg;
    ConfigObject root(doc, "", errors);
    if (!root.valid())
        return cfg;
    readSiteSection(root, cfg);
    readSimulation(root, cfg, fileName);
    readFleet(root, cfg);
    readOwnPosition(root, cfg);
    readTeleop(root, cfg);
    readStopButton(root, cfg);
    readRecord(root, cfg);
    if (auto b = root.object("background")) {
        cfg.background.raster = resolveSitePath(b->string("raster", cfg.background.raster), fileName);
        b->finish();
    }
    if (auto t = root.object("terrain")) {
        cfg.terrain.dem = resolveSitePath(t->string("dem", cfg.terrain.dem), fileName);
        t->finish();
    }
    cfg.compaction.configFile = fileName;
    readCompaction(root, cfg, fileName);
    readHistory(root, cfg);
    if (auto r = root.object("roles"))
        cfg.roles = parseRolesConfig(*r);
#ifdef OCU_SITE_HAVE_JAUS
    if (auto s = root.object("jaus"))
        cfg.jaus = jaus::parseJausConfig(*s);
#else
    root.raw("jaus");
#endif
#ifdef OCU_SITE_HAVE_ISO
    if (auto s = root.object("iso23725"))
        cfg.iso23725 = iso23725::parseIsoConfig(*s);
#else
    root.raw("iso23725");
#endif
#ifdef OCU_SITE_HAVE_OSYRIS
    if (auto s = root.object("osyris"))
        cfg.osyris = osyris::parseOsyrisConfig(*s);
#else
    root.raw("osyris");
#endif
    root.raw("$schema"); // editors may point at a schema; harmless
    root.finish();
    return cfg;
}

Result<SiteConfig> parseSiteConfig(std::string_view text, const std::string& fileName) {
    auto doc = ConfigDocument::parse(text, fileName);
    if (!doc)
        return Error{doc.error()};
    ConfigErrors errors;
    SiteConfig cfg = readSite(*doc, errors, fileName);
    if (!errors.empty())
        return Error{errors.joined()};
    return cfg;
}

Result<SiteConfig> loadSiteConfig(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return Error{path + ": cannot open the site configuration"};
    std::ostringstream ss;
    ss << in.rdbuf();
    return parseSiteConfig(ss.str(), path);
}

} // namespace ocu
