#include "app/ConsoleApp.h"

#include "app/LogRouting.h"
#include "app/MainWindow.h"
#include "app/ReplayRuntime.h"
#include "app/Screenshot.h"
#include "app/SiteLoader.h"
#include "app/SiteRuntime.h"

#ifdef OCU_HAVE_OCU_VIEW3D
#include "widgets/view3d/Site3DView.h"
#endif

#include <QApplication>
#include <QLabel>
#include <QLocale>
#include <QMessageBox>
#include <QSocketNotifier>
#include <QTimer>
#include <QTranslator>

#include <cerrno>
#include <csignal>
#include <cstdio>

#include <fcntl.h>
#include <unistd.h>

namespace ocu {

namespace {

constexpr int kQuitSignals[] = {SIGINT, SIGTERM, SIGHUP};
int g_signalPipe[2] = {-1, -1};
volatile std::sig_atomic_t g_quitSignal = 0;

// Async-signal-safe only: write(2) and sigaction(2) (POSIX.1-2017 §2.4.3).
extern "C" void onQuitSignal(int sig) {
    const int savedErrno = errno;
    g_quitSignal = sig;
    const unsigned char b = static_cast<unsigned char>(sig);
    if (g_signalPipe[1] >= 0) {
        [[maybe_unused]] const ssize_t n = ::write(g_signalPipe[1], &b, 1);
    }
    // A second signal while the console shuts down ends it at once.
    struct sigaction dfl {};
    dfl.sa_handler = SIG_DFL;
    sigemptyset(&dfl.sa_mask);
    for (int s : kQuitSignals)
        ::sigaction(s, &dfl, nullptr);
    errno = savedErrno;
}

} // namespace

void installQuitSignalHandlers() {
    if (g_signalPipe[0] >= 0)
        return;
    if (::pipe2(g_signalPipe, O_NONBLOCK | O_CLOEXEC) != 0) {
        g_signalPipe[0] = g_signalPipe[1] = -1;
        std::perror("ocu: signal pipe");
        return;
    }
    struct sigaction sa {};
    sa.sa_handler = onQuitSignal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESTART;
    for (int s : kQuitSignals)
        ::sigaction(s, &sa, nullptr);
}

void watchQuitSignals() {
    if (g_signalPipe[0] < 0 || !QCoreApplication::instance())
        return;
    auto* n = new QSocketNotifier(g_signalPipe[0], QSocketNotifier::Read, QCoreApplication::instance());
    QObject::connect(n, &QSocketNotifier::activated, n, [] {
        unsigned char b = 0;
        while (::read(g_signalPipe[0], &b, 1) > 0) {
        }
        std::fprintf(stderr, "ocu: SIG%s received, shutting down\n", sigabbrev_np(g_quitSignal));
        // exit(0), not quit(): every event loop ends (also a modal dialog's) and no window may refuse to
        // close; runConsole then stops the stacks as after closing the window.
        QCoreApplication::exit(0);
    });
}

int quitSignal() {
    return g_quitSignal;
}

int execUnlessQuitting(QApplication& app) {
    // A signal after this test leaves its byte in the pipe: the notifier fires inside exec().
    if (g_quitSignal != 0)
        return 0;
    return app.exec();
}

void prepareSurfaceFormat() {
#ifdef OCU_HAVE_OCU_VIEW3D
    Site3DView::prepareDefaultFormat(); // OpenGL 3.2 core for VTK (toolchain.md §4a)
#endif
}

QString languageFromArgs(const QStringList& args) {
    for (int i = 1; i < args.size(); ++i) {
        const QString& a = args[i];
        if (a == QLatin1String("--lang") && i + 1 < args.size())
            return args[i + 1].toLower();
        if (a.startsWith(QLatin1String("--lang=")))
            return a.mid(7).toLower();
    }
    return {};
}

QString installTranslator(QApplication& app, const QString& lang) {
    QString l = lang;
    if (l.isEmpty())
        l = QLocale::system().name().left(2).toLower();
    if (l != QLatin1String("de") && l != QLatin1String("fr"))
        return QStringLiteral("en");
    auto* t = new QTranslator(&app);
    if (!t->load(QStringLiteral(":/i18n/ocu_%1.qm").arg(l))) {
        delete t;
        return QStringLiteral("en");
    }
    app.installTranslator(t);
    QLocale::setDefault(QLocale(l));
    return l;
}

static bool interactive(const CommandLineOptions& o) {
    return !o.headless && o.screenshotFile.isEmpty() &&
           QGuiApplication::platformName() != QLatin1String("offscreen");
}

// --check-config: the strict reader's verdict on the file (each problem with file:line), nothing started.
static int checkConfig(const QString& file) {
    const auto site = loadSite(file);
    if (!site) {
        std::fprintf(stderr, "%s\n", site.error().c_str());
        return 1;
    }
    std::printf("%s\n", qPrintable(QCoreApplication::translate("ConsoleApp", "%1: the site configuration is "
                                                                             "valid (%2)")
                                       .arg(file, QString::fromStdString(site.value().name))));
    return 0;
}

int runConsole(QApplication& app, const CommandLineOptions& options) {
    if (!options.checkConfigFile.isEmpty())
        return checkConfig(options.checkConfigFile);
    installLogRouting();
    if (!options.logCategories.isEmpty())
        enableLogCategories(options.logCategories);
    if (!options.replayFile.isEmpty())
        return runReplay(app, options); // no site, no stacks

    auto site = loadSite(options.configFile);
    if (!site) {
        const QString msg =
            QCoreApplication::translate("ConsoleApp", "The site configuration was refused:\n%1")
                .arg(QString::fromStdString(site.error()));
        std::fprintf(stderr, "ocu: %s\n", qPrintable(msg));
        if (interactive(options))
            QMessageBox::critical(nullptr, QCoreApplication::translate("ConsoleApp", "Operator Control Unit"),
                                  msg);
        return 2;
    }
    SiteConfig config = std::move(site.value());
    if (options.noSim)
        config.simulation.enabled = false;
    if (options.noRecord)
        config.record.enabled = false;
    if (!options.recordDir.isEmpty())
        config.record.dir = options.recordDir.toStdString();

    SiteRuntime runtime(config);
    runtime.start();

    if (options.headless && (!options.shiftReportPdf.isEmpty() || !options.shiftReportCsv.isEmpty()))
        // Written while the stacks still run (before runHeadless stops them); result on stderr.
        QObject::connect(&app, &QCoreApplication::aboutToQuit, &runtime, [&runtime, &options] {
            const QJsonObject r = runtime.writeShiftReport(options.shiftReportPdf, options.shiftReportCsv);
            std::fprintf(stderr, "ocu: %s\n", qPrintable(r.value(QStringLiteral("message")).toString()));
        });
    if (options.headless)
        return runtime.runHeadless(app, options.durationSeconds, options.commandSocket);

    MainWindow window;
    window.setWindowTitle(QCoreApplication::translate("ConsoleApp", "Operator Control Unit — %1")
                              .arg(QString::fromStdString(config.name)));
    runtime.populate(window);
    const bool screenshot = !options.screenshotFile.isEmpty();
    if (screenshot) {
        if (Workspace w; workspaceFromKey(options.workspace, &w))
            window.setWorkspace(w);
        window.resize(options.size);
        window.show();
    } else if (options.resetLayout || !window.restoreLayout()) {
        window.showFirstStart(); // maximized, not 1200 x 720 on a 1920 x 1080 screen
    } else {
        window.show();
    }
    if (options.night)
        window.setNightMode(true);
    if (Workspace w; !screenshot && workspaceFromKey(options.workspace, &w))
        window.setWorkspace(w); // over the one last used

    int exitCode = 0;
    if (screenshot) {
        QTimer::singleShot(static_cast<int>(options.settleSeconds * 1000), &window, [&] {
            const QString err = saveScreenshot(window, options.view, options.screenshotFile);
            if (!err.isEmpty()) {
                std::fprintf(stderr, "ocu: screenshot failed: %s\n", qPrintable(err));
                exitCode = 4;
            }
            app.quit();
        });
        execUnlessQuitting(app);
        runtime.stop();
        return exitCode;
    }
    exitCode = execUnlessQuitting(app);
    runtime.stop();
    return exitCode;
}

} // namespace ocu
