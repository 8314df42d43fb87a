#include "protocols/site/SiteConfig.h"

#include <QtTest>

using namespace ocu;

class TestSiteConfig : public QObject {
    Q_OBJECT
private slots:
    void builtInSiteIsValid() {
        auto cfg = loadSiteConfig(OCU_SOURCE_DIR "/resources/sites/simulated-site.json");
        QVERIFY2(cfg.ok(), cfg.ok() ? "" : cfg.error().c_str());
        QVERIFY(cfg->simulation.enabled);
        QCOMPARE(cfg->origin.lat, 48.2085);
        QCOMPARE(cfg->origin.lon, 11.4702);
    }
    // The flight recorder's section.
    void recordSection() {
        auto def = parseSiteConfig(R"({"site":{"origin":{"latitude":1,"longitude":2}}})", "d.json");
        QVERIFY(def.ok());
        QVERIFY(def->record.enabled);
        QVERIFY(def->record.dir.empty());
        auto cfg = parseSiteConfig(R"({"site":{"origin":{"latitude":1,"longitude":2}},
            "record":{"enabled":false,"dir":"/var/rec","max_total_mb":100,"max_age_days":7,"max_file_mb":50,
                      "raw":true}})",
                                   "r.json");
        QVERIFY2(cfg.ok(), cfg.ok() ? "" : cfg.error().c_str());
        QVERIFY(!cfg->record.enabled);
        QCOMPARE(cfg->record.dir, std::string("/var/rec"));
        QCOMPARE(cfg->record.maxTotalMb, 100.0);
        QCOMPARE(cfg->record.maxAgeDays, 7.0);
        QCOMPARE(cfg->record.maxFileMb, 50.0);
        QVERIFY(cfg->record.raw);
        auto bad =
            parseSiteConfig(R"({"site":{"origin":{"latitude":1,"longitude":2}},"record":{"max_age_days":-1,
            "keep":true}})",
                            "b.json");
        QVERIFY(!bad.ok());
        QVERIFY(QString::fromStdString(bad.error()).contains("record.max_age_days"));
        QVERIFY(QString::fromStdString(bad.error()).contains("record.keep"));
    }
    // Users and groups mapped to roles; no entry = monitor; strict errors with file:line.
    void rolesSection() {
        auto none = parseSiteConfig(R"({"site":{"origin":{"latitude":1,"longitude":2}}})", "n.json");
        QVERIFY(none.ok());
        QVERIFY(!none->roles.configured);
        QCOMPARE(none->roles.roleOf("anyone", {}), OperatorRole::Admin);
        auto cfg = parseSiteConfig(R"({"site":{"origin":{"latitude":1,"longitude":2}},
            "roles":{"users":{"alice":"supervisor","bob":"monitor"},
                     "groups":{"ocu-dispatch":"dispatcher","ugv":"ugv_operator","paving":"site_manager"},
                     "authority":{"ugv_operator":210,"supervisor":240},"lock_after_idle_s":300}})",
                                   "r.json");
        QVERIFY2(cfg.ok(), cfg.ok() ? "" : cfg.error().c_str());
        const RolesConfig& r = cfg->roles;
        QVERIFY(r.configured);
        QCOMPARE(r.roleOf("alice", {"ugv"}), OperatorRole::Supervisor); // the user's own entry first
        QCOMPARE(r.roleOf("bob", {"ugv"}), OperatorRole::Monitor);
        QCOMPARE(r.roleOf("carol", {"paving", "ocu-dispatch"}), OperatorRole::SiteManager); // highest role
        QCOMPARE(r.roleOf("dave", {"ugv", "users"}), OperatorRole::UgvOperator);
        QCOMPARE(r.roleOf("erin", {"users"}), OperatorRole::Monitor); // no role: monitor
        QCOMPARE(r.authorityOf(OperatorRole::UgvOperator), 210);
        QCOMPARE(r.authorityOf(OperatorRole::Supervisor), 240);
        QCOMPARE(r.authorityOf(OperatorRole::Admin), 230); // default
        QCOMPARE(r.authorityOf(OperatorRole::Monitor), 0);
        QCOMPARE(r.lockAfterIdleS, 300.0);
        const char* text = "{\"site\":{\"origin\":{\"latitude\":1,\"longitude\":2}},\n"
                           "\"roles\":{\n"
                           "  \"users\":{\"alice\":\"superviser\"},\n"
                           "  \"authority\":{\"admin\":100},\n"
                           "  \"group\":{}}}\n";
        auto bad = parseSiteConfig(text, "bad.json");
        QVERIFY(!bad.ok());
        const QString e = QString::fromStdString(bad.error());
        QVERIFY2(e.contains("bad.json:3: roles.users.alice: \"superviser\" is not one of"), qPrintable(e));
        QVERIFY2(e.contains("bad.json:4: roles.authority.admin: authority 100 is in no OCU band"),
                 qPrintable(e));
        QVERIFY2(e.contains("bad.json:5: roles.group: unknown key \"group\""), qPrintable(e));
        QCOMPARE(roleFromName("ugv_operator"), std::optional(OperatorRole::UgvOperator));
        for (OperatorRole role : kAllOperatorRoles)
            QCOMPARE(roleFromName(roleName(role)), std::optional(role));
    }
    void misspelledKeyNamesKeyAndLine() {
        const char* text = "{\n"
                           "  \"site\": {\n"
                           "    \"name\": \"Quarry\",\n"
                           "    \"origin\": { \"latitude\": 48.1, \"longitude\": 11.2 }\n"
                           "  },\n"
                           "  \"fleet\": { \"stale_afer_s\": 3 }\n"
                           "}\n";
        auto cfg = parseSiteConfig(text, "quarry.json");
        QVERIFY(!cfg.ok());
        QCOMPARE(QString::fromStdString(cfg.error()),
                 QString("quarry.json:6: fleet.stale_afer_s: unknown key \"stale_afer_s\" (did you mean "
                         "\"stale_after_s\"?)"));
    }
    void latitudeOutOfRange() {
        const char* text = "{\n"
                           "  \"site\": {\n"
                           "    \"origin\": {\n"
                           "      \"latitude\": 123,\n"
                           "      \"longitude\": 11.2\n"
                           "    }\n"
                           "  }\n"
                           "}\n";
        auto cfg = parseSiteConfig(text, "bad.json");
        QVERIFY(!cfg.ok());
        QCOMPARE(QString::fromStdString(cfg.error()),
                 QString("bad.json:4: site.origin.latitude: 123 is out of range [-90, 90]"));
    }
    void everyProblemIsListed() {
        auto cfg = parseSiteConfig(R"({"site": {"origin": {"latitude": "x"}}, "simulaton": {}})", "m.json");
        QVERIFY(!cfg.ok());
        QString e = QString::fromStdString(cfg.error());
        QVERIFY2(e.contains("site.origin.latitude: must be a number, not string"), qPrintable(e));
        QVERIFY2(e.contains("site.origin.longitude: required number is missing"), qPrintable(e));
        QVERIFY2(e.contains("unknown key \"simulaton\" (did you mean \"simulation\"?)"), qPrintable(e));
    }
    void missingSiteIsRefused() {
        auto cfg = parseSiteConfig("{}", "e.json");
        QVERIFY(!cfg.ok());
        QVERIFY(QString::fromStdString(cfg.error()).contains("site: required object is missing"));
        QVERIFY(!parseSiteConfig("[1,2]", "a.json").ok());
        QVERIFY(!parseSiteConfig("", "z.json").ok());
        QVERIFY(!loadSiteConfig("/nonexistent/site.json").ok());
    }
    void joystickMapping() {
        auto cfg = parseSiteConfig(
            R"({"site": {"origin": {"latitude": 1, "longitude": 2}},
                "teleop": {"joystick": {"forward_axis": 3, "turn_axis": 2, "invert_forward": false, "dead_zone": 0.2}}})",
            "j.json");
        QVERIFY2(cfg.ok(), cfg.ok() ? "" : cfg.error().c_str());
        QCOMPARE(cfg->teleop.forwardAxis, 3);
        QCOMPARE(cfg->teleop.turnAxis, 2);
        QCOMPARE(cfg->teleop.invertForward, false);
        QCOMPARE(cfg->teleop.deadZone, 0.2);
        auto bad = parseSiteConfig(
            R"({"site": {"origin": {"latitude": 1, "longitude": 2}},
                "teleop": {"joystick": {"forward_axis": 1, "turn_axis": 1, "dead_zone": 0.95}}})",
            "b.json");
        QVERIFY(!bad.ok());
        QVERIFY(QString::fromStdString(bad.error())
                    .contains("teleop.joystick.turn_axis: must differ from forward_axis"));
        QVERIFY(
            QString::fromStdString(bad.error()).contains("teleop.joystick.dead_zone: 0.95 is out of range"));
    }
    // The teleop video watchdog's limit.
    void videoWatchdogLimit() {
        auto def = parseSiteConfig(R"({"site": {"origin": {"latitude": 1, "longitude": 2}}})", "d.json");
        QVERIFY(def.ok());
        QCOMPARE(def->teleop.videoWatchdogS, 1.0);
        auto cfg = parseSiteConfig(
            R"({"site": {"origin": {"latitude": 1, "longitude": 2}}, "teleop": {"video_watchdog_s": 0.5}})",
            "v.json");
        QVERIFY2(cfg.ok(), cfg.ok() ? "" : cfg.error().c_str());
        QCOMPARE(cfg->teleop.videoWatchdogS, 0.5);
        auto bad = parseSiteConfig(
            R"({"site": {"origin": {"latitude": 1, "longitude": 2}}, "teleop": {"video_watchdog_s": 0}})",
            "w.json");
        QVERIFY(!bad.ok());
        QVERIFY(QString::fromStdString(bad.error()).contains("teleop.video_watchdog_s"));
    }
    // The hardware STOP ALL button: absent by default, device and button read, a bad button index refused.
    void stopButton() {
        auto def = parseSiteConfig(R"({"site": {"origin": {"latitude": 1, "longitude": 2}}})", "d.json");
        QVERIFY(def.ok());
        QVERIFY(!def->stopButton);
        auto cfg = parseSiteConfig(R"({"site": {"origin": {"latitude": 1, "longitude": 2}},
                "stop_button": {"device": "Big red", "button": 3}})",
                                   "s.json");
        QVERIFY2(cfg.ok(), cfg.ok() ? "" : cfg.error().c_str());
        QVERIFY(cfg->stopButton);
        QCOMPARE(cfg->stopButton->device, std::string("Big red"));
        QCOMPARE(cfg->stopButton->button, 3);
        auto any = parseSiteConfig(
            R"({"site": {"origin": {"latitude": 1, "longitude": 2}}, "stop_button": {}})", "a.json");
        QVERIFY(any.ok());
        QCOMPARE(any->stopButton->device, std::string());
        QCOMPARE(any->stopButton->button, 0);
        auto bad = parseSiteConfig(R"({"site": {"origin": {"latitude": 1, "longitude": 2}},
                "stop_button": {"button": 40, "colour": "red"}})",
                                   "b.json");
        QVERIFY(!bad.ok());
        QVERIFY(QString::fromStdString(bad.error()).contains("stop_button.button: 40 is out of range"));
        QVERIFY(QString::fromStdString(bad.error()).contains("stop_button.colour"));
    }
    void crossFieldCheck() {
        auto cfg = parseSiteConfig(
            R"({"site": {"origin": {"latitude": 1, "longitude": 2}}, "fleet": {"stale_after_s": 10, "remove_after_s": 5}})",
            "c.json");
        QVERIFY(!cfg.ok());
        QVERIFY(QString::fromStdString(cfg.error())
                    .contains("remove_after_s: must not be shorter than stale_after_s"));
    }
    void postgresHistory() {
        auto none = parseSiteConfig(R"({"site": {"origin": {"latitude": 1, "longitude": 2}}})", "n.json");
        QVERIFY(none.ok());
        QVERIFY(!none->historyPostgres);
        auto cfg = parseSiteConfig(
            R"({"site": {"origin": {"latitude": 1, "longitude": 2}},
                "history": {"postgres": {"conninfo": "host=db dbname=ocu", "console": "dispatcher"}}})",
            "h.json");
        QVERIFY2(cfg.ok(), cfg.ok() ? "" : cfg.error().c_str());
        QVERIFY(cfg->historyPostgres);
        QCOMPARE(cfg->historyPostgres->conninfo, std::string("host=db dbname=ocu"));
        QCOMPARE(cfg->historyPostgres->console, std::string("dispatcher"));
        QVERIFY(cfg->historyPostgres->outbox.empty());
        auto bad = parseSiteConfig(
            R"({"site": {"origin": {"latitude": 1, "longitude": 2}}, "history": {"postgres": {"consle": "x"}}})",
            "b.json");
        QVERIFY(!bad.ok());
        QVERIFY(QString::fromStdString(bad.error()).contains("conninfo"));
        QVERIFY(QString::fromStdString(bad.error()).contains("consle"));
    }
    // The compaction section (design next to the file, areas as [lat, lon] rings).
    void compactionSection() {
        auto cfg = parseSiteConfig(R"({"site":{"origin":{"latitude":1,"longitude":2}},
            "compaction":{"design":"job.xml","station_step":25,"band_left":5,"band_right":7,"epsg":32632,
              "areas":[{"name":"Lot 1","points":[[48.1,11.1],[48.1,11.2],[48.2,11.2]]}]}})",
                                   "/etc/ocu/site.json");
        QVERIFY2(cfg.ok(), cfg.ok() ? "" : cfg.error().c_str());
        QCOMPARE(cfg->compaction.design, std::string("/etc/ocu/job.xml"));
        QCOMPARE(cfg->compaction.stationStep, 25.0);
        QCOMPARE(cfg->compaction.bandRight, 7.0);
        QCOMPARE(cfg->compaction.epsg, 32632);
        QCOMPARE(cfg->compaction.configFile, std::string("/etc/ocu/site.json"));
        QCOMPARE(cfg->compaction.areas.size(), std::size_t(1));
        QCOMPARE(cfg->compaction.areas[0].ring.size(), std::size_t(3));
        QCOMPARE(cfg->compaction.areas[0].ring[2].lat, 48.2);
        auto bad = parseSiteConfig(R"({"site":{"origin":{"latitude":1,"longitude":2}},
            "compaction":{"areas":[{"name":"x","points":[[1,2],[3]]},{"points":[[1,2],[1,3],[2,2]]}]}})",
                                   "b.json");
        QVERIFY(!bad.ok());
        QVERIFY(QString::fromStdString(bad.error()).contains("compaction/areas/0/points") ||
                QString::fromStdString(bad.error()).contains("points"));
        QVERIFY(QString::fromStdString(bad.error()).contains("name"));
        // The simulated paving job's LandXML file is next to the configuration, like the design.
        auto sim = parseSiteConfig(R"({"site":{"origin":{"latitude":1,"longitude":2}},
            "simulation":{"enabled":true,"osyris_paving_job":"../designs/job.xml"}})",
                                   "/etc/ocu/sites/site.json");
        QVERIFY2(sim.ok(), sim.ok() ? "" : sim.error().c_str());
        QCOMPARE(sim->simulation.osyrisPavingJob, std::string("/etc/ocu/designs/job.xml"));
        sim = parseSiteConfig(R"({"site":{"origin":{"latitude":1,"longitude":2}},
            "simulation":{"enabled":true,"osyris_paving_job":"built-in"}})",
                              "/etc/ocu/sites/site.json");
        QCOMPARE(sim->simulation.osyrisPavingJob, std::string("built-in"));
    }
};

QTEST_GUILESS_MAIN(TestSiteConfig)
#include "test_site_config.moc"
