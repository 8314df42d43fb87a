#pragma once
// Everything that runs behind the window for one site: the built-in simulators (when enabled), the
// protocol stacks on their worker threads, the bridges into Qt, and the models the panels show.
#include "models/commands/CommandPermissions.h"
#include "protocols/site/SiteConfig.h"

#include <QJsonObject>

#include <QObject>
#include <QString>

#include <memory>

class QApplication;
class QIODevice;

namespace ocu {

class HeadlessMonitor;
class OperatorSession;
class MainWindow;
struct PanelSpec;
namespace recording {
class Recorder;
}

class SiteRuntime : public QObject {
    Q_OBJECT
public:
    explicit SiteRuntime(SiteConfig config, QObject* parent = nullptr);
    ~SiteRuntime() override;

    // Starts simulators and stacks. What cannot start (a port taken, a bad URL) does not stop the console:
    // its link shows down and the reason is an alarm and a warning on stderr.
    void start();
    void stop();
    const SiteConfig& config() const { return m_config; }

    // Who is at the console: the OS user running it at start, their role from the site's "roles" section
    // (docs/roles.md), on the command gate (permissions, audit) and the alarms (acknowledgements,
    // shelvings); the session switches operator and locks (passwords through PAM, service "ocu").
    OperatorIdentity operatorIdentity() const;
    OperatorSession* operatorSession() const;
    // The identity the site's roles give an OS user at this console.
    OperatorIdentity identityOf(const QString& user) const;

    // The control-room panel (who is at which console), added to the window when the site configures the
    // shared history.
    static PanelSpec controlRoomPanel();
    // Fills the window's panels and connects STOP ALL, link indicators and alarms.
    void populate(MainWindow& window);
    // JSON-lines monitor on stdout, commands on stdin and, with a commandSocket path, on that local socket
    // (app/HeadlessSocket.h; the run then ends by signal or duration, not at the end of stdin); returns the
    // exit code.
    int runHeadless(QApplication& app, double durationSeconds, const QString& commandSocket = {});
    // A headless monitor over the started site (owned by it) with every module's commands and queries;
    // out = nullptr: stdout.
    HeadlessMonitor* attachHeadless(QIODevice* out = nullptr);
    // The shift report (PDF and/or CSV, empty = not asked); the result says what was written
    // (app/ShiftReportCommand.h).
    QJsonObject writeShiftReport(const QString& pdf, const QString& csv);
    // The flight recorder of this run, or nullptr when recording is off or could not start.
    recording::Recorder* recorder() const;

private:
    void startRecorder();
    void startControlRoomHistory();
    struct Impl;
    SiteConfig m_config;
    std::unique_ptr<Impl> m_impl;
};

} // namespace ocu
