// ocu-sim: the simulated site on its own — simulated JAUS UGVs, an ISO 23725 AHS with haul trucks and an
// OSYRIS paving train — for a second machine, for demos, or to drive another console.
#include "SiteLoader.h"

#include "common/Log.h"
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

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QTimer>

#include <atomic>
#include <csignal>
#include <cstdio>

namespace {
std::atomic<bool> g_quit{false};
void onSignal(int) { g_quit = true; }
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
    QCommandLineOption duration(QStringLiteral("duration"), QStringLiteral("Stop after SECONDS (default: never)."),
                                QStringLiteral("SECONDS"), QStringLiteral("0"));
    QCommandLineOption ugvs(QStringLiteral("ugvs"), QStringLiteral("Number of simulated JAUS UGVs."),
                            QStringLiteral("N"));
    QCommandLineOption trucks(QStringLiteral("trucks"), QStringLiteral("Number of simulated haul trucks (≤ 1000)."),
                              QStringLiteral("N"));
    QCommandLineOption rollers(QStringLiteral("rollers"), QStringLiteral("Number of simulated rollers (0-3)."),
                               QStringLiteral("N"));
    p.addOptions({config, duration, ugvs, trucks, rollers});
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
            std::fprintf(stderr, "ocu-sim: --%s must be an integer 0..%d\n", qPrintable(o.names().constLast()), max);
            return false;
        }
        target = v;
        return true;
    };
    if (!intOption(ugvs, cfg.simulation.jausUgvs, 50) || !intOption(trucks, cfg.simulation.ahsTrucks, 1000) ||
        !intOption(rollers, cfg.simulation.osyrisRollers, 3))
        return 2;
    cfg.simulation.enabled = true;

    ocu::sim::SimulatedSite sim;
    const std::string err = sim.start(cfg);
    if (!err.empty())
        std::fprintf(stderr, "ocu-sim: %s\n", err.c_str());

    std::printf("ocu-sim: simulated site \"%s\" around %.6f, %.6f\n", cfg.name.c_str(), cfg.origin.lat, cfg.origin.lon);
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
            std::printf("  ISO 23725: AHS with %d trucks at %s\n", cfg.simulation.ahsTrucks, l.ws.url.c_str());
#endif
#ifdef OCU_HAVE_SIM_OSYRIS
    if (auto* o = sim.osyris())
        std::printf("  OSYRIS: %zu stations on %s:%u (interface %s)\n", o->stationCount(), cfg.osyris->group.c_str(),
                    cfg.osyris->port, cfg.osyris->interfaceAddress.c_str());
#endif
    std::fflush(stdout);

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
