#pragma once
// A throwaway PostgreSQL server for tests: initdb and pg_ctl (Debian: /usr/lib/postgresql/<v>/bin) in a
// temporary directory, listening on a Unix socket in that directory only (no TCP port, nothing shared with
// other tests). initdb refuses to run as root, so under euid 0 (CI containers) the server runs as the
// `postgres` system user (or `nobody`) through runuser, in a directory handed to that user.
#include <QDir>
#include <QProcess>
#include <QStringList>
#include <QTemporaryDir>

#include <pwd.h>
#include <unistd.h>

#include <memory>

namespace ocu::testing {

class PgTestServer {
public:
    // The newest server binaries, or empty when PostgreSQL's server package is not installed.
    static QString binDir() {
        QDir root(QStringLiteral("/usr/lib/postgresql"));
        QStringList versions = root.entryList(QDir::Dirs | QDir::NoDotAndDotDot);
        std::sort(versions.begin(), versions.end(),
                  [](const QString& a, const QString& b) { return a.toDouble() > b.toDouble(); });
        for (const QString& v : versions) {
            const QString bin = root.filePath(v + QStringLiteral("/bin"));
            if (QFile::exists(bin + QStringLiteral("/initdb")) &&
                QFile::exists(bin + QStringLiteral("/pg_ctl")))
                return bin;
        }
        return {};
    }

    // Creates and starts the cluster; error text on failure.
    QString start() {
        m_bin = binDir();
        if (m_bin.isEmpty())
            return QStringLiteral("no PostgreSQL server binaries");
        // Short path: the socket path must stay under 107 bytes.
        m_dir = std::make_unique<QTemporaryDir>(QStringLiteral("/tmp/ocupg-XXXXXX"));
        if (!m_dir->isValid())
            return QStringLiteral("cannot create a temporary directory");
        if (geteuid() == 0) {
            const passwd* pw = getpwnam("postgres");
            if (!pw)
                pw = getpwnam("nobody");
            if (!pw)
                return QStringLiteral("running as root and no postgres/nobody user to run the server");
            m_user = QString::fromLocal8Bit(pw->pw_name);
            if (chown(m_dir->path().toLocal8Bit().constData(), pw->pw_uid, pw->pw_gid) != 0)
                return QStringLiteral("cannot hand %1 to %2").arg(m_dir->path(), m_user);
        }
        QString out;
        if (!run(QStringLiteral("initdb"),
                 {QStringLiteral("-D"), dataDir(), QStringLiteral("-A"), QStringLiteral("trust"),
                  QStringLiteral("-U"), QStringLiteral("ocu"), QStringLiteral("-E"), QStringLiteral("UTF8"),
                  QStringLiteral("--locale=C"), QStringLiteral("--no-sync")},
                 &out))
            return QStringLiteral("initdb failed: ") + out;
        return startServer();
    }

    QString startServer() {
        QString out;
        const QString opts =
            QStringLiteral("-k %1 -c listen_addresses= -p 5432 -c fsync=off").arg(m_dir->path());
        if (!run(QStringLiteral("pg_ctl"),
                 {QStringLiteral("-D"), dataDir(), QStringLiteral("-o"), opts, QStringLiteral("-l"),
                  m_dir->path() + QStringLiteral("/server.log"), QStringLiteral("-w"), QStringLiteral("-t"),
                  QStringLiteral("60"), QStringLiteral("start")},
                 &out))
            return QStringLiteral("pg_ctl start failed: ") + out;
        return {};
    }

    bool stopServer(const QString& mode = QStringLiteral("fast")) {
        return run(QStringLiteral("pg_ctl"),
                   {QStringLiteral("-D"), dataDir(), QStringLiteral("-m"), mode, QStringLiteral("-w"),
                    QStringLiteral("-t"), QStringLiteral("60"), QStringLiteral("stop")});
    }

    ~PgTestServer() {
        if (m_dir && m_dir->isValid() && QFile::exists(dataDir() + QStringLiteral("/postmaster.pid")))
            stopServer(QStringLiteral("immediate"));
    }

    QString conninfo() const {
        return QStringLiteral("host=%1 port=5432 user=ocu dbname=postgres").arg(m_dir->path());
    }
    QString dataDir() const { return m_dir->path() + QStringLiteral("/data"); }
    QString path() const { return m_dir->path(); }

private:
    bool run(const QString& tool, const QStringList& args, QString* output = nullptr) {
        QProcess p;
        p.setProcessChannelMode(QProcess::MergedChannels);
        p.setWorkingDirectory(m_dir->path());
        const QString exe = m_bin + QLatin1Char('/') + tool;
        if (m_user.isEmpty())
            p.start(exe, args);
        else
            p.start(QStringLiteral("runuser"),
                    QStringList{QStringLiteral("-u"), m_user, QStringLiteral("--"), exe} + args);
        const bool done = p.waitForFinished(120000);
        if (output)
            *output = QString::fromLocal8Bit(p.readAll());
        return done && p.exitStatus() == QProcess::NormalExit && p.exitCode() == 0;
    }

    QString m_bin;
    QString m_user;
    std::unique_ptr<QTemporaryDir> m_dir;
};

} // namespace ocu::testing
