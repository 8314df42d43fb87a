#pragma once
// The site configuration: one JSON file (docs/site-config.md) with the site origin, the fleet-picture
// settings and one section per protocol. Parsing is strict: every problem is reported with the key path
// and line, and a configuration with any error is refused as a whole.
#include "protocols/common/ConfigReader.h"
#include "protocols/common/GeoFrame.h"
#include "protocols/common/Result.h"
#include "protocols/common/OperatorRoles.h"

#include <optional>
#include <string>

// OCU_SITE_HAVE_* are set by CMake for each protocol stack that is part of the build.
#ifdef OCU_SITE_HAVE_JAUS
#include "protocols/jaus/JausConfig.h"
#endif
#ifdef OCU_SITE_HAVE_ISO
#include "protocols/iso23725/IsoConfig.h"
#endif
#ifdef OCU_SITE_HAVE_OSYRIS
#include "protocols/osyris/OsyrisConfig.h"
#endif

namespace ocu {

struct SimulationConfig {
    // When enabled the console starts the built-in simulated site in-process, on loopback sockets,
    // and points each protocol section at it.
    bool enabled = false;
    int jausUgvs = 2;
    int ahsTrucks = 6;
    double ahsPositionRateHz =
        2.0; // truck positions per second (1-10, ISO 23725 §5 row 3); ocu-sim --truck-rate
    // The simulated AHS serves its map service on a socket of its own (ISO 23725 Q10) instead of the main
    // one.
    bool ahsSeparateMapService = false;
    int osyrisRollers = 2;
    double osyrisSpeedUp = 30.0; // paver pace multiplied for demos
    // The simulated paving train drives a long job: "built-in" or a LandXML file (its first
    // alignment, UTM), in osyrisLifts lifts of osyrisLiftThickness m. Empty = the short test road.
    std::string osyrisPavingJob;
    int osyrisLifts = 3;
    double osyrisLiftThickness = 0.05;
    // Address the simulators listen on. 127.0.0.1 (default) keeps all traffic on the host; a LAN
    // address lets consoles on other hosts reach `ocu-sim`.
    std::string interfaceAddress = "127.0.0.1";
};

struct FleetConfig {
    double staleAfterSeconds = 5.0;    // grey after this much silence
    double removeAfterSeconds = 600.0; // dropped from the list after this
    double monitorRateHz = 1.0;        // headless monitor: lines per machine per second
    std::string auditLog;              // append-only audit file; empty = none
    // A stop not confirmed by the machine's own report (JAUS emergency, ISO 23725 all-stop) within this
    // time raises an alarm.
    double stopConfirmTimeoutSeconds = 3.0;
};

struct OwnPositionConfig {
    std::string source = "none"; // none | system | nmea-file | nmea-serial
    std::string path;            // NMEA log file or serial device
    std::string fmsMachineId;    // when set, sent to the AHS as MachinePositionV1
};

// Joystick / game controller used by the teleop panel (SDL2 axis indices).
struct TeleopInputConfig {
    int forwardAxis = 1;       // game controller left stick Y
    int turnAxis = 0;          // left stick X
    bool invertForward = true; // SDL reports a stick pushed away as negative
    bool invertTurn = false;
    double deadZone = 0.12;
    // Driving is held when the teleop video is lost or its frame older than this (seconds).
    double videoWatchdogS = 1.0;
};

// A gamepad or USB button that triggers STOP ALL, read off the GUI thread (docs/site-config.md
// `stop_button`).
struct StopButtonConfig {
    std::string device; // part of the device's name; empty = the first device that has the button
    int button = 0;     // SDL button index
};

// The flight recorder (docs/recording.md): always on unless enabled is false.
struct RecordConfig {
    bool enabled = true;
    std::string dir;          // folder of the per-run files; empty = the user's data folder /recordings
    double maxTotalMb = 2048; // the folder's recordings beyond this: the oldest go (0 = no limit)
    double maxAgeDays = 30;   // recordings older than this go (0 = no limit)
    double maxFileMb = 0;     // one run's file beyond this: its oldest machine data go (0 = no limit)
    bool raw = false;         // record.raw: raw frames too
    bool messages = false;    // record.messages: every decoded inbound message (off: the states drive replay)
};

// The 2D map's background raster (GeoTIFF or .mbtiles) and the 3D view's terrain (a GeoTIFF
// DEM; empty = flat ground). Relative paths are resolved against the configuration file's folder; empty =
// none.
struct MapBackgroundConfig {
    std::string raster;
};
struct TerrainConfig {
    std::string dem;
};

// The shared control-room history on PostgreSQL: "history": {"postgres": {...}}.
struct PostgresHistoryConfig {
    std::string conninfo; // libpq connection string, e.g. "host=ocu-db dbname=ocu user=ocu"
    std::string console;  // this console's name in the shared history; empty = the host name
    std::string outbox;   // the local SQLite outbox; empty = history-outbox-<console>.sqlite in the data dir
};

// The compaction job: its LandXML design and its named areas (rings of WGS 84 points), saved with
// the site ("compaction": {"design": "job.xml", "areas": [{"name": "Lot 1", "points": [[lat, lon], ...]}],
// "station_step": 20, "band_left": 6, "band_right": 6, "epsg": 0}).
struct CompactionAreaConfig {
    std::string name;
    std::string source = "drawn"; // or "design"
    std::vector<GeoPoint> ring;
};
struct CompactionConfig {
    std::string design; // LandXML file; relative to the configuration file's folder
    std::vector<CompactionAreaConfig> areas;
    double stationStep = 20, bandLeft = 6, bandRight = 6;
    int epsg = 0;           // report CRS; 0 = the design's, else the site's UTM zone
    std::string configFile; // the file this configuration came from (where areas are saved)
};

struct SiteConfig {
    std::string name = "Unnamed site";
    GeoPoint origin;
    SimulationConfig simulation;
    FleetConfig fleet;
    OwnPositionConfig ownPosition;
    TeleopInputConfig teleop;
    std::optional<StopButtonConfig> stopButton;
    RecordConfig record;
    MapBackgroundConfig background;
    TerrainConfig terrain;
    std::optional<PostgresHistoryConfig> historyPostgres;
    CompactionConfig compaction;
    RolesConfig roles; // who may do what (docs/roles.md)
#ifdef OCU_SITE_HAVE_JAUS
    std::optional<jaus::JausConfig> jaus;
#endif
#ifdef OCU_SITE_HAVE_ISO
    std::optional<iso23725::IsoConfig> iso23725;
#endif
#ifdef OCU_SITE_HAVE_OSYRIS
    std::optional<osyris::OsyrisConfig> osyris;
#endif
};

// Parses and validates; the error lists every problem found, one per line, each naming file, line and key.
Result<SiteConfig> parseSiteConfig(std::string_view text, const std::string& fileName);
Result<SiteConfig> loadSiteConfig(const std::string& path);

} // namespace ocu
