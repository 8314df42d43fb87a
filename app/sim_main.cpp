// ocu-sim: the simulated site on its own — the simulators of every protocol of this build (sim/SimModule.h) —
// for a second machine, for demos, or to drive another console.
#include "app/LogFormat.h"
#include "app/SiteLoader.h"
#include "app/Version.h"

#include "protocols/common/Log.h"
#include "sim/SimModule.h"
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
#include <optional>

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

// The site configuration with the command line's simulation options, or the exit code of a refusal.
struct SimSetup {
    ocu::SiteConfig config;
    int exitCode = 0; // not 0: refused (said on stderr)
    double durationSeconds = 0;
    QString writeConfig; // --write-config FILE
};

QString joinedSummaries(const std::vector<std::unique_ptr<ocu::sim::SimModule>>& modules) {
    QStringList parts;
    for (const auto& m : modules)
        parts << QString::fromStdString(m->summary());
    if (parts.size() < 2)
        return parts.value(0);
    return parts.mid(0, parts.size() - 1).join(QStringLiteral(", ")) + QStringLiteral(" and ") + parts.last();
}

SimSetup parseArguments(const QCoreApplication& app) {
    const auto modules = ocu::sim::makeSimModules();
    QCommandLineParser p;
    p.setApplicationDescription(
        QStringLiteral("The simulated site on its own: %1, speaking the real protocols. Prints where each "
                       "simulator listens, then runs until interrupted (or --duration).")
            .arg(joinedSummaries(modules)));
    p.addHelpOption();
    p.addVersionOption();
    QCommandLineOption config({QStringLiteral("c"), QStringLiteral("config")},
                              QStringLiteral("Site configuration whose \"site\" and \"simulation\" sections "
                                             "are used (default: the built-in simulated site)."),
                              QStringLiteral("FILE"));
    QCommandLineOption duration(QStringLiteral("duration"),
                                QStringLiteral("Stop after SECONDS (default: never)."),
                                QStringLiteral("SECONDS"), QStringLiteral("0"));
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
    p.addOptions({config, duration, iface, writeConfig});
    // The simulators' own options (how many machines, ...), from their modules.
    std::vector<std::pair<QCommandLineOption, ocu::sim::SimOption>> simOptions;
    for (const auto& m : modules)
        for (ocu::sim::SimOption& o : m->options()) {
            QStringList names;
            for (const std::string& n : o.names)
                names << QString::fromStdString(n);
            QCommandLineOption q(names, QString::fromStdString(o.description),
                                 QString::fromStdString(o.valueName));
            p.addOption(q);
            simOptions.emplace_back(q, std::move(o));
        }
    p.process(app);

    SimSetup out;
    auto site = ocu::loadSite(p.value(config));
    if (!site) {
        std::fprintf(stderr, "ocu-sim: the site configuration was refused:\n%s\n", site.error().c_str());
        out.exitCode = 2;
        return out;
    }
    out.config = std::move(site.value());
    auto refuse = [&out](const std::string& why) {
        std::fprintf(stderr, "ocu-sim: %s\n", why.c_str());
        out.exitCode = 2;
        return out;
    };
    for (const auto& [q, o] : simOptions)
        if (p.isSet(q))
            if (const std::string e = o.apply(p.value(q).toStdString(), out.config); !e.empty())
                return refuse(e);
    for (const auto& m : modules)
        if (const std::string e = m->checkSimulation(out.config); !e.empty())
            return refuse(e);
    out.config.simulation.enabled = true;
    if (p.isSet(iface)) {
        boost::system::error_code ec;
        boost::asio::ip::make_address_v4(p.value(iface).toStdString(), ec);
        if (ec)
            return refuse("--interface: \"" + p.value(iface).toStdString() + "\" is not an IPv4 address");
        out.config.simulation.interfaceAddress = p.value(iface).toStdString();
    }
    bool ok = false;
    const double d = p.value(duration).toDouble(&ok);
    out.durationSeconds = ok ? d : 0;
    out.writeConfig = p.value(writeConfig);
    return out;
}

// ocu-sim --write-config FILE; false when it could not be written (said on stderr).
bool writeConsoleConfigFile(const QString& path, const ocu::SiteConfig& cfg,
                            const ocu::sim::SimulatedSite& sim) {
    const std::string text = consoleConfig(cfg, sim).dump(2) + "\n";
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate) ||
        f.write(text.data(), static_cast<qint64>(text.size())) != static_cast<qint64>(text.size())) {
        std::fprintf(stderr, "ocu-sim: cannot write %s: %s\n", qPrintable(f.fileName()),
                     qPrintable(f.errorString()));
        return false;
    }
    std::printf("ocu-sim: console configuration written to %s (use: ocu --config %s --no-sim)\n",
                qPrintable(f.fileName()), qPrintable(f.fileName()));
    std::fflush(stdout);
    return true;
}
} // namespace

int main(int argc, char** argv) {
    ocu::installConsoleLogFormat(); // terminal, file or journal (app/LogFormat.h)
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("ocu-sim"));
    QCoreApplication::setApplicationVersion(ocu::versionString());
    SimSetup setup = parseArguments(app);
    if (setup.exitCode != 0)
        return setup.exitCode;
    const ocu::SiteConfig& cfg = setup.config;

    ocu::sim::SimulatedSite sim;
    const std::string err = sim.start(setup.config);
    if (!err.empty())
        std::fprintf(stderr, "ocu-sim: %s\n", err.c_str());

    std::printf("ocu-sim: simulated site \"%s\" around %.6f, %.6f\n", cfg.name.c_str(), cfg.origin.lat,
                cfg.origin.lon);
    for (const auto& m : sim.modules())
        for (const std::string& line : m->describe(cfg))
            std::printf("  %s\n", line.c_str());
    std::fflush(stdout);
    if (!setup.writeConfig.isEmpty() && !writeConsoleConfigFile(setup.writeConfig, cfg, sim))
        return 2;

    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
    QTimer poll;
    QObject::connect(&poll, &QTimer::timeout, &app, [&] {
        if (g_quit)
            app.quit();
    });
    poll.start(200);
    if (setup.durationSeconds > 0)
        QTimer::singleShot(static_cast<int>(setup.durationSeconds * 1000), &app, &QCoreApplication::quit);
    const int rc = app.exec();
    sim.stop();
    return rc;
}
