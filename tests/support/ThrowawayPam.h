#pragma once
// Tests: a throwaway PAM service folder (for pam_start_confdir) whose "ocu" service accepts the users and
// passwords given, through pam_exec running a shell script that reads the password pam_exec hands it on
// stdin (expose_authtok). Needs no privilege and leaves the machine's /etc/pam.d alone (docs/roles.md).
#include <QFile>
#include <QString>
#include <QTemporaryDir>

#include <map>

namespace ocu::testing {

class ThrowawayPam {
public:
    explicit ThrowawayPam(const std::map<QString, QString>& passwords) {
        const QString script = m_dir.filePath(QStringLiteral("check.sh"));
        QString body = QStringLiteral("#!/bin/sh\npw=$(tr -d '\\000')\ncase \"$PAM_USER:$pw\" in\n");
        for (const auto& [user, password] : passwords)
            body += QStringLiteral("  '%1:%2') exit 0 ;;\n").arg(user, password);
        body += QStringLiteral("esac\nexit 1\n");
        QFile s(script);
        if (s.open(QIODevice::WriteOnly))
            s.write(body.toUtf8());
        s.close();
        s.setPermissions(QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
        QFile service(m_dir.filePath(QStringLiteral("ocu")));
        if (service.open(QIODevice::WriteOnly))
            // pam_exec says a refusal as a system error: a wrong password goes on to pam_deny, which
            // says it as PAM_AUTH_ERR like pam_unix does.
            service.write(
                QStringLiteral("auth [success=1 default=ignore] pam_exec.so expose_authtok quiet %1\n"
                               "auth requisite pam_deny.so\n"
                               "auth required pam_permit.so\n"
                               "account required pam_permit.so\n")
                    .arg(script)
                    .toUtf8());
    }
    // The folder to give pam_start_confdir.
    QString confDir() const { return m_dir.path(); }

private:
    QTemporaryDir m_dir;
};

} // namespace ocu::testing
