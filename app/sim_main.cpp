// ocu-sim: the simulated site on its own — simulated JAUS UGVs, an ISO 23725 AHS with haul trucks and an
// OSYRIS paving train — for a second machine, for demos, or to drive another console.
#include "app/SiteLoader.h"

#include "protocols/common/Log.h"
#include "sim/SimulatedSite.h"

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
nlohmann::json consoleConfig(const ocu::SiteConfig& cfg, const ocu::sim::SimulatedSite& sim) {
    using nlohmann::json;
    json out;
    out["site"] = {
        {"name", cfg.name + " (ocu-sim)"},
        {"origin",
         {{"latitude", cfg.origin.lat}, {"longitude", cfg.origin.lon}, {"altitude", cfg.origin.alt}}}};
    for (const auto& m : sim.modules())
        m->writeConsoleConfig(cfg, out);
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
    QCommandLineOption truckRate(QStringList{QStringLiteral("position-rate"), QStringLiteral("truck-rate")},
                                 QStringLiteral("Positions per second of each simulated haul truck (1-10; "
                                                "--truck-rate is the older name)."),
                                 QStringLiteral("HZ"));
    // The simulated paving train on a long job.
    QCommandLineOption pavingJob(QStringLiteral("paving-job"),
                                 QStringLiteral("The paving train drives a long job: a LandXML file (first "
                                                "alignment, UTM) or \"built-in\"."),
                                 QStringLiteral("file"));
    QCommandLineOption speedup(QStringLiteral("speedup"),
                               QStringLiteral("Simulated seconds per real second for the rollers (1-1000)."),
                               QStringLiteral("factor"));
    QCommandLineOption lifts(QStringLiteral("lifts"), QStringLiteral("Lifts of the paving job (1-20)."),
                             QStringLiteral("n"));
    p.addOptions({config, duration, ugvs, trucks, rollers, iface, writeConfig, separateMap, truckRate,
                  pavingJob, speedup, lifts});
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
    if (p.isSet(truckRate)) {
        bool ok = false;
        const double hz = p.value(truckRate).toDouble(&ok);
        if (!ok || hz < 1.0 || hz > 10.0) {
            std::fprintf(stderr, "ocu-sim: --position-rate must be a number 1..10\n");
            return 2;
        }
        cfg.simulation.ahsPositionRateHz = hz;
    }
    if (p.isSet(speedup)) {
        bool ok = false;
        const double f = p.value(speedup).toDouble(&ok);
        if (!ok || f < 1 || f > 1000) {
            std::fprintf(stderr, "ocu-sim: --speedup must be a number 1..1000\n");
            return 2;
        }
        cfg.simulation.osyrisSpeedUp = f;
    }
    if (p.isSet(pavingJob))
        cfg.simulation.osyrisPavingJob = p.value(pavingJob).toStdString();
    if (!intOption(lifts, cfg.simulation.osyrisLifts, 20))
        return 2;
    if (cfg.simulation.osyrisLifts < 1) {
        std::fprintf(stderr, "ocu-sim: --lifts must be 1..20\n");
        return 2;
    }
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
    for (const auto& m : sim.modules())
        for (const std::string& line : m->describe(cfg))
            std::printf("  %s\n", line.c_str());
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
