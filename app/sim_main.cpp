// ocu-sim: the simulated site on its own — simulated JAUS UGVs, an ISO 23725 AHS with haul trucks and an
// OSYRIS paving train — for a second machine, for demos, or to drive another console.
#include "app/SiteLoader.h"

#include "protocols/common/Log.h"
#include "sim/SimulatedSite.h"

#ifdef OCU_HAVE_SIM_JAUS
#include "sim/jaus/JausDemo.h"
#endif
#ifdef OCU_HAVE_SIM_ISO23725
#include "sim/iso23725/IsoDemo.h"
#endif
#ifdef OCU_HAVE_SIM_OSYRIS
#include "sim/osyris/OsyrisDemo.h"
#endif

#include <boost/asio/ip/address_v4.hpp>
#include <nlohmann/json.hpp>

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFile>
#include <QTimer>

#include <atomic>
#include <csignal>
#include <cstdio>

namespace {
std::atomic<bool> g_quit{false};
void onSignal(int) {
    g_quit = true;
}

// The site configuration a console on any host needs to reach these simulators (keys as in
// docs/site-config.md and the protocol documents).
nlohmann::json consoleConfig(const ocu::SiteConfig& cfg, ocu::sim::SimulatedSite& sim) {
    using nlohmann::json;
    const std::string iface = cfg.simulation.interfaceAddress;
    json out;
    out["site"] = {
        {"name", cfg.name + " (ocu-sim)"},
        {"origin",
         {{"latitude", cfg.origin.lat}, {"longitude", cfg.origin.lon}, {"altitude", cfg.origin.alt}}}};
#ifdef OCU_HAVE_SIM_JAUS
    if (auto* j = sim.jaus()) {
        json statics = json::array();
        for (auto& u : j->ugvs())
            statics.push_back(
                {{"subsystem", u->config().subsystemId}, {"address", iface}, {"port", u->localPort()}});
        out["jaus"] = {{"subsystem_id", 200},
                       {"call_sign", "OCU"},
                       {"role", "primary_operator"},
                       {"authority", 205},
                       {"port", 0},
                       {"multicast_group", cfg.jaus->transport.multicastGroup},
                       {"multicast_port", j->multicastPort()},
                       {"multicast_ttl", iface == "127.0.0.1" ? 0 : 1},
                       {"interface_address", iface == "127.0.0.1" ? "127.0.0.1" : "0.0.0.0"},
                       {"static_endpoints", statics}};
    }
#endif
#ifdef OCU_HAVE_SIM_ISO23725
    if (auto* i = sim.iso(); i && i->ahs) {
        json links = json::array();
        for (const auto& l : cfg.iso23725->links) {
            json link = {{"name", l.name}, {"url", l.ws.url}};
            if (!l.mapWs.url.empty())
                link["mapUrl"] = l.mapWs.url;
            links.push_back(link);
        }
        out["iso23725"] = {{"links", links}};
    }
#endif
#ifdef OCU_HAVE_SIM_OSYRIS
    if (sim.osyris()) {
        const auto& o = *cfg.osyris;
        json machines = json::array();
        for (const auto& [idx, name] : o.machineNames) {
            auto t = o.machineTypes.find(idx);
            machines.push_back(
                {{"idx", idx}, {"name", name}, {"type", t == o.machineTypes.end() ? "" : t->second}});
        }
        out["osyris"] = {{"group", o.group},
                         {"port", o.port},
                         {"interface", iface == "127.0.0.1" ? "127.0.0.1" : "0.0.0.0"},
                         {"multicastTtl", o.multicastTtl},
                         {"originLat", o.originLat},
                         {"originLon", o.originLon},
                         {"originAlt", o.originAlt},
                         {"machines", machines}};
    }
#endif
    return out;
}
} // namespace

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("ocu-sim"));
    QCoreApplication::setApplicationVersion(QStringLiteral(OCU_VERSION));
    QCommandLineParser p;
    p.setApplicationDescription(QStringLiteral(
        "The simulated site on its own: JAUS UGVs, an ISO 23725 AHS with haul trucks and an OSYRIS paving "
        "train, speaking the real protocols. Prints where each simulator listens, then runs until "
        "interrupted (or --duration)."));
    p.addHelpOption();
    p.addVersionOption();
    QCommandLineOption config({QStringLiteral("c"), QStringLiteral("config")},
                              QStringLiteral("Site configuration whose \"site\" and \"simulation\" sections "
                                             "are used (default: the built-in simulated site)."),
                              QStringLiteral("FILE"));
    QCommandLineOption duration(QStringLiteral("duration"),
                                QStringLiteral("Stop after SECONDS (default: never)."),
                                QStringLiteral("SECONDS"), QStringLiteral("0"));
    QCommandLineOption ugvs(QStringLiteral("ugvs"), QStringLiteral("Number of simulated JAUS UGVs."),
                            QStringLiteral("N"));
    QCommandLineOption trucks(QStringLiteral("trucks"),
                              QStringLiteral("Number of simulated haul trucks (≤ 1000)."),
                              QStringLiteral("N"));
    QCommandLineOption rollers(QStringLiteral("rollers"),
                               QStringLiteral("Number of simulated rollers (0-3)."), QStringLiteral("N"));
    QCommandLineOption iface(
        QStringLiteral("interface"),
        QStringLiteral("IPv4 address the simulators listen on and send multicast from "
                       "(default 127.0.0.1: nothing leaves this host). Use this host's LAN "
                       "address to serve consoles on other hosts."),
        QStringLiteral("ADDR"));
    QCommandLineOption writeConfig(QStringLiteral("write-config"),
                                   QStringLiteral("Write a site configuration for a console that connects to "
                                                  "these simulators (ocu --config FILE --no-sim)."),
                                   QStringLiteral("FILE"));
    QCommandLineOption separateMap(
        QStringLiteral("separate-map-service"),
        QStringLiteral("The AHS serves its ISO 23725 map service on a socket of its "
                       "own (the written configuration gets its mapUrl)."));
    p.addOptions({config, duration, ugvs, trucks, rollers, iface, writeConfig, separateMap});
    p.process(app);

    auto site = ocu::loadSite(p.value(config));
    if (!site) {
        std::fprintf(stderr, "ocu-sim: the site configuration was refused:\n%s\n", site.error().c_str());
        return 2;
    }
    ocu::SiteConfig cfg = std::move(site.value());
    auto intOption = [&](const QCommandLineOption& o, int& target, int max) {
        if (!p.isSet(o))
            return true;
        bool ok = false;
        const int v = p.value(o).toInt(&ok);
        if (!ok || v < 0 || v > max) {
            std::fprintf(stderr, "ocu-sim: --%s must be an integer 0..%d\n",
                         qPrintable(o.names().constLast()), max);
            return false;
        }
        target = v;
        return true;
    };
    if (!intOption(ugvs, cfg.simulation.jausUgvs, 50) || !intOption(trucks, cfg.simulation.ahsTrucks, 1000) ||
        !intOption(rollers, cfg.simulation.osyrisRollers, 3))
        return 2;
    cfg.simulation.enabled = true;
    if (p.isSet(separateMap))
        cfg.simulation.ahsSeparateMapService = true;
    if (p.isSet(iface)) {
        boost::system::error_code ec;
        boost::asio::ip::make_address_v4(p.value(iface).toStdString(), ec);
        if (ec) {
            std::fprintf(stderr, "ocu-sim: --interface: \"%s\" is not an IPv4 address\n",
                         qPrintable(p.value(iface)));
            return 2;
        }
        cfg.simulation.interfaceAddress = p.value(iface).toStdString();
    }

    ocu::sim::SimulatedSite sim;
    const std::string err = sim.start(cfg);
    if (!err.empty())
        std::fprintf(stderr, "ocu-sim: %s\n", err.c_str());

    std::printf("ocu-sim: simulated site \"%s\" around %.6f, %.6f\n", cfg.name.c_str(), cfg.origin.lat,
                cfg.origin.lon);
#ifdef OCU_HAVE_SIM_JAUS
    if (auto* j = sim.jaus()) {
        std::printf("  JAUS: %zu UGVs, multicast %s:%u on 127.0.0.1\n", j->ugvs().size(),
                    cfg.jaus->transport.multicastGroup.c_str(), j->multicastPort());
        for (auto& u : j->ugvs())
            std::printf("    %s subsystem %u, unicast 127.0.0.1:%u\n", u->config().callSign.c_str(),
                        u->config().subsystemId, u->localPort());
    }
#endif
#ifdef OCU_HAVE_SIM_ISO23725
    if (auto* i = sim.iso(); i && i->ahs)
        for (const auto& l : cfg.iso23725->links)
            std::printf("  ISO 23725: AHS with %d trucks at %s%s%s\n", cfg.simulation.ahsTrucks,
                        l.ws.url.c_str(), l.mapWs.url.empty() ? "" : ", map service at ",
                        l.mapWs.url.c_str());
#endif
#ifdef OCU_HAVE_SIM_OSYRIS
    if (auto* o = sim.osyris())
        std::printf("  OSYRIS: %zu stations on %s:%u (interface %s)\n", o->stationCount(),
                    cfg.osyris->group.c_str(), cfg.osyris->port, cfg.osyris->interfaceAddress.c_str());
#endif
    std::fflush(stdout);
    if (p.isSet(writeConfig)) {
        const std::string text = consoleConfig(cfg, sim).dump(2) + "\n";
        QFile f(p.value(writeConfig));
        if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate) ||
            f.write(text.data(), static_cast<qint64>(text.size())) != static_cast<qint64>(text.size())) {
            std::fprintf(stderr, "ocu-sim: cannot write %s: %s\n", qPrintable(f.fileName()),
                         qPrintable(f.errorString()));
            return 2;
        }
        std::printf("ocu-sim: console configuration written to %s (use: ocu --config %s --no-sim)\n",
                    qPrintable(f.fileName()), qPrintable(f.fileName()));
        std::fflush(stdout);
    }

    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
    QTimer poll;
    QObject::connect(&poll, &QTimer::timeout, &app, [&] {
        if (g_quit)
            app.quit();
    });
    poll.start(200);
    bool ok = false;
    const double d = p.value(duration).toDouble(&ok);
    if (ok && d > 0)
        QTimer::singleShot(static_cast<int>(d * 1000), &app, &QCoreApplication::quit);
    const int rc = app.exec();
    sim.stop();
    return rc;
}
